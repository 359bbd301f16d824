// SPDX-License-Identifier: MIT
// The studio as a user meets it (run under Xvfb: the viewport needs OpenGL): it opens on
// the embedded defaults and runs; scene and router pickers, run/step/speed, the stop-all
// key, auditions and teleoperation drive the engine; the layout is saved and restored; German
// can be switched on in the preferences; the work survives a language switch, a restart and a
// crash; `--screenshot` grabs the window and quits.

#include "bandprocess.h"
#include "colors.h"
#include "devicemanager.h"
#include "devicespanel.h"
#include "emulatedband.h"
#include "eventlogmodel.h"
#include "eventlogpanel.h"
#include "fifocard.h"
#include "foxglovepeers.h"
#include "gamepadinput.h"
#include "handdrive.h"
#include "imagechecks.h"
#include "levelmeter.h"
#include "mainwindow.h"
#include "openwindow.h"
#include "patternauditioner.h"
#include "patterndocument.h"
#include "plotpanel.h"
#include "preferencesdialog.h"
#include "routerdocument.h"
#include "routereditor.h"
#include "runtoolbar.h"
#include "simviewport.h"
#include "studio.h"
#include "studiotesting.h"
#include "transport.h"
#include "waveformdesigner.h"
#include "widgetchecks.h"
#include "windowpictures.h"
#include "workspace.h"
#include "world.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QMatrix4x4>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTabWidget>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QtMath>
#include <QToolButton>
#include <QTreeWidget>
#include <QUdpSocket>
#include <QVector3D>
#include <QVector4D>

#include <qcustomplot.h>

#include <cmath>
#include <memory>

using namespace semhap;

namespace {

QVector3D vector(const std::array<double, 3> &point)
{
    return QVector3D(float(point[0]), float(point[1]), float(point[2]));
}

/** Where `camera` (MuJoCo's free camera: an orbit around its look-at point) looks from. */
QVector3D eyeOf(const OrbitCamera &camera)
{
    const float az = float(qDegreesToRadians(camera.azimuth));
    const float el = float(qDegreesToRadians(camera.elevation));
    const QVector3D towards(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                            std::sin(el));
    return vector(camera.lookAt) - float(camera.distance) * towards;
}

/**
 * Where `point` shows in a picture of `size` taken through `camera` (the scenes' 45°
 * vertical field of view, z up); none when it is behind the camera.
 */
std::optional<QPointF> projected(const OrbitCamera &camera, const std::array<double, 3> &point,
                                 QSize size)
{
    QMatrix4x4 view;
    view.perspective(45.0f, float(size.width()) / float(size.height()), 0.01f, 10.0f);
    view.lookAt(eyeOf(camera), vector(camera.lookAt), QVector3D(0, 0, 1));
    const QVector4D clip = view * QVector4D(vector(point), 1.0f);
    if (clip.w() <= 0)
        return std::nullopt;
    return QPointF((1.0 + clip.x() / clip.w()) / 2 * size.width(),
                   (1.0 - clip.y() / clip.w()) / 2 * size.height());
}

/**
 * Holds the drive key that moves the active hand's wrist target along world `axis` towards
 * `goal`, as a person would (which key depends on the view), until the target is there or
 * stops (the guard, the workspace's edge); empty when it got there, else what happened.
 */
QString driveTo(SimViewport *viewport, HandDrive *drive, size_t axis, double goal)
{
    auto at = [drive, axis] { return drive->command(drive->activeHand())->target.pos[axis]; };
    auto landed = [drive, axis](double sign) {
        return axis == 2 && sign < 0 && drive->status(drive->activeHand()).floor.has_value();
    };
    auto keyToward = [drive, axis](double sign) {
        if (axis == 2)
            return sign > 0 ? Qt::Key_R : Qt::Key_F;
        const auto [x, y] = drive->awayDirection();
        const double away = axis == 0 ? x : y;
        const double right = axis == 0 ? y : -x;
        return away != 0 ? (away * sign > 0 ? Qt::Key_W : Qt::Key_S)
                         : (right * sign > 0 ? Qt::Key_D : Qt::Key_A);
    };
    // As a person lands on a spot: the last centimetre at a quarter of the speed (Shift held),
    // then an overshoot taken back in taps. A busy machine that stalls while a key is held
    // moves the target further than asked (up to the drive's longest tick); a tap moves one
    // tick's worth whatever the machine, so the spot reached does not depend on its speed.
    constexpr double Tolerance = 0.002;
    QElapsedTimer clock;
    clock.start();
    const double sign = goal > at() ? 1.0 : -1.0;
    Qt::Key key = keyToward(sign);
    QTest::keyPress(viewport, key);
    bool slow = false;
    while ((goal - at()) * sign > 0 && clock.elapsed() < 10000 && !landed(sign)) {
        if (!slow && std::abs(goal - at()) < 0.01) {
            QTest::keyPress(viewport, Qt::Key_Shift);
            slow = true;
        }
        QTest::qWait(10);
    }
    QTest::keyRelease(viewport, key);
    if (!slow)
        QTest::keyPress(viewport, Qt::Key_Shift);
    for (int tap = 0; tap < 200 && !landed(sign) && std::abs(goal - at()) > Tolerance; ++tap) {
        key = keyToward(goal > at() ? 1.0 : -1.0);
        QTest::keyClick(viewport, key);
    }
    QTest::keyRelease(viewport, Qt::Key_Shift);
    // Landing ends the way down wherever the floor is; elsewhere the target must be there.
    if (landed(sign) || std::abs(goal - at()) <= Tolerance)
        return QString();
    return QString("key %1, %2 ms: the target is at %3 of %4, the view's azimuth %5, focus %6")
        .arg(QKeySequence(key).toString())
        .arg(clock.elapsed())
        .arg(at())
        .arg(goal)
        .arg(viewport->camera().azimuth)
        .arg(viewport->hasFocus());
}

} // namespace

class TestStudio : public StudioTestCase
{
    Q_OBJECT

private slots:
    void initTestCase() { setUp(); }
    void init() { reset(); }
    void opensOnTheDefaultsAndRuns();
    void picksSceneAndRouter();
    void runStepAndSpeedFromTheKeyboard();
    void pausedResetShowsTheScene();
    void timeWindowFollowsTheSpinBox();
    void stopAllWorksFromAnywhere();
    void auditionShowsInTheReadouts_data();
    void auditionShowsInTheReadouts();
    void auditionPlaysOnASoundCard_data();
    void auditionPlaysOnASoundCard();
    void auditionPlaysOnTheReferenceBand_data();
    void auditionPlaysOnTheReferenceBand();
    void disarmedBandsReadZero();
    void driveShowsTheGhostAtOnce_data();
    void driveShowsTheGhostAtOnce();
    void followKeepsTheHandInView_data();
    void followKeepsTheHandInView();
    void statusBarCountsDevicesAsThePanelShowsThem_data();
    void statusBarCountsDevicesAsThePanelShowsThem();
    void drivingOverlayShowsTheAppliedGrip_data();
    void drivingOverlayShowsTheAppliedGrip();
    void handingBackNeverStrikes_data();
    void handingBackNeverStrikes();
    void drivingPreferencesApply();
    void publishesToFoxglove();
    void aKeyInTheViewportTakesOver();
    void drivingOverlayLeavesTheHandInSight_data();
    void drivingOverlayLeavesTheHandInSight();
    void eventLogMovesThePlotCursor();
    void layoutIsSavedAndRestored();
    void switchesToGerman();
    void languageSwitchKeepsTheWork();
    void workComesBackAfterARestart();
    void workComesBackAfterACrash();
    void brokenWorkspacesAreReported_data();
    void brokenWorkspacesAreReported();
    void screenshotHook();
};

void TestStudio::opensOnTheDefaultsAndRuns()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QCOMPARE(window.runToolBar()->scenePicker()->currentData().toString(),
             QString("box_and_block"));
    QCOMPARE(window.runToolBar()->routerPicker()->currentData().toString(), QString("C3"));
    QVERIFY(window.engine().isRunning());
    QVERIFY(!window.engine().isDriving());
    for (const RunDevice &device : window.engine().history().devices())
        QCOMPARE(window.engine().devices().transport(device.name)->uri(),
                 "virtual:" + device.name);

    // Events reach the log and data the plots.
    QTRY_VERIFY_WITH_TIMEOUT(window.eventLog()->model()->rowCount() > 0, 30000);
    auto *plot = window.plots()->findChild<QCustomPlot *>();
    QVERIFY(plot);
    int points = 0;
    for (int g = 0; g < plot->graphCount(); ++g)
        points += plot->graph(g)->dataCount();
    QVERIFY2(points > 100, qPrintable(QString::number(points)));
    QVERIFY(window.findChild<QLabel *>("timeLabel")->text().startsWith("t = "));
    QVERIFY(window.windowTitle().contains("box_and_block"));
}

