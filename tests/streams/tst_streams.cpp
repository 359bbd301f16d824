// SPDX-License-Identifier: MIT
#include "actortable.h"
#include "contactframereader.h"
#include "jsonlineswriter.h"
#include "nametable.h"

#include <QBuffer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QTest>

#include <cmath>
#include <limits>

using namespace semhap;

namespace {

const QString File = QStringLiteral("frames.jsonl");

QString number(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

/** "f n actor [x y z]", the form the expected fingertips in the rows use. */
QString describe(const Fingertip &tip, const ActorTable &actors)
{
    QString text = number(tip.f) + QLatin1Char(' ') + QString::number(tip.n) + QLatin1Char(' ') +
                   (tip.actor < 0 ? QStringLiteral("-") : actors.name(tip.actor));
    if (tip.hasFxyz) {
        text += QStringLiteral(" [%1 %2 %3]")
                    .arg(number(tip.fxyz[0]), number(tip.fxyz[1]), number(tip.fxyz[2]));
    }
    if (tip.mu > 0)
        text += QStringLiteral(" mu ") + number(tip.mu);
    return text;
}

/** "t gripper | left | right", then " | name=value ..." for the signals. */
QString describe(const ContactFrame &frame, const ActorTable &actors)
{
    QString text = number(frame.t) + QLatin1Char(' ') + gripperName(frame.gripper) +
                   QStringLiteral(" | ") + describe(frame.left, actors) + QStringLiteral(" | ") +
                   describe(frame.right, actors);
    QStringList named;
    for (const SignalValue &signal : frame.signalValues)
        named.append(signalNames().name(signal.id) + QLatin1Char('=') + number(signal.value));
    named.sort();
    if (!named.isEmpty())
        text += QStringLiteral(" | ") + named.join(QLatin1Char(' '));
    return text;
}

/** Reads every frame of `input`, collecting described frames and rendered errors. */
struct ReadResult
{
    QStringList frames;
    QStringList errors;
    int rejected = 0;
};

ReadResult readAll(const QByteArray &input)
{
    QByteArray data = input;
    QBuffer buffer(&data);
    buffer.open(QIODevice::ReadOnly);
    ContactFrameReader reader(&buffer, File);
    ReadResult result;
    reader.setErrorHandler(
        [&result](const LoadError &error) { result.errors.append(error.toString()); });
    ContactFrame frame;
    while (reader.next(&frame))
        result.frames.append(describe(frame, reader.actors()));
    result.rejected = reader.rejectedCount();
    return result;
}

QByteArray writeEvent(const SemanticEvent &event)
{
    QByteArray data;
    QBuffer buffer(&data);
    buffer.open(QIODevice::WriteOnly);
    JsonLinesWriter writer(&buffer);
    writer.setNodeNames({QStringLiteral("left.slip"), QStringLiteral("right.force")});
    writer.write(event);
    return data;
}

} // namespace

class TestStreams : public QObject
{
    Q_OBJECT

private slots:
    void validFrames_data();
    void validFrames();
    void malformed_data();
    void malformed();
    void timePerGripper();
    void gapsAgainstTheStreamClock();
    void blankLinesAndLineNumbers();
    void longLine();
    void goldenFile();
    void eventText();
    void deviceFrameText();
    void numbers_data();
    void numbers();
    void escapes();
    void contactFrameRoundTrip();
};

void TestStreams::validFrames_data()
{
    QTest::addColumn<QByteArray>("line");
    QTest::addColumn<QString>("frame");

    QTest::newRow("all fields")
        << QByteArray(
               R"({"t": 1.250, "gripper": "right",)"
               R"( "left": {"f": 31.5, "n": 9, "actor": "cube_3", "fxyz": [0.1, 31.4, -2]},)"
               R"( "right": {"f": 30.2, "n": 8, "actor": "cube_3"}})")
        << QStringLiteral("1.25 right | 31.5 9 cube_3 [0.1 31.4 -2] | 30.2 8 cube_3");
    QTest::newRow("missing fingertip")
        << QByteArray(R"({"t": 0, "gripper": "left", "right": {"f": 2, "n": 1, "actor": "a"}})")
        << QStringLiteral("0 left | 0 0 - | 2 1 a");
    QTest::newRow("null fingertip")
        << QByteArray(R"({"t": 0, "gripper": "left", "left": null, "right": null})")
        << QStringLiteral("0 left | 0 0 - | 0 0 -");
    QTest::newRow("null actor, null fxyz")
        << QByteArray(R"({"t": 2, "gripper": "right",)"
                      R"( "left": {"f": 0, "n": 0, "actor": null, "fxyz": null}})")
        << QStringLiteral("2 right | 0 0 - | 0 0 -");
    QTest::newRow("friction coefficient")
        << QByteArray(R"({"t": 2, "gripper": "left", "left": {"f": 20, "n": 16, "actor": "c",)"
                      R"( "fxyz": [0, -20, 1.5], "mu": 0.1}, "right": {"f": 1, "n": 1,)"
                      R"( "actor": "c", "mu": null}})")
        << QStringLiteral("2 left | 20 16 c [0 -20 1.5] mu 0.1 | 1 1 c");
    QTest::newRow("9.0 as n")
        << QByteArray(R"({"t": 1, "gripper": "right", "left": {"f": 1, "n": 9.0, "actor": "b"}})")
        << QStringLiteral("1 right | 1 9 b | 0 0 -");
    QTest::newRow("unknown keys are extensions")
        << QByteArray(R"({"t": 1, "gripper": "right", "source": "sim",)"
                      R"( "left": {"f": 1, "n": 1, "actor": "b", "torque": 3}})")
        << QStringLiteral("1 right | 1 1 b | 0 0 -");
    QTest::newRow("signals")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": {"plug.angle_error": 0.05,)"
                      R"( "wrist.fz": 12.3, "x_2": -1e-9}})")
        << QStringLiteral("1 right | 0 0 - | 0 0 - | plug.angle_error=0.05 wrist.fz=12.3 "
                          "x_2=-1e-09");
    QTest::newRow("null and empty signals")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": null})")
        << QStringLiteral("1 right | 0 0 - | 0 0 -");
    QTest::newRow("CRLF line end") << QByteArray("{\"t\": 3, \"gripper\": \"left\"}\r")
                                   << QStringLiteral("3 left | 0 0 - | 0 0 -");
    QTest::newRow("byte order mark") << QByteArray("\xEF\xBB\xBF{\"t\": 3, \"gripper\": \"left\"}")
                                     << QStringLiteral("3 left | 0 0 - | 0 0 -");
}

