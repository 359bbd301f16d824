// SPDX-License-Identifier: MIT
// Import and export of AHAP and Meta .haptic files: envelopes survive a round trip through a
// semhap pattern (compared sampled at 1 kHz), malformed files are reported as
// FILE: /pointer: reason, and `semhap convert` does the same from the command line.
#include "ahapformat.h"
#include "clitool.h"
#include "hapticconverter.h"
#include "jsonreader.h"
#include "metahapticformat.h"
#include "pattern.h"
#include "patternlibrary.h"

#include <QBuffer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

const QString Data = QStringLiteral(SEMHAP_TEST_DATA);
/** lra4's modulation limit: 1 / (2π · 12 ms / ln 9). */
const double Lra4Limit = 1.0 / (2 * M_PI * 0.012 / std::log(9.0));

QJsonObject toJson(const QByteArray &text)
{
    return QJsonDocument::fromJson(text).object();
}

/** The largest difference of two envelopes sampled at 1 kHz over both their spans. */
double maxDifference(const EnvelopeCurve &a, const EnvelopeCurve &b)
{
    const double end = std::max(a.endTime(), b.endTime()) + 0.01;
    double worst = 0.0;
    for (int k = 0; k <= int(std::lround(end * 1000)); ++k) {
        const double t = k / 1000.0;
        worst = std::max(worst, std::abs(a.value(t) - b.value(t)));
    }
    return worst;
}

ConvertOptions lra4Options()
{
    ConvertOptions options;
    options.model = QStringLiteral("lra4");
    options.modulationLimit = Lra4Limit;
    return options;
}

HapticTimeline readTimeline(const QJsonObject &document, bool ahap)
{
    HapticTimeline timeline;
    LoadError error;
    const bool ok =
        ahap ? AhapFormat::read(document, QStringLiteral("in"), &timeline, nullptr, &error)
             : MetaHapticFormat::read(document, QStringLiteral("in"), &timeline, nullptr, &error);
    if (!ok)
        qWarning("%s", qPrintable(error.toString()));
    return timeline;
}

struct Result
{
    int code = 0;
    QByteArray out;
    QByteArray err;
};

