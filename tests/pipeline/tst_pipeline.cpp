// SPDX-License-Identifier: MIT
// The pipeline's clock and the player's mixing: when device frames come out and what they hold.
#include "allocationcounter.h"
#include "pipeline.h"
#include "sinklist.h"

#include <QJsonDocument>
#include <QTest>

using namespace semhap;

namespace {

struct Recorded
{
    std::vector<SemanticEvent> events;
    std::vector<DeviceFrame> frames;
};

class RecordingSink : public PipelineSink
{
public:
    explicit RecordingSink(Recorded &r) : m_r(r) {}
    void onEvent(const SemanticEvent &e) override { m_r.events.push_back(e); }
    void onDeviceFrame(const DeviceFrame &f) override { m_r.frames.push_back(f); }

private:
    Recorded &m_r;
};

/** A right-gripper frame with F split evenly over both fingertips on one cube. */
ContactFrame rightFrame(double t, double force)
{
    ContactFrame frame;
    frame.t = t;
    frame.gripper = Gripper::Right;
    for (Fingertip *tip : {&frame.left, &frame.right}) {
        tip->f = force / 2;
        tip->n = force > 0 ? 16 : 0;
        tip->actor = force > 0 ? 0 : -1;
    }
    return frame;
}

std::unique_ptr<Router> router(const QString &preset, const QStringList &overrides = {})
{
    LoadError error;
    std::unique_ptr<Router> r = loadRouter(preset, overrides, &error);
    if (!r)
        qFatal("%s", qPrintable(error.toString()));
    return r;
}

/** Runs frames at 1 kHz from t0 with F given by `force(t)`; returns what came out. */
template<typename Force> Recorded run(const QString &preset, double t0, double t1, Force force)
{
    Pipeline pipeline(router(preset));
    Recorded recorded;
    RecordingSink sink(recorded);
    for (int k = 0; t0 + k * 0.001 <= t1 + 1e-9; ++k) {
        pipeline.process(rightFrame(t0 + k * 0.001, force(k * 0.001)), sink);
        pipeline.flush(sink);
    }
    return recorded;
}

/** The values of one channel of one device over time, as (t, value). */
std::vector<std::pair<double, double>> channel(const Recorded &r, const Router &router,
                                               const QString &device, int c)
{
    const int index = router.player().deviceIndex(device);
    std::vector<std::pair<double, double>> series;
    for (const DeviceFrame &f : r.frames) {
        if (f.device == index)
            series.emplace_back(f.t, f.values[size_t(c)]);
    }
    return series;
}

double valueAt(const std::vector<std::pair<double, double>> &series, double t)
{
    for (const auto &[time, value] : series) {
        if (std::abs(time - t) < 1e-9)
            return value;
    }
    qFatal("no sample at %g", t);
}

} // namespace

class TestPipeline : public QObject
{
    Q_OBJECT

private slots:
    void instantsCoverFirstToLastFrame_data();
    void instantsCoverFirstToLastFrame();
    void framesOrderedByTimeThenName();
    void instantAtFrameTimeSeesThatFrame();
    void squeezeFollowsGrasp();
    void exceptionOverridesConfirmationOnSharedChannel();
    void maxPolicyMasksThePulse();
    void geigerRateFollowsIntensity();
    void hysteresisTimerActsBetweenFrames();
    void laggingGripperDoesNotRewindClock();
    void clockJumpsCostBoundedWork_data();
    void clockJumpsCostBoundedWork();
    void nonFiniteTimeIsNow();
    void endAllEndsActiveMessages();
    void overfullTickIsCounted();
    void routerSwapKeepsTheClock();
    void sinkListHandsEverythingToEach();
    void noAllocationPerTick();
};

void TestPipeline::instantsCoverFirstToLastFrame_data()
{
    QTest::addColumn<QString>("device");
    QTest::addColumn<int>("count");
    // Frames from 1.0 to 1.1 s: every instant t0 + k/rate <= 1.1, none after.
    QTest::newRow("pneumatic6 at 100 Hz") << "right.air" << 11;
    QTest::newRow("lra4 at 500 Hz") << "left.vibro" << 51;
    QTest::newRow("fingertips2 at 100 Hz") << "left.fingertips" << 11;
    QTest::newRow("overlay at 60 Hz") << "overlay" << 7;
}

