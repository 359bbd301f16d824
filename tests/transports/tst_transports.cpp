// SPDX-License-Identifier: MIT
// Transports without hardware: URIs, safety (clamp, gain, inflation limit, armed, stop-all),
// the virtual transport, what a transport says it sent (against an emulated band's
// setpoints), a band behind a TCP port, HID enumeration, the scheme table against its docs.
#include "deviceuri.h"
#include "emulatedband.h"
#include "framedecoder.h"
#include "framerate.h"
#include "hidlink.h"
#include "safetyfilter.h"
#include "transportfactory.h"
#include "transportscheme.h"
#include "virtualtransport.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTest>
#include <QThread>

#include <atomic>
#include <thread>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

using namespace semhap;

namespace {

DeviceFrame frameOf(std::initializer_list<double> values)
{
    DeviceFrame f;
    f.channelCount = int(values.size());
    std::copy(values.begin(), values.end(), f.values.begin());
    return f;
}

} // namespace

/**
 * ser2net in miniature: serves a pty's bytes on a loopback TCP port, one client at a time,
 * on its own thread. drop() ends the connection, as a server that restarts does.
 */
class TcpBridge
{
public:
    explicit TcpBridge(const QString &ptyPath) : m_ptyPath(ptyPath) {}
    ~TcpBridge()
    {
        m_quit = true;
        if (m_thread.joinable())
            m_thread.join();
        for (const int fd : {m_listen, m_pty}) {
            if (fd >= 0)
                ::close(fd);
        }
    }
    bool start(QString *error)
    {
        m_pty = ::open(m_ptyPath.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
        termios raw{};
        if (m_pty < 0 || ::tcgetattr(m_pty, &raw) != 0) {
            *error = m_ptyPath + QStringLiteral(": cannot open");
            return false;
        }
        ::cfmakeraw(&raw);
        ::tcsetattr(m_pty, TCSANOW, &raw);
        m_listen = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t size = sizeof address;
        if (::bind(m_listen, reinterpret_cast<sockaddr *>(&address), size) != 0 ||
            ::listen(m_listen, 1) != 0 ||
            ::getsockname(m_listen, reinterpret_cast<sockaddr *>(&address), &size) != 0) {
            *error = QStringLiteral("cannot listen on the loopback");
            return false;
        }
        m_port = ntohs(address.sin_port);
        m_thread = std::thread([this] { run(); });
        return true;
    }
    int port() const { return m_port; }
    void drop() { m_drop = true; }
    int connections() const { return m_connections; }

private:
    void run()
    {
        int client = -1;
        char buffer[256];
        while (!m_quit) {
            pollfd fds[3] = {{m_listen, POLLIN, 0}, {m_pty, POLLIN, 0}, {client, POLLIN, 0}};
            ::poll(fds, client >= 0 ? 3 : 2, 10);
            if (m_drop.exchange(false) && client >= 0) {
                ::close(client);
                client = -1;
                continue;
            }
            if (fds[0].revents & POLLIN) {
                const int accepted = ::accept4(m_listen, nullptr, nullptr, SOCK_CLOEXEC);
                if (accepted >= 0) {
                    if (client >= 0)
                        ::close(client);
                    client = accepted;
                    ++m_connections;
                }
            }
            // Without a client, what the band says is lost, as ser2net drops it.
            const ssize_t fromBand =
                (fds[1].revents & POLLIN) ? ::read(m_pty, buffer, sizeof buffer) : 0;
            if (fromBand > 0 && client >= 0)
                ::send(client, buffer, size_t(fromBand), MSG_NOSIGNAL);
            if (client >= 0 && (fds[2].revents & (POLLIN | POLLHUP))) {
                const ssize_t fromHost = ::recv(client, buffer, sizeof buffer, 0);
                if (fromHost > 0) {
                    [[maybe_unused]] const ssize_t n = ::write(m_pty, buffer, size_t(fromHost));
                } else {
                    ::close(client);
                    client = -1;
                }
            }
        }
        if (client >= 0)
            ::close(client);
    }

    QString m_ptyPath;
    int m_pty = -1;
    int m_listen = -1;
    int m_port = 0;
    std::atomic<bool> m_quit{false};
    std::atomic<bool> m_drop{false};
    std::atomic<int> m_connections{0};
    std::thread m_thread;
};

class TestTransports : public QObject
{
    Q_OBJECT

private slots:
    void parseUri_data();
    void parseUri();
    void safety_data();
    void safety();
    void inflationLimit();
    void inflationLimitOnlyForPneumatic();
    void virtualTransport();
    void virtualTransportCountsItsRate();
    void frameRateIsTheLastSecond_data();
    void frameRateIsTheLastSecond();
    void stopAllGetsThrough();
    void sentLogReadsWhatIsNew();
    void sentIsWhatTheBandGot_data();
    void sentIsWhatTheBandGot();
    void factoryMakesEachKind();
    void everySchemeIsDocumented();
    void tcpReachesABandBehindABridge();
    void identifyIsAskedUntilAnswered();
    void hidEnumerationWithoutDevices();
};

void TestTransports::parseUri_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("canonical"); ///< empty: must be rejected
    QTest::addColumn<QString>("errorPart");
    QTest::newRow("virtual") << "virtual:right.vibro"
                             << "virtual:right.vibro"
                             << "";
    QTest::newRow("virtual no name") << "virtual:"
                                     << ""
                                     << "needs a name";
    QTest::newRow("serial") << "serial:/dev/ttyACM0"
                            << "serial:/dev/ttyACM0"
                            << "";
    QTest::newRow("serial baud") << "serial:/dev/ttyUSB1?baud=921600"
                                 << "serial:/dev/ttyUSB1?baud=921600"
                                 << "";
    QTest::newRow("serial older default") << "serial:/dev/ttyUSB1?baud=115200"
                                          << "serial:/dev/ttyUSB1?baud=115200"
                                          << "";
    QTest::newRow("serial default baud") << "serial:/tmp/band?baud=250000"
                                         << "serial:/tmp/band"
                                         << "";
    QTest::newRow("serial bad baud") << "serial:/dev/ttyACM0?baud=fast"
                                     << ""
                                     << "baud=fast";
    QTest::newRow("serial other option") << "serial:/dev/ttyACM0?parity=odd"
                                         << ""
                                         << "parity=odd";
    QTest::newRow("serial no path") << "serial:"
                                    << ""
                                    << "needs a path";
    QTest::newRow("hid") << "hid:1234:ABCD"
                         << "hid:1234:abcd"
                         << "";
    QTest::newRow("hid short ids") << "hid:1:2"
                                   << "hid:0001:0002"
                                   << "";
    QTest::newRow("hid one id") << "hid:1234"
                                << ""
                                << "hid:VID:PID";
    QTest::newRow("hid not hex") << "hid:12g4:0001"
                                 << ""
                                 << "hex";
    QTest::newRow("hid too long") << "hid:12345:0001"
                                  << ""
                                  << "four hex";
    QTest::newRow("udp") << "udp:127.0.0.1:9000"
                         << "udp:127.0.0.1:9000"
                         << "";
    QTest::newRow("udp name") << "udp:band.local:9000"
                              << "udp:band.local:9000"
                              << "";
    QTest::newRow("udp ipv6") << "udp:[::1]:9000"
                              << "udp:[::1]:9000"
                              << "";
    QTest::newRow("udp no port") << "udp:127.0.0.1"
                                 << ""
                                 << "HOST:PORT";
    QTest::newRow("udp port zero") << "udp:127.0.0.1:0"
                                   << ""
                                   << "1-65535";
    QTest::newRow("udp port too big") << "udp:127.0.0.1:70000"
                                      << ""
                                      << "1-65535";
    QTest::newRow("tcp") << "tcp:band.local:2000"
                         << "tcp:band.local:2000"
                         << "";
    QTest::newRow("tcp ipv6") << "tcp:[fe80::1]:2000"
                              << "tcp:[fe80::1]:2000"
                              << "";
    QTest::newRow("tcp no port") << "tcp:band.local"
                                 << ""
                                 << "tcp:HOST:PORT";
    QTest::newRow("audio") << "audio:default"
                           << "audio:default"
                           << "";
    QTest::newRow("audio name with colons") << "audio:hw:2,0"
                                            << "audio:hw:2,0"
                                            << "";
    QTest::newRow("audio channels") << "audio:default?channels=3,4,1,2"
                                    << "audio:default?channels=3,4,1,2"
                                    << "";
    QTest::newRow("audio default carrier") << "audio:default?carrier=170"
                                           << "audio:default"
                                           << "";
    QTest::newRow("audio carriers") << "audio:x?channels=1,2&carrier=150,200.5"
                                    << "audio:x?channels=1,2&carrier=150,200.5"
                                    << "";
    QTest::newRow("audio carrier first") << "audio:x?carrier=200&channels=2"
                                         << "audio:x?channels=2&carrier=200"
                                         << "";
    QTest::newRow("audio no output") << "audio:?channels=1"
                                     << ""
                                     << "needs an output";
    QTest::newRow("audio channel not a number") << "audio:x?channels=1,a"
                                                << ""
                                                << "channels= takes";
    QTest::newRow("audio channel zero") << "audio:x?channels=0,1"
                                        << ""
                                        << "from 1";
    QTest::newRow("audio channel twice") << "audio:x?channels=1,2,1"
                                         << ""
                                         << "output channel 1 is given twice";
    QTest::newRow("audio no channels") << "audio:x?channels="
                                       << ""
                                       << "channels= takes";
    QTest::newRow("audio carrier zero") << "audio:x?carrier=0"
                                        << ""
                                        << "above 0 Hz";
    QTest::newRow("audio carrier negative") << "audio:x?carrier=-170"
                                            << ""
                                            << "above 0 Hz";
    QTest::newRow("audio carrier nan") << "audio:x?carrier=nan"
                                       << ""
                                       << "above 0 Hz";
    QTest::newRow("audio carriers per channel") << "audio:x?channels=1,2&carrier=1,2,3"
                                                << ""
                                                << "3 carriers for 2 channels";
    QTest::newRow("audio other option") << "audio:x?rate=48000"
                                        << ""
                                        << "unknown option 'rate=48000'";
    QTest::newRow("unknown scheme") << "usb:1"
                                    << ""
                                    << "unknown device scheme 'usb'";
    QTest::newRow("no scheme") << "/dev/ttyACM0"
                               << ""
                               << "unknown device scheme";
    QTest::newRow("empty") << ""
                           << ""
                           << "unknown device scheme";
}