Result semhapRun(const QStringList &arguments)
{
    Result r;
    QByteArray in;
    QBuffer inBuffer(&in);
    QBuffer outBuffer(&r.out);
    QBuffer errBuffer(&r.err);
    inBuffer.open(QIODevice::ReadOnly);
    outBuffer.open(QIODevice::WriteOnly);
    errBuffer.open(QIODevice::WriteOnly);
    CliTool tool({&inBuffer, &outBuffer, &errBuffer});
    r.code = tool.run(arguments);
    return r;
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class TestConvert : public QObject
{
    Q_OBJECT

private slots:
    void roundTrip_data();
    void roundTrip();
    void patternToAhap();
    void modulationMarksSharpness();
    void compatibilityCorpus_data();
    void compatibilityCorpus();
    void warnings();
    void malformed_data();
    void malformed();
    void command();
    void commandErrors_data();
    void commandErrors();
};

void TestConvert::roundTrip_data()
{
    QTest::addColumn<bool>("ahap");
    QTest::addColumn<QByteArray>("document");
    QTest::newRow("ahap file") << true << readFile(Data + QStringLiteral("/heartbeat.ahap"));
    QTest::newRow("ahap continuous") << true << QByteArray(R"({"Pattern": [{"Event": {
        "Time": 0.1, "EventType": "HapticContinuous", "EventDuration": 1.5, "EventParameters": [
        {"ParameterID": "HapticIntensity", "ParameterValue": 0.6},
        {"ParameterID": "AttackTime", "ParameterValue": 0.3},
        {"ParameterID": "ReleaseTime", "ParameterValue": 0.4}]}}]})");
    QTest::newRow("ahap decaying") << true << QByteArray(R"({"Pattern": [{"Event": {
        "Time": 0, "EventType": "HapticContinuous", "EventDuration": 1, "EventParameters": [
        {"ParameterID": "Sustained", "ParameterValue": 0},
        {"ParameterID": "DecayTime", "ParameterValue": 0.5}]}}]})");
    QTest::newRow("ahap transients") << true << QByteArray(R"({"Pattern": [
        {"Event": {"Time": 0, "EventType": "HapticTransient"}},
        {"Event": {"Time": 0.1, "EventType": "HapticTransient", "EventParameters": [
            {"ParameterID": "HapticIntensity", "ParameterValue": 0.5}]}},
        {"Event": {"Time": 0.2, "EventType": "HapticTransient"}}]})");
    QTest::newRow("ahap steps") << true << QByteArray(R"({"Pattern": [
        {"Event": {"Time": 0, "EventType": "HapticContinuous", "EventDuration": 2}},
        {"Parameter": {"ParameterID": "HapticIntensityControl", "Time": 0.5,
                       "ParameterValue": 0.25}},
        {"Parameter": {"ParameterID": "HapticIntensityControl", "Time": 1.5,
                       "ParameterValue": 0.75}}]})");
    // Many breakpoints: the export splits the control curve into curves of 16 points.
    QByteArray points;
    for (int i = 0; i <= 40; ++i)
        points += QByteArray(i ? "," : "") + R"({"Time": )" + QByteArray::number(i * 0.05) +
                  R"(, "ParameterValue": )" + QByteArray::number(i % 2 ? 0.2 : 0.9) + "}";
    QTest::newRow("ahap long curve")
        << true
        << QByteArray(R"({"Pattern": [{"Event": {"Time": 0, "EventType": "HapticContinuous",
           "EventDuration": 2}}, {"ParameterCurve": {"ParameterID": "HapticIntensityControl",
           "Time": 0, "ParameterCurveControlPoints": [)" +
                      points + "]}}]}");
    QTest::newRow("haptic file") << false << readFile(Data + QStringLiteral("/buzz.haptic"));
    QTest::newRow("haptic plain") << false << QByteArray(R"({"version": {"major": 1},
        "signals": {"continuous": {"envelopes": {"amplitude": [{"time": 0, "amplitude": 0.2},
        {"time": 0.4, "amplitude": 1}, {"time": 1.2, "amplitude": 0.3},
        {"time": 2, "amplitude": 0}]}}}})");
}

void TestConvert::roundTrip()
{
    QFETCH(bool, ahap);
    QFETCH(QByteArray, document);
    const HapticTimeline original = readTimeline(toJson(document), ahap);
    QVERIFY(!original.intensity.isEmpty());

    // File → semhap pattern → file → timeline.
    const QJsonObject pattern =
        HapticConverter::timelineToPattern(original, lra4Options(), QStringLiteral("test"));
    LoadError error;
    QVERIFY2(Pattern::fromJson(pattern, QStringLiteral("pattern"), &error),
             qPrintable(error.toString()));
    HapticTimeline rendered;
    QVERIFY2(HapticConverter::patternToTimeline(pattern, QStringLiteral("pattern"), lra4Options(),
                                                &rendered, nullptr, &error),
             qPrintable(error.toString()));
    const QJsonObject written = ahap ? AhapFormat::write(rendered, QStringLiteral("again"))
                                     : MetaHapticFormat::write(rendered, QStringLiteral("again"));
    const HapticTimeline back = readTimeline(written, ahap);

    const double difference = maxDifference(original.intensity, back.intensity);
    QVERIFY2(difference < 0.01,
             qPrintable(QStringLiteral("envelopes differ by %1").arg(difference)));
    QCOMPARE(back.sharpness < 0, original.sharpness < 0);
    if (original.sharpness >= 0)
        QVERIFY(std::abs(back.sharpness - original.sharpness) < 1e-9);
    if (ahap) {
        for (const QJsonValue &entry : written.value(QLatin1String("Pattern")).toArray()) {
            const QJsonObject curve =
                entry.toObject().value(QLatin1String("ParameterCurve")).toObject();
            QVERIFY(curve.value(QLatin1String("ParameterCurveControlPoints")).toArray().size() <=
                    AhapFormat::MaxCurvePoints);
        }
    }
}

