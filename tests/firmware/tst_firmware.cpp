// SPDX-License-Identifier: MIT
// The band firmware's core (firmware/core), compiled for the host and driven through its
// hardware interface: the shared test vectors (tests/vectors) byte for byte, then the
// behaviour devices/PROTOCOL.md asks of a band — watchdog, stop-all, clamping, overpressure,
// sequence gaps, resynchronisation after garbage.
#include "band.h"
#include "protocolvectors.h"

#include <QJsonArray>
#include <QRandomGenerator>
#include <QSet>
#include <QTest>

#include <array>
#include <vector>

namespace {

const std::uint8_t *bytes(const QByteArray &a)
{
    return reinterpret_cast<const std::uint8_t *>(a.constData());
}

/** A board in memory: what the band wrote, its outputs, a settable clock and sensor. */
class FakeBoard
{
public:
    explicit FakeBoard(int channels = 4, std::uint16_t limit = 0xFFFF)
    {
        static const char *const names[] = {"m1",  "m2",  "m3",  "m4",  "m5",  "m6",
                                            "m7",  "m8",  "m9",  "m10", "m11", "m12",
                                            "m13", "m14", "m15", "m16", "m17"};
        for (int c = 0; c < channels; ++c)
            m_channels.push_back({names[c], 0.0f, 1.0f, limit});
        model = {"lra4", {1, 2, 3}, std::uint8_t(channels), m_channels.data(), 0, -1, 0};
        hw = {this, &FakeBoard::write, &FakeBoard::millis, &FakeBoard::setOutput,
              &FakeBoard::readSensor};
        outputs.assign(size_t(channels), 0xBEEF); // not at rest before init
    }
    int init() { return semhap_band_init(&band, &model, &hw); }
    void feed(const QByteArray &stream)
    {
        semhap_band_receive(&band, bytes(stream), size_t(stream.size()));
    }
    void poll() { semhap_band_poll(&band); }
    QByteArray takeWritten()
    {
        const QByteArray out = written;
        written.clear();
        return out;
    }

    semhap_band band{};
    semhap_band_model model{};
    semhap_band_hw hw{};
    QByteArray written;
    std::vector<std::uint16_t> outputs;
    int outputCalls = 0;
    std::vector<std::pair<std::uint8_t, std::uint16_t>> driven; ///< every set_output call
    std::uint32_t now = 1000;
    std::uint16_t pressure = 0;

private:
    static FakeBoard *self(void *context) { return static_cast<FakeBoard *>(context); }
    static void write(void *context, const std::uint8_t *data, size_t size)
    {
        self(context)->written.append(reinterpret_cast<const char *>(data), qsizetype(size));
    }
    static std::uint32_t millis(void *context) { return self(context)->now; }
    static void setOutput(void *context, std::uint8_t channel, std::uint16_t value)
    {
        self(context)->outputs[channel] = value;
        self(context)->driven.emplace_back(channel, value);
        ++self(context)->outputCalls;
    }
    static std::uint16_t readSensor(void *context, std::uint8_t sensor)
    {
        return sensor == 0 ? self(context)->pressure : 0;
    }

    std::vector<semhap_band_channel> m_channels;
};

/** A set-values frame in the band's own framing. */
QByteArray setValues(std::uint16_t sequence, const std::vector<std::uint16_t> &values)
{
    std::array<std::uint8_t, SEMHAP_MAX_FRAME> frame{};
    frame[SEMHAP_HEADER_SIZE] = std::uint8_t(values.size());
    for (size_t c = 0; c < values.size(); ++c) {
        frame[SEMHAP_HEADER_SIZE + 1 + 2 * c] = std::uint8_t(values[c] & 0xFF);
        frame[SEMHAP_HEADER_SIZE + 2 + 2 * c] = std::uint8_t(values[c] >> 8);
    }
    const size_t length =
        semhap_seal_frame(frame.data(), SEMHAP_SET_VALUES, sequence, 1 + 2 * values.size());
    std::array<std::uint8_t, SEMHAP_MAX_ENCODED_FRAME + 1> out{};
    const size_t n = semhap_cobs_encode(frame.data(), length, out.data());
    return QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(n)) + '\0';
}

