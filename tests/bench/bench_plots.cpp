// SPDX-License-Identifier: MIT
// The live plots under load: a producer thread pushes two grippers' contact frames through
// a RunFeed and sends two 8-channel devices' frames to virtual transports at 1 kHz; the GUI
// thread drains the feed and what the transports sent (a SentFeed) into the RunHistory
// every 16 ms while a 1280×800 PlotPanel follows. Prints the replots per second, the GUI
// thread's CPU share and the feeds' drops. `--screenshot DIR` instead fills 12 s of
// the same synthetic run and saves the panel at 1280×800 and 1920×1080.
#include "devicemanager.h"
#include "plotpanel.h"
#include "runfeed.h"
#include "runhistory.h"
#include "sentfeed.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QTest>
#include <QTimer>

#include <qcustomplot.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <thread>

using namespace semhap;

namespace {

constexpr int Channels = 8;
constexpr double Pi = 3.14159265358979323846;

double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

GripperThresholds thresholds()
{
    using L = DetectorLevel;
    GripperThresholds t;
    t.levels = {{L::Quantity::Force, L::Meaning::ConfirmationBegins, QStringLiteral("grasp"), 5.0},
                {L::Quantity::Force, L::Meaning::ExceptionBegins, QStringLiteral("break"), 80.0},
                {L::Quantity::Force, L::Meaning::FullIntensity, QStringLiteral("max"), 100.0},
                {L::Quantity::Contacts, L::Meaning::ExceptionBegins, QStringLiteral("loss"), 28.0},
                {L::Quantity::Contacts, L::Meaning::FullIntensity, QStringLiteral("min"), 12.0}};
    return t;
}

/** What one pipeline tick hands to the feed. */
struct Tick
{
    std::array<ContactFrame, 2> frames;
    std::array<DeviceFrame, 2> devices;
    std::array<SemanticEvent, 6> events;
    int eventCount = 0;
};

/**
 * A bimanual run repeating every 10 s: the right hand grasps (ramp to 30 N), squeezes past
 * the break threshold to 90 N and back, and releases; the left hand holds a container
 * whose contact count falls 32 → 24 → 16 (slip) before a regrip. Events follow the
 * thresholds the way the detectors would.
 */
class Scenario
{
public:
    void tick(double t, Tick *out)
    {
        out->eventCount = 0;
        const double tau = std::fmod(t, 10.0);
        const double wobble = 0.6 * std::sin(2 * Pi * 1.3 * t);
        double right = 0.0;
        if (tau >= 0.5 && tau < 1.5)
            right = 30.0 * (tau - 0.5);
        else if (tau >= 1.5 && tau < 3.0)
            right = 30.0 + wobble;
        else if (tau >= 3.0 && tau < 3.6)
            right = 30.0 + 60.0 * (tau - 3.0) / 0.6;
        else if (tau >= 3.6 && tau < 4.2)
            right = 90.0 - 60.0 * (tau - 3.6) / 0.6;
        else if (tau >= 4.2 && tau < 7.0)
            right = 30.0 + wobble;
        else if (tau >= 7.0 && tau < 8.0)
            right = 30.0 * (8.0 - tau);
        double left = tau >= 0.3 && tau < 9.5 ? 20.0 + 0.5 * wobble : 0.0;
        int leftCount = left > 0.0 ? 32 : 0;
        if (tau >= 5.0 && tau < 7.0) {
            left = 20.0 - 4.0 * (tau - 5.0);
            leftCount = tau < 5.5 ? 32 : tau < 6.2 ? 24 : 16;
        }
        fill(&out->frames[0], t, Gripper::Right, right, right > 0.0 ? 32 : 0, 0.52);
        fill(&out->frames[1], t, Gripper::Left, left, leftCount, 0.47);
        for (size_t g = 0; g < 2; ++g)
            detect(g, out->frames[g], out);
        for (size_t d = 0; d < 2; ++d)
            drive(d, t, &out->devices[d]);
    }

private:
    static void fill(ContactFrame *frame, double t, Gripper gripper, double force, int count,
                     double share)
    {
        frame->t = t;
        frame->gripper = gripper;
        frame->left.f = force * share;
        frame->right.f = force * (1.0 - share);
        frame->left.n = count / 2;
        frame->right.n = count - count / 2;
    }