void TestConvert::patternToAhap()
{
    // air.squeeze: 0.5 s up, held for a second (no end given), 0.5 s down.
    LoadError error;
    const PatternPtr squeeze = PatternLibrary::builtin(QStringLiteral("air.squeeze"));
    QStringList warnings;
    HapticTimeline timeline;
    QVERIFY(HapticConverter::patternToTimeline(squeeze->toJson(), QStringLiteral("air.squeeze"),
                                               {}, &timeline, &warnings, &error));
    QVERIFY(warnings.join(QLatin1Char('\n')).contains(QStringLiteral("--release-at")));
    const EnvelopeCurve &e = timeline.intensity;
    QVERIFY(std::abs(e.value(0.25) - 0.5) < 0.01);
    QVERIFY(std::abs(e.value(1.0) - 1.0) < 0.01);
    QVERIFY(std::abs(e.value(1.75) - 0.5) < 0.01);
    QVERIFY(std::abs(e.value(2.0)) < 0.01);
    QVERIFY(e.points().size() <= 6); // ramps and holds are a few breakpoints, not samples

    ConvertOptions options;
    options.releaseAt = 0.25;
    QVERIFY(HapticConverter::patternToTimeline(squeeze->toJson(), QStringLiteral("air.squeeze"),
                                               options, &timeline, nullptr, &error));
    QVERIFY(std::abs(timeline.intensity.value(0.25) - 0.5) < 0.01);
    QVERIFY(std::abs(timeline.intensity.endTime() - 0.75) < 1e-9);
}

void TestConvert::modulationMarksSharpness()
{
    HapticTimeline timeline;
    timeline.intensity = EnvelopeCurve({{0, 0}, {0.5, 1}, {1, 0}});
    timeline.sharpness = 0.5;
    const QJsonObject pattern =
        HapticConverter::timelineToPattern(timeline, lra4Options(), QStringLiteral("test"));
    const QJsonObject attack = pattern.value(QLatin1String("tracks"))[0]
                                   .toObject()
                                   .value(QLatin1String("attack"))
                                   .toObject();
    QCOMPARE(attack.value(QLatin1String("type")).toString(), QStringLiteral("product"));
    QCOMPARE(attack.value(QLatin1String("of"))[1][QLatin1String("freq")].toDouble(),
             0.5 * Lra4Limit);
    QCOMPARE(pattern.value(QLatin1String("sharpness")).toDouble(), 0.5);
    // The pattern keeps its sharpness: any export takes the modulation off again.
    ConvertOptions plain = lra4Options();
    plain.modulationLimit = 0;
    HapticTimeline exported;
    LoadError error;
    QVERIFY(HapticConverter::patternToTimeline(pattern, QStringLiteral("p"), plain, &exported,
                                               nullptr, &error));
    QCOMPARE(exported.sharpness, 0.5);
    QVERIFY(maxDifference(exported.intensity, timeline.intensity) < 0.01);
    // A pattern of one's own with such an oscillation and no sharpness: unless the export
    // is asked to read it as sharpness, the oscillation is part of the envelope.
    QJsonObject own = pattern;
    own.remove(QLatin1String("sharpness"));
    HapticTimeline modulated;
    QVERIFY(HapticConverter::patternToTimeline(own, QStringLiteral("p"), plain, &modulated,
                                               nullptr, &error));
    QVERIFY(modulated.sharpness < 0);
    QVERIFY(maxDifference(modulated.intensity, timeline.intensity) > 0.3);
    QVERIFY(HapticConverter::patternToTimeline(own, QStringLiteral("p"), lra4Options(), &modulated,
                                               nullptr, &error));
    QCOMPARE(modulated.sharpness, 0.5);
}

using Samples = QList<QPair<double, double>>;