void TestTransports::parseUri()
{
    QFETCH(QString, text);
    QFETCH(QString, canonical);
    QFETCH(QString, errorPart);
    DeviceUri uri;
    QString error;
    const bool ok = DeviceUri::parse(text, &uri, &error);
    QCOMPARE(ok, !canonical.isEmpty());
    if (ok) {
        QCOMPARE(uri.toString(), canonical);
        DeviceUri again;
        QVERIFY(DeviceUri::parse(uri.toString(), &again, &error));
        QCOMPARE(again.toString(), canonical);
    } else {
        QVERIFY2(error.contains(errorPart), qPrintable(error));
        QVERIFY2(error.startsWith(text), qPrintable(error));
    }
}

void TestTransports::safety_data()
{
    QTest::addColumn<double>("commanded");
    QTest::addColumn<double>("gain");
    QTest::addColumn<bool>("armed");
    QTest::addColumn<double>("expected");
    QTest::newRow("passes") << 0.7 << 1.0 << true << 0.7;
    QTest::newRow("clamped above") << 3.0 << 1.0 << true << 1.0;
    QTest::newRow("clamped below") << -1.0 << 1.0 << true << 0.0;
    QTest::newRow("nan is the lower limit") << qQNaN() << 1.0 << true << 0.0;
    QTest::newRow("gain") << 0.8 << 0.5 << true << 0.4;
    QTest::newRow("gain above 1 is 1") << 0.8 << 7.0 << true << 0.8;
    QTest::newRow("gain nan is 0") << 0.8 << qQNaN() << true << 0.0;
    QTest::newRow("disarmed sends zeros") << 0.8 << 1.0 << false << 0.0;
}