void TestStudio::picksSceneAndRouter()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QSignalSpy loaded(&window.engine(), &Engine::sourceChanged);

    QComboBox *scene = window.runToolBar()->scenePicker();
    scene->setFocus();
    const int bimanual = scene->findData("bimanual_sorting");
    QVERIFY(bimanual >= 0);
    while (scene->currentIndex() != bimanual)
        QTest::keyClick(scene, bimanual > scene->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QTRY_COMPARE(window.engine().options().scene, QString("bimanual_sorting"));

    QComboBox *router = window.runToolBar()->routerPicker();
    router->setFocus();
    const int c1 = router->findData("C1");
    QVERIFY(c1 >= 0);
    while (router->currentIndex() != c1)
        QTest::keyClick(router, c1 > router->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QTRY_COMPARE(window.engine().options().router, QString("C1"));
    QVERIFY(loaded.count() >= 2);
    QVERIFY(window.engine().isRunning()); // picking keeps a running session running

    // The bimanual scene has a left hand: its frames and the slip detector show up.
    const std::vector<DetectorLevel> &left =
        window.engine().history().thresholds()[size_t(Gripper::Left)].levels;
    QVERIFY(std::any_of(left.begin(), left.end(), [](const DetectorLevel &level) {
        return level.quantity == DetectorLevel::Quantity::Contacts;
    }));
    QTRY_VERIFY_WITH_TIMEOUT(!window.engine().history().frames(Gripper::Left).isEmpty(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(window.eventLog()->model()->rowCount() > 0, 30000);
    QVERIFY(window.windowTitle().contains("C1"));

    // An edit applied from the router editor runs as "C1*" until another router is picked.
    QCOMPARE(router->currentText(), QString("C1"));
    RouterEditor *editor = window.routerEditor();
    editor->setParam("left.slip", "loss", 30);
    QVERIFY(editor->apply());
    QTRY_COMPARE(router->currentText(), QString("C1*"));
    const int c3 = router->findData("C3");
    while (router->currentIndex() != c3)
        QTest::keyClick(router, c3 > router->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QTRY_COMPARE(window.engine().options().router, QString("C3"));
    QCOMPARE(router->currentText(), QString("C3"));
    QCOMPARE(router->itemText(c1), QString("C1"));
}

void TestStudio::runStepAndSpeedFromTheKeyboard()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QVERIFY(window.engine().isRunning());
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(!window.engine().isRunning());
    QTest::qWait(50);
    const double t = window.engine().simTime();
    QTest::keyClick(&window, Qt::Key_F6);
    QTRY_VERIFY(window.engine().simTime() > t);
    QVERIFY(!window.engine().isRunning());

    QCOMPARE(window.engine().speed(), 4.0);
    QTest::keyClick(&window, Qt::Key_Minus, Qt::ControlModifier);
    QCOMPARE(window.engine().speed(), 2.0);
    QTest::keyClick(&window, Qt::Key_0, Qt::ControlModifier);
    QCOMPARE(window.engine().speed(), 1.0);
    QCOMPARE(window.runToolBar()->speedPicker()->currentData().toDouble(), 1.0);
    // Faster on either face of the key: Ctrl++, and Ctrl+= without Shift (in the viewport too,
    // where it leaves the grippers to the operator).
    QTest::keyClick(&window, Qt::Key_Plus, Qt::ControlModifier);
    QCOMPARE(window.engine().speed(), 2.0);
    window.viewport()->setFocus();
    QTest::keyClick(window.viewport(), Qt::Key_Equal, Qt::ControlModifier);
    QCOMPARE(window.engine().speed(), 4.0);
    QCOMPARE(window.runToolBar()->speedPicker()->currentData().toDouble(), 4.0);
    QVERIFY(!window.engine().isDriving());
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(window.engine().isRunning());

    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier);
    QVERIFY(window.engine().simTime() < 0.5);

    // Contact forces: Ctrl+F, the tool bar's button and the View menu's entry are the
    // viewport's one action, so each shows what the others did.
    QAction *forces = window.viewport()->showForcesAction();
    QToolButton *button = nullptr;
    for (QToolButton *b : window.runToolBar()->findChildren<QToolButton *>()) {
        if (b->defaultAction() == forces)
            button = b;
    }
    QVERIFY(button);
    QTest::keyClick(&window, Qt::Key_F, Qt::ControlModifier);
    QVERIFY(window.viewport()->showForces());
    QVERIFY(button->isChecked());
    QTest::mouseClick(button, Qt::LeftButton);
    QVERIFY(!window.viewport()->showForces());
    QVERIFY(!forces->isChecked());
    bool inViewMenu = false;
    for (QAction *menu : window.menuBar()->actions()) {
        if (menu->menu() && menu->menu()->actions().contains(forces))
            inViewMenu = true;
    }
    QVERIFY(inViewMenu);

    // Ctrl+, opens the preferences, as the manual says, on Linux too.
    QString opened;
    QTimer::singleShot(300, [&] {
        if (QWidget *dialog = QApplication::activeModalWidget()) {
            opened = dialog->objectName();
            dialog->close();
        }
    });
    QTest::keyClick(&window, Qt::Key_Comma, Qt::ControlModifier);
    QTRY_COMPARE(opened, QString("preferencesDialog"));
}

void TestStudio::pausedResetShowsTheScene()
{
    // Paused, then reset: the new run has not stepped, yet the viewport shows its scene.
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(!window.engine().isRunning());
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier);
    QCOMPARE(window.engine().simTime(), 0.0);
    QTest::qWait(500);
    auto *viewport = window.findChild<SimViewport *>();
    QString why;
    QVERIFY2(looksDrawn(viewport->grabFramebuffer(), &why), qPrintable(why));
    QCOMPARE(window.engine().simTime(), 0.0);
}

void TestStudio::timeWindowFollowsTheSpinBox()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    auto *spin = window.plots()->findChild<QAbstractSpinBox *>();
    QVERIFY(spin);
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, "30");
    QTest::keyClick(spin, Qt::Key_Enter);
    QTRY_COMPARE(window.plots()->windowSeconds(), 30.0);
    QVERIFY(window.engine().history().keepSeconds() >= 30.0);
}

void TestStudio::stopAllWorksFromAnywhere()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QVERIFY(window.engine().isRunning());
    // With the focus in a text field of a dock, Esc still stops everything.
    auto *filter = window.eventLog()->findChild<QLineEdit *>("filterText");
    QVERIFY(filter);
    filter->setFocus();
    QTest::keyClick(filter, Qt::Key_Escape);
    QVERIFY(!window.engine().isRunning());
    window.engine().run();
    QTest::mouseClick(window.findChild<QWidget *>("stopAllButton"), Qt::LeftButton);
    QVERIFY(!window.engine().isRunning());

    // A modal dialog has the keyboard: Esc there stops everything too, and closes it.
    window.engine().run();
    bool closed = false;
    QTimer::singleShot(0, this, [&closed] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        QWidget *dialog = QApplication::activeModalWidget();
        QTest::keyClick(dialog->focusWidget() ? dialog->focusWidget() : dialog, Qt::Key_Escape);
        QTest::qWait(200);
        closed = !dialog->isVisible();
        dialog->close(); // whatever happened, the test goes on
    });
    window.findChild<QAction *>("preferencesAction")->trigger();
    QVERIFY(closed);
    QVERIFY(!window.engine().isRunning());
    QVERIFY(window.statusBar()->currentMessage().startsWith("Stopped"));
}

void TestStudio::auditionShowsInTheReadouts_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << "en";
    QTest::newRow("de") << "de";
}

// An audition on a bound band plays alone (the run pauses), and its readouts show it: the
// Devices meters and the band's plot row draw what the band was sent — vib.rampup's ramp,
// after the paused run's time — and Stop all reads zero at once. Screenshots of both docks
// while it plays (beside the test binary, or in $SEMHAP_SCREENSHOTS).
void TestStudio::auditionShowsInTheReadouts()
{
    QFETCH(QString, language);
    Studio studio(options());
    studio.start();
    if (language != "en")
        studio.setLanguage(language);
    MainWindow &window = *studio.window();
    QVERIFY(openWindow(window)); // active: Esc is the window's shortcut
    // Past the first grasp (at 2.4 s), for the pictures.
    QTRY_VERIFY_WITH_TIMEOUT(window.engine().simTime() > 3.0, 20000);

    window.findChild<QDockWidget *>("patternsDock")->raise();
    WaveformDesigner *designer = window.waveformDesigner();
    designer->openBuiltin("vib.rampup"); // up to 1 in 0.5 s, then 0; released at 1.5 s
    QVERIFY(choose(designer->findChild<QComboBox *>("auditionDevice"), "right.vibro — lra4"));
    const SentLog &sent = window.engine().devices().transport("right.vibro")->sent();
    std::uint64_t next = sent.count();
    QTest::mouseClick(designer->findChild<QPushButton *>("auditionBegin"), Qt::LeftButton);
    QVERIFY(designer->auditioner()->isPlaying());
    QVERIFY(!window.engine().isRunning());
    const double paused = window.engine().simTime();
    window.findChild<QDockWidget *>("plotsDock")->raise();
    window.findChild<QDockWidget *>("devicesDock")->raise();

    auto *meter = window.findChild<LevelMeter *>("levels:right.vibro");
    QVERIFY(meter);
    QTRY_VERIFY_WITH_TIMEOUT(meter->values().at(0) > 0.6, 3000);

    // The band's row draws the frames the band was sent, one for one — the ramp, after the
    // run's time — and the axis goes on with it.
    auto *plot = window.plots()->findChild<QCustomPlot *>();
    QCPGraph *m1 = nullptr;
    for (int g = 0; g < plot->graphCount(); ++g) {
        if (plot->graph(g)->objectName() == "right.vibro.m1")
            m1 = plot->graph(g);
    }
    QVERIFY(m1);
    const auto drawnTo = [m1] { return (m1->data()->constEnd() - 1)->key; };
    QTRY_VERIFY(drawnTo() > paused + 0.5);
    QTRY_VERIFY(m1->keyAxis()->range().upper > paused + 0.5);
    const double drawn = drawnTo();
    std::vector<DeviceFrame> frames;
    sent.readSince(&next, &frames);
    // The run's last frames before the pause, the audition's, and those not drawn yet.
    const auto outside = [&](const DeviceFrame &f) { return f.t <= paused || f.t > drawn; };
    frames.erase(std::remove_if(frames.begin(), frames.end(), outside), frames.end());
    QVERIFY(!frames.empty());
    int compared = 0;
    for (auto it = m1->data()->findBegin(paused); it != m1->data()->constEnd(); ++it) {
        if (it->key <= paused)
            continue;
        const auto frame = std::find_if(frames.begin(), frames.end(),
                                        [&](const DeviceFrame &f) { return f.t == it->key; });
        QVERIFY2(frame != frames.end(), qPrintable(QString::number(it->key - paused)));
        QCOMPARE(it->value, frame->values[0]);
        ++compared;
    }
    QCOMPARE(compared, int(frames.size()));
    int ramp = 0;
    double previous = 0.0;
    for (const DeviceFrame &frame : frames) {
        if (frame.t > paused + 0.45)
            break;
        QVERIFY(frame.values[0] >= previous);
        QVERIFY2(std::abs(frame.values[0] - (frame.t - paused) / 0.5) < 0.1,
                 qPrintable(QString("%1 at %2 s").arg(frame.values[0]).arg(frame.t - paused)));
        previous = frame.values[0];
        ++ramp;
    }
    // The audition's timer runs on the GUI thread: how many frames a loaded machine manages.
    qInfo("%d frames in the ramp's first 0.45 s", ramp);
    QVERIFY(ramp >= 3);

    // Released at 1.5 s from its peak: the pictures show the whole shape and falling meters
    // (the Devices panel scrolled to the band, as a user would).
    for (QWidget *w = meter; w; w = w->parentWidget()) {
        if (auto *area = qobject_cast<QScrollArea *>(w)) {
            area->ensureWidgetVisible(meter);
            area->horizontalScrollBar()->setValue(0);
        }
    }
    QTRY_VERIFY_WITH_TIMEOUT(drawnTo() > paused + 1.6, 3000);
    // The release is drawn from the peak (what the meter shows at this moment depends on how
    // late this line runs on a loaded machine; the plot keeps it).
    double released = 0.0;
    for (auto it = m1->data()->findBegin(paused + 1.5); it != m1->data()->constEnd(); ++it) {
        if (it->key >= paused + 1.5 && it->key <= paused + 1.7)
            released = std::max(released, it->value);
    }
    QVERIFY2(released > 0.3, qPrintable(QString::number(released)));
    const QString dir = qEnvironmentVariableIsSet("SEMHAP_SCREENSHOTS")
                            ? qEnvironmentVariable("SEMHAP_SCREENSHOTS")
                            : QCoreApplication::applicationDirPath();
    QString error;
    QVERIFY2(Studio::screenshot(&window, QString("%1/studio-audition-%2.png").arg(dir, language),
                                &error),
             qPrintable(error));

    // Again, and Stop all mid-ramp: the band, its meters and its row are at rest at once.
    QTRY_VERIFY_WITH_TIMEOUT(!designer->auditioner()->isPlaying(), 3000);
    window.findChild<QDockWidget *>("patternsDock")->raise();
    QTest::mouseClick(designer->findChild<QPushButton *>("auditionBegin"), Qt::LeftButton);
    window.findChild<QDockWidget *>("plotsDock")->raise();
    QTRY_VERIFY_WITH_TIMEOUT(meter->values().at(0) > 0.3, 3000);
    QTest::keyClick(&window, Qt::Key_Escape);
    QVERIFY(!designer->auditioner()->isPlaying());
    QCOMPARE(meter->values(), std::vector<double>(4, 0.0));
    QCOMPARE((m1->data()->constEnd() - 1)->value, 0.0);
    QVERIFY(drawnTo() > paused + 2.0); // the second audition went on after the first

    // Step (F6) stops an audition too; the run goes on from its own time, and what the
    // auditions drew after it leaves the plots.
    window.findChild<QDockWidget *>("patternsDock")->raise();
    QTest::mouseClick(designer->findChild<QPushButton *>("auditionBegin"), Qt::LeftButton);
    QVERIFY(designer->auditioner()->isPlaying());
    QTest::keyClick(&window, Qt::Key_F6);
    QVERIFY(!designer->auditioner()->isPlaying());
    QTRY_VERIFY(window.engine().simTime() > paused);
    QTRY_VERIFY(drawnTo() > paused && drawnTo() <= window.engine().simTime());
    QVERIFY(m1->keyAxis()->range().upper <= window.engine().simTime());
}