void TestPipeline::instantsCoverFirstToLastFrame()
{
    QFETCH(QString, device);
    QFETCH(int, count);
    const Recorded r = run("C3", 1.0, 1.1, [](double) { return 0.0; });
    const std::unique_ptr<Router> c3 = router("C3");
    const auto series = channel(r, *c3, device, 0);
    QCOMPARE(int(series.size()), count);
    QCOMPARE(series.front().first, 1.0);
    QVERIFY(series.back().first <= 1.1 + 1e-9);
}

void TestPipeline::framesOrderedByTimeThenName()
{
    const Recorded r = run("C3", 0.0, 0.05, [](double) { return 0.0; });
    const std::unique_ptr<Router> c3 = router("C3");
    for (size_t i = 1; i < r.frames.size(); ++i) {
        const DeviceFrame &a = r.frames[i - 1];
        const DeviceFrame &b = r.frames[i];
        QVERIFY(a.t < b.t || (a.t == b.t && c3->player().deviceName(a.device) <
                                                c3->player().deviceName(b.device)));
    }
    // At t = 0 every device has an instant: all seven, in name order.
    QCOMPARE(r.frames.size() >= 7, true);
    for (int d = 0; d < 7; ++d)
        QCOMPARE(r.frames[size_t(d)].device, d);
}

void TestPipeline::instantAtFrameTimeSeesThatFrame()
{
    // pulse5hz on C4 starts high at begin: the instant at the break's frame already shows it,
    // but only once flush() says every frame of that tick is in.
    Pipeline pipeline(router("C4", {"right.force.grasp=1", "right.force.break=2"}));
    Recorded r;
    RecordingSink sink(r);
    pipeline.process(rightFrame(0.0, 0.0), sink);
    pipeline.process(rightFrame(0.01, 50.0), sink);
    const int air = pipeline.router().player().deviceIndex("right.air");
    const auto atBreak = [&] {
        return std::find_if(r.frames.begin(), r.frames.end(),
                            [&](const DeviceFrame &f) { return f.device == air && f.t == 0.01; });
    };
    QVERIFY(atBreak() == r.frames.end());
    for (const DeviceFrame &f : r.frames)
        QVERIFY(f.t < 0.01);
    pipeline.flush(sink);
    QVERIFY(atBreak() != r.frames.end());
    QCOMPARE(atBreak()->values[0], 1.0);
}

void TestPipeline::squeezeFollowsGrasp()
{
    // F steps to 30 N at t = 0.1: grasp begins, air.squeeze ramps 0 -> 1 over 0.5 s.
    const Recorded r = run("C3", 0.0, 1.0, [](double t) { return t >= 0.1 ? 30.0 : 0.0; });
    const std::unique_ptr<Router> c3 = router("C3");
    const auto air = channel(r, *c3, "right.air", 0);
    QCOMPARE(valueAt(air, 0.1), 0.0);
    QVERIFY(std::abs(valueAt(air, 0.35) - 0.5) < 1e-9);
    QCOMPARE(valueAt(air, 0.6), 1.0);
    QCOMPARE(valueAt(air, 1.0), 1.0);
    // Every bellow gets the same value; the other hand's band stays still.
    for (int b = 1; b < 6; ++b)
        QCOMPARE(channel(r, *c3, "right.air", b), air);
    for (const auto &[t, v] : channel(r, *c3, "left.air", 0))
        QCOMPARE(v, 0.0);
    QCOMPARE(r.events.size(), size_t(1));
    QCOMPARE(r.events[0].message, Message::Grasp);
}

