// SPDX-License-Identifier: MIT
#include "devicemodel.h"
#include "jsonreader.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace semhap;

class TestDeviceModel : public QObject
{
    Q_OBJECT

private slots:
    void builtins_data();
    void builtins();
    void actuators();
    void roundTrip();
    void clampsToLimits();
    void predictsDeadTimeThenLag();
    void riseTimeMatchesModel();
    void streamingFilterMatchesPredict();
    void malformed_data();
    void malformed();
    void libraryLoad();
};

void TestDeviceModel::builtins_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QStringList>("channels");
    QTest::addColumn<double>("rate");
    QTest::newRow("pneumatic6") << "pneumatic6" << QStringList{"b1", "b2", "b3", "b4", "b5", "b6"}
                                << 100.0;
    QTest::newRow("lra4") << "lra4" << QStringList{"m1", "m2", "m3", "m4"} << 500.0;
    QTest::newRow("fingertips2") << "fingertips2" << QStringList{"thumb", "index"} << 100.0;
    QTest::newRow("overlay") << "overlay"
                             << QStringList{"left.confirm", "left.warn", "right.confirm",
                                            "right.warn"}
                             << 60.0;
}

void TestDeviceModel::builtins()
{
    QFETCH(QString, name);
    QFETCH(QStringList, channels);
    QFETCH(double, rate);
    const DeviceModelPtr model = DeviceModelLibrary::builtin(name);
    QVERIFY(model);
    QCOMPARE(model->channelNames(), channels);
    QCOMPARE(model->rate(), rate);
    for (const ChannelSpec &c : model->channels()) {
        QCOMPARE(c.min, 0.0);
        QCOMPARE(c.max, 1.0);
    }
    QCOMPARE(DeviceModelLibrary::builtinNames().size(), 4);
}

void TestDeviceModel::actuators()
{
    const Actuator &lra = DeviceModelLibrary::builtin(QStringLiteral("lra4"))->actuator();
    QCOMPARE(lra.type, QStringLiteral("LRA"));
    QCOMPARE(lra.body, QStringLiteral("wrist"));
    QVERIFY(lra.hasCarrier());
    QCOMPARE(lra.resonance, 170.0);
    QCOMPARE(lra.minFrequency, 170.0);
    QCOMPARE(lra.maxFrequency, 175.0);
    QCOMPARE(lra.maxAmplitude, 1.0);
    const Actuator &air = DeviceModelLibrary::builtin(QStringLiteral("pneumatic6"))->actuator();
    QCOMPARE(air.type, QStringLiteral("bellows"));
    QVERIFY(!air.hasCarrier());
    QCOMPARE(air.maxFrequency, 7.0);
    QCOMPARE(air.amplitudeUnit, QStringLiteral("N"));
    QCOMPARE(DeviceModelLibrary::builtin(QStringLiteral("fingertips2"))->actuator().body,
             QStringLiteral("fingers"));
    const Actuator &none = DeviceModelLibrary::builtin(QStringLiteral("overlay"))->actuator();
    QVERIFY(none.isEmpty());
    QVERIFY(std::isnan(none.maxAmplitude));
}

void TestDeviceModel::roundTrip()
{
    for (const QString &name : DeviceModelLibrary::builtinNames()) {
        const DeviceModelPtr model = DeviceModelLibrary::builtin(name);
        LoadError error;
        const DeviceModelPtr again = DeviceModel::fromJson(model->toJson(), name, &error);
        QVERIFY2(again, qPrintable(error.toString()));
        QCOMPARE(again->toJson(), model->toJson());
        QCOMPARE(again->timeConstant(), model->timeConstant());
        QCOMPARE(again->latency(), model->latency());
    }
}

void TestDeviceModel::clampsToLimits()
{
    const DeviceModelPtr model = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    QCOMPARE(model->clamp(0, 1.5), 1.0);
    QCOMPARE(model->clamp(0, -0.2), 0.0);
    QCOMPARE(model->clamp(0, 0.25), 0.25);
    QCOMPARE(model->clamp(0, std::numeric_limits<double>::quiet_NaN()), 0.0);
    QCOMPARE(model->clamp(0, std::numeric_limits<double>::infinity()), 1.0);
}