void TestStudio::auditionPlaysOnASoundCard_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    QTest::newRow("1280x800") << QSize(1280, 800) << "en";
    QTest::newRow("1920x1080") << QSize(1920, 1080) << "en";
    QTest::newRow("1280x800-de") << QSize(1280, 800) << "de";
}

// A sound card in the Devices panel: listed with its channels and rate, typed into
// right.vibro's address box and connected, armed; an audition of vib.rampup plays on it
// through its transport (the card gets the 170 Hz carrier rising to full scale, the meter
// shows it), and Stop all (Esc) silences the card.
void TestStudio::auditionPlaysOnASoundCard()
{
    FifoCard card(m_fifo, 4);
    const std::unique_ptr<Studio> studio = startStudio(options());
    MainWindow &window = *studio->window();
    window.findChild<QDockWidget *>("devicesDock")->raise();
    DevicesPanel *devices = window.devicesPanel();
    const auto *present = devices->findChild<QTreeWidget *>("presentList");
    QTRY_VERIFY(!present->findItems("audio:semhaptest", Qt::MatchExactly, 1).isEmpty());
    auto *address = devices->findChild<QComboBox *>("uri:right.vibro");
    address->setFocus();
    address->lineEdit()->selectAll();
    QTest::keyClicks(address, "audio:semhaptest");
    QTest::mouseClick(devices->findChild<QWidget *>("connect:right.vibro"), Qt::LeftButton);
    QTRY_COMPARE(window.engine().devices().transport("right.vibro")->uri(), "audio:semhaptest");
    auto *state = devices->findChild<QLabel *>("state:right.vibro");
    QTRY_COMPARE_WITH_TIMEOUT(state->styleSheet().contains(colors::Ok.name()), true, 5000);
    QTest::mouseClick(devices->findChild<QPushButton *>("armAll"), Qt::LeftButton);

    window.findChild<QDockWidget *>("patternsDock")->raise();
    WaveformDesigner *designer = window.waveformDesigner();
    designer->openBuiltin("vib.rampup"); // up to 1 in 0.5 s, then 0; released at 1.5 s
    QVERIFY(choose(designer->findChild<QComboBox *>("auditionDevice"), "right.vibro — lra4"));
    const size_t before = card.frames();
    QTest::mouseClick(designer->findChild<QPushButton *>("auditionBegin"), Qt::LeftButton);
    QVERIFY(designer->auditioner()->isPlaying());
    window.findChild<QDockWidget *>("devicesDock")->raise();
    auto *meter = window.findChild<LevelMeter *>("levels:right.vibro");
    // The ramp is above 0.9 for only 50 ms: the meter, which shows the latest value the
    // card played, may well be between two polls then; the sent log behind it has them all.
    QTRY_VERIFY_WITH_TIMEOUT(meter->values().at(0) > 0.0, 3000);
    const Transport *transport = window.engine().devices().transport("right.vibro");
    std::uint64_t next = 0;
    std::vector<DeviceFrame> played;
    const auto peak = [&] {
        transport->sent().readSince(&next, &played);
        double high = 0.0;
        for (const DeviceFrame &f : played)
            high = std::max(high, f.values[0]);
        return high;
    };
    QTRY_VERIFY_WITH_TIMEOUT(peak() > 0.9, 3000);
    for (QWidget *w = meter; w; w = w->parentWidget()) {
        if (auto *area = qobject_cast<QScrollArea *>(w))
            area->ensureWidgetVisible(meter);
    }
    QFETCH(QString, language);
    QTRY_VERIFY(devices->findChild<QLabel *>("details:right.vibro")
                    ->text()
                    .contains(language == "de" ? "Latenz" : "latency"));
    savePicture(&window, "devices-audio");
    // The card's buffers hold what was played a few milliseconds longer.
    const auto cardPeak = [&card, before] {
        const std::vector<float> wave = card.channel(0, before);
        return wave.empty() ? 0.0f : *std::max_element(wave.begin(), wave.end());
    };
    QTRY_VERIFY(cardPeak() > 0.9f);

    // Stop all: the card falls silent at once, the meter reads zero.
    QTest::keyClick(&window, Qt::Key_Escape);
    QTRY_COMPARE(meter->values(), std::vector<double>(4, 0.0));
    const size_t stopped = card.frames();
    QTRY_VERIFY(card.frames() > stopped + 20000);
    const std::vector<float> after = card.channel(0, stopped + 10000);
    QCOMPARE(*std::max_element(after.begin(), after.end()), 0.0f);
}

void TestStudio::auditionPlaysOnTheReferenceBand_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    QTest::newRow("1280x800-de") << QSize(1280, 800) << "de";
}

// The reference band as a user with a Nano and four DRV2605L meets it — here its firmware
// image in simavr (`semhap bandsim lra4`): its port typed into right.vibro's address box
// and connected (the band says it is an lra4), armed, vib.geiger auditioned: the drivers
// pulse; Stop all (Esc) and they are still.
void TestStudio::auditionPlaysOnTheReferenceBand()
{
    QTemporaryDir dir;
    const QString link = dir.filePath("nano");
    const QString log = dir.filePath("nano.jsonl");
    BandProcess band({"bandsim", "lra4", "--pty", "--link", link, "--log", log});
    QVERIFY(band.started());
    const std::unique_ptr<Studio> studio = startStudio(options());
    MainWindow &window = *studio->window();
    window.findChild<QDockWidget *>("devicesDock")->raise();
    DevicesPanel *devices = window.devicesPanel();
    auto *address = devices->findChild<QComboBox *>("uri:right.vibro");
    address->setFocus();
    address->lineEdit()->selectAll();
    QTest::keyClicks(address, "serial:" + link);
    QTest::mouseClick(devices->findChild<QWidget *>("connect:right.vibro"), Qt::LeftButton);
    const Transport *transport = window.engine().devices().transport("right.vibro");
    QTRY_COMPARE(transport->uri(), "serial:" + link);
    QTRY_COMPARE_WITH_TIMEOUT(transport->status().identity, QStringLiteral("lra4"), 5000);
    QTest::mouseClick(devices->findChild<QPushButton *>("armAll"), Qt::LeftButton);

    window.findChild<QDockWidget *>("patternsDock")->raise();
    WaveformDesigner *designer = window.waveformDesigner();
    designer->openBuiltin("vib.geiger");
    QVERIFY(choose(designer->findChild<QComboBox *>("auditionDevice"), "right.vibro — lra4"));
    QTest::mouseClick(designer->findChild<QPushButton *>("auditionBegin"), Qt::LeftButton);
    // Three pulses at the drivers: the firmware drives every channel to 1 and back.
    QTRY_VERIFY_WITH_TIMEOUT(pulseStarts(readBandLog(log), 0).size() >= 3, 5000);
    window.findChild<QDockWidget *>("devicesDock")->raise();
    auto *meter = window.findChild<LevelMeter *>("levels:right.vibro");
    for (QWidget *w = meter; w; w = w->parentWidget()) {
        if (auto *area = qobject_cast<QScrollArea *>(w))
            area->ensureWidgetVisible(meter);
    }
    savePicture(&window, "devices-band");
    QTest::keyClick(&window, Qt::Key_Escape);
    QTRY_VERIFY(allAt(readBandLog(log).back(), 0.0));
    QTest::qWait(300); // no pulse after Stop all
    QVERIFY(allAt(readBandLog(log).back(), 0.0));
}