void TestConvert::compatibilityCorpus_data()
{
    // Files of our own that use every field the formats' public documentation describes
    // (Apple's "Representing Haptic Patterns in AHAP Files", Meta Haptics Studio's .haptic),
    // with what each must import as, by the default options: envelopes as they are.
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("warnings");
    QTest::addColumn<double>("sharpness"); // < 0: none
    QTest::addColumn<Samples>("samples");  // (t, intensity)
    QTest::newRow("AHAP transient, sustained and decaying events")
        << "transient-and-continuous.ahap" << 0
        << (0.4 * 0.8 * 0.025 + 0.6 * 0.6 * 0.5) / (0.8 * 0.025 + 0.6 * 0.5)
        << Samples{{0.01, 0.8}, {0.15, 0.3}, {0.3, 0.6}, {0.5, 0.3}, {0.9, 0.5}, {1.1, 0.0}};
    QTest::newRow("AHAP dynamic parameters and curves")
        << "parameters.ahap" << 5 << 0.5
        << Samples{{0.2, 0.6}, {0.45, 0.2}, {0.75, 0.5}, {0.99, 0.5}};
    QTest::newRow("AHAP audio beside a tap")
        << "audio.ahap" << 6 << -1.0 << Samples{{0.3, 0.0}, {0.51, 0.5}, {0.6, 0.0}};
    QTest::newRow("AHAP without sharpness")
        << "no-sharpness.ahap" << 0 << -1.0 << Samples{{0.5, 0.5}, {1.0, 1.0}, {1.5, 0.5}};
    QTest::newRow("AHAP with keys from the future")
        << "forward-compatible.ahap" << 6 << 0.3 << Samples{{0.5, 0.6}, {0.99, 0.404}};
    QTest::newRow(".haptic with every field")
        << "full.haptic" << 0 << 0.3357168784
        << Samples{{0.05, 0.5}, {0.11, 1.0}, {0.3, 0.7}, {0.75, 0.2}};
    QTest::newRow(".haptic amplitude only")
        << "amplitude-only.haptic" << 0 << -1.0 << Samples{{0.25, 0.55}, {0.75, 0.55}};
    QTest::newRow(".haptic with keys from the future")
        << "forward-compatible.haptic" << 8 << 0.5
        << Samples{{0.1, 0.75}, {0.21, 0.975}, {0.4, 0.5}};
}

void TestConvert::compatibilityCorpus()
{
    QFETCH(QString, file);
    QFETCH(int, warnings);
    QFETCH(double, sharpness);
    QFETCH(Samples, samples);
    const QString path = Data + QStringLiteral("/compat/") + file;
    ConvertOptions options; // the defaults: no modulation
    QJsonObject pattern;
    QStringList said;
    LoadError error;
    QVERIFY2(HapticConverter::readPattern(path, options, &pattern, &said, &error),
             qPrintable(error.toString()));
    QVERIFY2(said.size() == warnings, qPrintable(said.join(QLatin1Char('\n'))));
    for (const QString &warning : said)
        QVERIFY2(warning.startsWith(path + QStringLiteral(": /")), qPrintable(warning));
    QVERIFY2(Pattern::fromJson(pattern, path, &error), qPrintable(error.toString()));
    // A file that says nothing of sharpness has none; one that does keeps it, and neither
    // has its envelope chopped by it.
    QCOMPARE(pattern.contains(QLatin1String("sharpness")), sharpness >= 0);
    if (sharpness >= 0)
        QVERIFY(std::abs(pattern.value(QLatin1String("sharpness")).toDouble() - sharpness) < 1e-6);
    const QJsonObject attack = pattern.value(QLatin1String("tracks"))[0]
                                   .toObject()
                                   .value(QLatin1String("attack"))
                                   .toObject();
    QCOMPARE(attack.value(QLatin1String("type")).toString(), QStringLiteral("keyframes"));

    // The envelope, sampled.
    HapticTimeline imported;
    QVERIFY(
        HapticConverter::patternToTimeline(pattern, path, options, &imported, nullptr, &error));
    for (const auto &[t, v] : samples)
        QVERIFY2(std::abs(imported.intensity.value(t) - v) < 0.002,
                 qPrintable(QStringLiteral("at %1 s: %2, expected %3")
                                .arg(t)
                                .arg(imported.intensity.value(t))
                                .arg(v)));

    // Round trip through the same format: envelope and sharpness come back.
    const bool ahap = file.endsWith(QStringLiteral(".ahap"));
    const QJsonObject written = ahap ? AhapFormat::write(imported, QStringLiteral("again"))
                                     : MetaHapticFormat::write(imported, QStringLiteral("again"));
    const HapticTimeline back = readTimeline(written, ahap);
    QVERIFY(maxDifference(imported.intensity, back.intensity) < 0.01);
    QCOMPARE(back.sharpness < 0, sharpness < 0);
    if (sharpness >= 0)
        QVERIFY(std::abs(back.sharpness - imported.sharpness) < 1e-9);
}

