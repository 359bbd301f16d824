// SPDX-License-Identifier: MIT
// The MCAP reader on recordings the reference writer (@mcap/core, tests/interop) made, and on
// those recordings damaged: each damage is an error at the right offset, never a crash.
#include "mcapreader.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtEndian>
#include <QTest>

#include <vector>

using namespace semhap;

namespace {

QString recording(const QString &name)
{
    return QStringLiteral(SEMHAP_INTEROP_DIR "/") + name;
}

QByteArray bytesOf(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    return file.readAll();
}

struct Record
{
    qsizetype offset;
    quint8 opcode;
    qsizetype length;
};

/** The top-level records of a well-formed file, to aim the damage. */
std::vector<Record> records(const QByteArray &file)
{
    std::vector<Record> out;
    qsizetype at = 8;
    while (at + 9 <= file.size() - 8) {
        const auto opcode = quint8(file[at]);
        const auto length = qsizetype(qFromLittleEndian<quint64>(file.constData() + at + 1));
        out.push_back({at, opcode, length});
        at += 9 + length;
    }
    return out;
}

Record first(const QByteArray &file, quint8 opcode)
{
    for (const Record &r : records(file)) {
        if (r.opcode == opcode)
            return r;
    }
    qFatal("no record 0x%02x", opcode);
}

} // namespace

class TestMcap : public QObject
{
    Q_OBJECT

private slots:
    void readsTheReferenceWritersFiles_data();
    void readsTheReferenceWritersFiles();
    void damageIsALocatedError_data();
    void damageIsALocatedError();
    void fileThatIsNotThere();
};

void TestMcap::readsTheReferenceWritersFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("summary");
    QTest::newRow("zstd chunks") << "grasp-zstd.mcap" << true;
    QTest::newRow("lz4 chunks") << "grasp-lz4.mcap" << true;
    QTest::newRow("uncompressed chunks") << "grasp-none.mcap" << true;
    QTest::newRow("a stream: no chunks, summary or index") << "grasp-stream.mcap" << false;
}

void TestMcap::readsTheReferenceWritersFiles()
{
    QFETCH(QString, file);
    QFETCH(bool, summary);
    const QJsonArray expected =
        QJsonDocument::fromJson(bytesOf(recording(QStringLiteral("grasp.expected.json")))).array();
    QVERIFY(expected.size() > 2000);

    McapReader reader(recording(file));
    QVERIFY2(reader.open(), qPrintable(reader.error()));
    QCOMPARE(reader.profile(), QStringLiteral("ros2"));
    McapMessage message;
    qsizetype n = 0;
    while (reader.next(&message)) {
        QVERIFY(n < expected.size());
        const QJsonObject want = expected[n].toObject();
        const McapChannel *channel = reader.channel(message.channelId);
        QVERIFY(channel);
        QCOMPARE(channel->topic, want["topic"].toString());
        QCOMPARE(QString::number(message.logTime), want["logTime"].toString());
        QCOMPARE(message.sequence, quint32(n));
        QCOMPARE(QByteArray(message.data, qsizetype(message.size)).toBase64(),
                 want["data"].toString().toLatin1());
        ++n;
    }
    QVERIFY2(reader.error().isEmpty(), qPrintable(reader.error()));
    QVERIFY(reader.atEnd());
    QCOMPARE(n, expected.size());
    QCOMPARE(reader.hasSummary(), summary);

    // Every channel with its schema, as rosbag2 names them.
    QCOMPARE(reader.channels().size(), size_t(4));
    for (const auto &[id, channel] : reader.channels()) {
        const McapSchema *schema = reader.schema(channel.schemaId);
        QVERIFY(schema);
        if (channel.topic.endsWith(QLatin1String("/wrench"))) {
            QCOMPARE(schema->name, QStringLiteral("geometry_msgs/msg/WrenchStamped"));
            QCOMPARE(schema->encoding, QStringLiteral("ros2msg"));
            QCOMPARE(channel.messageEncoding, QStringLiteral("cdr"));
            QVERIFY(schema->data.contains("MSG: geometry_msgs/Vector3"));
        }
    }
    QCOMPARE(reader.metadata().size(), size_t(1));
    QCOMPARE(reader.metadata()[0].name, QStringLiteral("rosbag2"));
    QCOMPARE(reader.metadata()[0].values.at(QStringLiteral("storage")), QStringLiteral("mcap"));
}