void TestStreams::validFrames()
{
    QFETCH(QByteArray, line);
    QFETCH(QString, frame);

    const ReadResult result = readAll(line + '\n');
    QCOMPARE(result.errors, QStringList());
    QCOMPARE(result.frames, QStringList{frame});
    QCOMPARE(result.rejected, 0);
}

void TestStreams::malformed_data()
{
    QTest::addColumn<QByteArray>("line");
    // A trailing "*" matches any rest: the parser's own wording and offsets are Qt's.
    QTest::addColumn<QString>("reason");

    QTest::newRow("truncated JSON") << QByteArray(R"({"t": 1, "gripper": "right")")
                                    << QStringLiteral("invalid JSON at column *");
    QTest::newRow("not JSON") << QByteArray("hello") << QStringLiteral("invalid JSON at column *");
    QTest::newRow("array") << QByteArray("[1, 2]")
                           << QStringLiteral(
                                  "a contact frame must be a JSON object, got an array");
    QTest::newRow("missing t") << QByteArray(R"({"gripper": "right"})")
                               << QStringLiteral(R"("t" is missing)");
    QTest::newRow("t as string") << QByteArray(R"({"t": "1", "gripper": "right"})")
                                 << QStringLiteral(R"("t" must be a finite number, got "1")");
    QTest::newRow("missing gripper")
        << QByteArray(R"({"t": 1})") << QStringLiteral(R"("gripper" is missing)");
    QTest::newRow("unknown gripper")
        << QByteArray(R"({"t": 1, "gripper": "middle"})")
        << QStringLiteral(R"("gripper" must be "left" or "right", got "middle")");
    QTest::newRow("gripper not a string")
        << QByteArray(R"({"t": 1, "gripper": 0})")
        << QStringLiteral(R"("gripper" must be "left" or "right", got 0)");
    QTest::newRow("fingertip not an object")
        << QByteArray(R"({"t": 1, "gripper": "right", "left": 3})")
        << QStringLiteral(R"("left" must be an object or null, got 3)");
    QTest::newRow("missing f")
        << QByteArray(R"({"t": 1, "gripper": "right", "left": {"n": 1, "actor": null}})")
        << QStringLiteral(R"("left.f" is missing)");
    QTest::newRow("negative f")
        << QByteArray(R"({"t": 1, "gripper": "right", "left": {"f": -1, "n": 1, "actor": null}})")
        << QStringLiteral(R"("left.f" must be a finite non-negative number, got -1)");
    QTest::newRow("NaN as string")
        << QByteArray(
               R"({"t": 1, "gripper": "right", "left": {"f": "NaN", "n": 1, "actor": null}})")
        << QStringLiteral(R"("left.f" must be a finite non-negative number, got "NaN")");
    QTest::newRow("Infinity as string")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": 1, "actor": null,)"
                      R"( "fxyz": [0, "Infinity", 0]}})")
        << QStringLiteral(R"("right.fxyz" must be an array of 3 finite numbers, got an array)");
    QTest::newRow("bare NaN") << QByteArray(R"({"t": NaN, "gripper": "right"})")
                              << QStringLiteral("invalid JSON at column *");
    QTest::newRow("n 9.5")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": 9.5, "actor": "a"}})")
        << QStringLiteral(R"("right.n" must be a non-negative integer, got 9.5)");
    QTest::newRow("negative n")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": -2, "actor": "a"}})")
        << QStringLiteral(R"("right.n" must be a non-negative integer, got -2)");
    QTest::newRow("n as string")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": "3", "actor": "a"}})")
        << QStringLiteral(R"("right.n" must be a non-negative integer, got "3")");
    QTest::newRow("missing actor")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": 3}})")
        << QStringLiteral(R"("right.actor" is missing)");
    QTest::newRow("actor a number")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": 3, "actor": 7}})")
        << QStringLiteral(R"("right.actor" must be a non-empty string or null, got 7)");
    QTest::newRow("empty actor")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": 3, "actor": ""}})")
        << QStringLiteral(R"("right.actor" must be a non-empty string or null, got "")");
    QTest::newRow("fxyz of 2")
        << QByteArray(R"({"t": 1, "gripper": "right", "left": {"f": 1, "n": 3, "actor": "a",)"
                      R"( "fxyz": [1, 2]}})")
        << QStringLiteral(R"("left.fxyz" must be an array of 3 finite numbers, got an array)");
    QTest::newRow("fxyz not an array")
        << QByteArray(R"({"t": 1, "gripper": "right", "left": {"f": 1, "n": 3, "actor": "a",)"
                      R"( "fxyz": {}}})")
        << QStringLiteral(R"("left.fxyz" must be an array of 3 finite numbers, got an object)");
    QTest::newRow("mu zero")
        << QByteArray(R"({"t": 1, "gripper": "right", "left": {"f": 1, "n": 3, "actor": "a",)"
                      R"( "mu": 0}})")
        << QStringLiteral(R"("left.mu" must be a finite positive number or null, got 0)");
    QTest::newRow("mu as string")
        << QByteArray(R"({"t": 1, "gripper": "right", "right": {"f": 1, "n": 3, "actor": "a",)"
                      R"( "mu": "0.1"}})")
        << QStringLiteral(R"("right.mu" must be a finite positive number or null, got "0.1")");
    QTest::newRow("signals not an object")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": [1, 2]})")
        << QStringLiteral(R"("signals" must be an object or null, got an array)");
    QTest::newRow("signal not a number")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": {"plug.depth": "deep"}})")
        << QStringLiteral(R"("signals.plug.depth" must be a finite number, got "deep")");
    QTest::newRow("signal null")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": {"plug.depth": null}})")
        << QStringLiteral(R"("signals.plug.depth" must be a finite number, got null)");
    QTest::newRow("signal name with capitals")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": {"Wrist": 1}})")
        << QStringLiteral(R"("signals.Wrist": a signal's name must be 1 to 64 characters of )"
                          R"(a-z, 0-9, _ and .)");
    QTest::newRow("empty signal name")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": {"": 1}})")
        << QStringLiteral(R"("signals.": a signal's name must be 1 to 64 characters of )"
                          R"(a-z, 0-9, _ and .)");
    QTest::newRow("signal name too long")
        << (QByteArray(R"({"t": 1, "gripper": "right", "signals": {")") + QByteArray(65, 'a') +
            QByteArray(R"(": 1}})"))
        << QStringLiteral(R"("signals.)") + QString(65, 'a') +
               QStringLiteral(R"(": a signal's name must be 1 to 64 characters of a-z, 0-9, _ )"
                              R"(and .)");
    QTest::newRow("a built-in quantity's name")
        << QByteArray(R"({"t": 1, "gripper": "right", "signals": {"left.f": 1}})")
        << QStringLiteral(R"("signals.left.f": "left.f" is a built-in quantity, not a signal )"
                          R"(name)");
    QTest::newRow("65 signals") << [] {
        QByteArray line = R"({"t": 1, "gripper": "right", "signals": {)";
        for (int i = 0; i < 65; ++i)
            line += (i ? ", " : "") + QByteArray("\"s") + QByteArray::number(i) + "\": 1";
        line += "}}";
        return line;
    }() << QStringLiteral(R"("signals" has 65 signals, more than the 64 a frame may carry)");
    QTest::newRow("t jumps")
        << QByteArray(R"({"t": 1e9, "gripper": "left"})")
        << QStringLiteral(R"("t" jumps by 1e+09 s, more than the 10 s allowed (--max-gap))");
    QTest::newRow("t far in the past")
        << QByteArray(R"({"t": -1e308, "gripper": "left"})")
        << QStringLiteral(R"("t" must be within ±1e+10 s, got -1e+308)");
    QTest::newRow("t not increasing")
        << QByteArray(R"({"t": 0, "gripper": "right"})")
        << QStringLiteral(R"("t" must increase per gripper, got 0 after 0 for "right")");
}