void TestTransports::safety()
{
    QFETCH(double, commanded);
    QFETCH(double, gain);
    QFETCH(bool, armed);
    QFETCH(double, expected);
    for (const char *model : {"lra4", "pneumatic6"}) {
        DeviceModelPtr m = DeviceModelLibrary::builtin(QString::fromLatin1(model));
        SafetyFilter filter(m);
        std::vector<double> in(size_t(m->channelCount()), commanded);
        std::vector<double> out(in.size(), -1.0);
        filter.apply(in.data(), int(in.size()), 0.0, gain, armed, out.data());
        for (double v : out)
            QCOMPARE(v, expected);
        // Channels the caller did not send are at the lower limit, not left over.
        filter.apply(in.data(), 1, 0.0, gain, armed, out.data());
        QCOMPARE(out.back(), 0.0);
    }
}

void TestTransports::inflationLimit()
{
    SafetyFilter filter(DeviceModelLibrary::builtin(QStringLiteral("pneumatic6")));
    filter.setInflationLimit({60.0, 0.9, 0.6});
    std::array<double, 6> full;
    full.fill(1.0);
    std::array<double, 6> out{};
    for (double t = 0.0; t < 59.9; t += 0.1) {
        filter.apply(full.data(), 6, 100.0 + t, 1.0, true, out.data());
        QCOMPARE(out[0], 1.0);
    }
    filter.apply(full.data(), 6, 160.0, 1.0, true, out.data());
    QCOMPARE(out[0], 0.6);
    QVERIFY(filter.isCapped(0));
    // Dropping below the threshold is not enough; the cap holds down to the comfort level.
    std::array<double, 6> high;
    high.fill(0.8);
    filter.apply(high.data(), 6, 161.0, 1.0, true, out.data());
    QCOMPARE(out[0], 0.6);
    std::array<double, 6> low;
    low.fill(0.5);
    filter.apply(low.data(), 6, 162.0, 1.0, true, out.data());
    QCOMPARE(out[0], 0.5);
    QVERIFY(!filter.isCapped(0));
    filter.apply(full.data(), 6, 163.0, 1.0, true, out.data());
    QCOMPARE(out[0], 1.0);
    // A brief dip below the threshold restarts the count.
    filter.apply(full.data(), 6, 200.0, 1.0, true, out.data());
    filter.apply(low.data(), 6, 200.1, 1.0, true, out.data());
    filter.apply(full.data(), 6, 200.2, 1.0, true, out.data());
    filter.apply(full.data(), 6, 250.0, 1.0, true, out.data());
    QCOMPARE(out[0], 1.0);
}

