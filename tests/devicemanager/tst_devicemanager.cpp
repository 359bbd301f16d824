// SPDX-License-Identifier: MIT
// The device manager without hardware: bindings, listing and hot-plug polling of configured
// addresses, status, and the pipeline sink that forwards a preset's frames to bound devices.
#include "devicemanager.h"
#include "deviceoutputsink.h"

#include <QTest>

using namespace semhap;

class TestDeviceManager : public QObject
{
    Q_OBJECT

private slots:
    void parseBinding_data();
    void parseBinding();
    void bindAndStatus();
    void pollReportsChanges();
    void sinkForwardsBoundDevices();
};

void TestDeviceManager::parseBinding_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("name"); ///< empty: rejected
    QTest::addColumn<QString>("uri");
    QTest::newRow("serial") << "right.vibro=serial:/dev/ttyACM0"
                            << "right.vibro"
                            << "serial:/dev/ttyACM0";
    QTest::newRow("udp") << "left.air=udp:127.0.0.1:9000"
                         << "left.air"
                         << "udp:127.0.0.1:9000";
    QTest::newRow("no equals") << "right.vibro"
                               << ""
                               << "";
    QTest::newRow("no name") << "=virtual:x"
                             << ""
                             << "";
    QTest::newRow("no uri") << "right.vibro="
                            << ""
                            << "";
    QTest::newRow("bad uri") << "right.vibro=usb:1"
                             << ""
                             << "";
}

void TestDeviceManager::parseBinding()
{
    QFETCH(QString, text);
    QFETCH(QString, name);
    QFETCH(QString, uri);
    QString gotName;
    QString gotUri;
    QString error;
    QCOMPARE(DeviceManager::parseBinding(text, &gotName, &gotUri, &error), !name.isEmpty());
    if (name.isEmpty()) {
        QVERIFY(!error.isEmpty());
        return;
    }
    QCOMPARE(gotName, name);
    QCOMPARE(gotUri, uri);
}

void TestDeviceManager::bindAndStatus()
{
    DeviceManager manager;
    QString error;
    DeviceModelPtr lra4 = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    QVERIFY(
        manager.bind(QStringLiteral("right.vibro"), QStringLiteral("virtual:rv"), lra4, &error));
    QVERIFY(!manager.bind(QStringLiteral("left.vibro"), QStringLiteral("nope"), lra4, &error));
    // A band that is not there is kept, and connects when it appears.
    QVERIFY(manager.bind(QStringLiteral("left.vibro"), QStringLiteral("serial:/nonexistent"), lra4,
                         &error));
    QCOMPARE(manager.boundNames(),
             QStringList({QStringLiteral("left.vibro"), QStringLiteral("right.vibro")}));
    const std::vector<BoundDevice> status = manager.status();
    QCOMPARE(status.size(), size_t(2));
    QCOMPARE(status[0].uri, QStringLiteral("serial:/nonexistent"));
    QVERIFY(!status[0].status.connected);
    QVERIFY(status[0].status.lastError.contains(QStringLiteral("no such device")));
    QVERIFY(status[1].status.connected);
    manager.armAll(false);
    QVERIFY(!manager.transport(QStringLiteral("right.vibro"))->isArmed());
    manager.unbind(QStringLiteral("left.vibro"));
    QVERIFY(!manager.transport(QStringLiteral("left.vibro")));
}

void TestDeviceManager::pollReportsChanges()
{
    DeviceManager manager;
    QStringList added;
    QStringList removed;
    manager.poll(&added, &removed);
    QVERIFY(!manager.poll(&added, &removed));
    manager.addConfigured(QStringLiteral("udp:127.0.0.1:9000"));
    QVERIFY(manager.poll(&added, &removed));
    QCOMPARE(added, QStringList{QStringLiteral("udp:127.0.0.1:9000")});
    QVERIFY(removed.isEmpty());
    const std::vector<PortInfo> present = manager.present();
    QCOMPARE(present.back().kind, QStringLiteral("udp"));
}

void TestDeviceManager::sinkForwardsBoundDevices()
{
    LoadError error;
    std::unique_ptr<Router> router = loadRouter(QStringLiteral("C3"), {}, &error);
    QVERIFY(router);
    DeviceManager manager;
    QString reason;
    QVERIFY(manager.bind(QStringLiteral("right.vibro"), QStringLiteral("virtual:rv"),
                         DeviceModelLibrary::builtin(QStringLiteral("lra4")), &reason));
    Pipeline pipeline(std::move(router));
    DeviceOutputSink sink(pipeline.router().player(), manager);
    QCOMPARE(sink.boundCount(), 1);
    // A right hand crushing: break warnings (Geiger pulses) on right.vibro.
    ContactFrame frame;
    for (int k = 0; k < 400; ++k) {
        frame = ContactFrame{};
        frame.t = k * 0.005;
        frame.gripper = Gripper::Right;
        frame.left.f = frame.right.f = 50.0;
        frame.left.n = frame.right.n = 16;
        pipeline.process(frame, sink);
    }
    pipeline.flush(sink);
    // Two seconds at the band's 500 Hz, as sent.
    std::uint64_t next = 0;
    std::vector<DeviceFrame> history;
    manager.transport(QStringLiteral("right.vibro"))->sent().readSince(&next, &history);
    QVERIFY2(history.size() > 990 && history.size() <= 1001,
             qPrintable(QString::number(history.size())));
    QVERIFY(std::any_of(history.begin(), history.end(),
                        [](const DeviceFrame &f) { return f.values[0] == 1.0; }));
}

QTEST_GUILESS_MAIN(TestDeviceManager)
#include "tst_devicemanager.moc"