/** A request without payload (stop-all, status, identify). */
QByteArray request(std::uint8_t type, std::uint16_t sequence)
{
    std::array<std::uint8_t, 8> frame{};
    const size_t length = semhap_seal_frame(frame.data(), type, sequence, 0);
    std::array<std::uint8_t, 10> out{};
    const size_t n = semhap_cobs_encode(frame.data(), length, out.data());
    return QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(n)) + '\0';
}

/** The type and sequence of the single frame in `stream`; type 0 when there is none. */
std::pair<int, int> header(const QByteArray &stream)
{
    if (stream.count('\0') != 1 || !stream.endsWith('\0'))
        return {0, 0};
    std::vector<std::uint8_t> frame(size_t(stream.size()));
    const long n = semhap_cobs_decode(bytes(stream), size_t(stream.size() - 1), frame.data());
    if (n < 0 || semhap_check_frame(frame.data(), size_t(n)) != SEMHAP_FRAME_OK)
        return {0, 0};
    return {frame[1], frame[2] | (frame[3] << 8)};
}

std::uint32_t errorCount(const semhap_band &band, const QString &name)
{
    const semhap_band_errors &e = band.errors;
    if (name == QLatin1String("cobs"))
        return e.cobs;
    if (name == QLatin1String("truncated"))
        return e.truncated;
    if (name == QLatin1String("crc"))
        return e.crc;
    if (name == QLatin1String("version"))
        return e.version;
    if (name == QLatin1String("unknown_type"))
        return e.unknown_type;
    if (name == QLatin1String("malformed"))
        return e.malformed;
    if (name == QLatin1String("oversize"))
        return e.oversize;
    qFatal("unknown counter %s", qPrintable(name));
}

} // namespace

class TestFirmware : public QObject
{
    Q_OBJECT

private slots:
    void crc();
    void cobs_data();
    void cobs();
    void framesAsTheHostEncodesThem_data();
    void framesAsTheHostEncodesThem();
    void identifyReplyIsTheVector();
    void heartbeatReplyIsTheVector();
    void statusReplyIsTheVector();
    void rejected_data();
    void rejected();
    void startsAtRest();
    void watchdogZeroesAfterSilence();
    void heartbeatsKeepValuesAlive();
    void stopAllIsImmediateAndIdempotent();
    void clampsToTheChannelLimit();
    void channelCountMismatch_data();
    void channelCountMismatch();
    void sequenceGapsAreDropped();
    void newHostStartsTheCountAfresh();
    void overpressureClosesEverything();
    void randomGarbageNeverSticks();
    void modelsThatDoNotFitAreRefused();
};

void TestFirmware::crc()
{
    for (const protocolvectors::BytePair &v : protocolvectors::load().crc) {
        const std::uint16_t crc = semhap_crc16(bytes(v.in), size_t(v.in.size()), 0xFFFF);
        QCOMPARE(crc, std::uint16_t((std::uint8_t(v.out[0]) << 8) | std::uint8_t(v.out[1])));
    }
}

void TestFirmware::cobs_data()
{
    QTest::addColumn<QByteArray>("plain");
    QTest::addColumn<QByteArray>("encoded");
    for (const protocolvectors::BytePair &v : protocolvectors::load().cobs)
        QTest::newRow(qPrintable(v.name)) << v.in << v.out;
}

void TestFirmware::cobs()
{
    QFETCH(QByteArray, plain);
    QFETCH(QByteArray, encoded);
    std::vector<std::uint8_t> out(size_t(plain.size() + plain.size() / 254 + 2));
    const size_t n = semhap_cobs_encode(bytes(plain), size_t(plain.size()), out.data());
    QCOMPARE(QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(n)), encoded);
    // In place, as the band decodes its receive buffer.
    QByteArray buffer = encoded;
    auto *data = reinterpret_cast<std::uint8_t *>(buffer.data());
    const long m = semhap_cobs_decode(data, size_t(buffer.size()), data);
    QCOMPARE(buffer.left(qsizetype(m)), plain);
}

void TestFirmware::framesAsTheHostEncodesThem_data()
{
    QTest::addColumn<QJsonObject>("message");
    QTest::addColumn<QByteArray>("encoded");
    for (const protocolvectors::Frame &f : protocolvectors::load().frames)
        QTest::newRow(qPrintable(f.name)) << f.message << f.encoded;
}