// The readouts show what the bands were sent: disarmed (Devices → Disarm all), the router's
// requests on a grasp reach the meters and plots as zeros; armed again, they show.
void TestStudio::disarmedBandsReadZero()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    window.findChild<QDockWidget *>("devicesDock")->raise();
    QTest::mouseClick(window.findChild<QPushButton *>("disarmAll"), Qt::LeftButton);
    const double disarmed = window.engine().simTime();
    // The highest level a meter shows now or a device's plot row drew after `from`.
    const auto shown = [&window](double from) {
        double high = 0.0;
        auto *plot = window.plots()->findChild<QCustomPlot *>();
        for (int g = 0; g < plot->graphCount(); ++g) {
            const QString id = plot->graph(g)->objectName();
            const auto &devices = window.engine().history().devices();
            if (std::none_of(devices.begin(), devices.end(),
                             [&](const RunDevice &d) { return id.startsWith(d.name + '.'); }))
                continue;
            for (auto it = plot->graph(g)->data()->findBegin(from);
                 it != plot->graph(g)->data()->constEnd(); ++it)
                high = std::max(high, it->key > from ? it->value : 0.0);
        }
        for (LevelMeter *meter : window.findChildren<LevelMeter *>()) {
            for (double value : meter->values())
                high = std::max(high, value);
        }
        return high;
    };
    // The scripted operator grasps (C3 confirms it on the right band) and lets go.
    const auto grasps = [&window] {
        int count = 0;
        for (const MessageSpan &span : window.engine().history().spans())
            count += span.message == Message::Grasp ? 1 : 0;
        return count;
    };
    QTRY_VERIFY_WITH_TIMEOUT(grasps() > 0, 30000);
    QTest::qWait(1000);
    QCOMPARE(shown(disarmed + 0.1), 0.0);
    QTest::mouseClick(window.findChild<QPushButton *>("armAll"), Qt::LeftButton);
    const double armed = window.engine().simTime();
    QTRY_VERIFY_WITH_TIMEOUT(shown(armed) > 0.1, 30000);
}

void TestStudio::driveShowsTheGhostAtOnce_data()
{
    addWindowRows();
}

void TestStudio::driveShowsTheGhostAtOnce()
{
    // Ctrl+T takes the grippers from the scripted operator: the wrist target's ghost shows at
    // once, where the hand is, before any drive key and before any step; the run's next step
    // finds the surface its drop line reaches. (Before, nothing showed until the first key:
    // the drive had not started, and a ghost at the wrist hid inside the palm.)
    StudioOptions o = options();
    o.autoRun = false; // the hand where the scene starts it, in the view's near half
    const std::unique_ptr<Studio> studio = startStudio(o);
    MainWindow &window = *studio->window();
    SimViewport *viewport = window.viewport();
    auto *drive = window.findChild<HandDrive *>();
    QTRY_VERIFY(viewport->renderedFrames() > 0);
    const int scripted = ghostPixels(viewport->grabFramebuffer());
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_T, Qt::ControlModifier);
    QVERIFY(window.engine().isDriving());
    QTRY_VERIFY_WITH_TIMEOUT(ghostPixels(viewport->grabFramebuffer()) > scripted + 300, 1000);
    qInfo("ghost pixels: %d scripted, %d right after Ctrl+T", scripted,
          ghostPixels(viewport->grabFramebuffer()));
    // The target is where the hand is: taking the grippers moved nothing.
    const Pose wrist = window.engine().world()->gripperPose(Gripper::Right);
    const Pose target = drive->command(Gripper::Right)->target;
    for (size_t axis = 0; axis < 3; ++axis)
        QVERIFY2(std::abs(wrist.pos[axis] - target.pos[axis]) < 0.01,
                 qPrintable(QString("axis %1: wrist %2, target %3")
                                .arg(axis)
                                .arg(wrist.pos[axis])
                                .arg(target.pos[axis])));

    // Running, the operator has the target: its first step finds the surface below.
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(window.engine().isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(drive->status(Gripper::Right).surface.has_value(), 1000);
    QTest::qWait(100);
    savePicture(&window, "drive-ghost");
}

void TestStudio::followKeepsTheHandInView_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("hand");
    QTest::addColumn<bool>("drive");
    QTest::addColumn<double>("x"); // where the target goes (driving) or must pass (scripted)
    QTest::addColumn<double>("z");
    const int left = int(Gripper::Left);
    const int right = int(Gripper::Right);
    // Box B is on the far side of the partition (x > 0) from the first view.
    QTest::newRow("box_and_block, driven down into box B")
        << "box_and_block" << right << true << 0.16 << 0.07;
    QTest::newRow("box_and_block, scripted over box B")
        << "box_and_block" << right << false << 0.08 << 0.2;
    QTest::newRow("bimanual_sorting, right hand down to the cubes")
        << "bimanual_sorting" << right << true << 0.2 << 0.1;
    QTest::newRow("bimanual_sorting, left hand across to the right")
        << "bimanual_sorting" << left << true << 0.05 << 0.12;
}

void TestStudio::followKeepsTheHandInView()
{
    // Key 4 follows the active hand wherever it goes: it stays in the picture, and not
    // behind the partition (before, the view stayed where the hand had started while the
    // scripted operator drove, and looked at box B through the partition from box A).
    QFETCH(QString, scene);
    QFETCH(int, hand);
    QFETCH(bool, drive);
    QFETCH(double, x);
    QFETCH(double, z);
    StudioOptions o = options();
    o.run.scene = scene;
    Workspace workspace;
    MainWindow window(workspace, o);
    QVERIFY(openWindow(window));
    SimViewport *viewport = window.viewport();
    auto *handDrive = window.findChild<HandDrive *>();
    QTRY_VERIFY(viewport->renderedFrames() > 0);
    viewport->setFocus();
    if (drive) {
        QTest::keyClick(viewport, Qt::Key_T, Qt::ControlModifier);
        QVERIFY(window.engine().isDriving());
        if (Gripper(hand) != handDrive->activeHand())
            QTest::keyClick(viewport, Qt::Key_Tab);
        QCOMPARE(int(handDrive->activeHand()), hand);
    }
    QTest::keyClick(viewport, Qt::Key_4);
    QCOMPARE(viewport->cameraPreset(), CameraPreset::Follow);
    if (drive) {
        const QString across = driveTo(viewport, handDrive, 0, x);
        QVERIFY2(across.isEmpty(), qPrintable(across));
        const QString down = driveTo(viewport, handDrive, 2, z);
        // What is below (a stack, the other hand's container) may stop it first.
        QVERIFY2(down.isEmpty() || handDrive->status(Gripper(hand)).floor, qPrintable(down));
        QTest::qWait(600); // the hand follows its target
    } else {
        auto there = [&window, hand, x, z] {
            const auto commands = window.engine().handCommands();
            const Pose &target = commands[size_t(hand)]->target;
            return target.pos[0] > x && target.pos[2] < z;
        };
        QTRY_VERIFY_WITH_TIMEOUT(there(), 30000);
    }
    window.engine().pause();
    QTest::qWait(100); // the last picture and the view that follows it
    if (const QString folder = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !folder.isEmpty())
        viewport->grabFramebuffer().save(
            QString("%1/follow-%2.png")
                .arg(folder, QString(QTest::currentDataTag()).replace(", ", "-"))
                .replace(' ', '_'));

    const Pose wrist = window.engine().world()->gripperPose(Gripper(hand));
    const std::array<double, 3> pads{wrist.pos[0], wrist.pos[1], wrist.pos[2] - 0.06};
    // In the middle of the picture.
    const QRectF inner = QRectF(QPointF(), QSizeF(viewport->size()))
                             .adjusted(0.25 * viewport->width(), 0.25 * viewport->height(),
                                       -0.25 * viewport->width(), -0.25 * viewport->height());
    for (const auto &point : {wrist.pos, pads}) {
        const std::optional<QPointF> at = projected(viewport->camera(), point, viewport->size());
        QVERIFY2(at && inner.contains(*at),
                 qPrintable(QString("(%1, %2, %3) shows at (%4, %5) of %6x%7")
                                .arg(point[0])
                                .arg(point[1])
                                .arg(point[2])
                                .arg(at ? at->x() : qQNaN())
                                .arg(at ? at->y() : qQNaN())
                                .arg(viewport->width())
                                .arg(viewport->height())));
    }
    // Nothing stands between the eye and the hand: not the partition (box_and_block's, as
    // resources/scenes/box_and_block.xml places it), not the other hand's palm (its box in
    // the scenes, turned as the hand is). Boxes in their own frames: centre, half sizes, and
    // the rotation (w, x, y, z) of their axes.
    struct Obstacle
    {
        std::array<double, 3> centre;
        std::array<double, 3> half;
        std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0};
    };
    std::vector<Obstacle> obstacles;
    if (scene == "box_and_block")
        obstacles.push_back({{0.0, 0.0, 0.075}, {0.005, 0.14, 0.075}});
    const Gripper other = Gripper(hand) == Gripper::Left ? Gripper::Right : Gripper::Left;
    if (window.engine().world()->hasGripper(other)) {
        const Pose there = window.engine().world()->gripperPose(other);
        // The scenes' <hand>.palm: bimanual_sorting's left palm is the wider one.
        const double halfWidth = other == Gripper::Left ? 0.092 : 0.057;
        obstacles.push_back({there.pos, {0.03, halfWidth, 0.012}, there.quat});
    }
    const QVector3D eye = eyeOf(viewport->camera());
    for (const auto &point : {wrist.pos, pads}) {
        for (const Obstacle &box : obstacles) {
            const auto &[w, qx, qy, qz] = box.quat;
            // The rows of the box's rotation: a world offset turns into its own frame.
            const std::array<std::array<double, 3>, 3> rows{
                {{1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + w * qz), 2 * (qx * qz - w * qy)},
                 {2 * (qx * qy - w * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz + w * qx)},
                 {2 * (qx * qz + w * qy), 2 * (qy * qz - w * qx), 1 - 2 * (qx * qx + qy * qy)}}};
            bool hidden = false;
            for (int k = 0; k < 500 && !hidden; ++k) {
                const double f = k / 500.0;
                std::array<double, 3> offset{};
                for (size_t axis = 0; axis < 3; ++axis)
                    offset[axis] =
                        eye[int(axis)] + f * (point[axis] - eye[int(axis)]) - box.centre[axis];
                bool inside = true;
                for (size_t axis = 0; axis < 3; ++axis) {
                    const auto &r = rows[axis];
                    const double local = r[0] * offset[0] + r[1] * offset[1] + r[2] * offset[2];
                    inside = inside && std::abs(local) < box.half[axis];
                }
                hidden = inside;
            }
            QVERIFY2(!hidden, qPrintable(QString("(%1, %2, %3) is hidden behind (%4, %5, %6)")
                                             .arg(point[0])
                                             .arg(point[1])
                                             .arg(point[2])
                                             .arg(box.centre[0])
                                             .arg(box.centre[1])
                                             .arg(box.centre[2])));
        }
    }
}

