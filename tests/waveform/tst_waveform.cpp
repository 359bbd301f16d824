// SPDX-License-Identifier: MIT
// The signal algebra: samples of every node at chosen times, oscillator edges and phase
// continuity, curves, JSON round trips and parse errors.
#include "waveform.h"
#include "waveformparser.h"
#include "waveformtype.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <utility>
#include <vector>

using namespace semhap;

using Samples = std::vector<std::pair<double, double>>;
Q_DECLARE_METATYPE(Samples)

namespace {

QJsonValue json(const char *text)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray(text), &error);
    if (error.error != QJsonParseError::NoError)
        qFatal("bad JSON in test: %s", text);
    return doc.object();
}

/** Plays one signal the way a voice does: own state, dt from the previous sample. */
class Player
{
public:
    explicit Player(const char *text, const QVariantMap &params = {})
    {
        for (auto it = params.begin(); it != params.end(); ++it)
            m_table.declare(it.key(), it.value().toDouble());
        WaveformParser parser(m_table, QStringLiteral("test.json"));
        m_signal = parser.parse(json(text), QString());
        if (!m_signal)
            qFatal("%s", qPrintable(parser.error().toString()));
        int size = 0;
        m_signal->assignState(size);
        m_state.assign(size_t(size), 0.0);
        m_signal->reset(m_state.data());
        m_params = m_table.defaults();
    }

    double at(double t)
    {
        WaveformContext ctx;
        ctx.t = t;
        ctx.dt = m_started ? t - m_lastT : 0.0;
        ctx.from = from;
        ctx.peak = peak;
        ctx.params = m_params.data();
        ctx.state = m_state.data();
        m_started = true;
        m_lastT = t;
        return m_signal->sample(ctx);
    }

    void set(const QString &name, double value)
    {
        m_params[size_t(m_table.indexOf(name))] = value;
    }
    double duration() const { return m_signal->duration(m_params.data()); }

    double from = 0.0;
    double peak = 0.0;

private:
    ParamTable m_table;
    WaveformPtr m_signal;
    std::vector<double> m_state;
    std::vector<double> m_params;
    double m_lastT = 0.0;
    bool m_started = false;
};

bool near(double a, double b)
{
    return std::abs(a - b) < 1e-9;
}

} // namespace

class TestWaveform : public QObject
{
    Q_OBJECT

private slots:
    void typeTable();
    void numberJson_data();
    void numberJson();
    void samples_data();
    void samples();
    void durations_data();
    void durations();
    void curve_data();
    void curve();
    void squareEdges_data();
    void squareEdges();
    void pulseCount_data();
    void pulseCount();
    void pulsePhaseContinuity_data();
    void pulsePhaseContinuity();
    void roundTrip_data();
    void roundTrip();
    void errors_data();
    void errors();
};