void TestStreams::malformed()
{
    QFETCH(QByteArray, line);
    QFETCH(QString, reason);

    // A valid frame before and after: the bad line is line 2, and reading goes on.
    const QByteArray input =
        QByteArray(R"({"t": 0, "gripper": "right"})") + '\n' + line + '\n' +
        QByteArray(R"({"t": 5, "gripper": "right", "left": {"f": 1, "n": 1, "actor": "x"}})") +
        '\n';
    const ReadResult result = readAll(input);
    const QString expected = QStringLiteral("frames.jsonl:2: ") + reason;
    QCOMPARE(result.errors.size(), 1);
    if (expected.endsWith(QLatin1Char('*')))
        QVERIFY2(result.errors[0].startsWith(expected.chopped(1)), qPrintable(result.errors[0]));
    else
        QCOMPARE(result.errors[0], expected);
    QCOMPARE(result.frames, (QStringList{QStringLiteral("0 right | 0 0 - | 0 0 -"),
                                         QStringLiteral("5 right | 1 1 x | 0 0 -")}));
    QCOMPARE(result.rejected, 1);
}

void TestStreams::timePerGripper()
{
    const QByteArray input = "{\"t\": 1, \"gripper\": \"right\"}\n"
                             "{\"t\": 0.5, \"gripper\": \"left\"}\n"
                             "{\"t\": 0.5, \"gripper\": \"right\"}\n"
                             "{\"t\": 1, \"gripper\": \"left\"}\n"
                             "{\"t\": 1.5, \"gripper\": \"right\"}\n";
    const ReadResult result = readAll(input);
    QCOMPARE(
        result.errors,
        QStringList{QStringLiteral(
            R"(frames.jsonl:3: "t" must increase per gripper, got 0.5 after 1 for "right")")});
    QCOMPARE(result.frames.size(), 4);
    QCOMPARE(result.rejected, 1);
}