void TestTransports::inflationLimitOnlyForPneumatic()
{
    SafetyFilter vibro(DeviceModelLibrary::builtin(QStringLiteral("lra4")));
    QCOMPARE(vibro.inflationLimit().seconds, 0.0);
    SafetyFilter fingertips(DeviceModelLibrary::builtin(QStringLiteral("fingertips2")));
    QCOMPARE(fingertips.inflationLimit().seconds, 60.0);
}

void TestTransports::virtualTransport()
{
    VirtualTransport t(QStringLiteral("right.vibro"),
                       DeviceModelLibrary::builtin(QStringLiteral("lra4")));
    QString error;
    QVERIFY(t.open(&error));
    QCOMPARE(t.uri(), QStringLiteral("virtual:right.vibro"));
    QVERIFY(t.isArmed());
    t.setGain(0.5);
    t.send(frameOf({1.0, 0.5, 2.0, -1.0}));
    const DeviceFrame last = t.sent().last();
    QCOMPARE(last.channelCount, 4);
    QCOMPARE(last.values[0], 0.5);
    QCOMPARE(last.values[1], 0.25);
    QCOMPARE(last.values[2], 0.5);
    QCOMPARE(last.values[3], 0.0);
    for (int i = 0; i < SentLog::Capacity + 10; ++i)
        t.send(frameOf({0.1 * (i % 10), 0, 0, 0}));
    QCOMPARE(t.status().framesSent, std::uint32_t(SentLog::Capacity + 11));
    t.setArmed(false);
    t.send(frameOf({1, 1, 1, 1}));
    QCOMPARE(t.sent().last().values[0], 0.0);
}

void TestTransports::virtualTransportCountsItsRate()
{
    // A virtual device reports the frames it really got per second, as a real link does,
    // and falls to 0 once they stop.
    VirtualTransport transport(QStringLiteral("v"), DeviceModelLibrary::builtin("lra4"));
    QString error;
    QVERIFY(transport.open(&error));
    QCOMPARE(transport.status().framesPerSecond, 0.0);
    DeviceFrame frame;
    frame.channelCount = 4;
    QElapsedTimer clock;
    clock.start();
    int sent = 0;
    while (clock.elapsed() < 2100) {
        transport.send(frame);
        ++sent;
        QThread::msleep(10);
    }
    const double expected = sent / (double(clock.elapsed()) / 1000.0);
    const double rate = transport.status().framesPerSecond;
    QVERIFY2(std::abs(rate - expected) < 0.25 * expected,
             qPrintable(QStringLiteral("%1 reported, %2 sent").arg(rate).arg(expected)));
    QThread::msleep(2500);
    QVERIFY2(transport.status().framesPerSecond < 0.3 * expected,
             qPrintable(QString::number(transport.status().framesPerSecond)));
}

