// SPDX-License-Identifier: MIT
// The perceptual distance between patterns (core/distinctiveness.h, docs/perception.md): its
// scale pinned to the JNDs it is built from, and `semhap distinct` on the built-in patterns.
#include "clirun.h"
#include "distinctiveness.h"
#include "patternlibrary.h"
#include "router.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

/** A pattern of one track on every channel of `model` (its sustain) or of `channels`. */
PatternPtr pattern(const QString &model, const QJsonObject &sustain,
                   const QJsonArray &channels = {QStringLiteral("*")})
{
    const QJsonObject json{
        {"format", "semhap.pattern/1"},
        {"name", "test"},
        {"model", model},
        {"tracks", QJsonArray{QJsonObject{{"channels", channels}, {"sustain", sustain}}}}};
    LoadError error;
    PatternPtr made = Pattern::fromJson(json, QStringLiteral("test.json"), &error);
    if (!made)
        qWarning("%s", qPrintable(error.toString()));
    return made;
}

QJsonObject steady(double value)
{
    return {{"type", "const"}, {"value", value}};
}

QJsonObject pulses(double rate, double width, double amp = 1.0)
{
    return {{"type", "pulses"}, {"amp", amp}, {"width", width}, {"rate", rate}};
}

Percept perceive(const PatternPtr &p, double intensity = 1.0)
{
    const DeviceModelPtr model = DeviceModelLibrary::builtin(p->model());
    Percept percept;
    QString reason;
    if (!Distinctiveness().perceive(p, *model, intensity, &percept, &reason))
        qWarning("%s", qPrintable(reason));
    return percept;
}

PerceptDistance between(const PatternPtr &a, const PatternPtr &b)
{
    return Distinctiveness().distance(perceive(a), perceive(b));
}

} // namespace

class TestDistinct : public QObject
{
    Q_OBJECT

private slots:
    void identicalIsZero_data();
    void identicalIsZero();
    void amplitudeJndIsOne();
    void pulseRateJndIsOne();
    void otherModalityIsFar();
    void placeAroundTheWrist();
    void pulsesAreSeenAsTheBandRendersThem();
    void notFeltBelowDetection();
    void modelWithoutModalityIsRefused();
    void cliMatrixOfPatterns();
    void routerBands_data();
    void routerBands();
    void cliRouterMatrix();
    void cliRefusesBadInput_data();
    void cliRefusesBadInput();
};

void TestDistinct::identicalIsZero_data()
{
    QTest::addColumn<QString>("name");
    for (const QString &name : PatternLibrary::builtinNames())
        QTest::newRow(qPrintable(name)) << name;
}

void TestDistinct::identicalIsZero()
{
    QFETCH(QString, name);
    LoadError error;
    const PatternPtr p = PatternLibrary::load(name, &error);
    QVERIFY(p);
    const PerceptDistance d = between(p, p);
    QCOMPARE(d.total, 0.0);
}

void TestDistinct::amplitudeJndIsOne()
{
    // 2.5 dB apart, steady: about one JND (2.2-2.5 dB in the literature), all of it level.
    const PerceptDistance d =
        between(pattern("lra4", steady(0.5)), pattern("lra4", steady(0.5 * std::pow(10.0, 2.5 / 20))));
    QVERIFY2(d.total > 0.9 && d.total < 1.2, qPrintable(QString::number(d.total)));
    QCOMPARE(d.total, d.level);
}

void TestDistinct::pulseRateJndIsOne()
{
    // Pulse rates 5 and 6 per second: a ratio of 1.2, the rate's JND.
    const PerceptDistance d =
        between(pattern("lra4", pulses(5, 0.05)), pattern("lra4", pulses(6, 0.05)));
    QVERIFY2(std::abs(d.rate - 1.0) < 0.1, qPrintable(QString::number(d.rate)));
    QVERIFY(d.level < 0.1);
}

void TestDistinct::otherModalityIsFar()
{
    const PerceptDistance d =
        between(pattern("lra4", steady(1.0)), pattern("pneumatic6", steady(1.0)));
    QVERIFY(std::isfinite(d.total));
    QVERIFY2(d.total >= 10.0, qPrintable(QString::number(d.total)));
}

void TestDistinct::placeAroundTheWrist()
{
    // One LRA against the one beside it (90 degrees): one place apart; against the opposite
    // one: two.
    const PatternPtr m1 = pattern("lra4", steady(1.0), {"m1"});
    const PerceptDistance beside = between(m1, pattern("lra4", steady(1.0), {"m2"}));
    const PerceptDistance opposite = between(m1, pattern("lra4", steady(1.0), {"m3"}));
    QVERIFY2(std::abs(beside.place - 1.0) < 1e-6, qPrintable(QString::number(beside.place)));
    QVERIFY2(std::abs(opposite.place - 2.0) < 1e-6, qPrintable(QString::number(opposite.place)));
    // The band going round: m1 against m4 is as near as m1 against m2.
    const PerceptDistance round = between(m1, pattern("lra4", steady(1.0), {"m4"}));
    QVERIFY(std::abs(round.place - beside.place) < 1e-6);
}