void TestStreams::gapsAgainstTheStreamClock()
{
    // The gap is measured from the latest frame of either gripper; a first frame may be
    // anywhere within MaxTime, and so may the first after restartClock().
    ContactFrameParser parser;
    ContactFrame frame;
    QString reason;
    QVERIFY(parser.parse(QByteArray(R"({"t": 1e9, "gripper": "right"})"), &frame, &reason));
    QVERIFY(parser.parse(QByteArray(R"({"t": 1000000009, "gripper": "left"})"), &frame, &reason));
    QVERIFY(
        !parser.parse(QByteArray(R"({"t": 1000000020, "gripper": "right"})"), &frame, &reason));
    QCOMPARE(reason,
             QStringLiteral(R"("t" jumps by 11 s, more than the 10 s allowed (--max-gap))"));
    parser.setMaxGap(60.0);
    QVERIFY(parser.parse(QByteArray(R"({"t": 1000000020, "gripper": "right"})"), &frame, &reason));
    parser.restartClock();
    QVERIFY(parser.parse(QByteArray(R"({"t": -5, "gripper": "right"})"), &frame, &reason));
    QCOMPARE(frame.t, -5.0);
}

void TestStreams::blankLinesAndLineNumbers()
{
    const QByteArray input = "\n   \n{\"t\": 1, \"gripper\": \"right\"}\n\t\r\n{bad\n\n"
                             "{\"t\": 2, \"gripper\": \"right\"}";
    const ReadResult result = readAll(input);
    QCOMPARE(result.errors.size(), 1);
    QVERIFY2(result.errors[0].startsWith(QStringLiteral("frames.jsonl:5: invalid JSON")),
             qPrintable(result.errors[0]));
    QCOMPARE(result.frames.size(), 2);
    QCOMPARE(result.rejected, 1);
}

