// SPDX-License-Identifier: MIT
// ROS 2 message schemas (.msg) and their CDR encoding: messages the reference writer
// (@foxglove/rosmsg2-serialization, tests/interop) encoded, decoded by the schema text the
// recording carries, against what the reference reader decodes; schemas, paths and messages
// that are wrong get located errors; and the writer's strings, byte for byte.
#include "cdrdecoder.h"
#include "cdrwriter.h"
#include "mcapreader.h"
#include "msgschema.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

QString recording(const QString &name)
{
    return QStringLiteral(SEMHAP_INTEROP_DIR "/") + name;
}

QJsonArray expected(const QString &name)
{
    QFile file(recording(name));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(name));
    return QJsonDocument::fromJson(file.readAll()).array();
}

double number(const QJsonValue &v)
{
    if (v.isBool())
        return v.toBool() ? 1.0 : 0.0;
    if (v.isString())
        return v.toString().toDouble();
    return v.toDouble();
}

/** Every message of a recording, with its channel's schema. */
struct Message
{
    QString topic;
    QString schemaName;
    QByteArray schema;
    QByteArray data;
};

std::vector<Message> messagesOf(const QString &file)
{
    McapReader reader(recording(file));
    std::vector<Message> out;
    McapMessage m;
    if (!reader.open())
        qFatal("%s", qPrintable(reader.error()));
    while (reader.next(&m)) {
        const McapChannel *channel = reader.channel(m.channelId);
        const McapSchema *schema = reader.schema(channel->schemaId);
        out.push_back(
            {channel->topic, schema->name, schema->data, QByteArray(m.data, qsizetype(m.size))});
    }
    if (!reader.error().isEmpty())
        qFatal("%s", qPrintable(reader.error()));
    return out;
}

const char *const Wrench = "std_msgs/Header header\nWrench wrench\n"
                           "===\nMSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\n"
                           "string frame_id\n"
                           "===\nMSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n"
                           "===\nMSG: geometry_msgs/Wrench\nVector3 force\nVector3 torque\n"
                           "===\nMSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n";

} // namespace

class TestCdr : public QObject
{
    Q_OBJECT

private slots:
    void decodesWhatTheReferenceWrote();
    void everyKindOfField();
    void bigEndian();
    void schemaErrors_data();
    void schemaErrors();
    void pathErrors_data();
    void pathErrors();
    void damagedMessages();
    void writerStringsAreUtf8();
};

void TestCdr::decodesWhatTheReferenceWrote()
{
    const QJsonArray want = expected(QStringLiteral("grasp.expected.json"));
    const std::vector<Message> messages = messagesOf(QStringLiteral("grasp-zstd.mcap"));
    QCOMPARE(qsizetype(messages.size()), want.size());
    int decoded = 0;
    for (size_t i = 0; i < messages.size(); ++i) {
        const Message &m = messages[i];
        if (m.schemaName == QLatin1String("semhap_tests/Note"))
            continue; // JSON, not CDR
        const bool wrench = m.schemaName == QLatin1String("geometry_msgs/msg/WrenchStamped");
        const QStringList paths =
            wrench ? QStringList{"header.stamp", "wrench.force", "wrench.torque.z"}
                   : QStringList{"data"};
        MsgSchema schema;
        QString error;
        QVERIFY2(MsgSchema::parse(m.schemaName, m.schema, &schema, &error), qPrintable(error));
        CdrDecoder decoder;
        QVERIFY2(CdrDecoder::compile(schema, paths, &decoder, &error), qPrintable(error));
        std::vector<double> values(size_t(decoder.valueCount()));
        QVERIFY2(decoder.decode(m.data.constData(), size_t(m.data.size()), values.data(), &error),
                 qPrintable(error));
        const QJsonObject reference = want[qsizetype(i)].toObject()["decoded"].toObject();
        if (wrench) {
            QCOMPARE(decoder.width(0), 1);
            QCOMPARE(decoder.width(1), 3);
            const QJsonObject stamp = reference["header"].toObject()["stamp"].toObject();
            QCOMPARE(values[0], stamp["sec"].toDouble() + stamp["nanosec"].toDouble() * 1e-9);
            const QJsonObject force = reference["wrench"].toObject()["force"].toObject();
            QCOMPARE(values[1], force["x"].toDouble());
            QCOMPARE(values[2], force["y"].toDouble());
            QCOMPARE(values[3], force["z"].toDouble());
            QCOMPARE(values[4],
                     reference["wrench"].toObject()["torque"].toObject()["z"].toDouble());
        } else {
            QCOMPARE(values[0], reference["data"].toDouble());
        }
        ++decoded;
    }
    QVERIFY(decoded > 2000);
}