void TestWaveform::samples_data()
{
    QTest::addColumn<QByteArray>("signal");
    QTest::addColumn<QVariantMap>("params");
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("peak");
    QTest::addColumn<Samples>("samples");

    const QVariantMap none;
    QTest::newRow("const") << QByteArray(R"({"type":"const","value":0.7})") << none << 0.3 << 0.0
                           << Samples{{0, 0.7}, {5, 0.7}};
    QTest::newRow("param through gain")
        << QByteArray(R"({"type":"param","name":"intensity","gain":2,"offset":1})") << none << 0.0
        << 0.0 << Samples{{0, 3}, {1, 3}};
    QTest::newRow("param through curve")
        << QByteArray(R"({"type":"param","name":"f","curve":[[0,0],[10,1]]})")
        << QVariantMap{{QStringLiteral("f"), 4.0}} << 0.0 << 0.0 << Samples{{0, 0.4}};
    QTest::newRow("ramp from current")
        << QByteArray(R"({"type":"ramp","to":1,"time":0.5})") << none << 0.4 << 0.0
        << Samples{{0, 0.4}, {0.25, 0.7}, {0.5, 1}, {1, 1}};
    QTest::newRow("ramp from peak")
        << QByteArray(R"({"type":"ramp","to":0,"time":0.5,"from":"peak"})") << none << 0.2 << 0.8
        << Samples{{0, 0.8}, {0.25, 0.4}, {0.5, 0}, {0.7, 0}};
    QTest::newRow("ramp from a number")
        << QByteArray(R"({"type":"ramp","to":1,"time":1,"from":0.5})") << none << 0.9 << 0.0
        << Samples{{0, 0.5}, {0.5, 0.75}, {1, 1}};
    QTest::newRow("ramp of no time") << QByteArray(R"({"type":"ramp","to":0.6,"time":0})") << none
                                     << 0.1 << 0.0 << Samples{{0, 0.6}, {1, 0.6}};
    QTest::newRow("keyframes from current")
        << QByteArray(R"({"type":"keyframes","points":[[0.5,1],[1,0.5],[2,0.5]]})") << none << 0.2
        << 0.0 << Samples{{0, 0.2}, {0.25, 0.6}, {0.5, 1}, {0.75, 0.75}, {1, 0.5}, {3, 0.5}};
    QTest::newRow("keyframes with a knot at 0")
        << QByteArray(R"({"type":"keyframes","points":[[0,0.3],[1,1]]})") << none << 0.9 << 0.0
        << Samples{{0, 0.3}, {0.5, 0.65}, {1, 1}};
    QTest::newRow("keyframes step")
        << QByteArray(R"({"type":"keyframes","points":[[1,0],[1,1],[2,1]]})") << none << 0.0 << 0.0
        << Samples{{0.5, 0}, {1, 1}, {1.5, 1}};
    QTest::newRow("sine") << QByteArray(
                                 R"({"type":"sine","freq":1,"amp":2,"offset":1,"phase":0.25})")
                          << none << 0.0 << 0.0 << Samples{{0, 3}, {0.25, 1}, {0.5, -1}, {1, 3}};
    QTest::newRow("square at duty 0.25")
        << QByteArray(R"({"type":"square","freq":5,"duty":0.25,"high":0.8,"low":0.1})") << none
        << 0.0 << 0.0 << Samples{{0, 0.8}, {0.049, 0.8}, {0.05, 0.1}, {0.199, 0.1}, {0.2, 0.8}};
    QTest::newRow("pulses") << QByteArray(R"({"type":"pulses","rate":2,"width":0.1,"amp":0.5})")
                            << none << 0.0 << 0.0 << Samples{{0, 0.5},   {0.099, 0.5}, {0.1, 0},
                                                             {0.499, 0}, {0.5, 0.5},   {0.6, 0}};
    QTest::newRow("sum") << QByteArray(R"({"type":"sum","of":[{"type":"const","value":0.25},)"
                                       R"({"type":"ramp","to":1,"time":1}]})")
                         << none << 0.0 << 0.0 << Samples{{0, 0.25}, {0.5, 0.75}, {2, 1.25}};
    QTest::newRow("product") << QByteArray(R"({"type":"product","of":[
            {"type":"ramp","to":1,"time":1,"from":0},{"type":"square","freq":1}]})")
                             << none << 0.0 << 0.0
                             << Samples{{0, 0}, {0.25, 0.25}, {0.5, 0}, {0.75, 0}, {1, 1}};
    const QByteArray sequence(R"({"type":"sequence","of":[{"type":"ramp","to":1,"time":0.5},
            {"type":"ramp","to":0.5,"time":1},{"type":"const","value":0.2}]})");
    QTest::newRow("sequence hand-over")
        << sequence << none << 0.0 << 0.0
        << Samples{{0, 0}, {0.25, 0.5}, {0.5, 1}, {1, 0.75}, {1.4, 0.55}, {1.5, 0.2}};
    QTest::newRow("sequence skipping a whole child")
        << sequence << none << 0.0 << 0.0 << Samples{{0, 0}, {1, 0.75}, {3, 0.2}};
    QTest::newRow("sequence hands its from to the first child")
        << sequence << none << 0.6 << 0.0 << Samples{{0, 0.6}, {0.25, 0.8}};
    QTest::newRow("scale by a parameter")
        << QByteArray(
               R"({"type":"scale","in":{"type":"param","name":"left"},"div":{"param":"ref"}})")
        << QVariantMap{{QStringLiteral("left"), 60.0}, {QStringLiteral("ref"), 120.0}} << 0.0
        << 0.0 << Samples{{0, 0.5}};
    QTest::newRow("scale gain offset")
        << QByteArray(
               R"({"type":"scale","in":{"type":"const","value":3},"gain":2,"div":4,"offset":0.5})")
        << none << 0.0 << 0.0 << Samples{{0, 2}};
    QTest::newRow("scale by zero")
        << QByteArray(R"({"type":"scale","in":{"type":"const","value":3},"div":0,"offset":0.5})")
        << none << 0.0 << 0.0 << Samples{{0, 0.5}};
    QTest::newRow("clip above") << QByteArray(
                                       R"({"type":"clip","in":{"type":"const","value":1.7}})")
                                << none << 0.0 << 0.0 << Samples{{0, 1}};
    QTest::newRow("clip below") << QByteArray(
                                       R"({"type":"clip","in":{"type":"const","value":-0.3}})")
                                << none << 0.0 << 0.0 << Samples{{0, 0}};
    QTest::newRow("clip inside own bounds")
        << QByteArray(
               R"({"type":"clip","in":{"type":"ramp","to":1,"time":1},"min":0.2,"max":0.8})")
        << none << 0.0 << 0.0 << Samples{{0, 0.2}, {0.5, 0.5}, {1, 0.8}};
}