void TestDeviceModel::predictsDeadTimeThenLag()
{
    // pneumatic6: 15 ms dead time, then a 7 Hz first-order lag (tau = 22.7 ms).
    const DeviceModelPtr model = DeviceModelLibrary::builtin(QStringLiteral("pneumatic6"));
    const double rate = 1000;
    const std::vector<double> step(200, 1.0);
    const std::vector<double> out = model->predict(step, rate);
    QCOMPARE(out.size(), step.size());
    for (int k = 0; k < 15; ++k)
        QCOMPARE(out[size_t(k)], 0.0);
    QVERIFY(out[15] > 0.0);
    const double tau = 1.0 / (2 * M_PI * 7);
    QCOMPARE(model->timeConstant(), tau);
    // One time constant after the dead time the output is at 1 - 1/e.
    const auto k = size_t(std::lround(0.015 * rate + tau * rate));
    QVERIFY(std::abs(out[k] - (1 - std::exp(-1.0))) < 0.03);
    QVERIFY(out.back() > 0.99);
    QVERIFY(out.back() <= 1.0);
}

void TestDeviceModel::riseTimeMatchesModel()
{
    // lra4: 12 ms 10-90 % rise.
    const DeviceModelPtr model = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    const double rate = 100000;
    const std::vector<double> out = model->predict(std::vector<double>(5000, 1.0), rate);
    const auto crossing = [&](double level) {
        return double(std::find_if(out.begin(), out.end(), [&](double v) { return v >= level; }) -
                      out.begin()) /
               rate;
    };
    QVERIFY(std::abs(crossing(0.9) - crossing(0.1) - 0.012) < 1e-4);
}

void TestDeviceModel::streamingFilterMatchesPredict()
{
    const DeviceModelPtr model = DeviceModelLibrary::builtin(QStringLiteral("fingertips2"));
    std::vector<double> command;
    for (int k = 0; k < 300; ++k)
        command.push_back((k / 50) % 2 ? 1.0 : 0.0);
    const std::vector<double> predicted = model->predict(command, 500);
    ResponseFilter filter(*model, 500);
    for (size_t k = 0; k < command.size(); ++k)
        QCOMPARE(filter.step(command[k]), predicted[k]);
    filter.reset();
    QCOMPARE(filter.step(command[0]), predicted[0]);
}