void TestCdr::everyKindOfField()
{
    const QJsonArray want = expected(QStringLiteral("kinds.expected.json"));
    const std::vector<Message> messages = messagesOf(QStringLiteral("kinds.mcap"));
    QCOMPARE(qsizetype(messages.size()), want.size());
    MsgSchema schema;
    QString error;
    QVERIFY2(MsgSchema::parse(messages[0].schemaName, messages[0].schema, &schema, &error),
             qPrintable(error));
    QStringList paths{"flag", "b",   "c",   "i8",  "u8",  "i16", "u16",
                      "i32",  "u32", "i64", "u64", "f32", "f64"};
    for (int i = 0; i < 3; ++i)
        paths << QStringLiteral("fixed[%1]").arg(i);
    for (int i = 0; i < 6; ++i)
        paths << QStringLiteral("sequence[%1]").arg(i) << QStringLiteral("points[%1].x").arg(i)
              << QStringLiteral("points[%1].y").arg(i);
    for (int i = 0; i < 4; ++i)
        paths << QStringLiteral("bounded[%1]").arg(i);
    paths << "pair[0].x"
          << "pair[1].y";
    CdrDecoder decoder;
    QVERIFY2(CdrDecoder::compile(schema, paths, &decoder, &error), qPrintable(error));
    QCOMPARE(decoder.valueCount(), paths.size());
    for (size_t k = 0; k < messages.size(); ++k) {
        std::vector<double> values(size_t(decoder.valueCount()));
        const QByteArray &data = messages[k].data;
        QVERIFY2(decoder.decode(data.constData(), size_t(data.size()), values.data(), &error),
                 qPrintable(error));
        const QJsonObject reference = want[qsizetype(k)].toObject();
        for (int p = 0; p < paths.size(); ++p) {
            // Walk the reference's JSON by the same path; an element past the end is NaN.
            QJsonValue at = reference;
            for (const QString &part : paths[p].split(QLatin1Char('.'))) {
                const qsizetype bracket = part.indexOf(QLatin1Char('['));
                if (bracket < 0) {
                    at = at.toObject().value(part);
                    continue;
                }
                const QJsonArray array = at.toObject().value(part.left(bracket)).toArray();
                const int index = part.mid(bracket + 1).chopped(1).toInt();
                at = index < array.size() ? array[index] : QJsonValue(QJsonValue::Undefined);
            }
            const double got = values[size_t(decoder.offset(p))];
            if (at.isUndefined())
                QVERIFY2(std::isnan(got), qPrintable(paths[p]));
            else
                QVERIFY2(got == number(at), qPrintable(QStringLiteral("message %1, %2: %3, not %4")
                                                           .arg(k)
                                                           .arg(paths[p])
                                                           .arg(got)
                                                           .arg(number(at))));
        }
    }
}

void TestCdr::bigEndian()
{
    MsgSchema schema;
    QString error;
    QVERIFY(MsgSchema::parse("pkg/msg/Pair", "uint8 a\nint32 b\nfloat64 c\n", &schema, &error));
    CdrDecoder decoder;
    QVERIFY(CdrDecoder::compile(schema, {"a", "b", "c"}, &decoder, &error));
    // Header 00 00 (big-endian CDR); a at 0, b aligned to 4, c aligned to 8.
    const QByteArray data = QByteArray::fromHex("00000000"
                                                "07000000"
                                                "fffffffe"
                                                "3ff8000000000000");
    double values[3] = {};
    QVERIFY2(decoder.decode(data.constData(), size_t(data.size()), values, &error),
             qPrintable(error));
    QCOMPARE(values[0], 7.0);
    QCOMPARE(values[1], -2.0);
    QCOMPARE(values[2], 1.5);
}

void TestCdr::schemaErrors_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("error");
    QTest::newRow("no name") << QByteArray("float64\n")
                             << "1:1: expected 'TYPE NAME', got 'float64'";
    QTest::newRow("bad name") << QByteArray("int32 ok\nint32 9lives\n")
                              << "2:7: '9lives' is not a field name";
    QTest::newRow("bad type") << QByteArray("  int32[x] a\n") << "1:3: 'int32[x]' is not a type";
    QTest::newRow("empty array") << QByteArray("int32[0] a\n")
                                 << "1:1: 'int32[0]': an array of no elements";
    QTest::newRow("bound on a number")
        << QByteArray("int32<=3 a\n") << "1:1: 'int32<=3': only strings take a bound '<='";
    QTest::newRow("twice") << QByteArray("int32 a\nfloat64 a\n")
                           << "2:9: field 'a' is defined twice";
    QTest::newRow("unknown type")
        << QByteArray("Vector3 v\n===\nMSG: geometry_msgs/Point\nfloat64 x\n")
        << "1:1: type pkg/Vector3 is not defined here (the schema defines pkg/Thing, "
           "geometry_msgs/Point)";
    QTest::newRow("no MSG line") << QByteArray("int32 a\n===\nint32 b\n")
                                 << "3:1: expected 'MSG: package/Type' after a line of '='";
    QTest::newRow("MSG without a package") << QByteArray("int32 a\n===\nMSG: Point\n")
                                           << "3:1: expected 'MSG: package/Type', got 'MSG: "
                                              "Point'";
    QTest::newRow("ends after a rule")
        << QByteArray("int32 a\n===\n") << "3:1: expected 'MSG: package/Type' after a line of '='";
    QTest::newRow("type twice") << QByteArray("A a\n===\nMSG: pkg/A\nint8 x\n===\nMSG: pkg/A\n")
                                << "6:1: type pkg/A is defined twice";
    QTest::newRow("holds itself") << QByteArray("A a\n===\nMSG: pkg/A\nA again\n")
                                  << "1:1: pkg/Thing nests types more than 32 deep, or holds "
                                     "itself";
    QByteArray deep = "T0 t\n";
    for (int i = 0; i < 40; ++i)
        deep += QStringLiteral("===\nMSG: pkg/T%1\nT%2 t\n").arg(i).arg(i + 1).toUtf8();
    deep += "===\nMSG: pkg/T40\nint8 x\n";
    QTest::newRow("too deep") << deep
                              << "1:1: pkg/Thing nests types more than 32 deep, or holds "
                                 "itself";
}