void TestConvert::warnings()
{
    QStringList warnings;
    HapticTimeline timeline;
    LoadError error;
    QVERIFY(AhapFormat::read(toJson(readFile(Data + QStringLiteral("/heartbeat.ahap"))),
                             QStringLiteral("heartbeat.ahap"), &timeline, &warnings, &error));
    QCOMPARE(warnings, QStringList{QStringLiteral("heartbeat.ahap: /Pattern/3/Event: ignored: "
                                                  "audio events have no haptic equivalent")});
    // Two tracks on one channel collapse into one envelope.
    const PatternPtr proportional = PatternLibrary::builtin(QStringLiteral("air.proportional"));
    warnings.clear();
    QVERIFY(HapticConverter::patternToTimeline(proportional->toJson(), QStringLiteral("p.json"),
                                               {}, &timeline, &warnings, &error));
    QVERIFY(warnings.join(QLatin1Char('\n')).contains(QStringLiteral("2 tracks collapse")));
    ConvertOptions thumb;
    thumb.channel = QStringLiteral("thumb");
    warnings.clear();
    QVERIFY(HapticConverter::patternToTimeline(proportional->toJson(), QStringLiteral("p.json"),
                                               thumb, &timeline, &warnings, &error));
    QVERIFY(!warnings.join(QLatin1Char('\n')).contains(QStringLiteral("collapse")));
}

