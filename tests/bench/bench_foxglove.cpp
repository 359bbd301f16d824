// SPDX-License-Identifier: MIT
// What serving Foxglove costs the pipeline (`--foxglove-server`): two grippers' contact
// frames at 1 kHz through C3 in real time, first alone, then with every frame, event and band
// frame published to two viewers (the reference client, tests/interop/foxglove-viewer.mjs).
// Prints the CPU the process used as a share of one core, the tick's p50 and p99 (the
// pipeline and the publishing, in microseconds) and what the viewers got. Target (issue 35):
// serving costs at most 5 % of a core, and the tick's p99 is unchanged.
//
//   bench_foxglove [SECONDS]   (default 30 s per pass)
#include "actortable.h"
#include "foxglovepublisher.h"
#include "foxgloveserver.h"
#include "pipeline.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sys/resource.h>
#include <thread>
#include <vector>

using namespace semhap;

namespace {

using Clock = std::chrono::steady_clock;

class CountingSink : public PipelineSink
{
public:
    void onEvent(const SemanticEvent &) override { ++events; }
    void onDeviceFrame(const DeviceFrame &) override { ++frames; }
    long events = 0;
    long frames = 0;
};

/** Forwards to the counter and, when there is one, the publisher. */
class Sinks : public PipelineSink
{
public:
    Sinks(CountingSink &count, FoxglovePublisher *live) : m_count(count), m_live(live) {}
    void onEvent(const SemanticEvent &e) override
    {
        m_count.onEvent(e);
        if (m_live)
            m_live->onEvent(e);
    }
    void onDeviceFrame(const DeviceFrame &f) override
    {
        m_count.onDeviceFrame(f);
        if (m_live)
            m_live->onDeviceFrame(f);
    }

private:
    CountingSink &m_count;
    FoxglovePublisher *m_live;
};

/** A grasp, the break zone and a release every 4 s on each hand. */
void makeFrame(double t, Gripper gripper, ContactFrame *frame)
{
    const double phase = std::fmod(t + (gripper == Gripper::Left ? 2.0 : 0.0), 4.0);
    const double force = phase < 0.5 ? 0.0 : 20 + 50 * (1 - std::cos(phase * 2.2));
    frame->t = t;
    frame->gripper = gripper;
    for (Fingertip *tip : {&frame->left, &frame->right}) {
        tip->f = force / 2;
        tip->n = force > 0 ? 16 : 0;
        tip->actor = force > 0 ? 0 : -1;
    }
}

double cpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

double percentile(std::vector<double> values, double p)
{
    std::sort(values.begin(), values.end());
    return values[size_t(p * double(values.size() - 1))];
}

struct Pass
{
    double core = 0; ///< CPU seconds per wall second
    double p50 = 0, p99 = 0;
    long long published = 0, sent = 0, dropped = 0;
};

/** `seconds` of ticks at 1 kHz on the wall clock, published on `server` when given. */
Pass run(int seconds, FoxgloveServer *server)
{
    LoadError error;
    Pipeline pipeline(loadRouter(QStringLiteral("C3"), {}, &error));
    ActorTable actors;
    actors.intern(QStringLiteral("cube"));
    std::unique_ptr<FoxglovePublisher> live;
    if (server)
        live = std::make_unique<FoxglovePublisher>(*server, pipeline.router(), actors, 0);
    CountingSink count;
    Sinks sinks(count, live.get());
    ContactFrame left;
    ContactFrame right;
    std::vector<double> micros;
    micros.reserve(size_t(seconds) * 1000);
    const double cpu = cpuSeconds();
    const Clock::time_point start = Clock::now();
    for (int k = 0; k < seconds * 1000; ++k) {
        std::this_thread::sleep_until(start + std::chrono::microseconds(k * 1000));
        const Clock::time_point tick = Clock::now();
        const double t = k * 0.001;
        makeFrame(t, Gripper::Left, &left);
        makeFrame(t, Gripper::Right, &right);
        if (live) {
            live->onContactFrame(left);
            live->onContactFrame(right);
        }
        pipeline.process(left, sinks);
        pipeline.process(right, sinks);
        micros.push_back(std::chrono::duration<double, std::micro>(Clock::now() - tick).count());
    }
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    Pass pass;
    pass.core = (cpuSeconds() - cpu) / wall;
    pass.p50 = percentile(micros, 0.5);
    pass.p99 = percentile(micros, 0.99);
    if (server) {
        server->close();
        const FoxgloveServer::Stats stats = server->stats();
        pass.published = stats.published;
        pass.sent = stats.sent;
        pass.dropped = stats.dropped;
    }
    return pass;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    const int seconds = std::max(1, args.size() > 1 ? args[1].toInt() : 30);

    const Pass alone = run(seconds, nullptr);
    std::printf("pipeline alone: %.1f %% of a core; tick p50 %.1f us, p99 %.1f us\n",
                alone.core * 100, alone.p50, alone.p99);

    FoxgloveServer server(QStringLiteral("bench_foxglove"));
    QString error;
    if (!server.listen(QHostAddress::LocalHost, 0, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    std::vector<std::unique_ptr<QProcess>> viewers;
    for (int i = 0; i < 2; ++i) {
        auto viewer = std::make_unique<QProcess>();
        viewer->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        viewer->start(QStringLiteral(SEMHAP_NODE),
                      {QStringLiteral(SEMHAP_INTEROP_TOOLS "/foxglove-viewer.mjs"), server.url()});
        viewers.push_back(std::move(viewer));
    }
    // The viewers subscribe to the channels the publisher advertises at once (events, bands);
    // the grippers' come with their first frame.
    while (server.stats().clients < 2)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const Pass served = run(seconds, &server);
    long long received = 0;
    for (const auto &viewer : viewers) {
        viewer->waitForFinished(30000);
        const QByteArray out = viewer->readAllStandardOutput().trimmed();
        const QJsonObject view = QJsonDocument::fromJson(out.split('\n').last()).object();
        for (const QJsonValue &topic : view.value(QLatin1String("topics")).toObject())
            received += topic.toObject().value(QLatin1String("count")).toInteger();
    }
    std::printf("served to 2 viewers: %.1f %% of a core (serving: %+.1f %%, target <= 5 %%); "
                "tick p50 %.1f us, p99 %.1f us (alone: %.1f us)\n",
                served.core * 100, (served.core - alone.core) * 100, served.p50, served.p99,
                alone.p99);
    std::printf("messages: %lld published, %lld sent, %lld dropped; the viewers decoded %lld\n",
                served.published, served.sent, served.dropped, received);
    return 0;
}