void TestPipeline::exceptionOverridesConfirmationOnSharedChannel()
{
    // C4: squeeze (confirmation) and pulse5hz (exception) share right.air. F = 30 from 0.1 s,
    // 100 (break) from 1.0 s to 1.6 s, then 30 again.
    const auto force = [](double t) {
        return t < 0.1 ? 0.0 : (t >= 1.0 && t < 1.6 ? 100.0 : 30.0);
    };
    const Recorded r = run("C4", 0.0, 2.5, force);
    const std::unique_ptr<Router> c4 = router("C4");
    const auto air = channel(r, *c4, "right.air", 0);
    QCOMPARE(valueAt(air, 0.9), 1.0); // squeezed
    QCOMPARE(valueAt(air, 1.0), 1.0); // pulse starts high
    QCOMPARE(valueAt(air, 1.09), 1.0);
    QCOMPARE(valueAt(air, 1.1), 0.0); // low half of the 5 Hz square wins over the squeeze
    QCOMPARE(valueAt(air, 1.19), 0.0);
    QCOMPARE(valueAt(air, 1.2), 1.0);
    QCOMPARE(valueAt(air, 1.6), 1.0); // the exception ended: the squeeze is back
    QCOMPARE(valueAt(air, 2.5), 1.0);
}

void TestPipeline::maxPolicyMasksThePulse()
{
    // The same with the max policy: the squeeze at 1 hides the pulse. Why priority is default.
    const auto force = [](double t) {
        return t < 0.1 ? 0.0 : (t >= 1.0 && t < 1.6 ? 100.0 : 30.0);
    };
    Pipeline pipeline(router("C4", {"right.air.policy=\"max\""}));
    Recorded r;
    RecordingSink sink(r);
    for (int k = 0; k <= 1500; ++k) {
        pipeline.process(rightFrame(k * 0.001, force(k * 0.001)), sink);
        pipeline.flush(sink);
    }
    const auto air = channel(r, pipeline.router(), "right.air", 0);
    QCOMPARE(valueAt(air, 1.1), 1.0);
    QCOMPARE(valueAt(air, 1.15), 1.0);
}

void TestPipeline::geigerRateFollowsIntensity()
{
    // C3: F held at 100 N -> break intensity 0.5 -> 11 Hz pulses of 25 ms on right.vibro.
    const Recorded r = run("C3", 0.0, 2.0, [](double) { return 100.0; });
    const std::unique_ptr<Router> c3 = router("C3");
    const auto vibro = channel(r, *c3, "right.vibro", 0);
    int rising = 0;
    int high = 0;
    double previous = 0;
    for (const auto &[t, v] : vibro) {
        if (t >= 1.0)
            break;
        rising += v > 0.5 && previous <= 0.5;
        high += v > 0.5;
        previous = v;
    }
    QCOMPARE(rising, 11);                      // pulses at 0, 1/11, … 10/11 s
    QVERIFY(std::abs(high - 11 * 12.5) <= 11); // 25 ms each at 500 Hz
}

void TestPipeline::hysteresisTimerActsBetweenFrames()
{
    // A hold of 0.155 s on the squeeze's messages: its end lands between frames and instants.
    RouterGraph graph;
    LoadError error;
    QVERIFY(RouterPresets::preset("C3", &graph, &error));
    graph.nodes.push_back({"hold", "debounce", QJsonObject{{"hold", 0.155}}, {}});
    for (RouterLink &link : graph.links) {
        if (link.from == "right.confirm" && link.to == "right.squeeze")
            link.to = "hold";
    }
    graph.links.push_back({"hold", {}, "right.squeeze", {}});
    std::unique_ptr<Router> compiled = Router::compile(graph, &error);
    QVERIFY2(compiled, qPrintable(error.toString()));
    Pipeline pipeline(std::move(compiled));
    Recorded r;
    RecordingSink sink(r);
    // Grasp from 0.1 to 1 s, frames every 0.1 s; the end at 1.1 s is held until 1.255 s.
    for (int k = 0; k <= 20; ++k) {
        pipeline.process(rightFrame(k * 0.1, k <= 10 && k > 0 ? 30.0 : 0.0), sink);
        pipeline.flush(sink);
    }
    const auto air = channel(r, pipeline.router(), "right.air", 0);
    QCOMPARE(valueAt(air, 1.1), 1.0);
    QCOMPARE(valueAt(air, 1.25), 1.0);
    QVERIFY(std::abs(valueAt(air, 1.26) - (1.0 - 0.005 / 0.5)) < 1e-9);
    QVERIFY(std::abs(valueAt(air, 1.4) - (1.0 - 0.145 / 0.5)) < 1e-9);
}