void TestConvert::malformed_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("expected");
    QTest::newRow("ahap bad json") << "x.ahap" << QByteArray("{\"Pattern\": [],}")
                                   << "x.ahap:1:17: invalid JSON: object is missing after a comma";
    QTest::newRow("ahap no pattern")
        << "x.ahap" << QByteArray(R"({"Version": 1})") << "x.ahap: missing key 'Pattern'";
    QTest::newRow("ahap pattern type") << "x.ahap" << QByteArray(R"({"Pattern": {}})")
                                       << "x.ahap: /Pattern: expected an array, got an object";
    QTest::newRow("ahap entry") << "x.ahap" << QByteArray(R"({"Pattern": [{"Evnt": {}}]})")
                                << "x.ahap: /Pattern/0: expected one of 'Event', "
                                   "'ParameterCurve' or 'Parameter', got 'Evnt'";
    QTest::newRow("ahap misspelt curves")
        << "x.ahap"
        << QByteArray(R"({"Pattern": [{"ParameterCurves": {"ParameterID": "HapticIntensityControl",
           "Time": 0, "ParameterCurveControlPoints": [{"Time": 0, "ParameterValue": 1}]}}]})")
        << "x.ahap: /Pattern/0: expected one of 'Event', 'ParameterCurve' or 'Parameter', got "
           "'ParameterCurves'";
    QTest::newRow("ahap two entries")
        << "x.ahap" << QByteArray(R"({"Pattern": [{"Event": {}, "Parameter": {}}]})")
        << "x.ahap: /Pattern/0: holds both 'Event' and 'Parameter'; an element is one of them";
    QTest::newRow("ahap event type")
        << "x.ahap" << QByteArray(R"({"Pattern": [{"Event": {"Time": 0, "EventType": "Buzz"}}]})")
        << "x.ahap: /Pattern/0/Event/EventType: unknown event type 'Buzz' (expected "
           "HapticTransient, HapticContinuous, AudioContinuous or AudioCustom)";
    QTest::newRow("ahap no duration")
        << "x.ahap"
        << QByteArray(R"({"Pattern": [{"Event": {"Time": 0, "EventType": "HapticContinuous"}}]})")
        << "x.ahap: /Pattern/0/Event: missing key 'EventDuration'";
    QTest::newRow("ahap negative time")
        << "x.ahap"
        << QByteArray(R"({"Pattern": [{"Event": {"Time": -1, "EventType": "HapticTransient"}}]})")
        << "x.ahap: /Pattern/0/Event/Time: must not be negative, got -1";
    QTest::newRow("ahap intensity")
        << "x.ahap" << QByteArray(R"({"Pattern": [{"Event": {"Time": 0, "EventType":
           "HapticTransient", "EventParameters": [{"ParameterID": "HapticIntensity",
           "ParameterValue": 1.5}]}}]})")
        << "x.ahap: /Pattern/0/Event/EventParameters/0/ParameterValue: must be within [0, 1], "
           "got 1.5";
    QTest::newRow("ahap typo") << "x.ahap" << QByteArray(R"({"Pattern": [{"Event": {"Tme": 0}}]})")
                               << "x.ahap: /Pattern/0/Event: missing key 'Time'";
    QTest::newRow("ahap curve order")
        << "x.ahap" << QByteArray(R"({"Pattern": [{"ParameterCurve": {"ParameterID":
           "HapticIntensityControl", "Time": 0, "ParameterCurveControlPoints": [
           {"Time": 0.5, "ParameterValue": 1}, {"Time": 0.2, "ParameterValue": 0}]}}]})")
        << "x.ahap: /Pattern/0/ParameterCurve/ParameterCurveControlPoints/1/Time: control point "
           "times must not decrease";
    QTest::newRow("ahap empty curve")
        << "x.ahap" << QByteArray(R"({"Pattern": [{"ParameterCurve": {"ParameterID":
           "HapticIntensityControl", "Time": 0, "ParameterCurveControlPoints": []}}]})")
        << "x.ahap: /Pattern/0/ParameterCurve/ParameterCurveControlPoints: expected at least "
           "one control point";
    QTest::newRow("haptic no signals") << "x.haptic" << QByteArray(R"({"version": {"major": 1}})")
                                       << "x.haptic: missing key 'signals'";
    QTest::newRow("haptic version")
        << "x.haptic"
        << QByteArray(R"({"version": {"major": 2}, "signals": {"continuous": {"envelopes":
           {"amplitude": []}}}})")
        << "x.haptic: /version/major: unsupported version 2, expected 1";
    QTest::newRow("haptic no amplitude")
        << "x.haptic"
        << QByteArray(R"({"version": {"major": 1}, "signals": {"continuous": {"envelopes": {}}}})")
        << "x.haptic: /signals/continuous/envelopes: missing key 'amplitude'";
    QTest::newRow("haptic amplitude")
        << "x.haptic"
        << QByteArray(R"({"version": {"major": 1}, "signals": {"continuous": {"envelopes":
           {"amplitude": [{"time": 0, "amplitude": 2}]}}}})")
        << "x.haptic: /signals/continuous/envelopes/amplitude/0/amplitude: must be within "
           "[0, 1], got 2";
    QTest::newRow("haptic order")
        << "x.haptic"
        << QByteArray(R"({"version": {"major": 1}, "signals": {"continuous": {"envelopes":
           {"amplitude": [{"time": 1, "amplitude": 0}, {"time": 0.5, "amplitude": 1}]}}}})")
        << "x.haptic: /signals/continuous/envelopes/amplitude/1/time: times must not decrease";
    QTest::newRow("haptic emphasis")
        << "x.haptic"
        << QByteArray(R"({"version": {"major": 1}, "signals": {"continuous": {"envelopes":
           {"amplitude": [{"time": 0, "amplitude": 0, "emphasis": {"amplitude": 1}}]}}}})")
        << "x.haptic: /signals/continuous/envelopes/amplitude/0/emphasis: missing key "
           "'frequency'";
    QTest::newRow("haptic frequency type")
        << "x.haptic"
        << QByteArray(R"({"version": {"major": 1}, "signals": {"continuous": {"envelopes":
           {"amplitude": [], "frequency": [{"time": 0, "frequency": "high"}]}}}})")
        << "x.haptic: /signals/continuous/envelopes/frequency/0/frequency: expected a number, "
           "got a string";
    QTest::newRow("pattern") << "x.json" << QByteArray(R"({"format": "semhap.pattern/1"})")
                             << "x.json: missing key 'name'";
    QTest::newRow("extension")
        << "x.wav" << QByteArray("{}")
        << "x.wav: unknown file type '.wav': use .json (semhap pattern), "
           ".ahap (Apple Core Haptics), .haptic (Meta) or .hjif (MPEG haptics)";
}

void TestConvert::malformed()
{
    QFETCH(QString, file);
    QFETCH(QByteArray, content);
    QFETCH(QString, expected);
    QJsonObject pattern;
    LoadError error;
    QVERIFY(!HapticConverter::parsePattern(content, file, {}, &pattern, nullptr, &error));
    QCOMPARE(error.toString(), expected);
}