    void detect(size_t g, const ContactFrame &frame, Tick *out)
    {
        // The levels thresholds() gives: grasp, break and loss.
        const std::vector<DetectorLevel> levels = thresholds().levels;
        const double f = frame.totalForce();
        const int n = frame.totalContacts();
        const int forceNode = int(2 * g);
        toggle(&m_grasp[g], f >= levels[0].value, Message::Grasp, forceNode, frame, out);
        toggle(&m_break[g], f >= levels[1].value, Message::Break, forceNode, frame, out);
        toggle(&m_slip[g], n > 0 && n < levels[3].value, Message::Slip, forceNode + 1, frame, out);
    }

    static void toggle(bool *active, bool now, Message message, int node,
                       const ContactFrame &frame, Tick *out)
    {
        if (*active == now)
            return;
        *active = now;
        SemanticEvent &event = out->events[size_t(out->eventCount++)];
        event.t = frame.t;
        event.gripper = frame.gripper;
        event.node = node;
        event.detector = message == Message::Slip ? DetectorKind::Slip : DetectorKind::Force;
        event.message = message;
        event.category = categoryOf(message);
        event.phase = now ? EventPhase::Begin : EventPhase::End;
    }

    void drive(size_t d, double t, DeviceFrame *frame) const
    {
        frame->t = t;
        frame->device = int(d);
        frame->channelCount = Channels;
        for (int c = 0; c < Channels; ++c) {
            double v = m_grasp[d] && c < 4 ? 0.35 : 0.0;
            if (m_break[d])
                v = 0.5 + 0.5 * std::sin(2 * Pi * 6.0 * t + c * Pi / 4);
            if (m_slip[d]) // a wave travelling round the band
                v = 0.8 * std::max(0.0, std::cos(2 * Pi * 2.0 * t - c * 2 * Pi / Channels));
            frame->values[size_t(c)] = v;
        }
    }