void TestWaveform::samples()
{
    QFETCH(QByteArray, signal);
    QFETCH(QVariantMap, params);
    QFETCH(double, from);
    QFETCH(double, peak);
    QFETCH(Samples, samples);

    Player player(signal.constData(), params);
    player.from = from;
    player.peak = peak;
    for (const auto &[t, expected] : samples) {
        const double value = player.at(t);
        QVERIFY2(
            near(value, expected),
            qPrintable(QStringLiteral("at %1: %2, expected %3").arg(t).arg(value).arg(expected)));
    }
}

void TestWaveform::durations_data()
{
    QTest::addColumn<QByteArray>("signal");
    QTest::addColumn<double>("duration");

    const double endless = Waveform::Forever;
    QTest::newRow("const") << QByteArray(R"({"type":"const","value":1})") << endless;
    QTest::newRow("ramp") << QByteArray(R"({"type":"ramp","to":1,"time":0.5})") << 0.5;
    QTest::newRow("ramp bound to intensity")
        << QByteArray(R"({"type":"ramp","to":1,"time":{"param":"intensity","gain":0.5}})") << 0.5;
    QTest::newRow("keyframes") << QByteArray(R"({"type":"keyframes","points":[[0,1],[2,0]]})")
                               << 2.0;
    QTest::newRow("square") << QByteArray(R"({"type":"square","freq":5})") << endless;
    QTest::newRow("sum lasts while any lasts") << QByteArray(R"({"type":"sum","of":[
            {"type":"ramp","to":1,"time":0.5},{"type":"ramp","to":1,"time":2}]})")
                                               << 2.0;
    QTest::newRow("product lasts while all last") << QByteArray(R"({"type":"product","of":[
            {"type":"ramp","to":1,"time":0.5},{"type":"const","value":1}]})")
                                                  << 0.5;
    QTest::newRow("sequence adds up") << QByteArray(R"({"type":"sequence","of":[
            {"type":"ramp","to":1,"time":0.5},{"type":"ramp","to":1,"time":2}]})")
                                      << 2.5;
    QTest::newRow("scale")
        << QByteArray(R"({"type":"scale","in":{"type":"ramp","to":1,"time":0.5},"gain":2})")
        << 0.5;
}

void TestWaveform::durations()
{
    QFETCH(QByteArray, signal);
    QFETCH(double, duration);
    QCOMPARE(Player(signal.constData()).duration(), duration);
}

void TestWaveform::curve_data()
{
    QTest::addColumn<int>("kind"); // 0 identity, 1 linear 18x+2, 2 points
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");

    QTest::newRow("identity") << 0 << 0.3 << 0.3;
    QTest::newRow("linear") << 1 << 0.5 << 11.0;
    QTest::newRow("points below the first") << 2 << -1.0 << 2.0;
    QTest::newRow("points at the first") << 2 << 0.0 << 2.0;
    QTest::newRow("points inside") << 2 << 0.25 << 6.0;
    QTest::newRow("points at a knot") << 2 << 0.5 << 10.0;
    QTest::newRow("points inside the second") << 2 << 0.75 << 15.0;
    QTest::newRow("points above the last") << 2 << 3.0 << 20.0;
}

