// SPDX-License-Identifier: MIT
// Pattern documents: the built-in library loads and round-trips; malformed documents give
// the exact error a user reads.
#include "pattern.h"
#include "patternlibrary.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

using namespace semhap;

class TestPattern : public QObject
{
    Q_OBJECT

private slots:
    void builtinNames();
    void builtins_data();
    void builtins();
    void load();
    void declaredParams();
    void errors_data();
    void errors();
    void unreadable();

private:
    QTemporaryDir m_dir;
};

void TestPattern::builtinNames()
{
    const QStringList expected{QStringLiteral("air.proportional"), QStringLiteral("air.pulse5hz"),
                               QStringLiteral("air.squeeze"),      QStringLiteral("vib.geiger"),
                               QStringLiteral("vib.rampup"),       QStringLiteral("visual.blink"),
                               QStringLiteral("visual.confirm")};
    QCOMPARE(PatternLibrary::builtinNames(), expected);
}

void TestPattern::builtins_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QList<QStringList>>("channels");
    QTest::addColumn<bool>("attack");
    QTest::addColumn<bool>("release");

    const QStringList all{QStringLiteral("*")};
    QTest::newRow("air.squeeze") << "air.squeeze"
                                 << "pneumatic6" << QList<QStringList>{all} << true << true;
    QTest::newRow("vib.rampup") << "vib.rampup"
                                << "lra4" << QList<QStringList>{all} << true << true;
    QTest::newRow("air.pulse5hz") << "air.pulse5hz"
                                  << "pneumatic6" << QList<QStringList>{all} << false << false;
    QTest::newRow("vib.geiger") << "vib.geiger"
                                << "lra4" << QList<QStringList>{all} << false << false;
    QTest::newRow("air.proportional")
        << "air.proportional"
        << "fingertips2"
        << QList<QStringList>{{QStringLiteral("thumb")}, {QStringLiteral("index")}} << false
        << false;
    QTest::newRow("visual.confirm") << "visual.confirm"
                                    << "overlay" << QList<QStringList>{all} << false << false;
    QTest::newRow("visual.blink") << "visual.blink"
                                  << "overlay" << QList<QStringList>{all} << false << false;
}

void TestPattern::builtins()
{
    QFETCH(QString, name);
    QFETCH(QString, model);
    QFETCH(QList<QStringList>, channels);
    QFETCH(bool, attack);
    QFETCH(bool, release);

    const PatternPtr pattern = PatternLibrary::builtin(name);
    QVERIFY(pattern);
    QCOMPARE(PatternLibrary::builtin(name), pattern); // parsed once, then shared
    QCOMPARE(pattern->name(), name);
    QCOMPARE(pattern->model(), model);
    QVERIFY(!pattern->description().isEmpty());
    QCOMPARE(int(pattern->tracks().size()), int(channels.size()));
    for (size_t i = 0; i < pattern->tracks().size(); ++i) {
        const PatternTrack &track = pattern->tracks()[i];
        QCOMPARE(track.channels, channels[int(i)]);
        QCOMPARE(bool(track.attack), attack);
        QVERIFY(track.sustain);
        QCOMPARE(bool(track.release), release);
    }

    LoadError error;
    const PatternPtr again = Pattern::fromJson(pattern->toJson(), name, &error);
    QVERIFY2(again, qPrintable(error.toString()));
    QCOMPARE(again->toJson(), pattern->toJson());
    QCOMPARE(again->stateSize(), pattern->stateSize());
}

void TestPattern::load()
{
    LoadError error;
    QVERIFY(PatternLibrary::load(QStringLiteral("vib.geiger"), &error));
    QVERIFY(!PatternLibrary::load(QStringLiteral("vib.nope"), &error));
    QVERIFY(error.toString().startsWith(
        QLatin1String("vib.nope: no built-in pattern of that name (there are air.")));
    const QString path = QStringLiteral(SEMHAP_RESOURCES "/patterns/air.squeeze.json");
    const PatternPtr fromPath = PatternLibrary::load(path, &error);
    QVERIFY(fromPath);
    QCOMPARE(fromPath->name(), QStringLiteral("air.squeeze"));
}