void TestFirmware::framesAsTheHostEncodesThem()
{
    QFETCH(QJsonObject, message);
    QFETCH(QByteArray, encoded);
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(0xFFFF, {1000, 2000, 3000, 4000}));
    board.feed(encoded);
    const semhap_band &band = board.band;
    QCOMPARE(semhap_band_garbled(&band), 0u);
    QCOMPARE(band.received, 2u);
    const int sequence = message.value("sequence").toInt();
    QCOMPARE(int(band.last_sequence), sequence);
    const QString type = message.value("type").toString();
    const QByteArray reply = board.takeWritten();
    if (type == QLatin1String("set-values")) {
        const QJsonArray values = message.value("values").toArray();
        QVERIFY(reply.isEmpty()); // set-values are not answered
        for (int c = 0; c < 4; ++c) {
            // Channels the frame does not carry keep their value.
            const int expected = c < values.size() ? values[c].toInt() : 1000 * (c + 1);
            QCOMPARE(int(board.outputs[size_t(c)]), expected);
        }
        QCOMPARE(bool(band.flags & SEMHAP_CHANNEL_COUNT_MISMATCH), values.size() != 4);
    } else if (type == QLatin1String("stop-all")) {
        QCOMPARE(board.outputs, std::vector<std::uint16_t>(4, 0));
        QCOMPARE(header(reply), std::make_pair(int(SEMHAP_STATUS), sequence));
    } else if (type == QLatin1String("identify-request")) {
        QCOMPARE(header(reply), std::make_pair(int(SEMHAP_IDENTIFY_REPLY), sequence));
    } else if (type == QLatin1String("heartbeat")) {
        QCOMPARE(header(reply), std::make_pair(int(SEMHAP_HEARTBEAT_REPLY), sequence));
    } else if (type == QLatin1String("status-request")) {
        QCOMPARE(header(reply), std::make_pair(int(SEMHAP_STATUS), sequence));
    } else {
        // A band's reply on a shared line: valid, counted, not answered, values untouched.
        QVERIFY(reply.isEmpty());
        QCOMPARE(int(board.outputs[3]), 4000);
    }
}

void TestFirmware::identifyReplyIsTheVector()
{
    // The vector's identify reply is lra4's, firmware 1.2.3: the fake board's model.
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(protocolvectors::firstOf("identify-request").encoded);
    QCOMPARE(board.takeWritten().toHex(' '),
             protocolvectors::firstOf("identify-reply").encoded.toHex(' '));
}

void TestFirmware::heartbeatReplyIsTheVector()
{
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(protocolvectors::firstOf("heartbeat").encoded);
    QCOMPARE(board.takeWritten().toHex(' '),
             protocolvectors::firstOf("heartbeat-reply").encoded.toHex(' '));
}

void TestFirmware::statusReplyIsTheVector()
{
    const protocolvectors::Frame &status = protocolvectors::firstOf("status");
    const QJsonObject &m = status.message;
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    // The counters as the vector has them once the request itself is counted.
    board.band.received = std::uint32_t(m.value("received").toDouble()) - 1;
    board.band.dropped = std::uint32_t(m.value("dropped").toDouble());
    board.band.errors.crc = std::uint32_t(m.value("garbled").toDouble());
    board.band.flags = std::uint16_t(m.value("flags").toInt());
    board.band.heard = 1;
    board.band.last_sequence = std::uint16_t(m.value("acknowledged").toInt() - 1);
    const std::uint16_t sequence = std::uint16_t(m.value("sequence").toInt());
    board.feed(request(SEMHAP_STATUS_REQUEST, sequence));
    QCOMPARE(board.takeWritten().toHex(' '), status.encoded.toHex(' '));
    QCOMPARE(board.band.flags, std::uint16_t(0)); // flags are "since the last status"
}

void TestFirmware::rejected_data()
{
    QTest::addColumn<QByteArray>("garbage");
    QTest::addColumn<QString>("counter");
    for (const protocolvectors::Rejected &r : protocolvectors::load().rejected)
        QTest::newRow(qPrintable(r.name)) << r.stream << r.error;
}