void TestDeviceModel::malformed_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("error");
    const QByteArray ok = R"("format": "semhap.device/1", "name": "x", "rate": 100)";
    QTest::newRow("syntax") << QByteArray("{\n  \"format\": ,\n}")
                            << "m.json:2:14: invalid JSON: illegal value";
    QTest::newRow("not object") << QByteArray("[1]")
                                << "m.json:1:1: expected a JSON object, got an array";
    QTest::newRow("no format") << QByteArray(R"({"name": "x"})") << "m.json: missing key 'format'";
    QTest::newRow("wrong format")
        << QByteArray(R"({"format": "semhap.pattern/1"})")
        << "m.json: /format: unsupported format 'semhap.pattern/1', expected 'semhap.device/1'";
    QTest::newRow("no channels") << "{" + ok + "}"
                                 << "m.json: missing key 'channels'";
    QTest::newRow("empty channels") << "{" + ok + R"(, "channels": []})"
                                    << "m.json: /channels: must list 1 to 16 channels";
    QTest::newRow("channel not object")
        << "{" + ok + R"(, "channels": [3]})"
        << "m.json: /channels/0: expected a channel object, got a number";
    QTest::newRow("duplicate channel")
        << "{" + ok + R"(, "channels": [{"name": "a"}, {"name": "a"}]})"
        << "m.json: /channels/1/name: duplicate channel 'a'";
    QTest::newRow("min above max") << "{" + ok + R"(, "channels": [{"name": "a", "min": 2}]})"
                                   << "m.json: /channels/0: min must be below max";
    QTest::newRow("string limit") << "{" + ok + R"(, "channels": [{"name": "a", "max": "1"}]})"
                                  << "m.json: /channels/0/max: expected a number, got a string";
    QTest::newRow("zero rate")
        << QByteArray(R"({"format": "semhap.device/1", "name": "x", "rate": 0, "channels": []})")
        << "m.json: /rate: must be between 1 and 100000 frames/s, got 0";
    QTest::newRow("rate below 1 Hz")
        << QByteArray(
               R"({"format": "semhap.device/1", "name": "x", "rate": 1e-300, "channels": []})")
        << "m.json: /rate: must be between 1 and 100000 frames/s, got 1e-300";
    QTest::newRow("slash in name")
        << QByteArray(R"({"format": "semhap.device/1", "name": "a/b", "rate": 1})")
        << "m.json: /name: must be a non-empty name without '/'";
    QTest::newRow("both bandwidth and rise")
        << "{" + ok +
               R"(, "channels": [{"name": "a"}], "response": {"bandwidth": 7, "rise": 0.01}})"
        << "m.json: /response: give bandwidth or rise, not both";
    QTest::newRow("negative bandwidth")
        << "{" + ok + R"(, "channels": [{"name": "a"}], "response": {"bandwidth": -1}})"
        << "m.json: /response/bandwidth: must be positive (Hz)";
    QTest::newRow("unknown response key")
        << "{" + ok + R"(, "channels": [{"name": "a"}], "response": {"delay": 1}})"
        << "m.json: /response: unknown key 'delay'";
    QTest::newRow("latency too long")
        << "{" + ok + R"(, "channels": [{"name": "a"}], "response": {"latency": 5}})"
        << "m.json: /response/latency: must be between 0 and 1 s";
    const QByteArray withChannel = "{" + ok + R"(, "channels": [{"name": "a"}], "actuator": )";
    QTest::newRow("unknown actuator type")
        << withChannel + R"({"type": "solenoid"}})"
        << "m.json: /actuator/type: unknown type 'solenoid' (one of LRA, VCA, ERM, piezo, "
           "bellows)";
    QTest::newRow("unknown body")
        << withChannel + R"({"body": "ankle"}})"
        << "m.json: /actuator/body: unknown body 'ankle' (one of wrist, fingers)";
    QTest::newRow("frequencies not a pair")
        << withChannel + R"({"frequencies": [170]}})"
        << "m.json: /actuator/frequencies: expected [lowest, highest] in Hz";
    QTest::newRow("frequencies falling")
        << withChannel + R"({"frequencies": [200, 100]}})"
        << "m.json: /actuator/frequencies: must rise from 0 Hz or more, got [200, 100]";
    QTest::newRow("resonance outside frequencies")
        << withChannel + R"({"resonance": 90, "frequencies": [150, 200]}})"
        << "m.json: /actuator/resonance: 90 Hz lies outside the frequencies [150, 200]";
    QTest::newRow("zero weight") << withChannel + R"({"weight": 0}})"
                                 << "m.json: /actuator/weight: must be above 0, got 0";
    QTest::newRow("unit without amplitude")
        << withChannel + R"({"amplitude_unit": "N"}})"
        << "m.json: /actuator/amplitude_unit: a unit without max_amplitude";
    QTest::newRow("unknown actuator key") << withChannel + R"({"mass": 1}})"
                                          << "m.json: /actuator: unknown key 'mass'";
}

void TestDeviceModel::malformed()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, error);
    QJsonObject object;
    LoadError e;
    if (parseJsonObject(json, QStringLiteral("m.json"), &object, &e))
        QVERIFY(!DeviceModel::fromJson(object, QStringLiteral("m.json"), &e));
    QCOMPARE(e.toString(), error);
}

void TestDeviceModel::libraryLoad()
{
    LoadError error;
    QVERIFY(DeviceModelLibrary::load(QStringLiteral("lra4"), &error));
    QVERIFY(!DeviceModelLibrary::load(QStringLiteral("lra5"), &error));
    QCOMPARE(error.reason, QStringLiteral("unknown device model 'lra5' (built-in: "
                                          "fingertips2, lra4, overlay, pneumatic6)"));
    QVERIFY(!DeviceModelLibrary::load(QStringLiteral("/nonexistent/model.json"), &error));
    QVERIFY(error.toString().startsWith(QStringLiteral("/nonexistent/model.json: cannot read")));
}

QTEST_GUILESS_MAIN(TestDeviceModel)
#include "tst_devicemodel.moc"