void TestTransports::frameRateIsTheLastSecond_data()
{
    // 500 frames a second from 0 s to 3 s, each counted as it comes; read at `at`. The rate
    // is over the last second and up to one sample spacing (0.1 s) more.
    QTest::addColumn<double>("at");
    QTest::addColumn<double>("low");
    QTest::addColumn<double>("high");
    QTest::newRow("at once: too soon to tell") << 0.05 << 0.0 << 0.0;
    QTest::newRow("after 0.3 s, not a second later") << 0.3 << 495.0 << 505.0;
    QTest::newRow("steady") << 2.0 << 495.0 << 505.0;
    // Of the last 1.0…1.1 s, frames came for 0.5…0.6 s.
    QTest::newRow("half a second after they stop") << 3.5 << 249.0 << 274.0;
    QTest::newRow("a second after they stop") << 4.05 << 0.0 << 0.0;
}

void TestTransports::frameRateIsTheLastSecond()
{
    QFETCH(double, at);
    QFETCH(double, low);
    QFETCH(double, high);
    FrameRate rate;
    std::uint64_t total = 0;
    rate.record(total, 0.0);
    for (int k = 1; k <= 1500 && k * 0.002 <= at; ++k)
        rate.record(++total, k * 0.002);
    for (double t = 3.0; t <= at; t += 0.05) // the transport's loop goes on, frames or not
        rate.record(total, t);
    const double read = rate.perSecond(total, at);
    QVERIFY2(read >= low && read <= high, qPrintable(QString::number(read)));
}

void TestTransports::stopAllGetsThrough()
{
    VirtualTransport t(QStringLiteral("left.air"),
                       DeviceModelLibrary::builtin(QStringLiteral("pneumatic6")));
    QString error;
    QVERIFY(t.open(&error));
    t.send(frameOf({1, 1, 1, 1, 1, 1}));
    t.stopAll();
    QCOMPARE(t.stopCount(), 1);
    QCOMPARE(t.sent().last().values[0], 0.0);
    t.close();
    QCOMPARE(t.stopCount(), 2);
    QVERIFY(!t.status().connected);
}

void TestTransports::sentLogReadsWhatIsNew()
{
    SentLog log;
    QCOMPARE(log.last().channelCount, 0);
    std::uint64_t next = 0;
    std::vector<DeviceFrame> frames;
    QCOMPARE(log.readSince(&next, &frames), std::uint64_t(0));
    QVERIFY(frames.empty());
    for (int i = 0; i < 3; ++i) {
        DeviceFrame frame = frameOf({0.1 * i});
        frame.t = i;
        log.append(frame);
    }
    QCOMPARE(log.readSince(&next, &frames), std::uint64_t(0));
    QCOMPARE(int(frames.size()), 3);
    QCOMPARE(frames[2].t, 2.0);
    QCOMPARE(next, std::uint64_t(3));
    // Only what is new, and what was overwritten before it was read is counted.
    for (int i = 3; i < SentLog::Capacity + 13; ++i) {
        DeviceFrame frame = frameOf({0.0});
        frame.t = i;
        log.append(frame);
    }
    frames.clear();
    QCOMPARE(log.readSince(&next, &frames), std::uint64_t(10));
    QCOMPARE(int(frames.size()), SentLog::Capacity);
    QCOMPARE(frames.front().t, 13.0);
    QCOMPARE(log.last().t, double(SentLog::Capacity + 12));
    frames.clear();
    QCOMPARE(log.readSince(&next, &frames), std::uint64_t(0));
    QVERIFY(frames.empty());
}

void TestTransports::sentIsWhatTheBandGot_data()
{
    QTest::addColumn<bool>("link"); ///< over UDP to an emulated band, else virtual
    QTest::addColumn<double>("gain");
    QTest::addColumn<bool>("armed");
    QTest::addColumn<double>("asked");
    QTest::addColumn<double>("got");
    for (const bool link : {false, true}) {
        const char *kind = link ? "udp" : "virtual";
        QTest::addRow("%s gain 0.5", kind) << link << 0.5 << true << 1.0 << 0.5;
        QTest::addRow("%s clamped", kind) << link << 1.0 << true << 2.0 << 1.0;
        QTest::addRow("%s disarmed", kind) << link << 1.0 << false << 1.0 << 0.0;
    }
}

