// SPDX-License-Identifier: MIT
// The devices panel end to end without hardware: an emulated band on UDP loopback is added
// through the panel's address field, chosen in the router device's row and connected with
// the row's button; its state, the frames reaching the band, the level meters, arming and
// the fall back to the virtual device on disconnect are checked in the panel. A sound card
// (FifoCard: ALSA into a FIFO) is listed, bound, unplugged and plugged in again.
#include "devicemanager.h"
#include "devicespanel.h"
#include "emulatedband.h"
#include "emulator.h"
#include "fifocard.h"
#include "levelmeter.h"
#include "runhistory.h"
#include "transportscheme.h"
#include "widgetchecks.h"

#include <QApplication>
#include <QComboBox>
#include <QGuiApplication>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolTip>
#include <QTreeWidget>
#include <QWheelEvent>

#include <atomic>
#include <cmath>
#include <thread>

using namespace semhap;

namespace {

const QString Band = QStringLiteral("right.vibro");

/** A panel on a one-device run whose bind requests the manager carries out at once. */
struct Fixture
{
    RunHistory history;
    DeviceManager manager;
    DevicesPanel panel{manager, history};

    Fixture()
    {
        const DeviceModelPtr lra4 = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
        history.start({{Band, lra4->name(), lra4->channelNames()}}, {}, {});
        QObject::connect(
            &panel, &DevicesPanel::bindRequested, &panel,
            [this](const QString &name, const QString &uri) {
                QString error;
                for (const RunDevice &device : history.devices()) {
                    if (device.name == name)
                        manager.bind(name, uri, DeviceModelLibrary::builtin(device.model), &error);
                }
                panel.refresh();
            });
        panel.resize(420, 600);
        panel.show();
    }
    template<typename T> T *child(const QString &name) const { return panel.findChild<T *>(name); }
    void click(const QString &button) const
    {
        QTest::mouseClick(child<QPushButton>(button), Qt::LeftButton);
    }
    void addAddress(const QString &uri) const
    {
        QTest::keyClicks(child<QLineEdit>(QStringLiteral("address")), uri);
        click(QStringLiteral("addButton"));
    }
    QStringList presentUris() const
    {
        QStringList uris;
        const auto *list = child<QTreeWidget>(QStringLiteral("presentList"));
        for (int i = 0; i < list->topLevelItemCount(); ++i)
            uris.append(list->topLevelItem(i)->text(1));
        return uris;
    }
    QString state() const { return child<QLabel>(QStringLiteral("state:") + Band)->text(); }
};

} // namespace

class TestDevicesPanel : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void addAddress_data();
    void addAddress();
    void connectToEmulator();
    void connectToSoundCard();
    void metersShowTheirOwnDevice();
    void wheelScrollsTheRows_data();
    void wheelScrollsTheRows();
    void aWideDockShowsSeveralDevices();
    void screenshot();

private:
    QTemporaryDir m_dir;
    QString m_fifo;
};

void TestDevicesPanel::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_fifo = FifoCard::install(m_dir.path());
    QVERIFY(!m_fifo.isEmpty());
}

void TestDevicesPanel::addAddress_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("listed"); ///< empty: rejected with a message
    QTest::newRow("udp") << "udp:127.0.0.1:9000"
                         << "udp:127.0.0.1:9000";
    QTest::newRow("pty") << "serial:/dev/pts/3"
                         << "serial:/dev/pts/3";
    QTest::newRow("virtual") << " virtual:x "
                             << "virtual:x";
    QTest::newRow("tcp") << "tcp:band.local:2000"
                         << "tcp:band.local:2000";
    QTest::newRow("bad scheme") << "usb:1"
                                << "";
    QTest::newRow("no port") << "udp:127.0.0.1"
                             << "";
}