void TestStudio::statusBarCountsDevicesAsThePanelShowsThem_data()
{
    QTest::addColumn<QString>("band"); ///< what answers at the address
    QTest::addColumn<QString>("state");
    QTest::addColumn<QString>("status");
    QTest::newRow("nothing answers") << "silent"
                                     << "connecting"
                                     << "Devices: 6 virtual, 0 connected, 1 connecting";
    QTest::newRow("an emulated band") << "emulated"
                                      << "connected"
                                      << "Devices: 6 virtual, 1 connected";
    QTest::newRow("no such port") << "none"
                                  << "disconnected"
                                  << "Devices: 6 virtual, 0 connected, 1 disconnected";
}

// right.air bound in the Devices panel to a UDP address where nothing answers, to an emulated
// band, or to a serial port that is not there: the status bar counts it in the state the
// panel shows it in (a band that never answered is not connected).
void TestStudio::statusBarCountsDevicesAsThePanelShowsThem()
{
    QFETCH(QString, band);
    QFETCH(QString, state);
    QFETCH(QString, status);
    QUdpSocket silent; // listens and never answers
    EmulatedBand emulated("pneumatic6");
    QString uri = "serial:/dev/semhap-no-such-port";
    if (band == "silent") {
        QVERIFY(silent.bind(QHostAddress::LocalHost, 0));
        uri = QString("udp:127.0.0.1:%1").arg(silent.localPort());
    } else if (band == "emulated") {
        QString error;
        QVERIFY2(emulated.start(&error), qPrintable(error));
        uri = emulated.uri();
    }
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    window.findChild<QDockWidget *>("devicesDock")->raise();
    DevicesPanel *devices = window.devicesPanel();
    auto *choice = devices->findChild<QComboBox *>("uri:right.air");
    choice->setFocus();
    choice->lineEdit()->selectAll();
    QTest::keyClicks(choice, uri);
    QTest::mouseClick(devices->findChild<QWidget *>("connect:right.air"), Qt::LeftButton);
    QTRY_COMPARE(window.engine().devices().transport("right.air")->uri(), uri);
    auto *shown = devices->findChild<QLabel *>("state:right.air");
    QTRY_COMPARE_WITH_TIMEOUT(shown->text(), state, 5000);
    QTest::qWait(1000); // a band that answers would have answered by now
    QCOMPARE(shown->text(), state);
    QTRY_COMPARE(window.findChild<QLabel *>("devicesLabel")->text(), status);
}

void TestStudio::drivingOverlayShowsTheAppliedGrip_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    QTest::newRow("1280x800") << QSize(1280, 800) << "en";
    QTest::newRow("1280x800-de") << QSize(1280, 800) << "de";
}

// The overlay's grip line says what the simulation applies: closing on nothing, the guarded
// close holds the fingers to their approach force, and the line gives it with the force asked
// for ("Grip: 6 N of 30 N"); closed on a cube, the grip reaches the command and the line says
// so. Before, it said "closed, 30 N" from the moment Space was pressed.
void TestStudio::drivingOverlayShowsTheAppliedGrip()
{
    StudioOptions o = options();
    o.autoRun = false; // the hand where the scene starts it, above the pile
    const std::unique_ptr<Studio> studio = startStudio(o);
    MainWindow &window = *studio->window();
    SimViewport *viewport = window.viewport();
    auto *drive = window.findChild<HandDrive *>();
    Engine &engine = window.engine();
    const World &world = *engine.world();
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_T, Qt::ControlModifier);
    QVERIFY(engine.isDriving());
    const Gripper hand = drive->activeHand();
    const double start = drive->command(hand)->target.pos[1];
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(engine.isRunning());
    const QLocale locale;
    auto newtons = [&locale](double force) -> QString {
        return locale.toString(force, 'f', 0) + " N";
    };
    const QString asked = newtons(drive->gripSetpoint(hand));
    // The line under the title; the numbers of it are checked once the run is paused, when the
    // world's grip is the one the overlay was drawn from.
    auto gripLine = [viewport] {
        viewport->update();
        QTest::qWait(50);
        return viewport->overlayText().section(QLatin1Char('\n'), 1, 1);
    };

    // Closed in the air: the fingers meet with nothing between them.
    QTest::keyClick(viewport, Qt::Key_Space);
    QTRY_COMPARE(drive->command(hand)->grip, drive->gripSetpoint(hand));
    QTest::qWait(300);
    engine.pause();
    const double approach = world.closingForce(hand, DriveOperator::ClosingSpeed);
    QCOMPARE(world.grip(hand), approach);
    QVERIFY(approach < drive->gripSetpoint(hand) - 1);
    savePicture(&window, "driving-closing");
    const QString closing = gripLine();
    const qsizetype applied = closing.indexOf(newtons(approach));
    QVERIFY2(applied >= 0 && closing.indexOf(asked, applied + 1) > applied,
             qPrintable(QString("%1\nhas not %2 of %3").arg(closing, newtons(approach), asked)));

    // Open, beside the pile's middle cube, down onto the pile and closed: a cube is held.
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(engine.isRunning());
    QTest::keyClick(viewport, Qt::Key_Space);
    QTRY_COMPARE(drive->command(hand)->grip, HandDrive::OpenGrip);
    const QString across = driveTo(viewport, drive, 1, start - 0.06);
    QVERIFY2(across.isEmpty(), qPrintable(across));
    driveTo(viewport, drive, 2, 0.0);
    QVERIFY(drive->status(hand).floor);
    QTest::keyClick(viewport, Qt::Key_Space);
    QTRY_VERIFY2_WITH_TIMEOUT(drive->status(hand).grip == drive->gripSetpoint(hand),
                              qPrintable(QString("grip %1 of %2; between the fingers: %3; the "
                                                 "target %4 m across of %5")
                                             .arg(drive->status(hand).grip.value_or(-1))
                                             .arg(drive->gripSetpoint(hand))
                                             .arg(world.objectBetween(hand))
                                             .arg(drive->command(hand)->target.pos[1] - start)
                                             .arg(-0.06)),
                              10000);
    engine.pause();
    QVERIFY(world.objectBetween(hand) >= 0);
    QCOMPARE(world.grip(hand), drive->gripSetpoint(hand));
    const QString held = gripLine();
    QVERIFY2(held.count(asked) == 1 && !held.contains(newtons(approach)), qPrintable(held));
    savePicture(&window, "driving-holding");
}

void TestStudio::handingBackNeverStrikes_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    QTest::newRow("1280x800") << QSize(1280, 800) << "en";
}

void TestStudio::handingBackNeverStrikes()
{
    // Issue 33, D3: taken over on the way down to a cube, driven over box B and handed back,
    // the scripted operator resumed the move it had begun and jumped its target back to the
    // cube: the fingertips struck the pile with about 2000 N, counted as a grasp. It starts
    // from where the hand is now.
    const std::unique_ptr<Studio> studio = startStudio(options());
    MainWindow &window = *studio->window();
    SimViewport *viewport = window.viewport();
    auto *drive = window.findChild<HandDrive *>();
    Engine &engine = window.engine();
    QTRY_VERIFY_WITH_TIMEOUT(engine.simTime() > 1.6, 20000); // going down to the first cube
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_T, Qt::ControlModifier);
    QVERIFY(engine.isDriving());
    const double takenAt = engine.simTime();
    const QString up = driveTo(viewport, drive, 2, 0.25);
    QVERIFY2(up.isEmpty(), qPrintable(up));
    const QString over = driveTo(viewport, drive, 0, 0.15);
    QVERIFY2(over.isEmpty(), qPrintable(over));
    if (drive->command(Gripper::Right)->grip > 0)
        QTest::keyClick(viewport, Qt::Key_Space);
    QTest::keyClick(viewport, Qt::Key_T, Qt::ControlModifier);
    QVERIFY(!engine.isDriving());
    const double backAt = engine.simTime();
    QTRY_VERIFY_WITH_TIMEOUT(engine.simTime() > backAt + 3.0, 20000);
    engine.pause();
    const RunSeries<ContactFrame> &frames = engine.history().frames(Gripper::Right);
    double peak = 0.0;
    double peakAt = 0.0;
    for (qint64 i = frames.begin(); i < frames.end(); ++i) {
        const ContactFrame &frame = frames.at(i);
        const double force = std::max(frame.left.f, frame.right.f);
        if (frame.t >= takenAt && force > peak) {
            peak = force;
            peakAt = frame.t;
        }
    }
    QVERIFY(frames.at(frames.begin()).t < takenAt);
    // What a grip makes, never a strike: the scripted grips average 60 N (both fingers).
    QVERIFY2(peak < 100.0, qPrintable(QString("%1 N at %2 s (taken over at %3 s, handed back at "
                                              "%4 s)")
                                          .arg(peak)
                                          .arg(peakAt)
                                          .arg(takenAt)
                                          .arg(backAt)));
}

void TestStudio::drivingPreferencesApply()
{
    // Preferences → Driving: a new wrist speed and a remapped gamepad control reach the
    // window's drive and gamepad at once, and are there again in the next window.
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QTimer::singleShot(0, this, [] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        auto *dialog = qobject_cast<PreferencesDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        auto *tabs = dialog->findChild<QTabWidget *>("preferencesTabs");
        const QString folder = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
        if (!folder.isEmpty())
            dialog->grab().save(folder + "/preferences-general.png");
        tabs->setCurrentIndex(1);
        if (!folder.isEmpty())
            dialog->grab().save(folder + "/preferences-driving.png");
        auto *speed = dialog->findChild<QDoubleSpinBox *>("driveSpeed");
        speed->selectAll();
        QTest::keyClicks(speed, "25");
        QComboBox *turn = dialog->gamepadControl(GamepadMapping::Turn);
        turn->setFocus();
        while (turn->currentData().toString() != "leftshoulder+rightshoulder")
            QTest::keyClick(turn, Qt::Key_Down);
        QTest::keyClick(dialog, Qt::Key_Return);
    });
    window.findChild<QAction *>("preferencesAction")->trigger();
    QCOMPARE(window.findChild<HandDrive *>()->speed(), 0.25);
    QCOMPARE(window.findChild<GamepadInput *>()->mapping().motions[GamepadMapping::Turn],
             QString("leftshoulder+rightshoulder"));
    Workspace againWorkspace;
    MainWindow again(againWorkspace, options());
    QCOMPARE(again.findChild<HandDrive *>()->speed(), 0.25);
    QCOMPARE(again.findChild<GamepadInput *>()->mapping().motions[GamepadMapping::Turn],
             QString("leftshoulder+rightshoulder"));
    TeleopSettings().save(); // the defaults again for the other tests
}