void TestTransports::sentIsWhatTheBandGot()
{
    // What a transport keeps as sent — the readouts' one source — is what leaves it after
    // clamp, gain and arming: for a link, what the band receives.
    QFETCH(bool, link);
    QFETCH(double, gain);
    QFETCH(bool, armed);
    QFETCH(double, asked);
    QFETCH(double, got);
    EmulatedBand band(QStringLiteral("lra4"));
    QString error;
    QVERIFY2(!link || band.start(&error), qPrintable(error));
    std::unique_ptr<Transport> transport =
        TransportFactory::create(link ? band.uri() : QStringLiteral("virtual:v"),
                                 DeviceModelLibrary::builtin(QStringLiteral("lra4")), &error);
    QVERIFY2(transport && transport->open(&error), qPrintable(error));
    transport->setGain(gain);
    transport->setArmed(armed);
    DeviceFrame frame = frameOf({asked, asked, 0.25, 0.0});
    frame.t = 7.5;
    transport->send(frame);
    QTRY_COMPARE(transport->sent().last().t, 7.5); // a link's I/O thread writes it
    const DeviceFrame sent = transport->sent().last();
    QCOMPARE(sent.t, 7.5);
    QCOMPARE(sent.channelCount, 4);
    QCOMPARE(sent.values[0], got);
    QCOMPARE(sent.values[2], armed ? 0.25 * gain : 0.0);
    if (link) {
        QTRY_VERIFY(band.state().setpoints.size() == 4 &&
                    std::abs(band.state().setpoints[0] - got) < 1e-3);
        QVERIFY(std::abs(band.state().setpoints[2] - sent.values[2]) < 1e-3);
        // The heartbeats send the values again (every 100 ms), but that is no news: the
        // log keeps what was sent once, not a paused run's last time over and over.
        const std::uint64_t kept = transport->sent().count();
        const std::uint64_t written = transport->status().framesSent;
        QTest::qWait(450);
        QVERIFY(transport->status().framesSent >= written + 3);
        QCOMPARE(transport->sent().count(), kept);
    }

    // A stop-all is kept as the rest values, from the latest time sent.
    const std::uint64_t before = transport->sent().count();
    transport->stopAll();
    QTRY_VERIFY(transport->sent().count() > before);
    QCOMPARE(transport->sent().last().t, 7.5);
    QCOMPARE(transport->sent().last().values[0], 0.0);
    transport->close();
}

void TestTransports::factoryMakesEachKind()
{
    DeviceModelPtr model = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    QString error;
    for (const QString &uri :
         {QStringLiteral("virtual:a"), QStringLiteral("serial:/dev/null"),
          QStringLiteral("hid:1234:5678"), QStringLiteral("udp:127.0.0.1:9"),
          QStringLiteral("tcp:127.0.0.1:9"), QStringLiteral("audio:default?channels=1,2,3,4")}) {
        std::unique_ptr<Transport> t = TransportFactory::create(uri, model, &error);
        QVERIFY2(t, qPrintable(error));
        QCOMPARE(t->uri(), uri);
        QCOMPARE(t->model().name(), QStringLiteral("lra4"));
    }
    QVERIFY(!TransportFactory::create(QStringLiteral("usb:1"), model, &error));
    QVERIFY(error.contains(QStringLiteral("unknown device scheme")));
    // Real bands start disarmed.
    QVERIFY(
        !TransportFactory::create(QStringLiteral("udp:127.0.0.1:9"), model, &error)->isArmed());
}

void TestTransports::everySchemeIsDocumented()
{
    // The URI table of devices/README.md has a row for each registered scheme, and no other.
    QFile doc(QStringLiteral(SEMHAP_DEVICES_DOC));
    QVERIFY(doc.open(QIODevice::ReadOnly));
    QStringList documented;
    for (const QByteArray &line : doc.readAll().split('\n')) {
        if (line.startsWith("| `") && line.contains(':'))
            documented.append(QString::fromUtf8(line.mid(3, line.indexOf('`', 3) - 3)));
    }
    QStringList registered;
    for (const TransportScheme &scheme : TransportScheme::all())
        registered.append(QString::fromUtf8(scheme.syntax));
    QCOMPARE(documented, registered);
}

