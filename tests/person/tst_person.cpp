// SPDX-License-Identifier: MIT
// The perceiving operator's person (sim/person.h, docs/operator.md), one mechanism at a time:
// identification by distance, reaction times, detection of weak cues, gaze on the overlay,
// the squeeze read to a JND, and reliance that follows a warning's track record.
#include "devicemodel.h"
#include "person.h"
#include "router.h"
#include "task.h"

#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

/** A task that judges the n-th warning by a fixed rule, a horizon after its onset. */
class Judge : public Task
{
public:
    explicit Judge(int rightOfTen) : m_rightOfTen(rightOfTen) {}
    void observe(World &) override {}
    void feel(Gripper, const Feeling &, double) override {}
    QJsonObject metrics() const override { return {}; }
    std::optional<bool> warranted(Gripper, double onset, double t) const override
    {
        if (t < onset + DefaultHorizon)
            return std::nullopt;
        // Warnings come one per Period: the n-th is right when n mod 10 is under the rule.
        return int(std::lround(onset / Period)) % 10 < m_rightOfTen;
    }
    static constexpr double Period = 4.0;

private:
    int m_rightOfTen;
};

constexpr double Tick = 0.002;

/** The standard normal CDF. */
double phi(double x)
{
    return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

struct Rig
{
    std::unique_ptr<Router> router;
    std::vector<Perception::Band> bands;
    int device = -1; ///< the band the test plays on
    int pattern = -1;

    /** `routerName`'s band `deviceName`, playing the pattern node `patternName` when given. */
    bool load(const QString &routerName, const QString &deviceName, const QString &patternName)
    {
        LoadError error;
        router = loadRouter(routerName, {}, &error);
        if (!router)
            return false;
        bands.assign(size_t(router->player().deviceCount()), Perception::Band());
        device = router->player().deviceIndex(deviceName);
        pattern = int(router->nodeIds().indexOf(patternName));
        return device >= 0;
    }
    /** The band plays its pattern in `priority` at delivered `level` (0: nothing sounds). */
    void play(double level, int priority)
    {
        Perception::Band &band = bands[size_t(device)];
        band.level = level;
        band.priority = level > 0 ? priority : -1;
        band.pattern = level > 0 ? pattern : -1;
    }
};

} // namespace

class TestPerson : public QObject
{
    Q_OBJECT

private slots:
    void identificationFallsWithDistance_data();
    void identificationFallsWithDistance();
    void closePatternsAreMisreadFarMoreOften();
    void reactionTimesHaveTheirMean();
    void weakCueIsFeltLater();
    void unwatchedOverlayIsSeenLate();
    void squeezeIsReadToAJnd();
    void relianceFollowsTheTrackRecord();
    void aCueOfOneTickIsActedOn();
    void forgettingDropsTheSqueeze();
    void parametersStayInTheirRanges();
};

void TestPerson::identificationFallsWithDistance_data()
{
    QTest::addColumn<double>("distance");
    QTest::newRow("identical") << 0.0;
    QTest::newRow("half a JND") << 0.5;
    QTest::newRow("1 JND") << 1.0;
    QTest::newRow("3 JND") << 3.0;
}

void TestPerson::identificationFallsWithDistance()
{
    // Two patterns: the truth is mistaken for the other at Phi(-d' / 2), d' = 0.954 per JND.
    QFETCH(double, distance);
    Random random(7);
    const int draws = 20000;
    int misread = 0;
    for (int k = 0; k < draws; ++k)
        misread += Person::identify({0.0, distance}, 0, random) == 1 ? 1 : 0;
    const double expected = phi(-0.954 * distance / 2);
    const double share = double(misread) / draws;
    qInfo("%.1f JND: misread %.3f (expected %.3f)", distance, share, expected);
    QVERIFY(std::abs(share - expected) < 4 * std::sqrt(expected * (1 - expected) / draws));
}

void TestPerson::closePatternsAreMisreadFarMoreOften()
{
    Random random(3);
    std::array<int, 2> misread{};
    for (int k = 0; k < 5000; ++k) {
        misread[0] += Person::identify({0.0, 0.5, 20.0}, 0, random) != 0 ? 1 : 0;
        misread[1] += Person::identify({0.0, 3.0, 20.0}, 0, random) != 0 ? 1 : 0;
    }
    qInfo("misread at 0.5 JND: %d, at 3 JND: %d of 5000", misread[0], misread[1]);
    QVERIFY(misread[0] > 4 * misread[1]);
}

void TestPerson::reactionTimesHaveTheirMean()
{
    Person person({}, 5);
    double sum = 0.0;
    double fastest = 1.0;
    const int draws = 20000;
    for (int k = 0; k < draws; ++k) {
        const double rt = person.reactionTime(0.25);
        sum += rt;
        fastest = std::min(fastest, rt);
    }
    QVERIFY(std::abs(sum / draws - 0.25) < 0.002);
    QVERIFY(fastest >= 0.1);
}

