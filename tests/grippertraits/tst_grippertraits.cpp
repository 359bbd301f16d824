// SPDX-License-Identifier: MIT
#include "forcedetector.h"
#include "router.h"
#include "slipdetector.h"

#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

constexpr double Step = 0.002; // the simulation's frame period (s)

/** C3 (a slip node on the left gripper, a force node on the right) compiled for `context`. */
std::unique_ptr<Router> c3(const RouterContext &context)
{
    LoadError error;
    std::unique_ptr<Router> router = loadRouter("C3", {}, &error, context);
    if (!router)
        qWarning("%s", qPrintable(error.toString()));
    return router;
}

/** A frame of `gripper` holding actor 0 with `force` N split over the fingertips. */
ContactFrame holding(double t, Gripper gripper, double force, int leftContacts, int rightContacts)
{
    ContactFrame frame;
    frame.t = t;
    frame.gripper = gripper;
    frame.left.f = frame.right.f = force / 2;
    frame.left.n = leftContacts;
    frame.right.n = rightContacts;
    frame.left.actor = frame.right.actor = 0;
    return frame;
}

/** How many `message` begins the router's events had of detector kind `detector`. */
struct Begins
{
    int count(DetectorKind detector, Message message) const
    {
        int n = 0;
        for (const SemanticEvent &e : events) {
            n += e.detector == detector && e.message == message && e.phase == EventPhase::Begin;
        }
        return n;
    }
    std::vector<SemanticEvent> events;
};

Begins run(Router &router, const std::vector<ContactFrame> &frames)
{
    Begins result;
    EventBuffer events;
    router.start(frames.front().t);
    for (const ContactFrame &frame : frames) {
        events.clear();
        router.process(frame, events);
        result.events.insert(result.events.end(), events.begin(), events.end());
    }
    return result;
}

/** The router's compiled detector of type D on `gripper`. */
template<class D> const D *detectorOf(const Router &router, Gripper gripper)
{
    for (const Detector *detector : router.detectors()) {
        const auto *typed = dynamic_cast<const D *>(detector);
        if (typed && detector->gripper() == gripper)
            return typed;
    }
    return nullptr;
}

} // namespace

class TestGripperTraits : public QObject
{
    Q_OBJECT

private slots:
    void slipCountsAreScaled_data();
    void slipCountsAreScaled();
    void slipFollowsThePads_data();
    void slipFollowsThePads();
    void rippleDoesNotChatter_data();
    void rippleDoesNotChatter();
    void graphKeepsTheNodesOwnValues();
};

void TestGripperTraits::slipCountsAreScaled_data()
{
    QTest::addColumn<int>("fullContacts");
    QTest::addColumn<double>("loss");
    QTest::addColumn<double>("min");
    QTest::addColumn<double>("hysteresis");
    QTest::addColumn<double>("fittedLoss");
    QTest::addColumn<double>("fittedMin");
    QTest::addColumn<double>("fittedHysteresis");

    // The reference runs the values as written, fractions too; so does a count not known.
    QTest::newRow("reference") << 32 << 28.0 << 8.0 << 0.0 << 28.0 << 8.0 << 0.0;
    QTest::newRow("reference, fractions") << 32 << 27.5 << 8.5 << 0.5 << 27.5 << 8.5 << 0.5;
    QTest::newRow("not known") << 0 << 27.5 << 8.5 << 0.5 << 27.5 << 8.5 << 0.5;
    // 2 pads of 2: loss 3.5 is N <= 3, so a full grasp (4) holds and one lost contact slips.
    QTest::newRow("4: loss rounds up") << 4 << 28.0 << 8.0 << 0.0 << 4.0 << 1.0 << 0.0;
    QTest::newRow("8: exact") << 8 << 28.0 << 8.0 << 0.0 << 7.0 << 2.0 << 0.0;
    QTest::newRow("5: min rounds down") << 5 << 28.0 << 8.0 << 0.0 << 5.0 << 1.0 << 0.0;
    QTest::newRow("2: one per fingertip") << 2 << 28.0 << 8.0 << 0.0 << 2.0 << 0.0 << 0.0;
    QTest::newRow("1") << 1 << 28.0 << 8.0 << 0.0 << 1.0 << 0.0 << 0.0;
    QTest::newRow("64: scales up") << 64 << 28.0 << 8.0 << 2.0 << 56.0 << 16.0 << 4.0;
    // min and loss inside one whole contact still come out apart.
    QTest::newRow("4: min, loss in (2, 3)") << 4 << 20.0 << 18.0 << 0.0 << 3.0 << 2.0 << 0.0;
    QTest::newRow("4: loss whole, min just below")
        << 4 << 16.0 << 15.0 << 0.0 << 2.0 << 1.0 << 0.0;
    // The end level loss + hysteresis is rounded as loss is: under a contact it vanishes.
    QTest::newRow("4: hysteresis under a contact") << 4 << 28.0 << 8.0 << 1.0 << 4.0 << 1.0 << 0.0;
    QTest::newRow("4: end level whole") << 4 << 28.0 << 8.0 << 4.0 << 4.0 << 1.0 << 0.0;
    QTest::newRow("4: end level past it") << 4 << 28.0 << 8.0 << 5.0 << 4.0 << 1.0 << 1.0;
}