void TestTransports::tcpReachesABandBehindABridge()
{
    // tcp: drives a serial band another machine shares (ser2net, socat): here an emulated
    // band's pty served on a loopback port. The server restarting is a lost link, and the
    // transport connects again by itself.
    EmulatedBand band(QStringLiteral("lra4"), false);
    QString error;
    QVERIFY2(band.start(&error), qPrintable(error));
    TcpBridge bridge(band.address());
    QVERIFY2(bridge.start(&error), qPrintable(error));
    const QString uri = QStringLiteral("tcp:127.0.0.1:%1").arg(bridge.port());
    std::unique_ptr<Transport> transport =
        TransportFactory::create(uri, DeviceModelLibrary::builtin(QStringLiteral("lra4")), &error);
    QVERIFY2(transport, qPrintable(error));
    QCOMPARE(transport->uri(), uri);
    QVERIFY2(transport->open(&error), qPrintable(error));
    QTRY_VERIFY(transport->status().responding);
    transport->setArmed(true);
    transport->send(frameOf({0.5, 0.0, 0.0, 0.0}));
    QTRY_VERIFY(band.state().setpoints.size() == 4 &&
                std::abs(band.state().setpoints[0] - 0.5) < 1e-3);

    bridge.drop();
    QTRY_COMPARE(bridge.connections(), 2);
    QTRY_VERIFY(transport->status().reconnects >= 1);
    transport->send(frameOf({0.25, 0.0, 0.0, 0.0}));
    QTRY_VERIFY(std::abs(band.state().setpoints[0] - 0.25) < 1e-3);
    QTRY_VERIFY(transport->status().responding);
    transport->close();
}

void TestTransports::identifyIsAskedUntilAnswered()
{
    // A band that misses the first identify request (an Arduino resets when its port
    // opens, and its boot loader takes the bytes) is asked again with the heartbeats, and
    // no more once it has answered.
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
    QVERIFY(master >= 0 && ::grantpt(master) == 0 && ::unlockpt(master) == 0);
    const QString pty = QString::fromLocal8Bit(::ptsname(master));
    const int held = ::open(::ptsname(master), O_RDWR | O_NOCTTY | O_CLOEXEC);
    QString error;
    std::unique_ptr<Transport> transport =
        TransportFactory::create(QStringLiteral("serial:") + pty,
                                 DeviceModelLibrary::builtin(QStringLiteral("lra4")), &error);
    QVERIFY2(transport && transport->open(&error), qPrintable(error));
    FrameDecoder decoder;
    std::vector<protocol::Message> requests;
    const auto readFor = [&](int ms) {
        requests.clear();
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < ms) {
            pollfd fd{master, POLLIN, 0};
            if (::poll(&fd, 1, 20) <= 0)
                continue;
            std::array<std::uint8_t, 512> buffer{};
            const ssize_t n = ::read(master, buffer.data(), buffer.size());
            decoder.feed(buffer.data(), size_t(std::max<ssize_t>(n, 0)),
                         [&](const protocol::Message &m) {
                             if (m.type == protocol::MessageType::IdentifyRequest)
                                 requests.push_back(m);
                         });
        }
    };
    readFor(450);
    QVERIFY2(requests.size() >= 3, qPrintable(QString::number(requests.size())));
    protocol::Message reply;
    reply.type = protocol::MessageType::IdentifyReply;
    reply.sequence = requests.back().sequence;
    reply.identity.model = QStringLiteral("lra4");
    QByteArray bytes;
    protocol::encode(reply, &bytes);
    QCOMPARE(::write(master, bytes.constData(), size_t(bytes.size())), ssize_t(bytes.size()));
    QTRY_COMPARE(transport->status().identity, QStringLiteral("lra4"));
    readFor(350);
    QCOMPARE(requests.size(), size_t(0));
    transport->close();
    ::close(held);
    ::close(master);
}

void TestTransports::hidEnumerationWithoutDevices()
{
    QVERIFY(HidLink::enumerate(0, 0, 0).empty());
    QVERIFY(HidLink::enumerate(0x1234, 0x5678, 0xFF00).empty());
    HidLink link(0x1234, 0x5678);
    QString error;
    QVERIFY(!link.open(&error));
    QCOMPARE(error, QStringLiteral("hid:1234:5678: no such HID device"));
}

QTEST_GUILESS_MAIN(TestTransports)
#include "tst_transports.moc"