void TestPerson::weakCueIsFeltLater()
{
    // The grasp's pattern on the right LRAs, rising over 0.3 s to a weak and a strong level
    // through the band's response: the weak one crosses the detection level later.
    Rig rig;
    QVERIFY(rig.load(QStringLiteral("C1"), QStringLiteral("right.vibro"),
                     QStringLiteral("right.rampup")));
    const DeviceModel &model = rig.router->player().deviceModel(rig.device);
    const Judge judge(10);
    std::array<double, 3> latency{};
    const std::array<double, 3> peaks{0.8, 0.1, 0.03};
    for (size_t level = 0; level < peaks.size(); ++level) {
        Person person({}, 11);
        person.learn(*rig.router);
        ResponseFilter response(model, 1.0 / Tick);
        const int trials = 60;
        int felt = 0;
        double t = 0.0;
        for (int trial = 0; trial < trials; ++trial) {
            const double start = t;
            double takenIn = -1.0;
            for (; t < start + 2.0; t += Tick) {
                const double ramp = std::clamp((t - start) / 0.3, 0.0, 1.0);
                const double command = t < start + 1.0 ? peaks[level] * ramp : 0.0;
                const double range = model.channels()[0].max - model.channels()[0].min;
                const double delivered =
                    (response.step(model.channels()[0].min + command * range) -
                     model.channels()[0].min) /
                    range;
                rig.play(t < start + 1.0 ? std::max(delivered, 1e-9) : 0.0,
                         PlayerInput::Confirmation);
                person.take(rig.bands, {}, judge, t);
                if (takenIn < 0 && person.feeling(Gripper::Right).confirmation > 0)
                    takenIn = t - start;
            }
            if (takenIn >= 0) {
                latency[level] += takenIn;
                ++felt;
            }
        }
        latency[level] = felt ? latency[level] / felt : -1.0;
        qInfo("peak %.2f: felt %d of %d, taken in %.3f s after the command on average",
              peaks[level], felt, trials, latency[level]);
    }
    QVERIFY(latency[0] > 0 && latency[1] > latency[0] + 0.05);
    QCOMPARE(latency[2], -1.0); // under the LRAs' detection level: never felt
}

void TestPerson::unwatchedOverlayIsSeenLate()
{
    Rig rig;
    QVERIFY(rig.load(QStringLiteral("C1"), QStringLiteral("overlay"), QString()));
    const Judge judge(10);
    const PersonParameters parameters;
    std::array<double, 2> takenIn{-1.0, -1.0}; // watched, unwatched then looked at
    for (size_t watched = 0; watched < 2; ++watched) {
        Person person(parameters, 13);
        person.learn(*rig.router);
        person.look(watched == 0 ? Gripper::Left : Gripper::Right, -10.0);
        std::array<Feeling, 2> overlay{};
        for (double t = 0.0; t < 5.0 && takenIn[watched] < 0; t += Tick) {
            overlay[size_t(Gripper::Left)].shownWarning = t >= 1.0 ? 1.0 : 0.0;
            if (t >= 3.0)
                person.look(Gripper::Left, t); // the next switch
            person.take(rig.bands, overlay, judge, t);
            if (person.feeling(Gripper::Left).warning > 0)
                takenIn[watched] = t;
        }
    }
    qInfo("a warning shown at 1 s: watched, acted on at %.3f s; unwatched until 3 s, at %.3f s",
          takenIn[0], takenIn[1]);
    QVERIFY(takenIn[0] >= 1.0 + 0.1 && takenIn[0] < 1.0 + 1.0);
    QVERIFY(takenIn[1] >= 3.0 + parameters.saccade + 0.1);
}

void TestPerson::squeezeIsReadToAJnd()
{
    // The sensory router's proportional squeeze on the right: a slow drift down by a third
    // is read while the hand is watched, and goes unnoticed while it is not; a sudden step of
    // the same size is noticed either way.
    Rig rig;
    QVERIFY(rig.load(QStringLiteral("sensory"), QStringLiteral("right.air"),
                     QStringLiteral("right.proportional")));
    const Judge judge(10);
    struct Case
    {
        bool watched;
        double drift; ///< s over which the squeeze falls from 0.6 to 0.4
    };
    for (const Case &c : {Case{true, 20.0}, Case{false, 20.0}, Case{false, 0.05}}) {
        Person person({}, 17);
        person.learn(*rig.router);
        person.look(c.watched ? Gripper::Right : Gripper::Left, -10.0);
        for (double t = 0.0; t < 25.0; t += Tick) {
            const double level = t < 2.0 ? 0.6 : std::max(0.4, 0.6 - 0.2 * (t - 2.0) / c.drift);
            rig.play(level, PlayerInput::Continuous);
            person.take(rig.bands, {}, judge, t);
        }
        const double read = person.feeling(Gripper::Right).pressure;
        qInfo("%s, over %.2f s: read %.3f", c.watched ? "watched" : "unwatched", c.drift, read);
        const bool followed = std::abs(std::log(read / 0.4)) < std::log(1.15);
        QCOMPARE(followed, c.watched || c.drift < 1.0);
    }
}