void TestMcap::damageIsALocatedError_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("error"); // after "FILE: "; a trailing '*' matches any rest

    const QByteArray none = bytesOf(recording(QStringLiteral("grasp-none.mcap")));
    const QByteArray zstd = bytesOf(recording(QStringLiteral("grasp-zstd.mcap")));
    const QByteArray lz4 = bytesOf(recording(QStringLiteral("grasp-lz4.mcap")));
    const QByteArray stream = bytesOf(recording(QStringLiteral("grasp-stream.mcap")));
    const auto at = [](qsizetype offset) { return QStringLiteral("offset %1: ").arg(offset); };

    QByteArray b = none;
    b[1] = 'X';
    QTest::newRow("not MCAP") << "none" << b << at(0) + "not an MCAP file (no MCAP magic)";
    QTest::newRow("empty") << "none" << QByteArray() << at(0) + "not an MCAP file (no MCAP magic)";

    const Record chunk = first(none, 0x06);
    QTest::newRow("cut mid-chunk")
        << "none" << none.left(chunk.offset + 9 + chunk.length / 2)
        << at(chunk.offset) +
               QStringLiteral("Chunk of %1 bytes runs past the end of the file").arg(chunk.length);
    const Record index = first(none, 0x07);
    QTest::newRow("cut mid-index")
        << "none" << none.left(index.offset + 12)
        << at(index.offset) +
               QStringLiteral("MessageIndex of %1 bytes runs past the end of the file")
                   .arg(index.length);
    QTest::newRow("no closing magic") << "none" << none.left(none.size() - 1)
                                      << at(none.size() - 8) + "expected the closing MCAP magic "
                                                               "after the Footer";

    b = none;
    b[chunk.offset + 9 + chunk.length - 1] ^= 0x5a;
    QTest::newRow("chunk CRC") << "none" << b << at(chunk.offset) + "chunk CRC mismatch";

    b = none;
    qToLittleEndian<quint64>(quint64(1) << 40, b.data() + chunk.offset + 9 + 16);
    QTest::newRow("chunk too large")
        << "none" << b
        << at(chunk.offset) + "a chunk of 1099511627776 bytes unpacked, more than the 268435456 "
                              "this reader takes";

    const Record zchunk = first(zstd, 0x06);
    b = zstd;
    b[zchunk.offset + 9 + zchunk.length / 2] ^= 0x5a;
    QTest::newRow("zstd damaged") << "zstd" << b << at(zchunk.offset) + "*";

    const Record lchunk = first(lz4, 0x06);
    b = lz4;
    b[lchunk.offset + 9 + lchunk.length / 2] ^= 0x5a;
    QTest::newRow("lz4 damaged") << "lz4" << b << at(lchunk.offset) + "*";

    const Record message = first(stream, 0x05);
    const Record dataEnd = first(stream, 0x0F);
    b = stream;
    b[message.offset + 9 + message.length - 1] ^= 0x5a;
    QTest::newRow("data section CRC")
        << "stream" << b << at(dataEnd.offset) + "data section CRC mismatch";

    b = stream;
    qToLittleEndian<quint16>(999, b.data() + message.offset + 9);
    QTest::newRow("unknown channel")
        << "stream" << b
        << at(message.offset) +
               "a message on channel 999, which no Channel record before it defines";

    b = stream;
    qToLittleEndian<quint64>(quint64(1) << 62, b.data() + message.offset + 1);
    QTest::newRow("length past the end")
        << "stream" << b
        << at(message.offset) +
               "Message of 4611686018427387904 bytes runs past the end of the file";

    const Record chunkIndex = first(none, 0x08);
    const Record footer = first(none, 0x02);
    b = none;
    b[chunkIndex.offset + 9 + chunkIndex.length - 1] ^= 0x5a;
    QTest::newRow("summary CRC") << "none" << b << at(footer.offset) + "summary CRC mismatch";
}

void TestMcap::damageIsALocatedError()
{
    QFETCH(QString, file);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, error);
    QTemporaryDir dir;
    const QString path = dir.filePath(file + QStringLiteral(".mcap"));
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();

    McapReader reader(path);
    McapMessage message;
    if (reader.open()) {
        int n = 0;
        while (reader.next(&message))
            QVERIFY(++n < 100000);
    }
    QVERIFY(!reader.atEnd());
    const QString expected = path + QStringLiteral(": ") + error;
    if (expected.endsWith(QLatin1Char('*')))
        QVERIFY2(reader.error().startsWith(expected.chopped(1)), qPrintable(reader.error()));
    else
        QCOMPARE(reader.error(), expected);
}

void TestMcap::fileThatIsNotThere()
{
    McapReader reader(QStringLiteral("/nonexistent/robot.mcap"));
    QVERIFY(!reader.open());
    QVERIFY2(reader.error().startsWith(QLatin1String("/nonexistent/robot.mcap: cannot read: ")),
             qPrintable(reader.error()));
}

QTEST_GUILESS_MAIN(TestMcap)
#include "tst_mcap.moc"