void TestConvert::command()
{
    QTemporaryDir dir;
    const QString json = dir.filePath(QStringLiteral("heartbeat.json"));
    const QString ahap = dir.filePath(QStringLiteral("heartbeat.ahap"));
    Result r = semhapRun({QStringLiteral("convert"), Data + QStringLiteral("/heartbeat.ahap"),
                          json, QStringLiteral("--device"), QStringLiteral("pneumatic6"),
                          QStringLiteral("--channel"), QStringLiteral("b2")});
    QCOMPARE(r.code, 0);
    QVERIFY(r.err.contains("/Pattern/3/Event: ignored: audio events"));
    LoadError error;
    const PatternPtr pattern = Pattern::fromFile(json, &error);
    QVERIFY2(pattern, qPrintable(error.toString()));
    QCOMPARE(pattern->name(), QStringLiteral("heartbeat"));
    QCOMPARE(pattern->model(), QStringLiteral("pneumatic6"));
    QCOMPARE(pattern->tracks()[0].channels, QStringList{QStringLiteral("b2")});

    r = semhapRun({QStringLiteral("convert"), json, ahap});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.err, QByteArray());
    HapticTimeline original =
        readTimeline(toJson(readFile(Data + QStringLiteral("/heartbeat.ahap"))), true);
    HapticTimeline back = readTimeline(toJson(readFile(ahap)), true);
    QVERIFY(maxDifference(original.intensity, back.intensity) < 0.01);
    QVERIFY(std::abs(back.sharpness - original.sharpness) < 1e-9);

    // A built-in straight to .haptic.
    const QString haptic = dir.filePath(QStringLiteral("geiger.haptic"));
    const QString geiger = dir.filePath(QStringLiteral("geiger.json"));
    QFile file(geiger);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(
        QJsonDocument(PatternLibrary::builtin(QStringLiteral("vib.geiger"))->toJson()).toJson());
    file.close();
    r = semhapRun({QStringLiteral("convert"), geiger, haptic, QStringLiteral("--release-at"),
                   QStringLiteral("0.5")});
    QCOMPARE(r.code, 0);
    const HapticTimeline pulses = readTimeline(toJson(readFile(haptic)), false);
    // 20 Hz pulses of 25 ms: on at 0.01 s and 0.06 s, off at 0.035 s.
    QCOMPARE(pulses.intensity.value(0.01), 1.0);
    QCOMPARE(pulses.intensity.value(0.035), 0.0);
    QCOMPARE(pulses.intensity.value(0.06), 1.0);
}

void TestConvert::commandErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("message");
    const QString ahap = Data + QStringLiteral("/heartbeat.ahap");
    QTest::newRow("one file") << QStringList{ahap} << 2 << "expected IN and OUT, got 1";
    QTest::newRow("extension") << QStringList{ahap, QStringLiteral("out.wav")} << 2
                               << "out.wav: unknown file type '.wav'";
    QTest::newRow("device") << QStringList{ahap, QStringLiteral("out.json"),
                                           QStringLiteral("--device"), QStringLiteral("lra5")}
                            << 2 << "unknown device model 'lra5'";
    QTest::newRow("channel") << QStringList{ahap, QStringLiteral("out.json"),
                                            QStringLiteral("--channel"), QStringLiteral("b1")}
                             << 2 << "model lra4 has no channel 'b1'";
    QTest::newRow("missing") << QStringList{QStringLiteral("nothere.ahap"),
                                            QStringLiteral("out.json")}
                             << 1 << "nothere.ahap: cannot read";
    QTest::newRow("device for pattern")
        << QStringList{QStringLiteral("in.json"), QStringLiteral("out.ahap"),
                       QStringLiteral("--device"), QStringLiteral("lra4")}
        << 2 << "--device is for imports";
}

void TestConvert::commandErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QString, message);
    const Result r = semhapRun(QStringList{QStringLiteral("convert")} + arguments);
    QCOMPARE(r.code, code);
    QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
}

QTEST_GUILESS_MAIN(TestConvert)
#include "tst_convert.moc"