namespace {

/** Turns Preferences → General → Publish to Foxglove on (on `port`) or off, as a person does. */
void setPublishing(MainWindow &window, bool on, int port = 0)
{
    QTimer::singleShot(0, &window, [on, port] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        auto *dialog = qobject_cast<PreferencesDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        auto *publish = dialog->findChild<QCheckBox *>("publishToFoxglove");
        if (publish->isChecked() != on)
            QTest::mouseClick(publish, Qt::LeftButton, {}, QPoint(8, publish->height() / 2));
        QCOMPARE(publish->isChecked(), on);
        if (on) {
            auto *spin = dialog->findChild<QSpinBox *>("foxglovePort");
            QVERIFY(spin->isEnabled());
            spin->setFocus();
            spin->selectAll();
            QTest::keyClicks(spin, QString::number(port));
        }
        const QString folder = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
        if (!folder.isEmpty())
            dialog->grab().save(folder + "/preferences-foxglove.png");
        QTest::keyClick(dialog, Qt::Key_Return);
    });
    window.findChild<QAction *>("preferencesAction")->trigger();
}

} // namespace

void TestStudio::publishesToFoxglove()
{
    // Off until turned on; then Foxglove's client watches the run, every message decoded.
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QVERIFY(!window.engine().isPublishing());
    auto *label = window.findChild<QLabel *>("foxgloveLabel");
    QVERIFY(!label->isVisible());
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
    const int port = probe.serverPort();
    probe.close();
    setPublishing(window, true, port);
    const QString url = QStringLiteral("ws://127.0.0.1:%1").arg(port);
    QCOMPARE(window.engine().publishingUrl(), url);
    QTRY_VERIFY(label->isVisible());
    QProcess viewer;
    startViewer(viewer, url);
    const QByteArray said = waitForViewer(viewer, "subscribed /semhap/right/contact");
    QVERIFY2(said.contains("subscribed /semhap/right/contact"), said.constData());
    QTRY_COMPARE(label->text(), QString("Foxglove: 1 viewer(s)"));
    QVERIFY(window.engine().isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(window.engine().publishingStats().sent > 2000, 30000);
    QVERIFY2(label->toolTip().startsWith("Published at " + url), qPrintable(label->toolTip()));
    savePicture(&window, "foxglove-status");

    // Turned off: the viewer is served what waited for it, and told goodbye.
    setPublishing(window, false);
    QVERIFY(!window.engine().isPublishing());
    QTRY_VERIFY(!label->isVisible());
    const QJsonObject view = viewed(viewer);
    QCOMPARE(view["serverInfo"].toString(), QString("semhap studio"));
    QCOMPARE(view["undecoded"].toInt(), 0);
    const QJsonObject topics = view["topics"].toObject();
    QVERIFY2(topics["/semhap/right/contact"].toObject()["count"].toInt() > 100,
             QJsonDocument(view).toJson().constData());
    QCOMPARE(topics["/semhap/right/left/wrench"].toObject()["type"].toString(),
             QString("geometry_msgs/msg/WrenchStamped"));
    QVERIFY(topics.contains("/semhap/devices/right.vibro"));
}

void TestStudio::aKeyInTheViewportTakesOver()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    auto *teleop = window.findChild<QAction *>("driveAction");
    QVERIFY(!teleop->isChecked());
    window.viewport()->setFocus();
    QTest::keyPress(window.viewport(), Qt::Key_W);
    QTest::qWait(100);
    QTest::keyRelease(window.viewport(), Qt::Key_W);
    QTRY_VERIFY(window.engine().isDriving());
    QVERIFY(teleop->isChecked());
    QTRY_COMPARE(window.findChild<QLabel *>("operatorLabel")->text(), QString("You are driving"));
    // The toolbar toggle hands the grippers back.
    teleop->trigger();
    QVERIFY(!window.engine().isDriving());
}

void TestStudio::drivingOverlayLeavesTheHandInSight_data()
{
    addWindowRows();
}

namespace {

/**
 * Where a point of the world shows in `viewport`, as MuJoCo's free camera sees it (the test's
 * own reckoning, checked against the ghost's pixels); false behind the camera.
 */
bool shownAt(const SimViewport &viewport, const std::array<double, 3> &point, QPointF *shown)
{
    using Vec = std::array<double, 3>;
    const auto dot = [](const Vec &a, const Vec &b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const auto cross = [](const Vec &a, const Vec &b) {
        return Vec{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                   a[0] * b[1] - a[1] * b[0]};
    };
    const OrbitCamera &camera = viewport.camera();
    const double az = qDegreesToRadians(camera.azimuth);
    const double el = qDegreesToRadians(camera.elevation);
    // The camera sits `distance` back from lookAt along its view direction, level.
    const Vec view{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
    Vec side = cross(view, {0, 0, 1});
    const double length = std::sqrt(dot(side, side));
    for (double &c : side)
        c /= length;
    const Vec up = cross(side, view);
    Vec v{};
    for (size_t i = 0; i < 3; ++i)
        v[i] = point[i] - (camera.lookAt[i] - camera.distance * view[i]);
    const double depth = dot(v, view);
    if (depth <= 0)
        return false;
    const double focal = viewport.height() / 2.0 / std::tan(qDegreesToRadians(45.0 / 2));
    *shown = QPointF(viewport.width() / 2.0 + dot(v, side) * focal / depth,
                     viewport.height() / 2.0 - dot(v, up) * focal / depth);
    return true;
}

} // namespace

// Driving in each camera view (keys 1–4), the box saying who drives leaves the hand in sight:
// the wrist target's ghost, the fingers under it and the drop line to the surface are not
// under it (it covered the gripper in the default view at 1280×800). Its numbers are the
// interface language's (German had "25.9 cm" among commas).
void TestStudio::drivingOverlayLeavesTheHandInSight()
{
    // The grippers taken at the start, where they wait above the pile, and raised a little:
    // a long drop line, with nothing in front of it.
    StudioOptions o = options();
    o.autoRun = false;
    const std::unique_ptr<Studio> studio = startStudio(o);
    MainWindow &window = *studio->window();
    QVERIFY(window.isActiveWindow());
    SimViewport *viewport = window.viewport();
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_R);
    QTRY_VERIFY(window.engine().isDriving());
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(window.engine().isRunning());
    QTest::keyPress(viewport, Qt::Key_R);
    QTest::qWait(500);
    QTest::keyRelease(viewport, Qt::Key_R);
    HandDrive *drive = viewport->handDrive();
    const char *names[] = {"jaws", "top", "side", "follow"};
    for (int preset = 0; preset < CameraPresetCount; ++preset) {
        QTest::keyClick(viewport, Qt::Key(Qt::Key_1 + preset));
        QTest::qWait(400);
        const QImage picture = viewport->grabFramebuffer();
        savePicture(&window, QString("driving-%1").arg(names[preset]));
        const DriveStatus status = drive->status(drive->activeHand());
        QVERIFY(status.driven && status.surface);
        const auto &t = status.target.pos;
        // The wrist target, the fingertips 12 cm under it, the drop line's foot.
        const std::array<double, 3> points[] = {
            t, {t[0], t[1], t[2] - 0.12}, {t[0], t[1], *status.surface}};
        // The reckoning is the picture's: the ghost and its drop line are cyan, along the
        // line from the target down to the surface (whose foot a box wall may hide).
        QRect ghost;
        for (int y = 0; y < picture.height(); ++y) {
            for (int x = 0; x < picture.width(); ++x) {
                const QColor c = picture.pixelColor(x, y);
                if (c.blue() > 150 && c.green() > 120 && c.red() < c.green() - 40)
                    ghost |= QRect(x, y, 1, 1);
            }
        }
        const qreal ratio = picture.width() / qreal(viewport->width());
        int onTheLine = 0;
        for (int step = 0; step <= 50; ++step) {
            const double z = t[2] + (*status.surface - t[2]) * step / 50;
            QPointF shown;
            if (shownAt(*viewport, {t[0], t[1], z}, &shown))
                onTheLine += ghost.adjusted(-2, -2, 2, 2).contains((shown * ratio).toPoint());
        }
        QVERIFY2(onTheLine > 0,
                 qPrintable(QString("%1: the line from the target to the surface misses the "
                                    "cyan in %2,%3 %4x%5")
                                .arg(names[preset])
                                .arg(ghost.x())
                                .arg(ghost.y())
                                .arg(ghost.width())
                                .arg(ghost.height())));
        // It gives the height in the interface language's numbers (25,9 in German).
        const QString height = QLocale().toString((t[2] - *status.surface) * 100, 'f', 1);
        QVERIFY2(viewport->overlayText().contains(height + " cm"),
                 qPrintable(viewport->overlayText() + "\nhas no " + height));
        const QRectF box = viewport->overlayBox();
        QVERIFY(!box.isEmpty());
        for (const auto &point : points) {
            QPointF shown;
            QVERIFY(shownAt(*viewport, point, &shown));
            QVERIFY2(!box.contains(shown),
                     qPrintable(QString("%1: the box %2,%3 %4x%5 covers %6,%7")
                                    .arg(names[preset])
                                    .arg(box.x())
                                    .arg(box.y())
                                    .arg(box.width())
                                    .arg(box.height())
                                    .arg(shown.x())
                                    .arg(shown.y())));
        }
    }
}

void TestStudio::eventLogMovesThePlotCursor()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QTRY_VERIFY_WITH_TIMEOUT(window.eventLog()->model()->rowCount() > 0, 30000);
    window.engine().pause();
    QTableView *table = window.eventLog()->findChild<QTableView *>("eventTable");
    QVERIFY(table);
    window.findChild<QDockWidget *>("eventsDock")->raise();
    const QModelIndex first = table->model()->index(0, 1);
    const QRect cell = table->visualRect(first);
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
    QTRY_VERIFY(window.plots()->isPaused());
    const double t = first.data(EventLogModel::TimeRole).toDouble();
    QCOMPARE(window.plots()->cursorTime(), t);
}