void TestDevicesPanel::addAddress()
{
    QFETCH(QString, typed);
    QFETCH(QString, listed);
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.panel));
    f.addAddress(typed);
    auto *message = f.child<QLabel>(QStringLiteral("message"));
    QCOMPARE(message->isVisible(), listed.isEmpty());
    if (listed.isEmpty()) {
        QVERIFY(!message->text().isEmpty());
        return;
    }
    QVERIFY(f.presentUris().contains(listed));
    QCOMPARE(f.presentUris().last(), listed);
    QVERIFY(f.child<QComboBox>(QStringLiteral("uri:") + Band)->findText(listed) >= 0);
    QVERIFY(f.child<QLineEdit>(QStringLiteral("address"))->text().isEmpty());
    // The field's tooltip names every form an address can take (TransportScheme).
    const QString tooltip = f.child<QLineEdit>(QStringLiteral("address"))->toolTip();
    for (const TransportScheme &scheme : TransportScheme::all())
        QVERIFY2(tooltip.contains(QString::fromUtf8(scheme.syntax).toHtmlEscaped()),
                 scheme.syntax);
}

void TestDevicesPanel::connectToEmulator()
{
    EmulatedBand band(QStringLiteral("lra4"));
    QString error;
    QVERIFY2(band.start(&error), qPrintable(error));
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.panel));
    QCOMPARE(f.state(), QStringLiteral("not bound"));

    f.addAddress(band.uri());
    QVERIFY(f.presentUris().contains(band.uri()));
    QVERIFY(choose(f.child<QComboBox>(QStringLiteral("uri:") + Band), band.uri()));
    QSignalSpy requested(&f.panel, &DevicesPanel::bindRequested);
    f.click(QStringLiteral("connect:") + Band);
    QCOMPARE(requested.count(), 1);
    QCOMPARE(requested[0][0].toString(), Band);
    QCOMPARE(requested[0][1].toString(), band.uri());
    QVERIFY(f.manager.transport(Band));
    QCOMPARE(f.manager.transport(Band)->uri(), band.uri());
    QTRY_COMPARE_WITH_TIMEOUT(f.state(), QStringLiteral("connected"), 5000);
    QTRY_VERIFY(f.child<QLabel>(QStringLiteral("details:") + Band)
                    ->text()
                    .contains(QStringLiteral("RTT")));

    // Real bands start disarmed: nothing reaches the motors until armed.
    auto *details = f.child<QLabel>(QStringLiteral("details:") + Band);
    QVERIFY(details->text().contains(QStringLiteral("disarmed")));
    f.click(QStringLiteral("armAll"));
    QVERIFY(f.manager.transport(Band)->isArmed());
    QCOMPARE(f.child<QLabel>(QStringLiteral("armedSummary"))->text(),
             QStringLiteral("1 of 1 armed"));
    QVERIFY(!details->text().contains(QStringLiteral("disarmed")));

    DeviceFrame frame;
    frame.t = 0.5;
    frame.device = 0;
    frame.channelCount = 4;
    frame.values = {0.5, 0.25, 0.0, 1.0};
    f.manager.transport(Band)->send(frame);
    QTRY_VERIFY_WITH_TIMEOUT(band.state().setpoints.size() == 4 &&
                                 std::abs(band.state().setpoints[0] - 0.5) < 1e-3 &&
                                 std::abs(band.state().setpoints[3] - 1.0) < 1e-3,
                             3000);

    // The meters show the newest frame the history holds.
    auto *meter = f.child<LevelMeter>(QStringLiteral("levels:") + Band);
    QCOMPARE(int(meter->channels().size()), 4);
    f.history.append(frame);
    frame.t = 0.6;
    frame.values = {0.1, 0.2, 0.3, 0.4};
    f.history.append(frame);
    f.history.commit();
    QCOMPARE(meter->values(), std::vector<double>({0.1, 0.2, 0.3, 0.4}));

    // Disconnecting falls back to the virtual device: the run keeps going.
    f.click(QStringLiteral("disconnect:") + Band);
    QCOMPARE(requested.count(), 2);
    QCOMPARE(f.manager.transport(Band)->uri(), QStringLiteral("virtual:") + Band);
    QCOMPARE(f.state(), QStringLiteral("connected"));
    QCOMPARE(f.child<QComboBox>(QStringLiteral("uri:") + Band)->currentText(),
             QStringLiteral("virtual:") + Band);
    QVERIFY(!f.child<QPushButton>(QStringLiteral("disconnect:") + Band)->isEnabled());
    // The band's watchdog takes it to rest once the host has gone.
    QTRY_VERIFY_WITH_TIMEOUT(band.state().setpoints[0] == 0.0, 3000);
}