void TestDistinct::pulsesAreSeenAsTheBandRendersThem()
{
    // 5 Hz pulses on the pneumatic band (7 Hz bandwidth) still come through as 5 Hz; the
    // Geiger's rate follows its intensity.
    const Percept air = perceive(pattern("pneumatic6", pulses(5, 0.1)));
    QVERIFY2(std::abs(air.pulseRate - 5.0) < 0.3, qPrintable(QString::number(air.pulseRate)));
    LoadError error;
    const PatternPtr geiger = PatternLibrary::load("vib.geiger", &error);
    const Percept slow = perceive(geiger, 0.0);
    const Percept fast = perceive(geiger, 1.0);
    QVERIFY2(std::abs(slow.pulseRate - 2.0) < 0.2, qPrintable(QString::number(slow.pulseRate)));
    QVERIFY2(std::abs(fast.pulseRate - 20.0) < 1.0, qPrintable(QString::number(fast.pulseRate)));
    QVERIFY(Distinctiveness().distance(slow, fast).rate > 10);
}

void TestDistinct::notFeltBelowDetection()
{
    const Percept faint = perceive(pattern("lra4", steady(0.001)));
    QVERIFY(!faint.felt());
    const PerceptDistance d = Distinctiveness().distance(faint, perceive(pattern("lra4", steady(0.0))));
    QCOMPARE(d.total, 0.0);
    QVERIFY(Distinctiveness().distance(faint, perceive(pattern("lra4", steady(1.0)))).total > 5);
}

void TestDistinct::modelWithoutModalityIsRefused()
{
    QJsonObject json = DeviceModelLibrary::builtin("lra4")->toJson();
    json.remove("modality");
    json.insert("name", "bare");
    LoadError error;
    const DeviceModelPtr bare = DeviceModel::fromJson(json, "bare.json", &error);
    QVERIFY2(bare, qPrintable(error.toString()));
    QJsonObject withBad = json;
    withBad.insert("modality", "smell");
    QVERIFY(!DeviceModel::fromJson(withBad, "smell.json", &error));
    QCOMPARE(error.toString(),
             QString("smell.json: /modality: unknown modality 'smell' (modalities: vibration, "
                     "pressure, sight)"));
    Percept percept;
    QString reason;
    QVERIFY(!Distinctiveness().perceive(pattern("lra4", steady(1.0)), *bare, 0.5, &percept, &reason));
    QCOMPARE(reason, QString("bare: the model names no modality (vibration, pressure, sight)"));
}