void TestGripperTraits::slipCountsAreScaled()
{
    QFETCH(int, fullContacts);
    QFETCH(double, loss);
    QFETCH(double, min);
    QFETCH(double, hysteresis);
    QFETCH(double, fittedLoss);
    QFETCH(double, fittedMin);
    QFETCH(double, fittedHysteresis);

    SlipDetector::Params written;
    written.loss = loss;
    written.min = min;
    written.hysteresis = hysteresis;
    written.grasp = 15.0;
    written.minDuration = 0.1;
    GripperTraits traits;
    traits.fullContacts = fullContacts;
    const SlipDetector::Params fitted = written.fittedTo(traits);
    QCOMPARE(fitted.loss, fittedLoss);
    QCOMPARE(fitted.min, fittedMin);
    QCOMPARE(fitted.hysteresis, fittedHysteresis);
    QCOMPARE(fitted.grasp, written.grasp); // forces and times are not counts
    QCOMPARE(fitted.minDuration, written.minDuration);
    QString key;
    QString reason;
    QVERIFY2(fitted.validate(&key, &reason), qPrintable(key + ": " + reason));

    // Each rule holds for a whole count N at the share of a full grasp it has as written.
    const int full = fullContacts < 1 ? ReferenceFullContacts : fullContacts;
    for (int n = 0; n <= 2 * full; ++n) {
        const double share = double(n) * ReferenceFullContacts / full;
        QCOMPARE(n < fitted.loss, share < loss);
        QCOMPARE(n <= fitted.min, share <= min);
        QCOMPARE(n < fitted.loss + fitted.hysteresis, share < loss + hysteresis);
    }
}

void TestGripperTraits::slipFollowsThePads_data()
{
    QTest::addColumn<int>("fullContacts");
    QTest::addColumn<int>("perFingertip"); // contacts of each pad in the steady grasp
    QTest::addColumn<int>("lost");         // contacts the left pad loses after 1 s
    QTest::addColumn<int>("grasps");
    QTest::addColumn<int>("slips");

    QTest::newRow("2 pads of 2, steady") << 4 << 2 << 0 << 1 << 0;
    QTest::newRow("2 pads of 2, one contact lost") << 4 << 2 << 1 << 1 << 1;
    QTest::newRow("2 pads of 4, steady") << 8 << 4 << 0 << 1 << 0;
    QTest::newRow("2 pads of 4, two contacts lost") << 8 << 4 << 2 << 1 << 1;
    // What every such grasp gave before: a slip warning from the first frame.
    QTest::newRow("reference traits, 2 pads of 2") << 32 << 2 << 0 << 1 << 1;
    QTest::newRow("reference traits, taxel pads") << 32 << 16 << 0 << 1 << 0;
}

void TestGripperTraits::slipFollowsThePads()
{
    QFETCH(int, fullContacts);
    QFETCH(int, perFingertip);
    QFETCH(int, lost);
    QFETCH(int, grasps);
    QFETCH(int, slips);

    RouterContext context;
    context.grippers[size_t(Gripper::Left)].fullContacts = fullContacts;
    std::unique_ptr<Router> router = c3(context);
    QVERIFY(router);
    // 2 s of a steady 40 N hold; the left pad loses `lost` contacts for the second one.
    std::vector<ContactFrame> frames;
    for (int k = 0; k < 1000; ++k) {
        const int left = k < 500 ? perFingertip : perFingertip - lost;
        frames.push_back(holding(k * Step, Gripper::Left, 40.0, left, perFingertip));
    }
    const Begins begins = run(*router, frames);
    QCOMPARE(begins.count(DetectorKind::Slip, Message::Grasp), grasps);
    QCOMPARE(begins.count(DetectorKind::Slip, Message::Slip), slips);
    for (const SemanticEvent &e : begins.events) {
        // A slip of a steady grasp begins only once the contact is lost.
        if (e.message == Message::Slip && e.phase == EventPhase::Begin && lost > 0)
            QCOMPARE(e.t, 500 * Step);
    }
}