void TestStudio::layoutIsSavedAndRestored()
{
    StudioOptions o = options();
    {
        Workspace workspace;
        MainWindow window(workspace, o);
        QVERIFY(openWindow(window));
        window.findChild<QDockWidget *>("metricsDock")->close();
        // The views' settings come back with the layout.
        window.viewport()->setFocus();
        QTest::keyClick(window.viewport(), Qt::Key_3);
        QCOMPARE(window.viewport()->cameraPreset(), CameraPreset::Side);
        window.plots()->setWindowSeconds(45);
        window.close();
    }
    Workspace workspace;
    MainWindow window(workspace, o);
    QVERIFY(openWindow(window));
    QVERIFY(window.findChild<QDockWidget *>("metricsDock")->isHidden());
    QCOMPARE(window.viewport()->cameraPreset(), CameraPreset::Side);
    QCOMPARE(window.plots()->findChild<QSpinBox *>()->value(), 45);
    QVERIFY(!window.findChild<QDockWidget *>("plotsDock")->isHidden());
    window.findChild<QAction *>("resetLayoutAction")->trigger();
    QVERIFY(!window.findChild<QDockWidget *>("metricsDock")->isHidden());
}

void TestStudio::switchesToGerman()
{
    Studio studio(options());
    studio.start();
    QCOMPARE(studio.language(), QString("en"));
    QVERIFY(QTest::qWaitForWindowExposed(studio.window()));
    QCOMPARE(studio.window()->findChild<QDockWidget *>("plotsDock")->windowTitle(),
             QString("Plots"));
    pickLanguage(studio, "de");
    QCOMPARE(studio.language(), QString("de"));
    QCOMPARE(PreferencesDialog::savedLanguage(), QString("de"));
    MainWindow *window = studio.window();
    QCOMPARE(window->findChild<QDockWidget *>("plotsDock")->windowTitle(), QString("Diagramme"));
    QCOMPARE(window->findChild<QAction *>("stopAllAction")->text(), QString("Alles stoppen"));
    QCOMPARE(window->findChild<QDockWidget *>("eventsDock")->windowTitle(), QString("Ereignisse"));
    // Qt's own words too: a dialog's standard buttons.
    QString cancel;
    QTimer::singleShot(0, this, [&cancel] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        QWidget *dialog = QApplication::activeModalWidget();
        auto *buttons = dialog->findChild<QDialogButtonBox *>();
        QVERIFY(buttons);
        cancel = buttons->button(QDialogButtonBox::Cancel)->text();
        dialog->close();
    });
    window->findChild<QAction *>("preferencesAction")->trigger();
    QCOMPARE(cancel, QString("Abbrechen"));
    studio.setLanguage("en");
    QCOMPARE(studio.window()->findChild<QDockWidget *>("plotsDock")->windowTitle(),
             QString("Plots"));
}

void TestStudio::languageSwitchKeepsTheWork()
{
    // A person sets up a session — an edited router applied and another edit not yet, a band
    // address added, bound and armed, a recording with notes, the grippers driven — and
    // switches the language: all of it is there in the new window, and the run never stopped.
    QTemporaryDir sessions;
    QSettings().setValue("sessions/folder", sessions.path());
    Studio studio(options());
    studio.start();
    MainWindow *window = studio.window();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    Engine &engine = window->engine();
    QTRY_VERIFY_WITH_TIMEOUT(engine.simTime() > 1.0, 20000);

    // The router: one edit applied (C3*), one more left in the editor.
    RouterEditor *editor = window->routerEditor();
    window->findChild<QDockWidget *>("routerDock")->raise();
    editor->setParam("right.force", "grasp", 25.0);
    QTest::mouseClick(editor->findChild<QWidget *>("applyButton"), Qt::LeftButton);
    QTRY_COMPARE(window->runToolBar()->routerPicker()->currentText(), QString("C3*"));
    editor->setParam("right.force", "grasp", 30.0);
    const QJsonObject edited = editor->graph().toJson();
    const int undoSteps = editor->undoStack()->count();

    // A pattern being designed, not saved yet.
    window->findChild<QDockWidget *>("patternsDock")->raise();
    WaveformDesigner *designer = window->waveformDesigner();
    designer->duplicate();
    designer->document()->setValue("/description", "mine, not saved");
    const QJsonObject pattern = designer->document()->json();

    // A band's address, bound and armed.
    window->findChild<QDockWidget *>("devicesDock")->raise();
    DevicesPanel *devices = window->devicesPanel();
    auto *address = devices->findChild<QLineEdit *>("address");
    address->setFocus();
    QTest::keyClicks(address, "udp:127.0.0.1:9");
    QTest::mouseClick(devices->findChild<QWidget *>("addButton"), Qt::LeftButton);
    auto *uri = devices->findChild<QComboBox *>("uri:right.vibro");
    QVERIFY(uri);
    uri->setCurrentText("udp:127.0.0.1:9");
    QTest::mouseClick(devices->findChild<QWidget *>("connect:right.vibro"), Qt::LeftButton);
    QTRY_COMPARE(engine.devices().transport("right.vibro")->uri(), QString("udp:127.0.0.1:9"));
    QTest::mouseClick(devices->findChild<QWidget *>("armAll"), Qt::LeftButton);
    QVERIFY(engine.devices().transport("right.vibro")->isArmed());

    // A recording with notes, and the user driving.
    auto *notes = window->runToolBar()->notesEdit();
    notes->setFocus();
    QTest::keyClicks(notes, "participant 7");
    window->findChild<QAction *>("recordAction")->trigger();
    QVERIFY(engine.isRecording());
    const QString recording = engine.recordingPath();
    window->findChild<QAction *>("driveAction")->trigger();
    QVERIFY(engine.isDriving());
    const double before = engine.simTime();

    // How the user looks at it: a longer plot window, the top view, the band to audition on.
    auto *spin = window->plots()->findChild<QAbstractSpinBox *>();
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, "30");
    QTest::keyClick(spin, Qt::Key_Enter);
    QTRY_COMPARE(window->plots()->windowSeconds(), 30.0);
    QVERIFY(openWindow(*window)); // the presets' keys work in the active window
    window->viewport()->setFocus();
    QTest::keyClick(window->viewport(), Qt::Key_2);
    QCOMPARE(window->viewport()->cameraPreset(), CameraPreset::Top);
    const OrbitCamera top = window->viewport()->camera();
    window->findChild<QDockWidget *>("patternsDock")->raise();
    QVERIFY(choose(designer->findChild<QComboBox *>("auditionDevice"), "right.vibro — lra4"));
    // How the pattern plays: ends at 3 s (typed), at intensity 0.7 (the keys).
    auto *endAt = designer->findChild<QDoubleSpinBox *>("endAt");
    endAt->setFocus();
    endAt->selectAll();
    QTest::keyClicks(endAt, "3");
    QTest::keyClick(endAt, Qt::Key_Enter);
    QCOMPARE(endAt->value(), 3.0);
    auto *intensity = designer->findChild<QSlider *>("intensity");
    intensity->setFocus();
    QTest::keyClick(intensity, Qt::Key_End);
    for (int k = 0; k < 30; ++k)
        QTest::keyClick(intensity, Qt::Key_Left);
    QCOMPARE(intensity->value(), 70);

    pickLanguage(studio, "de");
    window = studio.window();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    QCOMPARE(&window->engine(), &engine);
    QVERIFY(engine.isRunning());
    QTRY_VERIFY(engine.simTime() > before + 0.5);
    QCOMPARE(window->runToolBar()->scenePicker()->currentData().toString(),
             QString("box_and_block"));
    QCOMPARE(window->runToolBar()->routerPicker()->currentText(), QString("C3*"));
    QCOMPARE(window->routerEditor()->graph().toJson(), edited);
    QCOMPARE(window->routerEditor()->undoStack()->count(), undoSteps);
    QCOMPARE(window->waveformDesigner()->document()->json(), pattern);
    QVERIFY(window->waveformDesigner()->document()->isModified());
    QCOMPARE(engine.devices().transport("right.vibro")->uri(), QString("udp:127.0.0.1:9"));
    QVERIFY(engine.devices().transport("right.vibro")->isArmed());
    QCOMPARE(window->devicesPanel()->findChild<QComboBox *>("uri:right.vibro")->currentText(),
             QString("udp:127.0.0.1:9"));
    QVERIFY(engine.isRecording());
    QCOMPARE(engine.recordingPath(), recording);
    QVERIFY(window->findChild<QAction *>("recordAction")->isChecked());
    QVERIFY(window->findChild<QLabel *>("recordLabel")->isVisible());
    QCOMPARE(window->runToolBar()->notesEdit()->text(), QString("participant 7"));
    QVERIFY(engine.isDriving());
    QVERIFY(window->findChild<QAction *>("driveAction")->isChecked());
    QCOMPARE(window->findChild<QDockWidget *>("plotsDock")->windowTitle(), QString("Diagramme"));
    QCOMPARE(window->plots()->windowSeconds(), 30.0);
    QCOMPARE(window->plots()->findChild<QSpinBox *>()->value(), 30);
    QCOMPARE(window->viewport()->cameraPreset(), CameraPreset::Top);
    QVERIFY(window->viewport()->cameraPresetAction(CameraPreset::Top)->isChecked());
    QCOMPARE(window->viewport()->camera().elevation, top.elevation);
    QCOMPARE(window->findChild<QComboBox *>("auditionDevice")->currentData().toString(),
             QString("right.vibro"));
    QCOMPARE(window->findChild<QDoubleSpinBox *>("endAt")->value(), 3.0);
    QCOMPARE(window->findChild<QSlider *>("intensity")->value(), 70);

    // The address the user added is there at the next start, in the listing.
    Workspace next;
    QVERIFY(next.engine().devices().configured().contains("udp:127.0.0.1:9"));
    window->findChild<QAction *>("recordAction")->trigger();
    studio.setLanguage("en");
}