void TestDistinct::cliMatrixOfPatterns()
{
    const CliResult r = semhapRun(
        {"distinct", "--patterns", "vib.geiger,vib.rampup,air.squeeze", "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject json = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(json.value("patterns").toArray().size(), 3);
    const QJsonArray distance = json.value("distance").toArray();
    QCOMPARE(distance.size(), 3);
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(distance[i].toArray()[i].toDouble(), 0.0);
        for (int j = 0; j < 3; ++j)
            QCOMPARE(distance[i].toArray()[j].toDouble(), distance[j].toArray()[i].toDouble());
    }
    QVERIFY(distance[0].toArray()[2].toDouble() >= 10.0); // vibration against pressure

    const CliResult text = semhapRun({"distinct", "--patterns", "vib.geiger,vib.rampup"});
    QVERIFY2(text.code == 0, text.err.constData());
    QVERIFY(text.out.startsWith("Distance in JND at intensity 0.5:\n"));
}

void TestDistinct::routerBands_data()
{
    QTest::addColumn<QString>("router");
    for (const QString &name : QStringList{"C1", "C2", "C3", "C3p", "C4", "C4p", "sensory",
                                           "visual", "none", "usb", "wipe"})
        QTest::newRow(qPrintable(name)) << name;
}

void TestDistinct::routerBands()
{
    QFETCH(QString, router);
    LoadError error;
    std::unique_ptr<Router> compiled = loadRouter(router, {}, &error);
    QVERIFY2(compiled, qPrintable(error.toString()));
    std::vector<BandDistinctiveness> bands;
    QString reason;
    QVERIFY2(Distinctiveness().bands(*compiled, 0.5, &bands, &reason), qPrintable(reason));
    for (const BandDistinctiveness &band : bands) {
        const int n = int(band.messages.size());
        QVERIFY(n > 0);
        QCOMPARE(int(band.distance.size()), n);
        for (int a = 0; a < n; ++a) {
            QCOMPARE(band.distance[size_t(a)][size_t(a)], 0.0);
            for (int b = 0; b < n; ++b)
                QCOMPARE(band.distance[size_t(a)][size_t(b)], band.distance[size_t(b)][size_t(a)]);
        }
        for (const BandDistinctiveness::Pair &pair : band.confusable)
            QVERIFY(pair.a < pair.b && pair.distance < 1.0);
        qInfo("%s %s: %s", qPrintable(router), qPrintable(band.device),
              qPrintable(band.messages.join(", ")));
    }
}

void TestDistinct::cliRouterMatrix()
{
    // One band, three messages: the force detector's grasp and break on two patterns, and
    // a threshold's message on the grasp's pattern again, which nobody can tell from it.
    QTemporaryDir dir;
    const QString path = dir.filePath("one-band.json");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "semhap.router/1", "name": "one-band",
      "nodes": [
        {"id": "right.force", "type": "force", "params": {"gripper": "right"}},
        {"id": "right.F", "type": "signal", "params": {"gripper": "right", "quantity": "F"}},
        {"id": "right.firm", "type": "threshold", "params": {"gripper": "right",
          "message": "grasp", "condition": "above", "begin": 30, "end": 25}},
        {"id": "confirm", "type": "filter", "params": {"category": "confirmation"}},
        {"id": "warn", "type": "filter", "params": {"category": "exception"}},
        {"id": "ramp", "type": "pattern", "params": {"pattern": "vib.rampup"}},
        {"id": "geiger", "type": "pattern", "params": {"pattern": "vib.geiger"}},
        {"id": "right.vibro", "type": "device", "params": {"model": "lra4"}}],
      "links": [
        {"from": "right.force", "to": "confirm"}, {"from": "right.force", "to": "warn"},
        {"from": "right.F", "to": "right.firm"}, {"from": "right.firm", "to": "ramp"},
        {"from": "confirm", "to": "ramp"}, {"from": "warn", "to": "geiger"},
        {"from": "ramp", "to": "right.vibro"}, {"from": "geiger", "to": "right.vibro"}]})");
    file.close();
    const CliResult r = semhapRun({"distinct", path, "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject json = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(json.value("router").toString(), QString("one-band"));
    const QJsonArray bands = json.value("bands").toArray();
    QCOMPARE(bands.size(), 1);
    const QJsonObject band = bands[0].toObject();
    QCOMPARE(band.value("device").toString(), QString("right.vibro"));
    QCOMPARE(band.value("model").toString(), QString("lra4"));
    QCOMPARE(band.value("messages").toArray(),
             (QJsonArray{"right.force:grasp", "right.force:break", "right.firm:grasp"}));
    // One pair (appended: a braced list of one array is a copy of it, to clang).
    QJsonArray confusable;
    confusable.append(QJsonArray{"right.force:grasp", "right.firm:grasp", 0.0});
    QCOMPARE(band.value("confusable").toArray(), confusable);
    const QJsonArray distance = band.value("distance").toArray();
    QVERIFY(distance[0].toArray()[1].toDouble() > 1.0); // the ramp against the Geiger

    const CliResult text = semhapRun({"distinct", path});
    QVERIFY2(text.code == 0, text.err.constData());
    QVERIFY2(text.out.contains("confusable: right.force:grasp and right.firm:grasp, 0.00 JND "
                               "apart"),
             text.out.constData());

    // validate still passes the router, and says which pair a person will confuse.
    const CliResult validated = semhapRun({"validate", path});
    QCOMPARE(validated.code, 0);
    QCOMPARE(QString::fromUtf8(validated.err),
             path + ": warning: on right.vibro, right.force:grasp and right.firm:grasp feel "
                    "0.00 JND apart: a person will confuse them (semhap distinct)\n");
}

void TestDistinct::cliRefusesBadInput_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("error");
    QTest::newRow("nothing") << QStringList{"distinct"} << 2
                             << "a ROUTER or --patterns is required";
    QTest::newRow("both") << QStringList{"distinct", "C3", "--patterns", "vib.geiger"} << 2
                          << "unexpected argument 'C3'";
    QTest::newRow("no router") << QStringList{"distinct", "C9"} << 1 << "C9";
    QTest::newRow("empty name") << QStringList{"distinct", "--patterns", "vib.geiger,"} << 2
                                << "--patterns has an empty name";
    QTest::newRow("intensity") << QStringList{"distinct", "--patterns", "vib.geiger",
                                              "--intensity", "2"}
                               << 2 << "--intensity must be between 0 and 1";
    QTest::newRow("unknown") << QStringList{"distinct", "--patterns", "vib.none"} << 1
                             << "vib.none";
}

void TestDistinct::cliRefusesBadInput()
{
    QFETCH(QStringList, args);
    QFETCH(int, code);
    QFETCH(QString, error);
    const CliResult r = semhapRun(args);
    QCOMPARE(r.code, code);
    QVERIFY2(QString::fromUtf8(r.err).contains(error), r.err.constData());
}

QTEST_GUILESS_MAIN(TestDistinct)
#include "tst_distinct.moc"
