// SPDX-License-Identifier: MIT
// Sessions under load. Recording: both hands at 1 kHz (every field filled, fxyz too)
// through the C3 router, its events and all seven devices' frames into a SessionWriter,
// paced to the wall clock (zero drops required); then the same as fast as the producer
// can go, which outruns any disk by design: it measures the writer's capacity. Scrubbing:
// the scene state at random moments of the paced session, as the studio's scrubber asks
// for it, then a moment after the last, as playback does. UDP: frames
// over loopback into a UdpFrameSource, one per datagram and in batches of 10.
#include "actortable.h"
#include "pipeline.h"
#include "sessionreader.h"
#include "sessionwriter.h"
#include "udpframesource.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QHostAddress>
#include <QTemporaryDir>
#include <QUdpSocket>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <thread>

using namespace semhap;

namespace {

using Clock = std::chrono::steady_clock;

/** A gripper's frame at t: forces swell and fade, contacts follow, fxyz is filled in. */
ContactFrame frameAt(Gripper gripper, double t)
{
    ContactFrame frame;
    frame.t = t;
    frame.gripper = gripper;
    const double shift = gripper == Gripper::Left ? 1.3 : 0.0;
    const double force = std::max(0.0, 70 * std::sin(0.9 * t + shift) + 10 * std::sin(31 * t));
    for (Fingertip *tip : {&frame.left, &frame.right}) {
        tip->f = force / 2;
        tip->n = force > 0 ? 8 + int(8 * std::fabs(std::sin(3 * t))) : 0;
        tip->actor = force > 0 ? 0 : -1;
        tip->hasFxyz = true;
        tip->fxyz = {0.1 * tip->f, tip->f, -0.05 * tip->f};
    }
    return frame;
}

/** Counts what the pipeline hands the recorder. */
class Tee : public PipelineSink
{
public:
    explicit Tee(SessionWriter &writer) : m_writer(writer) {}
    void onEvent(const SemanticEvent &event) override
    {
        ++events;
        m_writer.onEvent(event);
    }
    void onDeviceFrame(const DeviceFrame &frame) override
    {
        ++deviceFrames;
        m_writer.onDeviceFrame(frame);
    }
    long events = 0;
    long deviceFrames = 0;

private:
    SessionWriter &m_writer;
};

/** Records `seconds` of the bimanual workload; paced to the wall clock or flat out. */
void record(const QString &path, double seconds, bool paced)
{
    LoadError error;
    std::unique_ptr<Router> router = loadRouter(QStringLiteral("C3"), {}, &error);
    QString message;
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(path, SessionInfo(), *router, &message);
    if (!writer) {
        std::fprintf(stderr, "%s\n", qPrintable(message));
        return;
    }
    ActorTable actors;
    actors.intern(QStringLiteral("cube_1"));
    writer->setActorTable(&actors);
    Pipeline pipeline(std::move(router));
    Tee tee(*writer);
    const Clock::time_point start = Clock::now();
    long frames = 0;
    long states = 0;
    double t = 0;
    // A bimanual scene's state: 100 numbers (qpos and the two mocap wrists) 30 times a second.
    SceneState state;
    state.pose.assign(100, 0.25);
    for (long tick = 0;; ++tick) {
        t = double(tick) / 1000;
        if (paced) {
            std::this_thread::sleep_until(start + std::chrono::microseconds(tick * 1000));
        }
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        if ((paced ? t : elapsed) >= seconds)
            break;
        for (Gripper g : {Gripper::Left, Gripper::Right}) {
            const ContactFrame frame = frameAt(g, t);
            writer->recordContactFrame(frame, paced ? elapsed : qQNaN());
            pipeline.process(frame, tee);
            ++frames;
        }
        pipeline.flush(tee);
        if (tick % 33 == 0) {
            state.t = t;
            writer->recordSceneState(state);
            ++states;
        }
    }
    const double produced = std::chrono::duration<double>(Clock::now() - start).count();
    const Clock::time_point closing = Clock::now();
    writer->finish();
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    const double close = std::chrono::duration<double>(Clock::now() - closing).count();
    const double values = double(frames + tee.events + tee.deviceFrames + states);
    std::printf("%s: %.1f s of session in %.2f s (close %.0f ms)\n",
                paced ? "recording, real time" : "recording, flat out", t, wall, close * 1000);
    std::printf("  contact frames %ld (%.0f/s), events %ld, device frames %ld (%.0f/s), scene "
                "states %ld\n",
                frames, double(frames) / produced, tee.events, tee.deviceFrames,
                double(tee.deviceFrames) / produced, states);
    std::printf("  values committed %.0f/s of %.0f/s produced, dropped %llu, writer thread "
                "%.1f%% of a core (%.0f values per CPU second), %.1f MB\n",
                double(writer->committed()) / wall, values / produced,
                static_cast<unsigned long long>(writer->dropped()),
                100 * writer->writerCpuSeconds() / wall,
                double(writer->committed()) / std::max(1e-9, writer->writerCpuSeconds()),
                double(QFileInfo(path).size()) / 1e6);
}

/**
 * Sends frames over loopback for `seconds` and reports what the source parsed per second
 * and the receiver's CPU time per datagram. `invalid`: every frame lacks its gripper (a
 * flood of garbage must cost about what good frames cost).
 */
/** The scene state at moments of the session: at random, and one after another. */
void scrub(const QString &path)
{
    QString error;
    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    if (!reader) {
        std::printf("scrub: %s\n", qPrintable(error));
        return;
    }
    std::mt19937 random(1);
    std::uniform_real_distribution<double> moment(reader->startTime(), reader->endTime());
    SceneState state;
    const auto time = [&](int count, const std::function<double(int)> &at) {
        const auto start = Clock::now();
        for (int i = 0; i < count; ++i)
            reader->readSceneState(at(i), &state, &error);
        return std::chrono::duration<double, std::micro>(Clock::now() - start).count() / count;
    };
    const double jumps = time(1000, [&](int) { return moment(random); });
    const double steps = time(1000, [&](int i) { return reader->startTime() + i / 60.0; });
    std::printf("scrub: scene state at a random moment %.0f µs, at the next frame of playback "
                "(60 Hz) %.0f µs\n",
                jumps, steps);
}

void udp(double seconds, int batch, bool invalid = false)
{
    std::atomic<int> port{0};
    std::atomic<quint64> received{0};
    std::atomic<bool> stop{false};
    quint64 frames = 0;
    double busy = 0;
    std::thread receiver([&] {
        UdpFrameSource source;
        QString error;
        if (!source.bind(QStringLiteral("127.0.0.1"), 0, &error))
            return;
        port = source.port();
        while (!stop.load() || source.waitForDatagrams(100)) {
            source.waitForDatagrams(10);
            source.poll([](const ContactFrame &, double) {});
            received = source.stats().datagrams;
        }
        frames = source.stats().frames;
        timespec cpu{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
        busy = double(cpu.tv_sec) + double(cpu.tv_nsec) * 1e-9;
    });
    while (port.load() == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    QUdpSocket sender;
    const Clock::time_point start = Clock::now();
    quint64 sent = 0;
    long tick = 0;
    while (std::chrono::duration<double>(Clock::now() - start).count() < seconds) {
        QByteArray datagram = batch > 1 ? QByteArray("[") : QByteArray();
        for (int i = 0; i < batch; ++i, ++tick) {
            if (i > 0)
                datagram += ',';
            const ContactFrame f = frameAt(Gripper::Right, double(tick) * 1e-3);
            if (invalid) {
                datagram += QStringLiteral("{\"t\":%1,\"left\":{\"f\":1,\"n\":1,\"actor\":"
                                           "\"cube_1\"}}")
                                .arg(f.t, 0, 'g', 17)
                                .toUtf8();
                continue;
            }
            datagram += QStringLiteral("{\"t\":%1,\"gripper\":\"right\",\"left\":{\"f\":%2,"
                                       "\"n\":%3,\"actor\":\"cube_1\"},\"right\":{\"f\":%2,"
                                       "\"n\":%3,\"actor\":\"cube_1\"}}")
                            .arg(f.t, 0, 'g', 17)
                            .arg(f.left.f, 0, 'g', 17)
                            .arg(f.left.n)
                            .toUtf8();
        }
        if (batch > 1)
            datagram += ']';
        sender.writeDatagram(datagram, QHostAddress::LocalHost, quint16(port.load()));
        ++sent;
        // Flow control: the kernel's buffer never overflows, so nothing is lost unseen.
        while (sent > received.load() + 128)
            std::this_thread::yield();
    }
    stop = true;
    receiver.join();
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    std::printf("udp, %d %sframe(s) per datagram: %.0f frames/s (%llu of %llu datagrams), "
                "receiver %.0f%% of a core, %.1f µs of it per datagram\n",
                batch, invalid ? "invalid " : "", double(frames) / wall,
                static_cast<unsigned long long>(received.load()),
                static_cast<unsigned long long>(sent), 100 * busy / wall,
                1e6 * busy / std::max<double>(1.0, double(received.load())));
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    const double seconds = args.size() > 1 ? args[1].toDouble() : 10.0;
    QTemporaryDir dir;
    record(dir.filePath(QStringLiteral("paced.db")), seconds, true);
    scrub(dir.filePath(QStringLiteral("paced.db")));
    record(dir.filePath(QStringLiteral("flat.db")), 3.0, false);
    udp(3.0, 1);
    udp(3.0, 10);
    udp(3.0, 300, true);
    return 0;
}