void TestCdr::schemaErrors()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, error);
    MsgSchema schema;
    QString got;
    QVERIFY(!MsgSchema::parse(QStringLiteral("pkg/msg/Thing"), text, &schema, &got));
    QCOMPARE(got, error);
}

void TestCdr::pathErrors_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("error");
    QTest::newRow("no field") << "wrench.forc"
                              << "'wrench.forc': geometry_msgs/Wrench has no field 'forc'; its "
                                 "fields: force, torque";
    QTest::newRow("a string") << "header.frame_id"
                              << "'header.frame_id': 'frame_id' is a string, not a number";
    QTest::newRow("not numbers") << "header"
                                 << "'header': 'header' is std_msgs/Header, not a number or a "
                                    "message of numbers; its fields: stamp, frame_id";
    QTest::newRow("past a number") << "wrench.force.x.y"
                                   << "'wrench.force.x.y': 'x' is a number (float64), with no "
                                      "fields";
    QTest::newRow("not an array")
        << "wrench[0]"
        << "'wrench[0]': 'wrench' is not an array (geometry_msgs/Wrench)";
    QTest::newRow("bad part") << "wrench..force"
                              << "'wrench..force': '' is not a field name or NAME[INDEX]";
}

void TestCdr::pathErrors()
{
    QFETCH(QString, path);
    QFETCH(QString, error);
    MsgSchema schema;
    QString got;
    QVERIFY(MsgSchema::parse("geometry_msgs/msg/WrenchStamped", Wrench, &schema, &got));
    CdrDecoder decoder;
    QVERIFY(!CdrDecoder::compile(schema, {path}, &decoder, &got));
    QCOMPARE(got, error);
}

void TestCdr::damagedMessages()
{
    // Every cut of a real message is an error at a byte, never a read past its end.
    const std::vector<Message> messages = messagesOf(QStringLiteral("kinds.mcap"));
    const Message &m = messages.back();
    MsgSchema schema;
    QString error;
    QVERIFY(MsgSchema::parse(m.schemaName, m.schema, &schema, &error));
    CdrDecoder decoder;
    QVERIFY(CdrDecoder::compile(schema, {"points[3].y", "f64"}, &decoder, &error));
    double values[2];
    for (qsizetype cut = 0; cut < m.data.size(); ++cut) {
        const QByteArray part = m.data.left(cut);
        const bool ok = decoder.decode(part.constData(), size_t(cut), values, &error);
        // CDR pads the end to 4 bytes: the last few cuts may lose padding only.
        if (cut < m.data.size() - 3) {
            QVERIFY2(!ok, qPrintable(QString::number(cut)));
            QVERIFY2(error.startsWith(QLatin1String("byte ")), qPrintable(error));
        }
    }
    QVERIFY(!decoder.decode("\x00\x07\x00\x00", 4, values, &error));
    QCOMPARE(error, QStringLiteral("byte 0: encapsulation 0x0007 is not plain CDR"));

    // A sequence claiming more elements than there are bytes is refused before it is read.
    QVERIFY(MsgSchema::parse("pkg/msg/Many", "float64[] many\n", &schema, &error));
    QVERIFY(CdrDecoder::compile(schema, {"many[1]"}, &decoder, &error));
    const QByteArray lie = QByteArray::fromHex("00010000ffffff7f0000000000000000");
    QVERIFY(!decoder.decode(lie.constData(), size_t(lie.size()), values, &error));
    QCOMPARE(error, QStringLiteral("byte 8: 'many' claims 2147483647 elements, more than the "
                                   "message holds"));
}

void TestCdr::writerStringsAreUtf8()
{
    // ASCII names are copied byte by byte, others encoded: both as UTF-8, with the length
    // counting the terminating zero, and the number after them aligned again.
    CdrWriter cdr;
    cdr.string(QStringLiteral("cube"));
    cdr.string(QString::fromUtf8("W\u00fcrfel"));
    cdr.string(QString());
    cdr.float64(1.0);
    const QByteArray want = QByteArray::fromHex("00010000"
                                                "05000000"
                                                "6375626500"
                                                "000000"
                                                "08000000"
                                                "57c3bc7266656c00"
                                                "01000000"
                                                "00"
                                                "000000"
                                                "000000000000f03f");
    QCOMPARE(cdr.bytes().toByteArray().toHex(), want.toHex());
}

QTEST_GUILESS_MAIN(TestCdr)
#include "tst_cdr.moc"