void TestFirmware::rejected()
{
    QFETCH(QByteArray, garbage);
    QFETCH(QString, counter);
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(10, {1, 2, 3, 4}) + garbage + setValues(11, {5, 6, 7, 8}));
    QCOMPARE(board.band.received, 2u);
    QCOMPARE(board.outputs, (std::vector<std::uint16_t>{5, 6, 7, 8}));
    QCOMPARE(semhap_band_garbled(&board.band), counter.isEmpty() ? 0u : 1u);
    if (!counter.isEmpty() && counter != QLatin1String("any"))
        QCOMPARE(errorCount(board.band, counter), 1u);
    QVERIFY(board.takeWritten().isEmpty());
}

void TestFirmware::startsAtRest()
{
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    QCOMPARE(board.outputs, std::vector<std::uint16_t>(4, 0));
    // Unchanged values are not driven again: a DRV2605L write costs bus time.
    board.outputCalls = 0;
    board.feed(setValues(0, {0, 0, 9, 0}));
    board.feed(setValues(1, {0, 0, 9, 0}));
    QCOMPARE(board.outputCalls, 1);
}

void TestFirmware::watchdogZeroesAfterSilence()
{
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(0, {100, 200, 300, 400}));
    board.now += SEMHAP_BAND_WATCHDOG_MS;
    board.poll();
    QCOMPARE(int(board.outputs[3]), 400);
    QCOMPARE(board.band.watchdog_trips, 0u);
    board.now += 1;
    board.poll();
    QCOMPARE(board.outputs, std::vector<std::uint16_t>(4, 0));
    QVERIFY(board.band.flags & SEMHAP_WATCHDOG_TRIPPED);
    QCOMPARE(board.band.watchdog_trips, 1u);
    // At rest there is nothing to trip again.
    board.now += 1000;
    board.poll();
    QCOMPARE(board.band.watchdog_trips, 1u);
    // The clock wraps at 2^32 without tripping early.
    board.now = 0xFFFFFF00u;
    board.feed(setValues(1, {1, 1, 1, 1}));
    board.now += 200; // past the wrap
    board.poll();
    QCOMPARE(int(board.outputs[0]), 1);
}

void TestFirmware::heartbeatsKeepValuesAlive()
{
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(0, {100, 200, 300, 400}));
    QByteArray heartbeat = protocolvectors::firstOf("heartbeat").encoded;
    for (int i = 0; i < 20; ++i) {
        board.now += 100;
        board.feed(heartbeat);
        board.poll();
    }
    QCOMPARE(int(board.outputs[0]), 100);
    QCOMPARE(board.band.watchdog_trips, 0u);
}

void TestFirmware::stopAllIsImmediateAndIdempotent()
{
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(0, {100, 200, 300, 400}));
    // The host repeats stop-all three times back to back.
    for (std::uint16_t s = 1; s <= 3; ++s)
        board.feed(request(SEMHAP_STOP_ALL, s));
    QCOMPARE(board.outputs, std::vector<std::uint16_t>(4, 0));
    const QByteArray replies = board.takeWritten();
    QCOMPARE(replies.count('\0'), 3); // each acknowledged with a status
    QCOMPARE(header(replies.left(replies.indexOf('\0') + 1)),
             std::make_pair(int(SEMHAP_STATUS), 1));
    QCOMPARE(board.band.dropped, 0u);
}

void TestFirmware::clampsToTheChannelLimit()
{
    FakeBoard board(4, 50000);
    QCOMPARE(board.init(), 0);
    board.feed(setValues(0, {65535, 49999, 50000, 50001}));
    QCOMPARE(board.outputs, (std::vector<std::uint16_t>{50000, 49999, 50000, 50000}));
}

void TestFirmware::channelCountMismatch_data()
{
    QTest::addColumn<int>("sent");
    QTest::newRow("fewer") << 2;
    QTest::newRow("more") << 6;
    QTest::newRow("none") << 0;
}

void TestFirmware::channelCountMismatch()
{
    QFETCH(int, sent);
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    std::vector<std::uint16_t> values;
    for (int c = 0; c < sent; ++c)
        values.push_back(std::uint16_t(100 + c));
    board.feed(setValues(0, values));
    QVERIFY(board.band.flags & SEMHAP_CHANNEL_COUNT_MISMATCH);
    for (int c = 0; c < 4; ++c)
        QCOMPARE(int(board.outputs[size_t(c)]), c < sent ? 100 + c : 0);
}