void TestStreams::longLine()
{
    const QByteArray padding(int(ContactFrameReader::MaxLineLength), ' ');
    // Exactly the limit is still read; one byte more is rejected without parsing.
    const QByteArray atLimit =
        QByteArray(R"({"t": 1, "gripper": "right"})") + padding.left(padding.size() - 28);
    QCOMPARE(atLimit.size(), ContactFrameReader::MaxLineLength);
    const QByteArray input = atLimit + '\n' + atLimit + " \n" +
                             QByteArray(R"({"t": 2, "gripper": "right"})") + '\n' + padding +
                             padding + "x";
    const ReadResult result = readAll(input);
    QCOMPARE(result.errors, (QStringList{QStringLiteral("frames.jsonl:2: line longer than "
                                                        "1048576 bytes"),
                                         QStringLiteral("frames.jsonl:4: line longer than "
                                                        "1048576 bytes")}));
    QCOMPARE(result.frames.size(), 2);
    QCOMPARE(result.rejected, 2);
}

void TestStreams::goldenFile()
{
    QFile file(QStringLiteral(SEMHAP_TEST_DATA "/mixed.jsonl"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QFile expected(QStringLiteral(SEMHAP_TEST_DATA "/mixed.errors"));
    QVERIFY(expected.open(QIODevice::ReadOnly | QIODevice::Text));
    ContactFrameReader reader(&file, QStringLiteral("mixed.jsonl"));
    QStringList errors;
    reader.setErrorHandler([&errors](const LoadError &e) { errors.append(e.toString()); });
    ContactFrame frame;
    int frames = 0;
    while (reader.next(&frame))
        ++frames;
    QCOMPARE(errors.join(QLatin1Char('\n')), QString::fromUtf8(expected.readAll()).trimmed());
    QCOMPARE(frames, 4);
    QCOMPARE(reader.frameCount(), 4);
    QCOMPARE(reader.rejectedCount(), int(errors.size()));
    QCOMPARE(reader.actors().size(), 2);
    QCOMPARE(reader.lastError().toString(), errors.last());
}

void TestStreams::eventText()
{
    SemanticEvent event;
    event.t = 1.25;
    event.gripper = Gripper::Right;
    event.node = 1;
    event.detector = DetectorKind::Force;
    event.message = Message::Break;
    event.category = Category::Exception;
    event.phase = EventPhase::Update;
    event.intensity = 0.42;
    QCOMPARE(writeEvent(event),
             QByteArray(R"({"t":1.25,"gripper":"right","node":"right.force","detector":"force",)"
                        R"("message":"break","category":"exception","phase":"update",)"
                        R"("intensity":0.42})"
                        "\n"));
    event.node = 5;
    event.t = 2;
    event.intensity = 1;
    QVERIFY(writeEvent(event).startsWith(R"({"t":2,"gripper":"right","node":null,)"));
}

void TestStreams::deviceFrameText()
{
    QByteArray data;
    QBuffer buffer(&data);
    buffer.open(QIODevice::WriteOnly);
    JsonLinesWriter writer(&buffer);
    writer.setDeviceNames({QStringLiteral("left.vibro"), QStringLiteral("right.vibro")});
    DeviceFrame frame;
    frame.t = 1.255;
    frame.device = 1;
    frame.channelCount = 4;
    frame.values = {0.0, 0.8, 0.8, 0.0};
    QVERIFY(writer.write(frame));
    frame.channelCount = 0;
    QVERIFY(writer.write(frame));
    QCOMPARE(data, QByteArray("{\"t\":1.255,\"device\":\"right.vibro\",\"values\":[0,0.8,0.8,0]}\n"
                              "{\"t\":1.255,\"device\":\"right.vibro\",\"values\":[]}\n"));
}

void TestStreams::numbers_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QByteArray>("text");

    QTest::newRow("0.1") << 0.1 << QByteArray("0.1");
    QTest::newRow("1e-300") << 1e-300 << QByteArray("1e-300");
    QTest::newRow("123456.789") << 123456.789 << QByteArray("123456.789");
    QTest::newRow("integer") << 42.0 << QByteArray("42");
    QTest::newRow("zero") << 0.0 << QByteArray("0");
    QTest::newRow("negative") << -2.5 << QByteArray("-2.5");
    QTest::newRow("one third") << 1.0 / 3.0 << QByteArray("0.3333333333333333");
    QTest::newRow("largest") << std::numeric_limits<double>::max()
                             << QByteArray("1.7976931348623157e+308");
    QTest::newRow("denormal") << std::numeric_limits<double>::denorm_min() << QByteArray("5e-324");
}

void TestStreams::numbers()
{
    QFETCH(double, value);
    QFETCH(QByteArray, text);

    QByteArray out;
    JsonLinesWriter::appendNumber(out, value);
    QCOMPARE(out, text);

    // Written in every stream position, each parses back to exactly the same double.
    DeviceFrame frame;
    frame.t = value;
    frame.device = 0;
    frame.channelCount = 2;
    frame.values = {value, value};
    QByteArray data;
    QBuffer buffer(&data);
    buffer.open(QIODevice::WriteOnly);
    JsonLinesWriter writer(&buffer);
    writer.setDeviceNames({QStringLiteral("overlay")});
    QVERIFY(writer.write(frame));
    const QJsonObject json = QJsonDocument::fromJson(data).object();
    QCOMPARE(json.value(QLatin1String("t")).toDouble(), value);
    QCOMPARE(json.value(QLatin1String("values")).toArray().at(1).toDouble(), value);
}

void TestStreams::escapes()
{
    QByteArray out;
    JsonLinesWriter::appendString(out, QStringLiteral("a\"b\\c\nd\x01 é"));
    QCOMPARE(out, QByteArray("\"a\\\"b\\\\c\\u000ad\\u0001 \xC3\xA9\""));
    QCOMPARE(QJsonDocument::fromJson("[" + out + "]").array().at(0).toString(),
             QStringLiteral("a\"b\\c\nd\x01 é"));
    out.clear();
    JsonLinesWriter::appendNumber(out, std::nan(""));
    QCOMPARE(out, QByteArray("null"));
}

void TestStreams::contactFrameRoundTrip()
{
    ActorTable actors;
    ContactFrame first;
    first.t = 0.1;
    first.gripper = Gripper::Left;
    first.left = {31.5, 9, actors.intern(QStringLiteral("cube_3")), true, {0.1, 31.4, -2.0}, 0.1};
    first.right = {1e-300, 8, actors.intern(QStringLiteral("cube_3")), false, {}};
    ContactFrame second;
    second.t = 123456.789;
    second.gripper = Gripper::Right;
    second.right = {0.25, 1, actors.intern(QStringLiteral("odd \"name\"")), false, {}};
    second.signalValues.set(signalNames().intern(QStringLiteral("wrist.fz")), 12.3);
    second.signalValues.set(signalNames().intern(QStringLiteral("plug.depth")), -1e-300);

    QByteArray data;
    QBuffer out(&data);
    out.open(QIODevice::WriteOnly);
    JsonLinesWriter writer(&out);
    writer.setActorTable(&actors);
    QVERIFY(writer.write(first));
    QVERIFY(writer.write(second));
    QVERIFY(data.startsWith(
        R"({"t":0.1,"gripper":"left","left":{"f":31.5,"n":9,)"
        R"("actor":"cube_3","fxyz":[0.1,31.4,-2],"mu":0.1},"right":{"f":1e-300,)"));

    QBuffer in(&data);
    in.open(QIODevice::ReadOnly);
    ContactFrameReader reader(&in, File);
    reader.parser().setMaxGap(1e6); // the second frame is far on, to round-trip a long t
    ContactFrame back;
    QVERIFY(reader.next(&back));
    QCOMPARE(describe(back, reader.actors()), describe(first, actors));
    QCOMPARE(back.right.f, 1e-300);
    QVERIFY(reader.next(&back));
    QCOMPARE(describe(back, reader.actors()), describe(second, actors));
    QCOMPARE(back.t, 123456.789);
    QCOMPARE(back.signalValues, second.signalValues);
    QVERIFY(data.contains(R"("signals":{"wrist.fz":12.3,"plug.depth":-1e-300}})"));
    QVERIFY(!reader.next(&back));
    QCOMPARE(reader.rejectedCount(), 0);
}

QTEST_GUILESS_MAIN(TestStreams)
#include "tst_streams.moc"