void TestWaveform::curve()
{
    QFETCH(int, kind);
    QFETCH(double, x);
    QFETCH(double, y);

    const Curve curves[] = {Curve(), Curve::linear(18, 2),
                            Curve::points({{0, 2}, {0.5, 10}, {1, 20}})};
    QCOMPARE(curves[kind].map(x), y);
}

void TestWaveform::squareEdges_data()
{
    QTest::addColumn<double>("duty");
    QTest::addColumn<int>("highSamples"); // per 200-sample period at 1 kHz

    QTest::newRow("duty 0.5") << 0.5 << 100;
    QTest::newRow("duty 0.3") << 0.3 << 60;
    QTest::newRow("duty 0") << 0.0 << 0;
    QTest::newRow("duty 1") << 1.0 << 200;
}

void TestWaveform::squareEdges()
{
    QFETCH(double, duty);
    QFETCH(int, highSamples);

    const QByteArray signal =
        R"({"type":"square","freq":5,"duty":)" + QByteArray::number(duty) + "}";
    Player player(signal.constData());
    for (int k = 0; k < 3000; ++k) {
        const double expected = k % 200 < highSamples ? 1.0 : 0.0;
        QVERIFY2(player.at(k / 1000.0) == expected, qPrintable(QString::number(k)));
    }
}

void TestWaveform::pulseCount_data()
{
    QTest::addColumn<double>("intensity");
    QTest::addColumn<int>("pulses");

    QTest::newRow("intensity 0 (2 Hz)") << 0.0 << 6;
    QTest::newRow("intensity 0.25 (6.5 Hz)") << 0.25 << 20;
    QTest::newRow("intensity 0.5 (11 Hz)") << 0.5 << 33;
    QTest::newRow("intensity 1 (20 Hz)") << 1.0 << 60;
}

void TestWaveform::pulseCount()
{
    QFETCH(double, intensity);
    QFETCH(int, pulses);

    Player geiger(R"({"type":"pulses","amp":1,"width":0.025,"rate":{"param":"intensity",)"
                  R"("gain":18,"offset":2}})");
    geiger.set(QStringLiteral("intensity"), intensity);
    std::vector<int> lengths;
    double previous = 0.0;
    for (int k = 0; k < 3000; ++k) {
        const double value = geiger.at(k / 1000.0);
        if (value == 1.0 && previous == 0.0)
            lengths.push_back(0);
        if (value == 1.0)
            ++lengths.back();
        previous = value;
    }
    QCOMPARE(int(lengths.size()), pulses);
    for (int length : lengths)
        QCOMPARE(length, 25);
}

void TestWaveform::pulsePhaseContinuity_data()
{
    QTest::addColumn<double>("before");
    QTest::addColumn<double>("after");
    QTest::addColumn<int>("changeAt");      // ms
    QTest::addColumn<QList<int>>("starts"); // ms of the pulse starts in the first second

    // 2 Hz until 300 ms (0.6 cycles done), then 20 Hz: 0.4 cycles left = 20 ms.
    QTest::newRow("speeding up between pulses")
        << 0.0 << 1.0 << 300
        << QList<int>{0, 320, 370, 420, 470, 520, 570, 620, 670, 720, 770, 820, 870, 920, 970};
    // 20 Hz until 10 ms, inside the first pulse (0.2 cycles), then 2 Hz: 0.8 cycles = 400 ms.
    QTest::newRow("slowing down inside a pulse") << 1.0 << 0.0 << 10 << QList<int>{0, 410, 910};
}

void TestWaveform::pulsePhaseContinuity()
{
    QFETCH(double, before);
    QFETCH(double, after);
    QFETCH(int, changeAt);
    QFETCH(QList<int>, starts);

    Player geiger(
        R"({"type":"pulses","width":0.025,"rate":{"param":"intensity","gain":18,"offset":2}})");
    geiger.set(QStringLiteral("intensity"), before);
    QList<int> found;
    QList<int> lengths;
    double previous = 0.0;
    for (int k = 0; k < 1000; ++k) {
        const double value = geiger.at(k / 1000.0);
        if (k == changeAt) // as a voice does: advance to the change, then change
            geiger.set(QStringLiteral("intensity"), after);
        if (value == 1.0 && previous == 0.0) {
            found.append(k);
            lengths.append(0);
        }
        if (value == 1.0)
            ++lengths.back();
        previous = value;
    }
    QCOMPARE(found, starts);
    for (int length : lengths)
        QCOMPARE(length, 25); // the width is in seconds, whatever the rate did
}