void TestFirmware::sequenceGapsAreDropped()
{
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(65534, {1, 1, 1, 1}));
    board.feed(setValues(65535, {1, 1, 1, 1}));
    board.feed(setValues(0, {1, 1, 1, 1})); // the wrap is not a gap
    QCOMPARE(board.band.dropped, 0u);
    board.feed(setValues(5, {1, 1, 1, 1}));
    QCOMPARE(board.band.dropped, 4u);
}

void TestFirmware::newHostStartsTheCountAfresh()
{
    // A host that comes after another numbers from 0 again; it says so with an empty frame
    // (its two leading delimiters), and the jump back is no gap.
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(5000, {1, 1, 1, 1}));
    board.feed(QByteArray(2, '\0') + setValues(0, {2, 2, 2, 2}));
    QCOMPARE(board.band.dropped, 0u);
    QCOMPARE(semhap_band_garbled(&board.band), 0u);
    QCOMPARE(int(board.outputs[0]), 2);
    // Without it, the jump is counted.
    board.feed(setValues(5000, {3, 3, 3, 3}));
    QCOMPARE(board.band.dropped, 4999u);
}

void TestFirmware::overpressureClosesEverything()
{
    FakeBoard board(6);
    board.model.pressure_sensor = 0;
    board.model.overpressure = 62000;
    QCOMPARE(board.init(), 0);
    board.feed(setValues(0, {9000, 9000, 9000, 9000, 9000, 9000}));
    board.pressure = 61999;
    board.poll();
    QCOMPARE(int(board.outputs[5]), 9000);
    board.pressure = 62000;
    board.poll();
    QCOMPARE(board.outputs, std::vector<std::uint16_t>(6, 0));
    QVERIFY(board.band.flags & SEMHAP_OVERPRESSURE);
    // Ignored while the pressure stays up, heeded once it falls.
    board.feed(setValues(1, {7000, 7000, 7000, 7000, 7000, 7000}));
    QCOMPARE(int(board.outputs[0]), 0);
    board.pressure = 30000;
    board.poll();
    board.feed(setValues(2, {7000, 7000, 7000, 7000, 7000, 7000}));
    QCOMPARE(int(board.outputs[0]), 7000);
    // The flag reaches the host in the next status, then clears.
    board.feed(request(SEMHAP_STATUS_REQUEST, 3));
    QVERIFY(!(board.band.flags & SEMHAP_OVERPRESSURE));
}

void TestFirmware::randomGarbageNeverSticks()
{
    QRandomGenerator random(4321);
    FakeBoard board;
    QCOMPARE(board.init(), 0);
    QByteArray stream;
    for (int i = 0; i < 400; ++i) {
        stream += setValues(std::uint16_t(i), {std::uint16_t(i), 7, 7, 7});
        QByteArray junk(int(random.bounded(700)), '\0');
        for (char &b : junk)
            b = char(random.bounded(1, 256));
        stream += junk + '\0';
    }
    // Each frame carries its own number on channel 0: every number must have been driven.
    for (int pos = 0; pos < stream.size();) {
        const int n = std::min(int(random.bounded(1, 64)), int(stream.size() - pos));
        board.feed(stream.mid(pos, n));
        pos += n;
    }
    QSet<int> applied;
    for (const auto &[channel, value] : board.driven) {
        if (channel == 0)
            applied.insert(value);
    }
    for (int i = 0; i < 400; ++i)
        QVERIFY2(applied.contains(i), qPrintable(QString::number(i)));
    QVERIFY(semhap_band_garbled(&board.band) >= 390);
    QVERIFY(board.band.errors.oversize > 0); // junk longer than a frame was among it
}

void TestFirmware::modelsThatDoNotFitAreRefused()
{
    FakeBoard tooMany(17);
    QCOMPARE(tooMany.init(), -1);
    FakeBoard longName;
    const char *name = "a-model-name-longer-than-32-bytes";
    longName.model.name = name;
    QCOMPARE(longName.init(), -1);
    FakeBoard sixteen(16);
    QCOMPARE(sixteen.init(), 0);
}

QTEST_GUILESS_MAIN(TestFirmware)
#include "tst_firmware.moc"
