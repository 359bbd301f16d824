// SPDX-License-Identifier: MIT
// Voices of the built-in patterns: lifecycles as the spec words them (ramps from wherever
// the value is, no dip on end+begin, phase-continuous rates) and no allocation while playing.
#include "allocationcounter.h"
#include "patternlibrary.h"
#include "voice.h"

#include <QTest>

#include <vector>

using namespace semhap;

namespace {

/** One line of a voice script: an action at a time, or an expected value of track 0. */
struct Step
{
    enum Action
    {
        Begin,
        End,
        Intensity,
        Expect
    };
    Action action;
    double t;
    double value = 0.0;
};

Step begin(double t)
{
    return {Step::Begin, t};
}

Step end(double t)
{
    return {Step::End, t};
}

Step intensity(double t, double value)
{
    return {Step::Intensity, t, value};
}

Step expect(double t, double value)
{
    return {Step::Expect, t, value};
}

} // namespace

using Script = QList<Step>;
Q_DECLARE_METATYPE(Script)

class TestVoice : public QObject
{
    Q_OBJECT

private slots:
    void script_data();
    void script();
    void noDipOnEndAndBegin();
    void phases();
    void clampsTime();
    void proportional();
    void stop();
    void allocationCounterCounts();
    void noAllocation_data();
    void noAllocation();
};

void TestVoice::script_data()
{
    QTest::addColumn<QString>("pattern");
    QTest::addColumn<Script>("steps");

    const QString squeeze = QStringLiteral("air.squeeze");
    QTest::newRow("squeeze: begin ramps 0 to 1 in 0.5 s, end ramps down in 0.5 s")
        << squeeze
        << Script{begin(0), expect(0, 0),      expect(0.25, 0.5), expect(0.5, 1), expect(2, 1),
                  end(2),   expect(2.25, 0.5), expect(2.5, 0),    expect(3, 0)};
    QTest::newRow("squeeze: end during the attack ramps down from there in 0.5 s")
        << squeeze
        << Script{begin(0),          expect(0.3, 0.6),      end(0.3),      expect(0.3, 0.6),
                  expect(0.55, 0.3), expect(0.799, 0.0012), expect(0.8, 0)};
    QTest::newRow("squeeze: begin during the release ramps up from there in 0.5 s")
        << squeeze << Script{begin(0),          end(1),          expect(1.25, 0.5), begin(1.25),
                             expect(1.5, 0.75), expect(1.75, 1), expect(3, 1)};
    QTest::newRow("squeeze: begin again during the attack restarts from there")
        << squeeze
        << Script{begin(0), expect(0.2, 0.4), begin(0.2), expect(0.45, 0.7), expect(0.7, 1)};
    const QString rampup = QStringLiteral("vib.rampup");
    QTest::newRow("rampup: 0 to 1 in 0.5 s, then 0; end after it ramps 1 to 0 in 0.5 s")
        << rampup
        << Script{
               begin(0),     expect(0, 0), expect(0.25, 0.5), expect(0.499, 0.998), expect(0.5, 0),
               expect(1, 0), end(1),       expect(1, 1),      expect(1.25, 0.5),    expect(1.5, 0),
               expect(2, 0)};
    QTest::newRow("rampup: end during the attack ramps from the value reached")
        << rampup
        << Script{begin(0), expect(0.3, 0.6), end(0.3), expect(0.55, 0.3), expect(0.8, 0)};
    QTest::newRow("rampup: end during the attack, not sampled since begin")
        << rampup << Script{begin(0), end(0.3), expect(0.3, 0.6), expect(0.55, 0.3)};
    const QString pulse = QStringLiteral("air.pulse5hz");
    QTest::newRow("pulse5hz: high at begin, 5 Hz edges, 0 at end")
        << pulse << Script{expect(0.1, 0),  begin(0.37),      expect(0.37, 1), expect(0.469, 1),
                           expect(0.47, 0), expect(0.569, 0), expect(0.57, 1), end(0.6),
                           expect(0.6, 0),  expect(0.7, 0)};
    QTest::newRow("pulse5hz: a new begin starts high again")
        << pulse << Script{begin(0),        expect(0.15, 0),  end(0.15),      begin(1.03),
                           expect(1.03, 1), expect(1.129, 1), expect(1.13, 0)};
    const QString geiger = QStringLiteral("vib.geiger");
    // 2 Hz until 0.3 s (0.6 cycles done), then 20 Hz: the next pulse 0.4 cycles = 20 ms on.
    QTest::newRow("geiger: an intensity change keeps the phase")
        << geiger
        << Script{intensity(0, 0),  begin(0),          expect(0, 1),     expect(0.024, 1),
                  expect(0.025, 0), intensity(0.3, 1), expect(0.319, 0), expect(0.32, 1),
                  expect(0.344, 1), expect(0.345, 0),  expect(0.37, 1),  end(0.4),
                  expect(0.4, 0),   expect(0.42, 0)};
    // 20 Hz until 10 ms, inside the first pulse: the pulse keeps its 25 ms.
    QTest::newRow("geiger: a change inside a pulse does not cut or restart it")
        << geiger
        << Script{begin(0),         expect(0.005, 1), intensity(0.01, 0), expect(0.02, 1),
                  expect(0.024, 1), expect(0.025, 0), expect(0.409, 0),   expect(0.41, 1)};
}