void TestPerson::relianceFollowsTheTrackRecord()
{
    Rig rig;
    QVERIFY(rig.load(QStringLiteral("C1"), QStringLiteral("right.vibro"),
                     QStringLiteral("right.geiger")));
    std::array<double, 2> answered{};
    const std::array<int, 2> rules{1, 9};
    for (size_t r = 0; r < rules.size(); ++r) {
        const Judge judge(rules[r]);
        Person person({}, 19);
        person.learn(*rig.router);
        int late = 0;
        int lateIgnored = 0;
        for (int n = 0; n < 200; ++n) {
            // A warning of 0.5 s every Period: the n-th, answered or not.
            const double start = n * Judge::Period;
            const int ignoredBefore = person.record(Gripper::Right).ignored;
            for (double t = start; t < start + Judge::Period; t += 0.01) {
                rig.play(t < start + 0.5 ? 0.8 : 0.0, PlayerInput::Exception);
                person.take(rig.bands, {}, judge, t);
            }
            if (n >= 100) {
                ++late;
                lateIgnored += person.record(Gripper::Right).ignored - ignoredBefore;
            }
        }
        answered[r] = 1.0 - double(lateIgnored) / late;
        qInfo("right %d in 10: answered %.2f of the last 100, reliance %.2f", rules[r],
              answered[r], person.reliance(Gripper::Right));
    }
    QVERIFY(answered[1] > answered[0] + 0.5);
}

void TestPerson::aCueOfOneTickIsActedOn()
{
    // Felt for a single tick, a cue still reaches the hands once, its reaction time later.
    Rig rig;
    QVERIFY(rig.load(QStringLiteral("C1"), QStringLiteral("right.vibro"),
                     QStringLiteral("right.rampup")));
    const Judge judge(10);
    Person person({}, 23);
    person.learn(*rig.router);
    int ticksActedOn = 0;
    for (double t = 0.0; t < 2.0; t += Tick) {
        rig.play(std::abs(t - 0.5) < Tick / 2 ? 0.8 : 0.0, PlayerInput::Confirmation);
        person.take(rig.bands, {}, judge, t);
        ticksActedOn += person.feeling(Gripper::Right).confirmation > 0 ? 1 : 0;
    }
    QCOMPARE(ticksActedOn, 1);
}

void TestPerson::forgettingDropsTheSqueeze()
{
    // After a hand-over the squeeze is read afresh, not acted on as it was last read.
    Rig rig;
    QVERIFY(rig.load(QStringLiteral("sensory"), QStringLiteral("right.air"),
                     QStringLiteral("right.proportional")));
    const Judge judge(10);
    Person person({}, 29);
    person.learn(*rig.router);
    double t = 0.0;
    for (; t < 2.0; t += Tick) {
        rig.play(0.6, PlayerInput::Continuous);
        person.take(rig.bands, {}, judge, t);
    }
    QVERIFY(person.feeling(Gripper::Right).pressure > 0.5);
    person.forget();
    person.take(rig.bands, {}, judge, t);
    QCOMPARE(person.feeling(Gripper::Right).pressure, 0.0);
}

void TestPerson::parametersStayInTheirRanges()
{
    PersonParameters p;
    QString reason;
    QVERIFY(p.set(QStringLiteral("saccade=0.15"), &reason));
    QCOMPARE(p.saccade, 0.15);
    QVERIFY(!p.set(QStringLiteral("saccade=0.5"), &reason));
    QCOMPARE(reason, QStringLiteral("saccade=0.5: expected a number from 0.15 to 0.25 s (default 0.2)"));
    QVERIFY(!p.set(QStringLiteral("sacade=0.2"), &reason));
    QVERIFY(reason.startsWith(QStringLiteral("sacade=0.2: expected NAME=VALUE, NAME one of")));
    // Every default lies in its range.
    const PersonParameters defaults;
    for (const PersonParameters::Row &row : PersonParameters::rows()) {
        QVERIFY2(defaults.value(row) >= row.low && defaults.value(row) <= row.high, row.name);
    }
}

QTEST_GUILESS_MAIN(TestPerson)
#include "tst_person.moc"