void TestPattern::declaredParams()
{
    const QByteArray text = R"({"format":"semhap.pattern/1","name":"p","model":"lra4",
        "params":{"speed":3,"intensity":0.5},
        "tracks":[{"channels":["m1","m2"],"sustain":{"type":"pulses","rate":{"param":"speed"},
        "width":0.01}}]})";
    const PatternPtr pattern =
        Pattern::fromJson(QJsonDocument::fromJson(text).object(), QStringLiteral("p"), nullptr);
    QVERIFY(pattern);
    QCOMPARE(pattern->params().size(), 2);
    QCOMPARE(pattern->params().defaultValue(ParamTable::Intensity), 0.5);
    QCOMPARE(pattern->params().defaultValue(pattern->params().indexOf(QStringLiteral("speed"))),
             3.0);
    QCOMPARE(pattern->stateSize(), 2);
    const QJsonObject params = pattern->toJson().value(QLatin1String("params")).toObject();
    QCOMPARE(params.value(QLatin1String("intensity")).toDouble(), 0.5);
    QCOMPARE(params.value(QLatin1String("speed")).toDouble(), 3.0);
}

void TestPattern::errors_data()
{
    QTest::addColumn<QByteArray>("document");
    QTest::addColumn<QString>("error");

    // A valid document's start, so each row shows only what it breaks.
    const QByteArray head = R"({"format":"semhap.pattern/1","name":"p","model":"lra4",)";

    QTest::newRow("bad JSON: missing comma")
        << QByteArray("{\n  \"format\": \"semhap.pattern/1\",\n  \"name\": \"x\"\n"
                      "  \"model\": \"lra4\"\n}")
        << "FILE:4:4: invalid JSON: unterminated object";
    QTest::newRow("bad JSON: truncated")
        << QByteArray("{\"format\": ") << "FILE:1:12: invalid JSON: unterminated object";
    QTest::newRow("bad JSON: stray comma, after a multi-byte line")
        << QByteArray("{\"a\": 1,\n \"Über\": [1, 2,,]\n}")
        << "FILE:2:17: invalid JSON: illegal value";
    QTest::newRow("not an object")
        << QByteArray("[1]") << "FILE:1:1: expected a JSON object, got an array";
    QTest::newRow("a key twice")
        << QByteArray(R"({"format": "semhap.pattern/1", "name": "p", "name": "q"})")
        << "FILE: /name: the key appears twice in its object; which value was meant is unknown";
    QByteArray tracks;
    for (int i = 0; i <= Pattern::MaxTracks; ++i)
        tracks += QByteArray(i ? "," : "") + R"({"channels": ["*"]})";
    QTest::newRow("too many tracks")
        << QByteArray(
               R"({"format": "semhap.pattern/1", "name": "p", "model": "lra4", "tracks": [)" +
               tracks + "]}")
        << "FILE: /tracks: 1025 tracks, more than the 1024 a pattern may have";
    QTest::newRow("no format") << QByteArray(R"({"name":"p"})") << "FILE: missing key 'format'";
    QTest::newRow("wrong format")
        << QByteArray(R"({"format":"semhap.router/1","name":"p"})")
        << "FILE: /format: unsupported format 'semhap.router/1', expected 'semhap.pattern/1'";
    QTest::newRow("format of the wrong type")
        << QByteArray(R"({"format":1})") << "FILE: /format: expected a string, got a number";
    QTest::newRow("unknown key") << QByteArray(R"({"format":"semhap.pattern/1","nmae":"p"})")
                                 << "FILE: unknown key 'nmae'";
    QTest::newRow("missing name")
        << QByteArray(R"({"format":"semhap.pattern/1","model":"lra4","tracks":[]})")
        << "FILE: missing key 'name'";
    QTest::newRow("empty name") << QByteArray(
                                       R"({"format":"semhap.pattern/1","name":"","model":"lra4"})")
                                << "FILE: /name: must not be empty";
    QTest::newRow("model of the wrong type")
        << QByteArray(R"({"format":"semhap.pattern/1","name":"p","model":4})")
        << "FILE: /model: expected a string, got a number";
    QTest::newRow("description of the wrong type")
        << head + R"("description":["a"],"tracks":[]})"
        << "FILE: /description: expected a string, got an array";
    QTest::newRow("param of the wrong type")
        << head + R"("params":{"ref":"120"},"tracks":[]})"
        << "FILE: /params/ref: expected a number, got a string";
    QTest::newRow("no tracks") << head.chopped(1) + "}"
                               << "FILE: missing key 'tracks'";
    QTest::newRow("empty tracks") << head + R"("tracks":[]})"
                                  << "FILE: /tracks: expected at least one track";
    QTest::newRow("tracks of the wrong type") << head + R"("tracks":{}})"
                                              << "FILE: /tracks: expected an array, got an object";
    QTest::newRow("track of the wrong type") << head + R"("tracks":[true]})"
                                             << "FILE: /tracks/0: expected a track object, got "
                                                "a boolean";
    QTest::newRow("no channels") << head + R"("tracks":[{"sustain":{"type":"const","value":1}}]})"
                                 << "FILE: /tracks/0: missing key 'channels'";
    QTest::newRow("empty channels") << head + R"("tracks":[{"channels":[]}]})"
                                    << "FILE: /tracks/0/channels: expected at least one channel";
    QTest::newRow("empty channel name") << head + R"("tracks":[{"channels":["m1",""]}]})"
                                        << "FILE: /tracks/0/channels/1: expected a channel "
                                           "name, got a string";
    QTest::newRow("unknown track key") << head + R"("tracks":[{"channels":["*"],"sustian":1}]})"
                                       << "FILE: /tracks/0: unknown key 'sustian'";
    QTest::newRow("unknown waveform type")
        << head + R"("tracks":[{"channels":["*"]},{"channels":["*"],"sustain":{"type":"saw"}}]})"
        << "FILE: /tracks/1/sustain/type: unknown waveform type 'saw'";
    QTest::newRow("unknown parameter")
        << head + R"("tracks":[{"channels":["*"],)"
                  R"("sustain":{"type":"pulses","rate":{"param":"speed"},"width":0.1}}]})"
        << "FILE: /tracks/0/sustain/rate: unknown parameter 'speed'";
    QTest::newRow("negative time")
        << head + R"("tracks":[{"channels":["*"],"attack":{"type":"ramp","to":1,"time":-0.5}}]})"
        << "FILE: /tracks/0/attack/time: must not be negative, got -0.5";
    QTest::newRow("infinite release")
        << head + R"("tracks":[{"channels":["*"],"release":{"type":"square","freq":5}}]})"
        << "FILE: /tracks/0/release: a release must end, but this one lasts forever";
    QTest::newRow("wrong-typed signal key")
        << head + R"("tracks":[{"channels":["*"],"sustain":{"type":"square","freq":[5]}}]})"
        << "FILE: /tracks/0/sustain/freq: expected a number or a {\"param\": …} object, got "
           "an array";
}

void TestPattern::errors()
{
    QFETCH(QByteArray, document);
    QFETCH(QString, error);

    QVERIFY(m_dir.isValid());
    const QString path = m_dir.filePath(QStringLiteral("bad.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(document);
    file.close();

    LoadError found;
    QVERIFY(!Pattern::fromFile(path, &found));
    QCOMPARE(found.toString(), QString(error).replace(QLatin1String("FILE"), path));
}

void TestPattern::unreadable()
{
    LoadError error;
    QVERIFY(!Pattern::fromFile(QStringLiteral("/nonexistent/p.json"), &error));
    QCOMPARE(error.toString(),
             QStringLiteral("/nonexistent/p.json: cannot read: No such file or directory"));
}

QTEST_GUILESS_MAIN(TestPattern)
#include "tst_pattern.moc"