void TestVoice::script()
{
    QFETCH(QString, pattern);
    QFETCH(Script, steps);

    Voice voice(PatternLibrary::builtin(pattern));
    for (const Step &step : steps) {
        switch (step.action) {
        case Step::Begin:
            voice.begin(step.t);
            break;
        case Step::End:
            voice.end(step.t);
            break;
        case Step::Intensity:
            voice.setParam(ParamTable::Intensity, step.value, step.t);
            break;
        case Step::Expect:
            voice.advance(step.t);
            QVERIFY2(std::abs(voice.value(0) - step.value) < 1e-9,
                     qPrintable(QStringLiteral("at %1: %2, expected %3")
                                    .arg(step.t)
                                    .arg(voice.value(0))
                                    .arg(step.value)));
            break;
        }
    }
}

void TestVoice::noDipOnEndAndBegin()
{
    for (const QString &name : {QStringLiteral("air.squeeze"), QStringLiteral("vib.rampup")}) {
        Voice voice(PatternLibrary::builtin(name));
        voice.begin(0);
        voice.advance(0.4);
        double previous = voice.value(0);
        voice.end(0.4);
        voice.begin(0.4);
        // From 0.8, the attack ramps on to 1 and takes its full 0.5 s to get there.
        for (int k = 400; k < 900; ++k) {
            voice.advance(k / 1000.0);
            QVERIFY2(voice.value(0) >= previous - 1e-12, qPrintable(name + QString::number(k)));
            previous = voice.value(0);
        }
        QVERIFY(previous > 0.999 && previous < 1.0);
    }
}

void TestVoice::phases()
{
    Voice voice(PatternLibrary::builtin(QStringLiteral("air.squeeze")));
    QVERIFY(voice.isIdle());
    voice.begin(0);
    QCOMPARE(voice.phase(), Voice::Phase::Attack);
    QVERIFY(voice.isActive());
    voice.advance(0.5);
    QCOMPARE(voice.phase(), Voice::Phase::Sustain);
    voice.end(1);
    QCOMPARE(voice.phase(), Voice::Phase::Release);
    QVERIFY(!voice.isActive());
    voice.end(1.2); // a releasing voice is left alone
    voice.advance(1.49);
    QCOMPARE(voice.phase(), Voice::Phase::Release);
    QVERIFY(voice.value(0) > 0);
    voice.advance(1.5);
    QVERIFY(voice.isIdle());
    QCOMPARE(voice.value(0), 0.0);

    Voice geiger(PatternLibrary::builtin(QStringLiteral("vib.geiger")));
    geiger.begin(0);
    QCOMPARE(geiger.phase(), Voice::Phase::Sustain); // no attack
    geiger.end(0.01);
    QVERIFY(geiger.isIdle()); // no release: 0 at once
    QCOMPARE(geiger.value(0), 0.0);
}

void TestVoice::clampsTime()
{
    Voice voice(PatternLibrary::builtin(QStringLiteral("air.squeeze")));
    voice.begin(0);
    voice.advance(0.25);
    voice.advance(0.1);
    QCOMPARE(voice.value(0), 0.5);
    voice.advance(0.3);
    QCOMPARE(voice.value(0), 0.6);
}

void TestVoice::proportional()
{
    const PatternPtr pattern = PatternLibrary::builtin(QStringLiteral("air.proportional"));
    const ParamTable &params = pattern->params();
    Voice voice(pattern);
    voice.begin(0);
    voice.advance(0);
    QCOMPARE(voice.value(0), 0.0);
    voice.setParam(params.indexOf(QStringLiteral("left")), 60, 0.01);
    voice.setParam(params.indexOf(QStringLiteral("right")), 300, 0.01);
    voice.advance(0.01);
    QCOMPARE(voice.value(0), 0.5);
    QCOMPARE(voice.value(1), 1.0); // clipped
    voice.setParam(params.indexOf(QStringLiteral("ref")), 30, 0.02);
    voice.advance(0.02);
    QCOMPARE(voice.value(0), 1.0);
    voice.setParam(params.indexOf(QStringLiteral("ref")), 0, 0.03);
    voice.advance(0.03);
    QCOMPARE(voice.value(0), 0.0); // a zero reference gives 0, not infinity
}

void TestVoice::stop()
{
    Voice voice(PatternLibrary::builtin(QStringLiteral("vib.geiger")));
    voice.setParam(ParamTable::Intensity, 0.2, 0);
    voice.begin(0);
    voice.advance(1);
    voice.stop();
    QVERIFY(voice.isIdle());
    QVERIFY(!voice.isActive());
    QCOMPARE(voice.value(0), 0.0);
    QCOMPARE(voice.param(ParamTable::Intensity), 1.0);
}

void TestVoice::allocationCounterCounts()
{
    test::startCountingAllocations();
    // A direct call: the compiler may elide a new-expression, but not this.
    void *probe = ::operator new(64);
    const long allocations = test::stopCountingAllocations();
    ::operator delete(probe);
    QCOMPARE(allocations, 1L);
}

void TestVoice::noAllocation_data()
{
    QTest::addColumn<QString>("pattern");
    for (const QString &name : PatternLibrary::builtinNames())
        QTest::newRow(qPrintable(name)) << name;
}

void TestVoice::noAllocation()
{
    QFETCH(QString, pattern);

    Voice voice(PatternLibrary::builtin(pattern));
    test::startCountingAllocations();
    for (int cycle = 0; cycle < 3; ++cycle) {
        const double start = cycle * 2.0;
        voice.begin(start);
        for (int k = 0; k < 2000; ++k) {
            const double t = start + k / 1000.0;
            if (k % 100 == 0)
                voice.setParam(ParamTable::Intensity, (k % 700) / 700.0, t);
            if (k == 1200)
                voice.end(t);
            voice.advance(t);
        }
    }
    voice.resetParams();
    voice.stop();
    QCOMPARE(test::stopCountingAllocations(), 0L);
}

QTEST_GUILESS_MAIN(TestVoice)
#include "tst_voice.moc"