void TestGripperTraits::rippleDoesNotChatter_data()
{
    QTest::addColumn<double>("forceRipple");
    QTest::addColumn<double>("hysteresis"); // the node's own
    QTest::addColumn<double>("runsWith");   // the hysteresis the detector runs with
    QTest::addColumn<int>("breaks");

    // 81 ± 4 N every 12 ms sampled every 2 ms: 77.5 N twice a cycle, under 80 N; 1 s is
    // 83.3 cycles, and each one begins the warning again.
    QTest::newRow("no ripple known") << 0.0 << 0.0 << 0.0 << 84;
    QTest::newRow("ripple 8 N") << 8.0 << 0.0 << 8.0 << 1;
    QTest::newRow("node's hysteresis above the ripple") << 8.0 << 10.0 << 10.0 << 1;
    QTest::newRow("node's hysteresis below the ripple") << 8.0 << 2.0 << 8.0 << 1;
    QTest::newRow("node's hysteresis 2 N, no ripple known") << 0.0 << 2.0 << 2.0 << 84;
}

void TestGripperTraits::rippleDoesNotChatter()
{
    QFETCH(double, forceRipple);
    QFETCH(double, hysteresis);
    QFETCH(double, runsWith);
    QFETCH(int, breaks);

    RouterContext context;
    context.grippers[size_t(Gripper::Right)].forceRipple = forceRipple;
    LoadError error;
    const QStringList overrides{QString("right.force.hysteresis=%1").arg(hysteresis)};
    std::unique_ptr<Router> router = loadRouter("C3", overrides, &error, context);
    QVERIFY2(router, qPrintable(error.toString()));

    // A lightly damped finger at an 81 N command: 77..85 N, a cycle every 12 ms, for 1 s.
    std::vector<ContactFrame> frames;
    for (int k = 0; k < 500; ++k) {
        const double t = k * Step;
        const double force = 81.0 + 4.0 * std::sin(2 * M_PI * t / 0.012);
        frames.push_back(holding(t, Gripper::Right, force, 16, 16));
    }
    const Begins begins = run(*router, frames);
    QCOMPARE(begins.count(DetectorKind::Force, Message::Break), breaks);
    QCOMPARE(begins.count(DetectorKind::Force, Message::Grasp), 1);
    QCOMPARE(detectorOf<ForceDetector>(*router, Gripper::Right)->params().hysteresis, runsWith);
}

void TestGripperTraits::graphKeepsTheNodesOwnValues()
{
    // The left gripper has pads of 2, the right one ripples: each detector runs fitted to its
    // own gripper, and the graph (what is saved and recorded) keeps what the user wrote.
    RouterContext context;
    context.grippers[size_t(Gripper::Left)] = {4, 0.0};
    context.grippers[size_t(Gripper::Right)] = {32, 8.0};
    std::unique_ptr<Router> fitted = c3(context);
    std::unique_ptr<Router> plain = c3(RouterContext());
    QVERIFY(fitted && plain);

    const SlipDetector::Params &slip = detectorOf<SlipDetector>(*fitted, Gripper::Left)->params();
    QCOMPARE(slip.loss, 4.0);
    QCOMPARE(slip.min, 1.0);
    QCOMPARE(detectorOf<ForceDetector>(*fitted, Gripper::Right)->params().hysteresis, 8.0);
    QCOMPARE(detectorOf<SlipDetector>(*plain, Gripper::Left)->params().loss, 28.0);
    QCOMPARE(detectorOf<ForceDetector>(*plain, Gripper::Right)->params().hysteresis, 0.0);

    QCOMPARE(fitted->graph().toJson(), plain->graph().toJson());
    QCOMPARE(fitted->selfContained().toJson(), plain->selfContained().toJson());
    QVERIFY(routesAs(*fitted, "C3"));
}

QTEST_GUILESS_MAIN(TestGripperTraits)
#include "tst_grippertraits.moc"