void TestStudio::workComesBackAfterARestart()
{
    // What a person left at quitting — an applied router edit, another edit in the editor,
    // a pattern not saved, a band bound, the notes — is there at the next start; the band
    // comes back disarmed, as every real band starts.
    QJsonObject edited;
    QJsonObject pattern;
    {
        Studio studio(options());
        studio.start();
        MainWindow *window = studio.window();
        QVERIFY(QTest::qWaitForWindowExposed(window));
        Engine &engine = window->engine();
        RouterEditor *editor = window->routerEditor();
        editor->setParam("right.force", "grasp", 25.0);
        QTest::mouseClick(editor->findChild<QWidget *>("applyButton"), Qt::LeftButton);
        QTRY_COMPARE(window->runToolBar()->routerPicker()->currentText(), QString("C3*"));
        editor->setParam("right.force", "grasp", 30.0);
        edited = editor->graph().toJson();
        window->waveformDesigner()->duplicate();
        window->waveformDesigner()->document()->setValue("/description", "mine, not saved");
        pattern = window->waveformDesigner()->document()->json();
        QString error;
        QVERIFY2(engine.bindDevice("right.vibro", "udp:127.0.0.1:9", &error), qPrintable(error));
        engine.devices().armAll(true);
        window->runToolBar()->notesEdit()->setFocus();
        QTest::keyClicks(window->runToolBar()->notesEdit(), "participant 7");
        window->close();
    }
    Studio studio(options());
    studio.start();
    MainWindow *window = studio.window();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    Engine &engine = window->engine();
    QVERIFY(engine.isRunning());
    QCOMPARE(window->runToolBar()->routerPicker()->currentText(), QString("C3*"));
    const RouterGraph &running = engine.routerGraph();
    QCOMPARE(running.nodes[size_t(running.nodeIndex("right.force"))].params.value("grasp"),
             QJsonValue(25.0));
    QCOMPARE(window->routerEditor()->graph().toJson(), edited);
    QVERIFY(window->routerEditor()->document()->isModified());
    // ... and says so, beside the toolbar's name of the run's router.
    QCOMPARE(window->routerEditor()->findChild<QLabel *>("routerDocument")->text(),
             QString("* C3 — changed from the preset, not saved to a file"));
    QCOMPARE(window->waveformDesigner()->document()->json(), pattern);
    QVERIFY(window->waveformDesigner()->document()->isModified());
    QVERIFY(
        window->waveformDesigner()->findChild<QLabel *>("banner")->text().contains("not saved"));
    QCOMPARE(engine.devices().transport("right.vibro")->uri(), QString("udp:127.0.0.1:9"));
    QVERIFY(!engine.devices().transport("right.vibro")->isArmed());
    QCOMPARE(window->runToolBar()->notesEdit()->text(), QString("participant 7"));

    // A run named on the command line wins over the saved one; the rest comes back.
    window->close();
    StudioOptions named;
    QString message;
    bool help = false;
    QVERIFY(StudioOptions::parse({"--scene", "bimanual_sorting", "--pose-port", "0"}, &named,
                                 &message, &help));
    Studio again(named);
    again.start();
    QCOMPARE(again.window()->engine().options().scene, QString("bimanual_sorting"));
    QCOMPARE(again.window()->runToolBar()->routerPicker()->currentText(), QString("C3"));
    QCOMPARE(again.window()->routerEditor()->graph().toJson(), edited);
    QCOMPARE(again.window()->runToolBar()->notesEdit()->text(), QString("participant 7"));
    QCOMPARE(again.window()->engine().devices().transport("right.vibro")->uri(),
             QString("udp:127.0.0.1:9"));
}

void TestStudio::workComesBackAfterACrash()
{
    // The studio killed without warning: the workspace it wrote a moment before is whole,
    // and the next start opens it.
    QTemporaryDir dir;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "xcb");
    env.insert("XDG_CONFIG_HOME", dir.path());
    const QString file = dir.filePath("semhap/semhap-studio.workspace.json");
    QProcess studio;
    studio.setProcessEnvironment(env);
    studio.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    studio.start(SEMHAP_STUDIO_BINARY,
                 {"--scene", "bimanual_sorting", "--router", "C1", "--pose-port", "0"});
    QVERIFY(studio.waitForStarted());
    const auto saved = [&file](QJsonObject *simulation) {
        QFile f(file);
        if (!f.open(QIODevice::ReadOnly))
            return false;
        const QJsonObject json = QJsonDocument::fromJson(f.readAll()).object();
        *simulation = json.value("simulation").toObject();
        return json.value("format").toString() == "semhap.workspace/1";
    };
    QJsonObject simulation;
    QTRY_VERIFY_WITH_TIMEOUT(saved(&simulation), 30000);
    studio.kill();
    QVERIFY(studio.waitForFinished());
    QVERIFY(saved(&simulation));
    QCOMPARE(simulation.value("scene").toString(), QString("bimanual_sorting"));
    QCOMPARE(simulation.value("router").toString(), QString("C1"));

    // Started again without naming a run, it opens the same one (and keeps it when it quits).
    studio.start(SEMHAP_STUDIO_BINARY, {"--quit-after", "1", "--pose-port", "0"});
    QVERIFY(studio.waitForFinished(60000));
    QCOMPARE(studio.exitCode(), 0);
    QVERIFY(saved(&simulation));
    QCOMPARE(simulation.value("scene").toString(), QString("bimanual_sorting"));
    QCOMPARE(simulation.value("router").toString(), QString("C1"));
}

void TestStudio::brokenWorkspacesAreReported_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("problem"); // after "FILE"
    QTest::newRow("not JSON") << QByteArray("{\n  \"format\": \"semhap.workspace/1\",\n  oops")
                              << ":3:";
    QTest::newRow("another format")
        << QByteArray(R"({"format": "semhap.router/1"})") << ": /format:";
    QTest::newRow("unknown key")
        << QByteArray(R"({"format": "semhap.workspace/1", "simulation": {"scene": "box_and_block",
           "colour": 1}})")
        << ": /simulation: unknown key 'colour'";
    QTest::newRow("gripper not a name")
        << QByteArray(R"({"format": "semhap.workspace/1", "simulation": {"scene": "box_and_block",
           "gripper": 2}})")
        << ": /simulation/gripper: expected a string";
    QTest::newRow("scene gone")
        << QByteArray(R"({"format": "semhap.workspace/1", "simulation": {"scene": "/gone.xml",
           "router": "C3", "operator": "scripted", "seed": 1, "reaction_time": 0.25}})")
        << ": /simulation: ";
    QTest::newRow("broken edit")
        << QByteArray(R"({"format": "semhap.workspace/1", "simulation": {"scene": "box_and_block",
           "router": "C3", "operator": "scripted", "seed": 1, "reaction_time": 0.25},
           "router": {"graph": {"format": "semhap.router/1", "nodes": [{"id": "x",
           "type": "nope"}]}}})")
        << ": /router: ";
    QTest::newRow("bad binding")
        << QByteArray(R"({"format": "semhap.workspace/1", "simulation": {"scene": "box_and_block",
           "router": "C3", "operator": "scripted", "seed": 1, "reaction_time": 0.25},
           "bindings": [{"device": "right.vibro", "uri": "serial:", "model": "lra4"}]})")
        << ": /bindings/0: ";
    QTest::newRow("binding of no such device")
        << QByteArray(R"({"format": "semhap.workspace/1", "simulation": {"scene": "box_and_block",
           "router": "C3", "operator": "scripted", "seed": 1, "reaction_time": 0.25},
           "bindings": [{"device": "right.vibro", "uri": "udp:127.0.0.1:9", "model": "lra8"}]})")
        << ": /bindings/0: udp:127.0.0.1:9 stays unbound: the router that runs has no lra8 "
           "device 'right.vibro'";
}

void TestStudio::brokenWorkspacesAreReported()
{
    // A workspace file that does not read leaves the studio on its defaults (or on what
    // did read), and says where the file is wrong.
    QFETCH(QByteArray, content);
    QFETCH(QString, problem);
    const QString file = Workspace::defaultFile();
    QDir().mkpath(QFileInfo(file).absolutePath());
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(content);
    f.close();
    Studio studio(options());
    studio.start();
    MainWindow *window = studio.window();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    QVERIFY(window->engine().isLoaded());
    const QString message = window->statusBar()->currentMessage();
    QVERIFY2(message.contains(file + problem), qPrintable(message));
    // What did not come back is not lost to the next autosave: the file is kept as it was.
    QVERIFY2(message.contains(file + ".bak"), qPrintable(message));
    QFile copy(file + ".bak");
    QVERIFY(copy.open(QIODevice::ReadOnly));
    QCOMPARE(copy.readAll(), content);
    window->close();
}

void TestStudio::screenshotHook()
{
    QTemporaryDir dir;
    const QString png = dir.filePath("studio.png");
    QProcess studio;
    studio.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "xcb");
    env.insert("XDG_CONFIG_HOME", dir.path());
    studio.setProcessEnvironment(env);
    studio.start(SEMHAP_STUDIO_BINARY, {"--screenshot", png, "--quit-after", "2", "--size",
                                        "1280x800", "--pose-port", "0"});
    QVERIFY(studio.waitForFinished(60000));
    QCOMPARE(studio.exitCode(), 0);
    QCOMPARE(QString::fromUtf8(studio.readAllStandardOutput()).trimmed(), png);
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1280, 800));

    // A router that does not load leaves the window open with the reason; a malformed
    // option is refused at once with exit code 2.
    studio.start(SEMHAP_STUDIO_BINARY,
                 {"--router", "C9", "--quit-after", "0.5", "--pose-port", "0"});
    QVERIFY(studio.waitForFinished(60000));
    QCOMPARE(studio.exitCode(), 0); // the window opens and says what is wrong
    studio.start(SEMHAP_STUDIO_BINARY, {"--speed", "fast"});
    QVERIFY(studio.waitForFinished(60000));
    QCOMPARE(studio.exitCode(), 2);

    // The help and the version need no display (a terminal over ssh, a packaging check).
    QProcessEnvironment headless = env;
    headless.remove("DISPLAY");
    headless.remove("WAYLAND_DISPLAY");
    headless.remove("QT_QPA_PLATFORM");
    studio.setProcessEnvironment(headless);
    for (const char *ask : {"--help", "--version"}) {
        studio.start(SEMHAP_STUDIO_BINARY, {ask});
        QVERIFY(studio.waitForFinished(60000));
        QCOMPARE(studio.exitCode(), 0);
        const QString out = QString::fromUtf8(studio.readAllStandardOutput());
        QVERIFY2(out.contains(QString(ask) == "--help" ? "--scene" : "semhap-studio "),
                 qPrintable(out));
    }
}

QTEST_MAIN(TestStudio)
#include "tst_studio.moc"