void TestDevicesPanel::connectToSoundCard()
{
    auto card = std::make_unique<FifoCard>(m_fifo, 4);
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.panel));
    const QString uri = QStringLiteral("audio:semhaptest");
    const auto *list = f.child<QTreeWidget>(QStringLiteral("presentList"));
    const QList<QTreeWidgetItem *> rows = list->findItems(uri, Qt::MatchExactly, 1);
    QCOMPARE(rows.size(), 1);
    QCOMPARE(rows[0]->text(0), QStringLiteral("audio"));
    QCOMPARE(rows[0]->text(2),
             QStringLiteral("128 ch, %1 Hz (ALSA)").arg(QLocale().toString(44100.0, 'f', 0)));

    QVERIFY(choose(f.child<QComboBox>(QStringLiteral("uri:") + Band), uri));
    f.click(QStringLiteral("connect:") + Band);
    QCOMPARE(f.manager.transport(Band)->uri(), uri);
    QTRY_COMPARE_WITH_TIMEOUT(f.state(), QStringLiteral("connected"), 5000);
    f.click(QStringLiteral("armAll"));
    DeviceFrame frame;
    frame.t = 0.5;
    frame.channelCount = 4;
    frame.values = {0.5, 0.0, 0.0, 0.0};
    f.manager.transport(Band)->send(frame);
    auto *details = f.child<QLabel>(QStringLiteral("details:") + Band);
    QTRY_VERIFY(details->text().contains(QStringLiteral("latency")));
    QTRY_VERIFY(card->frames() > 8000);
    const std::vector<float> wave = card->channel(0);
    QVERIFY(std::abs(*std::max_element(wave.begin(), wave.end()) - 0.5f) < 0.01f);

    // Unplugged: the panel says so and why; plugged in again, the band plays on.
    card->stop();
    QTRY_COMPARE_WITH_TIMEOUT(f.state(), QStringLiteral("disconnected"), 5000);
    QTRY_VERIFY(details->text().contains(
        QStringLiteral("retrying: 'semhaptest' stopped playing (unplugged?)")));
    card = std::make_unique<FifoCard>(m_fifo, 4);
    QTRY_COMPARE_WITH_TIMEOUT(f.state(), QStringLiteral("connected"), 5000);
    QTRY_VERIFY(details->text().contains(QStringLiteral("reconnects: 1")));
    QTRY_VERIFY(card->frames() > 8000);

    // Disconnecting closes the stream: the card's last samples are silence.
    f.click(QStringLiteral("disconnect:") + Band);
    QTRY_VERIFY(card->ended());
    QCOMPARE(card->channel(0).back(), 0.0f);
}