void TestWaveform::roundTrip_data()
{
    QTest::addColumn<QByteArray>("signal");

    QTest::newRow("const") << QByteArray(R"({"type":"const","value":0.5})");
    QTest::newRow("const bound") << QByteArray(
        R"({"type":"const","value":{"param":"intensity"}})");
    QTest::newRow("param") << QByteArray(R"({"type":"param","name":"ref"})");
    QTest::newRow("param linear") << QByteArray(
        R"({"type":"param","name":"ref","gain":0.5,"offset":1})");
    QTest::newRow("param curve") << QByteArray(
        R"({"type":"param","name":"ref","curve":[[0,1],[2,3]]})");
    QTest::newRow("ramp") << QByteArray(R"({"type":"ramp","to":1,"time":0.5})");
    QTest::newRow("ramp from peak")
        << QByteArray(R"({"type":"ramp","to":0,"time":0.5,"from":"peak"})");
    QTest::newRow("ramp from bound number")
        << QByteArray(R"({"type":"ramp","to":0,"time":{"param":"ref","gain":2,"offset":0},)"
                      R"("from":{"param":"intensity"}})");
    QTest::newRow("keyframes") << QByteArray(R"({"type":"keyframes","points":[[0.5,1],[1,0]]})");
    QTest::newRow("keyframes from number")
        << QByteArray(R"({"type":"keyframes","points":[[1,0]],"from":0.25})");
    QTest::newRow("sine") << QByteArray(R"({"type":"sine","freq":3})");
    QTest::newRow("sine full") << QByteArray(
        R"({"type":"sine","freq":3,"amp":0.5,"offset":0.5,"phase":0.25})");
    QTest::newRow("square") << QByteArray(R"({"type":"square","freq":5})");
    QTest::newRow("square full") << QByteArray(
        R"({"type":"square","freq":{"param":"intensity","gain":8,"offset":2},)"
        R"("duty":0.3,"high":0.9,"low":0.1})");
    QTest::newRow("pulses") << QByteArray(R"({"type":"pulses","rate":4,"width":0.025})");
    QTest::newRow("pulses full") << QByteArray(
        R"({"type":"pulses","rate":{"param":"intensity","curve":[[0,2],[1,20]]},)"
        R"("width":0.025,"amp":0.5})");
    QTest::newRow("sum") << QByteArray(
        R"({"type":"sum","of":[{"type":"const","value":1},{"type":"sine","freq":2}]})");
    QTest::newRow("product") << QByteArray(
        R"({"type":"product","of":[{"type":"ramp","to":1,"time":1},{"type":"square","freq":2}]})");
    QTest::newRow("sequence") << QByteArray(
        R"({"type":"sequence","of":[{"type":"ramp","to":1,"time":1},)"
        R"({"type":"const","value":0}]})");
    QTest::newRow("scale") << QByteArray(
        R"({"type":"scale","in":{"type":"param","name":"ref"},"gain":2,)"
        R"("div":{"param":"ref"},"offset":1})");
    QTest::newRow("clip") << QByteArray(
        R"({"type":"clip","in":{"type":"const","value":2},"min":-1,"max":0.5})");
}

void TestWaveform::roundTrip()
{
    QFETCH(QByteArray, signal);

    ParamTable table;
    table.declare(QStringLiteral("ref"), 120);
    WaveformParser parser(table, QStringLiteral("test.json"));
    const QJsonValue source = json(signal.constData());
    WaveformPtr parsed = parser.parse(source, QString());
    QVERIFY2(parsed, qPrintable(parser.error().toString()));
    const QJsonValue written = parsed->toJson(table);
    QCOMPARE(written, source);
    WaveformPtr reparsed = parser.parse(written, QString());
    QVERIFY(reparsed);
    QCOMPARE(reparsed->toJson(table), written);
}