void TestPipeline::laggingGripperDoesNotRewindClock()
{
    Pipeline pipeline(router("C3"));
    Recorded r;
    RecordingSink sink(r);
    pipeline.process(rightFrame(1.0, 0.0), sink);
    ContactFrame late;
    late.t = 0.5;
    late.gripper = Gripper::Left;
    pipeline.process(late, sink);
    QCOMPARE(pipeline.now(), 1.0);
    pipeline.flush(sink);
    for (const DeviceFrame &f : r.frames)
        QCOMPARE(f.t, 1.0);
}

void TestPipeline::clockJumpsCostBoundedWork_data()
{
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::newRow("a billion seconds") << 0.0 << 1e9;
    QTest::newRow("across the range") << -1e10 << 1e10;
    QTest::newRow("a minute") << 5.0 << 65.0;
}

void TestPipeline::clockJumpsCostBoundedWork()
{
    // Before, every device instant of the gap was rendered: a jump of 1e9 s never ended.
    QFETCH(double, t0);
    QFETCH(double, t1);
    std::unique_ptr<Router> r = router("C3");
    const int devices = r->player().deviceCount();
    Pipeline pipeline(std::move(r));
    Recorded recorded;
    RecordingSink sink(recorded);
    pipeline.process(rightFrame(t0, 50.0), sink);
    pipeline.process(rightFrame(t1, 50.0), sink);
    pipeline.flush(sink);
    QCOMPARE(pipeline.now(), t1);
    QVERIFY(recorded.frames.size() <= size_t(devices * (Pipeline::MaxInstantsPerGap + 1)));
    // The devices go on from the new time: the last frames are at it, in order.
    QCOMPARE(recorded.frames.back().t, t1);
    for (size_t i = 1; i < recorded.frames.size(); ++i)
        QVERIFY(recorded.frames[i].t >= recorded.frames[i - 1].t);
    // And the next frame costs what a frame costs.
    const size_t before = recorded.frames.size();
    pipeline.process(rightFrame(t1 + 0.01, 50.0), sink);
    pipeline.flush(sink);
    QVERIFY(recorded.frames.size() - before <= size_t(devices * 11));
}

void TestPipeline::nonFiniteTimeIsNow()
{
    Pipeline pipeline(router("C3"));
    Recorded r;
    RecordingSink sink(r);
    pipeline.process(rightFrame(qQNaN(), 0.0), sink);
    QCOMPARE(pipeline.now(), 0.0);
    pipeline.process(rightFrame(1.0, 0.0), sink);
    pipeline.process(rightFrame(qInf(), 0.0), sink);
    pipeline.process(rightFrame(-qInf(), 0.0), sink);
    QCOMPARE(pipeline.now(), 1.0);
    pipeline.flush(sink);
    QCOMPARE(r.frames.back().t, 1.0);
}

void TestPipeline::endAllEndsActiveMessages()
{
    // A silent source: the grasp it left active ends at "now", and only once.
    Pipeline pipeline(router("C3"));
    Recorded r;
    RecordingSink sink(r);
    for (int k = 0; k <= 100; ++k)
        pipeline.process(rightFrame(k * 0.001, 50.0), sink);
    QCOMPARE(r.events.size(), size_t(1));
    QCOMPARE(r.events.front().phase, EventPhase::Begin);
    pipeline.endAll(sink);
    QCOMPARE(r.events.size(), size_t(2));
    QCOMPARE(r.events.back().phase, EventPhase::End);
    QCOMPARE(r.events.back().t, 0.1);
    pipeline.endAll(sink);
    QCOMPARE(r.events.size(), size_t(2));
}

void TestPipeline::overfullTickIsCounted()
{
    // Seventeen force detectors on one gripper: a frame past break makes 34 events in one
    // tick, two more than a tick holds. They are counted, for the commands to say so.
    RouterGraph graph;
    for (int d = 0; d < 17; ++d)
        graph.nodes.push_back(
            {QString("f%1").arg(d), "force", QJsonObject{{"gripper", "right"}}, {}});
    LoadError error;
    std::unique_ptr<Router> compiled = Router::compile(graph, &error);
    QVERIFY2(compiled, qPrintable(error.toString()));
    Pipeline pipeline(std::move(compiled));
    Recorded r;
    RecordingSink sink(r);
    pipeline.process(rightFrame(0.0, 100.0), sink);
    QCOMPARE(r.events.size(), size_t(EventBuffer::Capacity));
    QCOMPARE(pipeline.droppedEvents(), 2);
}