void TestDevicesPanel::metersShowTheirOwnDevice()
{
    // A device of a hand the scene lacks is listed last, yet every row's meter shows its own
    // device's frames (the left band here comes first in the router).
    RunHistory history;
    DeviceManager manager;
    const DeviceModelPtr lra4 = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    history.start({{QStringLiteral("left.vibro"), lra4->name(), lra4->channelNames(), true},
                   {Band, lra4->name(), lra4->channelNames(), false}},
                  {}, {});
    DevicesPanel panel(manager, history);
    panel.resize(420, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const std::vector<std::vector<double>> levels = {{0.1, 0.1, 0.1, 0.1}, {0.9, 0.8, 0.7, 0.6}};
    for (int d = 0; d < 2; ++d) {
        DeviceFrame frame;
        frame.t = 1.0;
        frame.device = d;
        frame.channelCount = 4;
        std::copy(levels[size_t(d)].begin(), levels[size_t(d)].end(), frame.values.begin());
        history.append(frame);
    }
    history.commit();
    QCOMPARE(panel.findChild<LevelMeter *>(QStringLiteral("levels:") + Band)->values(), levels[1]);
    QCOMPARE(panel.findChild<LevelMeter *>(QStringLiteral("levels:left.vibro"))->values(),
             levels[0]);
}

void TestDevicesPanel::wheelScrollsTheRows_data()
{
    // Where the wheel event lands once Qt has passed it up from under the pointer: the
    // rows' viewport (over a label, a meter, a gap), or an address box (over its field).
    QTest::addColumn<QString>("over");
    QTest::newRow("the rows") << "qt_scrollarea_viewport";
    QTest::newRow("an address box without the focus") << "uri:band0";
}

void TestDevicesPanel::wheelScrollsTheRows()
{
    // Seven bands, more than the panel shows: a wheel notch scrolls the rows by one (it
    // moved them by a fixed bit of a row), also over an address box, whose address stays
    // (the wheel picked another one while the user only meant to scroll).
    QFETCH(QString, over);
    RunHistory history;
    DeviceManager manager;
    const DeviceModelPtr lra4 = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    std::vector<RunDevice> devices;
    for (int d = 0; d < 7; ++d)
        devices.push_back({QStringLiteral("band%1").arg(d), lra4->name(), lra4->channelNames()});
    history.start(devices, {}, {});
    DevicesPanel panel(manager, history);
    panel.resize(420, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto *rows = panel.findChild<QScrollArea *>(QStringLiteral("rowsScroll"));
    QVERIFY(rows);
    QScrollBar *bar = rows->verticalScrollBar();
    QVERIFY(bar->maximum() > 0);
    QCOMPARE(bar->value(), 0);
    auto *address = panel.findChild<QComboBox *>(QStringLiteral("uri:band0"));
    QVERIFY(address->count() > 1);
    const QString before = address->currentText();
    QWidget *target = rows->findChild<QWidget *>(over);
    QVERIFY(target);
    QVERIFY(!target->hasFocus());
    const QPointF at = QRectF(target->rect()).center();
    QWheelEvent wheel(at, target->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(target, &wheel);
    // The next row at the top, but for the step's rounding.
    const auto *next = address->parentWidget()->parentWidget()->findChild<QComboBox *>(
        QStringLiteral("uri:band1"));
    const int row = next->parentWidget()->y();
    QVERIFY2(std::abs(bar->value() - row) < QApplication::wheelScrollLines(),
             qPrintable(QStringLiteral("%1 for %2").arg(bar->value()).arg(row)));
    QCOMPARE(address->currentText(), before);
}

void TestDevicesPanel::aWideDockShowsSeveralDevices()
{
    // The Devices dock under the viewport of a 1920×1080 window: wide and short. Each
    // device's meter goes beside its controls, so two devices can be bound without
    // scrolling (only the first one's address box was in sight).
    RunHistory history;
    DeviceManager manager;
    std::vector<RunDevice> devices;
    for (const char *model : {"pneumatic6", "lra4", "fingertips2"}) {
        const DeviceModelPtr m = DeviceModelLibrary::builtin(model);
        devices.push_back({QStringLiteral("right.") + model, m->name(), m->channelNames()});
    }
    history.start(devices, {}, {});
    DevicesPanel panel(manager, history);
    panel.resize(920, 340);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto *rows = panel.findChild<QScrollArea *>(QStringLiteral("rowsScroll"));
    const auto inSight = [&](const QString &name) {
        QWidget *widget = panel.findChild<QWidget *>(name);
        const QRect at(widget->mapTo(rows->viewport(), QPoint()), widget->size());
        return rows->viewport()->rect().contains(at);
    };
    for (const char *name : {"right.pneumatic6", "right.lra4"}) {
        QTRY_VERIFY2(inSight(QStringLiteral("uri:") + name), name);
        QVERIFY2(inSight(QStringLiteral("connect:") + name), name);
    }
    // Its meter beside the address, not under it.
    QVERIFY(panel.findChild<LevelMeter *>("levels:right.lra4")->x() >
            panel.findChild<QComboBox *>("uri:right.lra4")->x());
    // Narrow again (the dock beside the plots): the meter under the controls, as before.
    panel.resize(420, 600);
    QTRY_VERIFY(panel.findChild<LevelMeter *>("levels:right.lra4")->y() >
                panel.findChild<QComboBox *>("uri:right.lra4")->y());
}

/** With SEMHAP_SCREENSHOTS=DIR: the panel of a bimanual run, for docs/screenshots. */
void TestDevicesPanel::screenshot()
{
    const QString dir = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    if (dir.isEmpty())
        QSKIP("set SEMHAP_SCREENSHOTS to a folder to write the screenshot");
    EmulatorOptions options;
    options.model = DeviceModelLibrary::builtin(QStringLiteral("pneumatic6"));
    options.udp = true;
    Emulator emulator(options);
    QString error;
    QVERIFY2(emulator.open(&error), qPrintable(error));
    std::atomic<bool> quit{false};
    std::thread thread([&] { emulator.run([&] { return quit.load(); }); });

    RunHistory history;
    DeviceManager manager;
    const DeviceModelPtr air = options.model;
    const DeviceModelPtr lra4 = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
    history.start({{QStringLiteral("right.air"), air->name(), air->channelNames()},
                   {QStringLiteral("left.air"), air->name(), air->channelNames()},
                   {QStringLiteral("right.vibro"), lra4->name(), lra4->channelNames()}},
                  {}, {});
    manager.addConfigured(emulator.uri());
    manager.bind(QStringLiteral("right.air"), emulator.uri(), air, &error);
    manager.bind(QStringLiteral("left.air"), QStringLiteral("virtual:left.air"), air, &error);
    manager.bind(QStringLiteral("right.vibro"), QStringLiteral("udp:127.0.0.1:9"), lra4, &error);
    manager.armAll(true);
    const std::vector<std::vector<double>> levels = {
        {0.62, 0.58, 0.4, 0.0, 0.12, 0.3}, {0.2, 0.2, 0.2, 0.2, 0.2, 0.2}, {0.8, 0.0, 0.8, 0.0}};
    for (int d = 0; d < 3; ++d) {
        DeviceFrame frame;
        frame.t = 12.5;
        frame.device = d;
        frame.channelCount = int(levels[size_t(d)].size());
        std::copy(levels[size_t(d)].begin(), levels[size_t(d)].end(), frame.values.begin());
        history.append(frame);
    }
    history.commit();
    // Keep the band fed at 100 frames/s, as a run would.
    QTimer feed;
    QObject::connect(&feed, &QTimer::timeout, [&] {
        DeviceFrame frame;
        frame.channelCount = int(levels[0].size());
        std::copy(levels[0].begin(), levels[0].end(), frame.values.begin());
        manager.transport(QStringLiteral("right.air"))->send(frame);
    });
    feed.start(10);
    DevicesPanel panel(manager, history);
    for (const QSize size : {QSize(420, 600), QSize(640, 800)}) {
        panel.resize(size);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTRY_COMPARE_WITH_TIMEOUT(
            panel.findChild<QLabel *>(QStringLiteral("state:right.air"))->text(),
            QStringLiteral("connected"), 5000);
        QTest::qWait(1200); // a second of rates
        QVERIFY(panel.grab().save(
            QStringLiteral("%1/devices-%2x%3.png").arg(dir).arg(size.width()).arg(size.height())));
    }
    auto *address = panel.findChild<QLineEdit *>(QStringLiteral("address"));
    QToolTip::showText(address->mapToGlobal(QPoint(0, address->height())), address->toolTip(),
                       address);
    QTest::qWait(400);
    const QPoint corner = address->mapToGlobal(QPoint(0, -100));
    QVERIFY(QGuiApplication::primaryScreen()
                ->grabWindow(0, corner.x(), corner.y(), 640, 320)
                .save(dir + "/devices-address-tooltip.png"));
    QToolTip::hideText();
    quit = true;
    thread.join();
}

QTEST_MAIN(TestDevicesPanel)
#include "tst_devicespanel.moc"