void TestWaveform::errors_data()
{
    QTest::addColumn<QByteArray>("signal");
    QTest::addColumn<QString>("error");

    QTest::newRow("not an object") << QByteArray(R"({"s":[1]})")
                                   << "test.json: /s/0: expected a waveform object, got a number";
    QTest::newRow("no type") << QByteArray(R"({"s":{"value":1}})")
                             << "test.json: /s: missing key 'type'";
    QTest::newRow("unknown type") << QByteArray(R"({"s":{"type":"saw","freq":1}})")
                                  << "test.json: /s/type: unknown waveform type 'saw'";
    QTest::newRow("unknown key") << QByteArray(R"({"s":{"type":"square","frq":1}})")
                                 << "test.json: /s: unknown key 'frq'";
    QTest::newRow("missing key") << QByteArray(R"({"s":{"type":"ramp","to":1}})")
                                 << "test.json: /s: missing key 'time'";
    QTest::newRow("wrong type") << QByteArray(R"({"s":{"type":"ramp","to":"1","time":1}})")
                                << "test.json: /s/to: expected a number or a {\"param\": …} "
                                   "object, got a string";
    QTest::newRow("unknown parameter")
        << QByteArray(R"({"s":{"type":"pulses","rate":{"param":"speed"},"width":1}})")
        << "test.json: /s/rate: unknown parameter 'speed'";
    QTest::newRow("unknown parameter signal") << QByteArray(R"({"s":{"type":"param","name":"x"}})")
                                              << "test.json: /s: unknown parameter 'x'";
    QTest::newRow("negative time") << QByteArray(R"({"s":{"type":"ramp","to":1,"time":-0.5}})")
                                   << "test.json: /s/time: must not be negative, got -0.5";
    QTest::newRow("negative rate")
        << QByteArray(R"({"s":{"type":"pulses","rate":-1,"width":0.1}})")
        << "test.json: /s/rate: must not be negative, got -1";
    QTest::newRow("duty above 1") << QByteArray(R"({"s":{"type":"square","freq":1,"duty":1.5}})")
                                  << "test.json: /s/duty: must be within [0, 1], got 1.5";
    QTest::newRow("bad from") << QByteArray(R"({"s":{"type":"ramp","to":1,"time":1,"from":"x"}})")
                              << "test.json: /s/from: expected \"current\", \"peak\" or a "
                                 "number, got 'x'";
    QTest::newRow("keyframes decreasing")
        << QByteArray(R"({"s":{"type":"keyframes","points":[[1,0],[0.5,1]]}})")
        << "test.json: /s/points/1: times must not decrease";
    QTest::newRow("keyframes not pairs")
        << QByteArray(R"({"s":{"type":"keyframes","points":[[1,0,2]]}})")
        << "test.json: /s/points/0: expected a pair [x, y]";
    QTest::newRow("empty of") << QByteArray(R"({"s":{"type":"sum","of":[]}})")
                              << "test.json: /s/of: expected at least one waveform";
    QTest::newRow("endless step in a sequence")
        << QByteArray(R"({"s":{"type":"sequence","of":[{"type":"const","value":1},)"
                      R"({"type":"const","value":0}]}})")
        << "test.json: /s/of/0: only the last waveform "
           "of a sequence may last forever";
    QTest::newRow("nested error")
        << QByteArray(R"({"s":{"type":"clip","in":{"type":"sum","of":[{"type":"sine"}]}}})")
        << "test.json: /s/in/of/0: missing key 'freq'";
    QTest::newRow("curve not increasing")
        << QByteArray(
               R"({"s":{"type":"const","value":{"param":"intensity","curve":[[1,0],[1,2]]}}})")
        << "test.json: /s/value/curve/1: the x values of a curve must increase";
    QTest::newRow("curve and gain")
        << QByteArray(
               R"({"s":{"type":"const","value":{"param":"intensity","curve":[[1,0]],"gain":2}}})")
        << "test.json: /s/value: give either 'curve' or "
           "'gain'/'offset', not both";
    QTest::newRow("clip inverted")
        << QByteArray(R"({"s":{"type":"clip","in":{"type":"const","value":1},"min":1,"max":0}})")
        << "test.json: /s/max: must not be below min";
}

void TestWaveform::errors()
{
    QFETCH(QByteArray, signal);
    QFETCH(QString, error);

    const ParamTable table;
    WaveformParser parser(table, QStringLiteral("test.json"));
    const QJsonObject document = json(signal.constData()).toObject();
    const QJsonValue s = document.value(QLatin1String("s"));
    const QJsonValue input = s.isArray() ? s.toArray().at(0) : s;
    const QString pointer = s.isArray() ? QStringLiteral("/s/0") : QStringLiteral("/s");
    QVERIFY(!parser.parse(input, pointer));
    QCOMPARE(parser.error().toString(), error);
}