void TestPipeline::routerSwapKeepsTheClock()
{
    // C3 to C4 while the right hand holds: C3's grasp ends at the swap's time, C4 starts on
    // the same clock, and the right band's 100 Hz instants go on without a gap or a repeat.
    Pipeline pipeline(router("C3"));
    Recorded r;
    RecordingSink sink(r);
    for (int k = 0; k <= 50; ++k)
        pipeline.process(rightFrame(1.0 + k * 0.001, 50.0), sink);
    pipeline.setRouter(router("C4"), sink);
    QCOMPARE(r.events.back().phase, EventPhase::End);
    QCOMPARE(r.events.back().t, 1.05);
    QVERIFY(pipeline.router().isStarted());
    for (int k = 51; k <= 100; ++k)
        pipeline.process(rightFrame(1.0 + k * 0.001, 50.0), sink);
    pipeline.flush(sink);
    QCOMPARE(r.events.back().phase, EventPhase::Begin); // C4's own grasp
    const int air = pipeline.router().player().deviceIndex("right.air");
    std::vector<double> instants;
    for (const DeviceFrame &frame : r.frames) {
        if (frame.device == air)
            instants.push_back(frame.t);
    }
    QCOMPARE(instants.size(), size_t(11)); // 1.00 … 1.10 at 100 Hz
    for (size_t i = 1; i < instants.size(); ++i)
        QVERIFY(std::abs(instants[i] - instants[i - 1] - 0.01) < 1e-9);
}

void TestPipeline::sinkListHandsEverythingToEach()
{
    // Two recorders on one list (a null left out) get the same streams, the same as one
    // recorder alone.
    Recorded alone;
    {
        Pipeline pipeline(router("C3"));
        RecordingSink sink(alone);
        for (int k = 0; k <= 200; ++k)
            pipeline.process(rightFrame(k * 0.001, k < 100 ? 50.0 : 0.0), sink);
        pipeline.flush(sink);
    }
    Recorded first;
    Recorded second;
    RecordingSink a(first);
    RecordingSink b(second);
    SinkList list{&a, nullptr, &b};
    Pipeline pipeline(router("C3"));
    for (int k = 0; k <= 200; ++k)
        pipeline.process(rightFrame(k * 0.001, k < 100 ? 50.0 : 0.0), list);
    pipeline.flush(list);
    QVERIFY(alone.events.size() == 2);
    for (const Recorded *r : {&first, &second}) {
        QCOMPARE(r->events.size(), alone.events.size());
        QCOMPARE(r->frames.size(), alone.frames.size());
        QCOMPARE(r->events.back().t, alone.events.back().t);
    }
}

void TestPipeline::noAllocationPerTick()
{
    Pipeline pipeline(router("C3"));
    Recorded r;
    r.frames.reserve(100000);
    r.events.reserve(100000);
    RecordingSink sink(r);
    const auto tick = [&](int k) {
        const double t = k * 0.001;
        const double f = 60 + 50 * std::sin(t * 3); // in and out of the break zone
        ContactFrame right = rightFrame(t, f);
        ContactFrame left = rightFrame(t, 40);
        left.gripper = Gripper::Left;
        left.left.n = left.right.n = 8 + (k / 200) % 9; // slipping and recovering
        pipeline.process(left, sink);
        pipeline.process(right, sink);
        pipeline.flush(sink);
    };
    tick(0);
    test::startCountingAllocations();
    for (int k = 1; k < 5000; ++k)
        tick(k);
    const long allocations = test::stopCountingAllocations();
    QVERIFY(r.events.size() > 10);
    QCOMPARE(allocations, 0L);
}

QTEST_GUILESS_MAIN(TestPipeline)
#include "tst_pipeline.moc"