    std::array<bool, 2> m_grasp{};
    std::array<bool, 2> m_break{};
    std::array<bool, 2> m_slip{};
};

const QStringList Bands = {QStringLiteral("right.band"), QStringLiteral("left.band")};

/** The bands' model: eight channels 0..1 at 1 kHz. */
DeviceModelPtr band8()
{
    QJsonArray channels;
    for (int c = 0; c < Channels; ++c)
        channels.append(QJsonObject{{QStringLiteral("name"), QStringLiteral("m%1").arg(c)},
                                    {QStringLiteral("unit"), QStringLiteral("amplitude")},
                                    {QStringLiteral("min"), 0},
                                    {QStringLiteral("max"), 1}});
    LoadError error;
    return DeviceModel::fromJson(
        QJsonObject{{QStringLiteral("format"), QLatin1String(DeviceModel::Format)},
                    {QStringLiteral("name"), QStringLiteral("band8")},
                    {QStringLiteral("rate"), 1000},
                    {QStringLiteral("channels"), channels}},
        QString(), &error);
}

void startRun(RunHistory &history)
{
    const QStringList channels = band8()->channelNames();
    history.start({{Bands[0], QStringLiteral("band8"), channels},
                   {Bands[1], QStringLiteral("band8"), channels}},
                  {thresholds(), thresholds()},
                  {QStringLiteral("right.force"), QStringLiteral("right.slip"),
                   QStringLiteral("left.force"), QStringLiteral("left.slip")});
}

int screenshots(RunHistory &history, PlotPanel &panel, const QString &dir)
{
    Scenario scenario;
    Tick tick;
    for (int k = 0; k <= 6000; ++k) { // 12 s at the pipeline's 2 ms step
        scenario.tick(k * 0.002, &tick);
        for (const ContactFrame &frame : tick.frames)
            history.append(frame);
        for (int e = 0; e < tick.eventCount; ++e)
            history.append(tick.events[size_t(e)]);
        for (const DeviceFrame &frame : tick.devices)
            history.append(frame);
    }
    history.commit();
    panel.setCursorTime(9.2);
    panel.goLive();
    panel.show();
    for (const QSize size : {QSize(1280, 800), QSize(1920, 1080)}) {
        panel.resize(size);
        QTest::qWait(100);
        const QString path = QDir(dir).filePath(QStringLiteral("plots-%1.png").arg(size.width()));
        if (!panel.grab().save(path)) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
            return 1;
        }
        std::printf("%s\n", qPrintable(path));
    }
    return 0;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addHelpOption();
    const QCommandLineOption secondsOption(QStringLiteral("seconds"),
                                           QStringLiteral("Seconds of real time to run."),
                                           QStringLiteral("N"), QStringLiteral("10"));
    const QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"), QStringLiteral("Save screenshots into DIR and exit."),
        QStringLiteral("DIR"));
    parser.addOption(secondsOption);
    parser.addOption(screenshotOption);
    parser.process(app);

    RunHistory history;
    PlotPanel panel(history);
    startRun(history);
    if (parser.isSet(screenshotOption))
        return screenshots(history, panel, parser.value(screenshotOption));

    const double seconds = std::max(1.0, parser.value(secondsOption).toDouble());
    RunFeed feed;
    DeviceManager devices;
    QString error;
    for (const QString &band : Bands) {
        if (!devices.bind(band, QStringLiteral("virtual:") + band, band8(), &error)) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 1;
        }
    }
    const std::array<Transport *, 2> transports = {devices.transport(Bands[0]),
                                                   devices.transport(Bands[1])};
    SentFeed sent;
    sent.start(Bands, devices);
    std::atomic<bool> done{false};
    std::thread producer([&] {
        Scenario scenario;
        Tick tick;
        const auto start = std::chrono::steady_clock::now();
        long long k = 0;
        while (!done) {
            // Catch up to real time after each sleep: 1 kHz on average.
            const auto due =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            for (; double(k) * 0.001 <= due; ++k) {
                scenario.tick(double(k) * 0.001, &tick);
                for (const ContactFrame &frame : tick.frames)
                    feed.push(frame);
                for (int e = 0; e < tick.eventCount; ++e)
                    feed.onEvent(tick.events[size_t(e)]);
                for (const DeviceFrame &frame : tick.devices)
                    transports[size_t(frame.device)]->send(frame);
            }
            std::this_thread::sleep_for(std::chrono::microseconds(500));
        }
    });

    QTimer drain;
    QObject::connect(&drain, &QTimer::timeout, [&] {
        feed.drainInto(history);
        sent.drainInto(history);
        history.commit();
    });
    drain.start(16);
    auto *plot = panel.findChild<QCustomPlot *>();
    long long replots = 0;
    QObject::connect(plot, &QCustomPlot::afterReplot, [&replots] { ++replots; });

    panel.resize(1280, 800);
    panel.show();
    if (!QTest::qWaitForWindowExposed(&panel))
        return 1;
    QTest::qWait(500); // first layout and caches, outside the measurement
    replots = 0;
    const double cpu0 = threadCpuSeconds();
    QElapsedTimer wall;
    wall.start();
    QTimer::singleShot(int(seconds * 1000.0), &app, &QApplication::quit);
    app.exec();
    const double elapsed = double(wall.nsecsElapsed()) * 1e-9;
    const double cpu = threadCpuSeconds() - cpu0;
    done = true;
    producer.join();

    std::printf("bench_plots: %.1f s, 2 grippers + 2 devices x %d channels at 1 kHz, "
                "1280x800\n",
                elapsed, Channels);
    std::printf("replots/s      %.1f\n", double(replots) / elapsed);
    std::printf("GUI thread CPU %.1f %% of one core\n", 100.0 * cpu / elapsed);
    std::printf("feed drops     %llu\n",
                static_cast<unsigned long long>(feed.dropped() + sent.lost()));
    return 0;
}