QTEST_GUILESS_MAIN(TestWaveform)
void TestWaveform::numberJson_data()
{
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("param");
    QTest::addColumn<double>("gain");
    QTest::addColumn<double>("offset");
    QTest::addColumn<bool>("curve");
    QTest::newRow("constant") << "1.5"
                              << "" << 1.0 << 0.0 << false;
    QTest::newRow("bound") << R"({"param": "intensity"})"
                           << "intensity" << 1.0 << 0.0 << false;
    QTest::newRow("linear") << R"({"param": "intensity", "gain": 18, "offset": 2})"
                            << "intensity" << 18.0 << 2.0 << false;
    QTest::newRow("curve") << R"({"param": "intensity", "curve": [[0, 2], [1, 20]]})"
                           << "intensity" << 1.0 << 0.0 << true;
}

void TestWaveform::numberJson()
{
    // What an editor reads of a Number, and writes back exactly as it came, in the form the
    // parser reads.
    QFETCH(QString, json);
    QFETCH(QString, param);
    QFETCH(double, gain);
    QFETCH(double, offset);
    QFETCH(bool, curve);
    const QJsonValue value = QJsonDocument::fromJson(("[" + json + "]").toUtf8()).array().first();
    const NumberJson number = NumberJson::read(value);
    QCOMPARE(number.param, param);
    QCOMPARE(number.isBound(), !param.isEmpty());
    QCOMPARE(number.gain, gain);
    QCOMPARE(number.offset, offset);
    QCOMPARE(!number.curve.isUndefined(), curve);
    QCOMPARE(number.toJson(), value);
    const QJsonObject ramp{{"type", "ramp"}, {"from", 0}, {"to", number.toJson()}, {"time", 1}};
    ParamTable params; // declares intensity
    WaveformParser parser(params, QStringLiteral("t.json"));
    QVERIFY2(parser.parse(ramp, QString()), qPrintable(parser.error().toString()));
}

void TestWaveform::typeTable()
{
    // Every type the table lists parses from its required fields' starting values (what the
    // designer makes a new waveform of), with every field described; the parser knows no
    // type the table lacks.
    ParamTable table;
    for (const WaveformType &type : waveformTypes()) {
        QVERIFY(!type.description.isEmpty());
        QCOMPARE(waveformType(type.type), &type);
        QJsonObject json{{"type", type.type}};
        for (const ParamSpec &field : type.fields) {
            QVERIFY2(!field.help.isEmpty(), qPrintable(type.type + '.' + field.name));
            if (field.absent != ParamAbsent::Required)
                continue;
            if (field.kind == ParamKind::Waveform)
                json.insert(field.name, QJsonObject{{"type", "const"}, {"value", 1}});
            else
                json.insert(field.name, field.example);
        }
        WaveformParser parser(table, QStringLiteral("test.json"));
        const WaveformPtr waveform = parser.parse(json, QString());
        QVERIFY2(waveform, qPrintable(parser.error().toString()));
        QCOMPARE(waveform->type(), type.type);
        QCOMPARE(type.isModifier(), type.field("in") != nullptr || type.field("of") != nullptr);
        // Its first Number field bound to a parameter parses exactly when the type says so.
        for (const ParamSpec &field : type.fields) {
            if (field.kind != ParamKind::Number)
                continue;
            QJsonObject bound = json;
            bound.insert(field.name, QJsonObject{{"param", "intensity"}});
            WaveformParser binding(table, QStringLiteral("test.json"));
            QVERIFY2(bool(binding.parse(bound, QString())) == type.bindsParams(),
                     qPrintable(type.type + '.' + field.name));
            break;
        }
    }
    WaveformParser parser(table, QStringLiteral("test.json"));
    QVERIFY(!parser.parse(QJsonObject{{"type", "triangle"}, {"freq", 1}}, QString()));
    QCOMPARE(parser.error().toString(),
             QString("test.json: /type: unknown waveform type 'triangle'"));
}

#include "tst_waveform.moc"
