// SPDX-License-Identifier: MIT
// The studio as a user meets it (run under Xvfb: the viewport needs OpenGL): it opens on
// the embedded defaults and runs; scene and router pickers, run/step/speed, the stop-all
// key and teleoperation drive the engine; the layout is saved and restored; German can be
// switched on in the preferences; `--screenshot` grabs the window and quits.
#include "bandprocess.h"
#include "colors.h"
#include "devicemanager.h"
#include "devicespanel.h"
#include "editordriver.h"
#include "emulatedband.h"
#include "eventlogmodel.h"
#include "eventlogpanel.h"
#include "fifocard.h"
#include "gamepadinput.h"
#include "gripperlibrary.h"
#include "handdrive.h"
#include "imagechecks.h"
#include "keymapdialog.h"
#include "levelmeter.h"
#include "mainwindow.h"
#include "manualwindow.h"
#include "metricspanel.h"
#include "nodeinspector.h"
#include "openwindow.h"
#include "patternauditioner.h"
#include "patterndocument.h"
#include "plotchecks.h"
#include "plotpanel.h"
#include "preferencesdialog.h"
#include "routerdocument.h"
#include "routereditor.h"
#include "routernodeitem.h"
#include "routernodetype.h"
#include "routerscene.h"
#include "simviewport.h"
#include "studio.h"
#include "userpatterns.h"
#include "virtualscreen.h"
#include "waveformdesigner.h"
#include "widgetchecks.h"
#include "windowpictures.h"
#include "workspace.h"
#include "world.h"

#include <QComboBox>
#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QGraphicsView>
#include <QImage>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMatrix4x4>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTimer>
#include <QtMath>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QUdpSocket>
#include <QUndoStack>
#include <QVector3D>
#include <QVector4D>

#include <qcustomplot.h>

#include <cmath>
#include <functional>
#include <memory>

using namespace semhap;

namespace {

/** Catches what QDesktopServices is asked to open, instead of a browser. */
class UrlCatcher : public QObject
{
    Q_OBJECT

public:
    QList<QUrl> urls;

public slots:
    void open(const QUrl &url) { urls.append(url); }
};

/**
 * A home folder of the test's own for as long as it lives: the user pattern folder, the
 * sessions folder and the documents folder are in it.
 */
class OwnHome
{
public:
    OwnHome()
    {
        for (const char *name : {"HOME", "XDG_CONFIG_HOME", "XDG_DATA_HOME"})
            m_saved.append({name, qgetenv(name), qEnvironmentVariableIsSet(name)});
        QDir(m_home.path()).mkpath("Documents");
        qputenv("HOME", m_home.path().toUtf8());
        qputenv("XDG_CONFIG_HOME", m_home.filePath(".config").toUtf8());
        qputenv("XDG_DATA_HOME", m_home.filePath(".local/share").toUtf8());
    }
    ~OwnHome()
    {
        for (const Saved &saved : m_saved) {
            if (saved.set)
                qputenv(saved.name, saved.value);
            else
                qunsetenv(saved.name);
        }
    }
    QString documents() const { return m_home.filePath("Documents"); }

private:
    struct Saved
    {
        const char *name;
        QByteArray value;
        bool set;
    };
    QTemporaryDir m_home;
    QList<Saved> m_saved;
};

/**
 * Does `open` (which opens a file dialog) and answers the dialog: with `answer` when given,
 * else Cancel. The folder the dialog started in.
 */
QString dialogFolder(const std::function<void()> &open, const QString &answer = QString())
{
    QString folder = QStringLiteral("(no file dialog)");
    QTimer::singleShot(0, [&folder, answer] {
        QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()));
        auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        folder = dialog->directory().absolutePath();
        if (answer.isEmpty()) {
            dialog->reject();
            return;
        }
        dialog->selectFile(answer);
        QTest::keyClick(dialog->focusWidget() ? dialog->focusWidget() : dialog, Qt::Key_Return);
    });
    open();
    return folder;
}

/** Clicks the designer's action `name`: its toolbar button, or its entry in the Pattern menu. */
void clickDesignerAction(MainWindow &window, const QString &name)
{
    window.findChild<QDockWidget *>("patternsDock")->raise();
    WaveformDesigner *designer = window.waveformDesigner();
    auto *bar = designer->findChild<QToolBar *>("designerToolBar");
    auto *action = designer->findChild<QAction *>(name);
    QVERIFY(action);
    if (QWidget *button = bar->widgetForAction(action)) {
        QTest::mouseClick(button, Qt::LeftButton);
        return;
    }
    auto *menu = designer->findChild<QMenu *>("patternMenu");
    QVERIFY(menu && menu->actions().contains(action));
    QWidget *menuButton =
        bar->widgetForAction(designer->findChild<QAction *>("patternMenuAction"));
    // No waiting in between: a caller may have a dialog's answer queued for what it opens.
    menu->popup(menuButton->mapToGlobal(menuButton->rect().bottomLeft()));
    QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(action).center());
}

/** A studio at the test row's size and language; its window is shown and active. */
std::unique_ptr<Studio> startStudio(StudioOptions o)
{
    QFETCH(QSize, size);
    QFETCH(QString, language);
    o.size = size;
    auto studio = std::make_unique<Studio>(o);
    studio->start();
    if (language != "en")
        studio->setLanguage(language);
    if (!openWindow(*studio->window()))
        qWarning("the window did not become active");
    return studio;
}

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
    const double sign = goal > at() ? 1.0 : -1.0;
    Qt::Key key = sign > 0 ? Qt::Key_R : Qt::Key_F;
    if (axis < 2) {
        const auto [x, y] = drive->awayDirection();
        const double away = axis == 0 ? x : y;
        const double right = axis == 0 ? y : -x;
        key = away != 0 ? (away * sign > 0 ? Qt::Key_W : Qt::Key_S)
                        : (right * sign > 0 ? Qt::Key_D : Qt::Key_A);
    }
    QTest::keyPress(viewport, key);
    QElapsedTimer clock;
    clock.start();
    // Until there, or the guard holds the target on what is below.
    while ((goal - at()) * sign > 0 && clock.elapsed() < 10000 &&
           !(axis == 2 && drive->status(drive->activeHand()).floor))
        QTest::qWait(10);
    QTest::keyRelease(viewport, key);
    if ((goal - at()) * sign <= 0)
        return QString();
    return QString("key %1 held %2 ms: the target is at %3 of %4, the view's azimuth %5, "
                   "focus %6")
        .arg(QKeySequence(key).toString())
        .arg(clock.elapsed())
        .arg(at())
        .arg(goal)
        .arg(viewport->camera().azimuth)
        .arg(viewport->hasFocus());
}

} // namespace

class TestStudio : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
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
    void statusBarCountsDevicesAsThePanelShowsThem_data();
    void statusBarCountsDevicesAsThePanelShowsThem();
    void aKeyInTheViewportTakesOver();
    void driveShowsTheGhostAtOnce_data();
    void driveShowsTheGhostAtOnce();
    void followKeepsTheHandInView_data();
    void followKeepsTheHandInView();
    void drivingOverlayLeavesTheHandInSight_data();
    void drivingOverlayLeavesTheHandInSight();
    void drivingOverlayShowsTheAppliedGrip_data();
    void drivingOverlayShowsTheAppliedGrip();
    void drivingPreferencesApply();
    void handingBackNeverStrikes_data();
    void handingBackNeverStrikes();
    void eventLogMovesThePlotCursor();
    void layoutIsSavedAndRestored();
    void switchesToGerman();
    void languageSwitchKeepsTheWork();
    void workComesBackAfterARestart();
    void workComesBackAfterACrash();
    void brokenWorkspacesAreReported_data();
    void brokenWorkspacesAreReported();
    void screenshotHook();
    void firstWindowFitsTheScreen_data();
    void firstWindowFitsTheScreen();
    void routerFitsItsGraphWhenRaised_data();
    void routerFitsItsGraphWhenRaised();
    void inspectorsShowEveryFieldWhole_data();
    void inspectorsShowEveryFieldWhole();
    void toolbarsFitAt1280_data();
    void toolbarsFitAt1280();
    void screenshotsOfEveryPanel_data();
    void screenshotsOfEveryPanel();
    void saysWhenTheTaskIsDone_data();
    void saysWhenTheTaskIsDone();
    void keyMapAndManual_data();
    void keyMapAndManual();
    void fileDialogsStartWhereTheirKindLives_data();
    void fileDialogsStartWhereTheirKindLives();
    void fileDialogsRememberTheirKindsFolder();
    void routerFollowsARenamedPattern_data();
    void routerFollowsARenamedPattern();
    void buildsAnAlignmentConfirmationByMouse_data();
    void buildsAnAlignmentConfirmationByMouse();
    void aSceneThatDoesNotLoadLeavesTheRun_data();
    void aSceneThatDoesNotLoadLeavesTheRun();
    void eachSceneComesWithItsRouter();
    void aRunThatDoesNotLoadAtTheStartLeavesTheDefaults_data();
    void aRunThatDoesNotLoadAtTheStartLeavesTheDefaults();
    void gripperMenuPicksAnAdapter_data();
    void gripperMenuPicksAnAdapter();
    void gripperIsKept();
    void aGripperThatDoesNotLoadAtTheStartIsReported();
    void gripperMenuScreenshots_data();
    void gripperMenuScreenshots();

private:
    StudioOptions options() const;
    /** Picks `language` in File → Preferences, as a person would, and waits for the window. */
    static void pickLanguage(Studio &studio, const QString &language);
    QTemporaryDir m_config;
    QString m_fifo; ///< the sound card's (FifoCard)
};

void TestStudio::initTestCase()
{
    QVERIFY(m_config.isValid());
    QCoreApplication::setOrganizationName("semhap");
    QCoreApplication::setApplicationName("semhap-studio-test");
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_config.path());
    m_fifo = FifoCard::install(m_config.path());
    QVERIFY(!m_fifo.isEmpty());
}

void TestStudio::init()
{
    QSettings().clear();
    QFile::remove(Workspace::defaultFile()); // each test starts on the defaults
}

StudioOptions TestStudio::options() const
{
    StudioOptions o;
    QString message;
    bool help = false;
    // Fast, so the first grasp comes soon; no network input, so tests can run side by side.
    StudioOptions::parse({"--speed", "4", "--pose-port", "0", "--size", "1280x800"}, &o, &message,
                         &help);
    return o;
}

void TestStudio::opensOnTheDefaultsAndRuns()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    QCOMPARE(window.scenePicker()->currentData().toString(), QString("box_and_block"));
    QCOMPARE(window.routerPicker()->currentData().toString(), QString("C3"));
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

    QComboBox *scene = window.scenePicker();
    scene->setFocus();
    const int bimanual = scene->findData("bimanual_sorting");
    QVERIFY(bimanual >= 0);
    while (scene->currentIndex() != bimanual)
        QTest::keyClick(scene, bimanual > scene->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QTRY_COMPARE(window.engine().options().scene, QString("bimanual_sorting"));

    QComboBox *router = window.routerPicker();
    router->setFocus();
    const int c1 = router->findData("C1");
    QVERIFY(c1 >= 0);
    while (router->currentIndex() != c1)
        QTest::keyClick(router, c1 > router->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QTRY_COMPARE(window.engine().options().router, QString("C1"));
    QVERIFY(loaded.count() >= 2);
    QVERIFY(window.engine().isRunning()); // picking keeps a running session running

    // The bimanual scene has a left hand: its frames and the slip detector show up.
    QVERIFY(window.engine().history().thresholds()[size_t(Gripper::Left)].hasSlip);
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
    QCOMPARE(window.speedPicker()->currentData().toDouble(), 1.0);
    // Faster on either face of the key: Ctrl++, and Ctrl+= without Shift (in the viewport too,
    // where it leaves the grippers to the operator).
    QTest::keyClick(&window, Qt::Key_Plus, Qt::ControlModifier);
    QCOMPARE(window.engine().speed(), 2.0);
    window.viewport()->setFocus();
    QTest::keyClick(window.viewport(), Qt::Key_Equal, Qt::ControlModifier);
    QCOMPARE(window.engine().speed(), 4.0);
    QCOMPARE(window.speedPicker()->currentData().toDouble(), 4.0);
    QVERIFY(!window.engine().isDriving());
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(window.engine().isRunning());

    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier);
    QVERIFY(window.engine().simTime() < 0.5);

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
    QTRY_VERIFY_WITH_TIMEOUT(drive->status(hand).grip == drive->gripSetpoint(hand), 10000);
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

void TestStudio::pickLanguage(Studio &studio, const QString &language)
{
    QSignalSpy rebuilt(&studio, &Studio::windowRebuilt);
    // The preferences dialog is modal: answer it once it is up.
    QTimer::singleShot(0, [language] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        auto *dialog = qobject_cast<PreferencesDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        QComboBox *picker = dialog->languagePicker();
        picker->setFocus();
        picker->setCurrentIndex(0);
        while (picker->currentData().toString() != language &&
               picker->currentIndex() < picker->count() - 1)
            QTest::keyClick(picker, Qt::Key_Down);
        QCOMPARE(picker->currentData().toString(), language);
        QTest::keyClick(dialog, Qt::Key_Return);
    });
    studio.window()->findChild<QAction *>("preferencesAction")->trigger();
    QTRY_COMPARE(rebuilt.count(), 1);
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
    QTRY_COMPARE(window->routerPicker()->currentText(), QString("C3*"));
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
    auto *notes = window->notesEdit();
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
    QCOMPARE(window->scenePicker()->currentData().toString(), QString("box_and_block"));
    QCOMPARE(window->routerPicker()->currentText(), QString("C3*"));
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
    QCOMPARE(window->notesEdit()->text(), QString("participant 7"));
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
        QTRY_COMPARE(window->routerPicker()->currentText(), QString("C3*"));
        editor->setParam("right.force", "grasp", 30.0);
        edited = editor->graph().toJson();
        window->waveformDesigner()->duplicate();
        window->waveformDesigner()->document()->setValue("/description", "mine, not saved");
        pattern = window->waveformDesigner()->document()->json();
        QString error;
        QVERIFY2(engine.bindDevice("right.vibro", "udp:127.0.0.1:9", &error), qPrintable(error));
        engine.devices().armAll(true);
        window->notesEdit()->setFocus();
        QTest::keyClicks(window->notesEdit(), "participant 7");
        window->close();
    }
    Studio studio(options());
    studio.start();
    MainWindow *window = studio.window();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    Engine &engine = window->engine();
    QVERIFY(engine.isRunning());
    QCOMPARE(window->routerPicker()->currentText(), QString("C3*"));
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
    QCOMPARE(window->notesEdit()->text(), QString("participant 7"));

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
    QCOMPARE(again.window()->routerPicker()->currentText(), QString("C3"));
    QCOMPARE(again.window()->routerEditor()->graph().toJson(), edited);
    QCOMPARE(again.window()->notesEdit()->text(), QString("participant 7"));
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

void TestStudio::firstWindowFitsTheScreen_data()
{
    QTest::addColumn<QSize>("screen");
    QTest::addColumn<bool>("windowManager");
    QTest::addColumn<QSize>("savedOnLarger"); // a window of this size closed on 2560×1440
    QTest::addColumn<bool>("roomy");          // the window should use most of the screen
    QTest::newRow("1280x800") << QSize(1280, 800) << true << QSize() << false;
    QTest::newRow("1366x768") << QSize(1366, 768) << true << QSize() << false;
    QTest::newRow("1366x768, no window manager") << QSize(1366, 768) << false << QSize() << false;
    QTest::newRow("1920x1080") << QSize(1920, 1080) << true << QSize() << true;
    QTest::newRow("2560x1440") << QSize(2560, 1440) << true << QSize() << true;
    QTest::newRow("1366x768, saved on 2560x1440")
        << QSize(1366, 768) << true << QSize(2400, 1300) << false;
}

// The real semhap-studio on screens of its own, framed by a real window manager (openbox)
// with a 36 px panel: the whole window, title bar and frame included, lies in the area the
// panel leaves, so the status bar at its bottom shows; on a large screen it uses the room.
void TestStudio::firstWindowFitsTheScreen()
{
    QFETCH(QSize, screen);
    QFETCH(bool, windowManager);
    QFETCH(QSize, savedOnLarger);
    QFETCH(bool, roomy);
    constexpr int Panel = 36;
    QTemporaryDir dir;
    const auto studioOn = [&](VirtualScreen &display, const QStringList &arguments) {
        auto studio = std::make_unique<QProcess>();
        QProcessEnvironment env = display.environment();
        env.insert("XDG_CONFIG_HOME", dir.path());
        studio->setProcessEnvironment(env);
        studio->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        studio->start(SEMHAP_STUDIO_BINARY, QStringList{"--pose-port", "0"} + arguments);
        return studio;
    };
    QString error;
    if (savedOnLarger.isValid()) {
        VirtualScreen large;
        QVERIFY2(large.start(QSize(2560, 1440), true, Panel, dir.path(), &error),
                 qPrintable(error));
        auto studio = studioOn(
            large,
            {"--size", QString("%1x%2").arg(savedOnLarger.width()).arg(savedOnLarger.height())});
        QVERIFY(QTest::qWaitFor(
            [&] { return large.window("semhap-studio").inside.size() == savedOnLarger; }, 30000));
        studio->terminate(); // closes the window as the user would: the geometry is saved
        QVERIFY(studio->waitForFinished(30000));
    }
    VirtualScreen display;
    QVERIFY2(display.start(screen, windowManager, Panel, dir.path(), &error), qPrintable(error));
    const QRect area = display.workArea();
    auto studio = studioOn(display, {});
    const auto fits = [&] {
        const VirtualScreen::Window window = display.window("semhap-studio");
        return !window.id.isEmpty() && area.contains(window.frame);
    };
    // On screen, then placed again once the window manager has framed it; and it stays so.
    QVERIFY(QTest::qWaitFor([&] { return !display.window("semhap-studio").id.isEmpty(); }, 30000));
    const bool placed = QTest::qWaitFor(fits, 10000);
    QTest::qWait(1000);
    const VirtualScreen::Window window = display.window("semhap-studio");
    QVERIFY2(placed && fits(), qPrintable(QString("frame %1,%2 %3x%4 on a work area of %5x%6")
                                              .arg(window.frame.x())
                                              .arg(window.frame.y())
                                              .arg(window.frame.width())
                                              .arg(window.frame.height())
                                              .arg(area.width())
                                              .arg(area.height())));
    if (windowManager)
        QVERIFY(window.frame.height() > window.inside.height()); // a title bar is counted
    if (roomy) {
        QVERIFY2(
            window.frame.width() >= area.width() * 8 / 10 &&
                window.frame.height() >= area.height() * 8 / 10,
            qPrintable(QString("%1x%2").arg(window.frame.width()).arg(window.frame.height())));
    }
    studio->terminate();
    QVERIFY(studio->waitForFinished(30000));
}

void TestStudio::routerFitsItsGraphWhenRaised_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("scene");
    QTest::newRow("1280x800") << QSize(1280, 800) << "box_and_block";
    QTest::newRow("1366x768, bimanual") << QSize(1366, 768) << "bimanual_sorting";
    QTest::newRow("1920x1080") << QSize(1920, 1080) << "box_and_block";
    QTest::newRow("1920x1080, bimanual") << QSize(1920, 1080) << "bimanual_sorting";
}

/** Whether every node of the router editor's graph lies inside its view; which not, else. */
/**
 * The nodes outside the router's view, when that is wrong: a graph is shown whole, unless
 * whole its words would be too small to read (C3p at 1280×800): then it is shown at the
 * readable zoom from its left edge, its sources, and the rest is scrolled to.
 */
static QStringList nodesOutsideTheView(RouterEditor *editor)
{
    QStringList outside;
    QGraphicsView *view = editor->view();
    for (const RouterNode &node : editor->graph().nodes) {
        const QRectF box = editor->scene()->nodeItem(node.id)->sceneBoundingRect();
        if (!view->viewport()->rect().contains(view->mapFromScene(box).boundingRect()))
            outside.append(node.id);
    }
    const QRect graph = view->mapFromScene(editor->scene()->itemsBoundingRect()).boundingRect();
    if (!outside.isEmpty() &&
        std::abs(view->transform().m11() - RouterEditor::MinReadableScale) < 1e-9 &&
        graph.left() >= 0 && graph.left() < view->viewport()->width() / 4)
        return {};
    return outside;
}

// The Router tab sits behind the plots: its canvas is first shown when the tab is raised,
// and then shows the whole graph, at every window size; so after the window grows.
void TestStudio::routerFitsItsGraphWhenRaised()
{
    QFETCH(QSize, size);
    QFETCH(QString, scene);
    StudioOptions o = options();
    o.size = size;
    o.run.scene = scene;
    Workspace workspace;
    MainWindow window(workspace, o);
    QVERIFY(openWindow(window));
    QTabBar *right = nullptr;
    for (QTabBar *bar : window.findChildren<QTabBar *>()) {
        for (int i = 0; i < bar->count(); ++i)
            right = bar->tabText(i) == "Router" ? bar : right;
    }
    QVERIFY(right);
    for (int i = 0; i < right->count(); ++i) {
        if (right->tabText(i) == "Router")
            QTest::mouseClick(right, Qt::LeftButton, {}, right->tabRect(i).center());
    }
    QTRY_VERIFY(window.routerEditor()->view()->isVisible());
    QTest::qWait(100);
    QStringList outside = nodesOutsideTheView(window.routerEditor());
    QVERIFY2(outside.isEmpty(), qPrintable(outside.join(", ") + " outside the router's view"));
    // Not blown up either: the graph fills the view one way or the other.
    const QRect drawn = window.routerEditor()
                            ->view()
                            ->mapFromScene(window.routerEditor()->scene()->itemsBoundingRect())
                            .boundingRect();
    const QRect room = window.routerEditor()->view()->viewport()->rect();
    QVERIFY2(drawn.width() > room.width() * 6 / 10 || drawn.height() > room.height() * 6 / 10 ||
                 window.routerEditor()->view()->transform().m11() == 1.0,
             qPrintable(QString("the graph takes %1x%2 of %3x%4")
                            .arg(drawn.width())
                            .arg(drawn.height())
                            .arg(room.width())
                            .arg(room.height())));

    // The window shrinks (moved to a smaller screen): the graph still fits.
    window.resize(size - QSize(240, 120));
    QTest::qWait(200);
    outside = nodesOutsideTheView(window.routerEditor());
    QVERIFY2(outside.isEmpty(), qPrintable(outside.join(", ") + " outside after a resize"));
}

/** Clicks the tab named `title` among the window's dock tabs. */
static bool raiseTab(MainWindow &window, const QString &title)
{
    for (QTabBar *bar : window.findChildren<QTabBar *>()) {
        for (int i = 0; i < bar->count(); ++i) {
            if (bar->tabText(i) == title) {
                QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(i).center());
                return true;
            }
        }
    }
    return false;
}

/** A row per interface language, "en" and "de", in column `language`. */
static void languageRows()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << "en";
    QTest::newRow("de") << "de";
}

/** Starts `studio` in `language`, switched to as a user does it (the window is rebuilt). */
static MainWindow &startIn(Studio &studio, const QString &language)
{
    studio.start();
    if (language != "en")
        studio.setLanguage(language);
    return *studio.window();
}

void TestStudio::inspectorsShowEveryFieldWhole_data()
{
    languageRows();
}

// At 1280×800, in either language: the router editor's inspector for a node of every type
// and every node of C3p, and the pattern designer's inspector for every node of every
// built-in pattern, show each field whole: none cut by the dock or a scroll area, no text
// or value squeezed.
void TestStudio::inspectorsShowEveryFieldWhole()
{
    QFETCH(QString, language);
    StudioOptions o = options();
    o.run.router = "C3p";
    o.autoRun = false;
    Studio studio(o);
    MainWindow &window = startIn(studio, language);
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    QStringList clipped;
    const auto look = [&](QWidget *dock, const QString &what) {
        QCoreApplication::processEvents(); // the inspectors rebuild queued
        QCoreApplication::processEvents();
        const QStringList here = clippedTexts(dock);
        for (const QString &text : here)
            clipped.append(what + ": " + text);
        if (!shots.isEmpty() && !here.isEmpty())
            window.grab().save(QString("%1/inspector-%2-%3.png")
                                   .arg(shots, language, QString(what).replace('/', '_')));
    };

    RouterEditor *editor = window.routerEditor();
    QVERIFY(raiseTab(window, window.findChild<QDockWidget *>("routerDock")->windowTitle()));
    QTRY_VERIFY(editor->view()->isVisible());
    QListWidget *palette = editor->palette();
    for (const RouterNodeType &type : routerNodeTypes()) {
        const QList<QListWidgetItem *> items = palette->findItems(type.type, Qt::MatchExactly);
        QCOMPARE(items.size(), 1);
        palette->scrollToItem(items.front());
        const QPoint center = palette->visualItemRect(items.front()).center();
        QTest::mouseClick(palette->viewport(), Qt::LeftButton, {}, center);
        QTest::mouseDClick(palette->viewport(), Qt::LeftButton, {}, center);
        QTRY_COMPARE(editor->scene()->selectedNodeIds().size(), 1);
    }
    editor->arrange(); // apart, so that a click hits the node it means
    for (const RouterNode &node : editor->graph().nodes) {
        RouterNodeItem *item = editor->scene()->nodeItem(node.id);
        editor->view()->ensureVisible(item);
        QTest::mouseClick(editor->view()->viewport(), Qt::LeftButton, {},
                          editor->view()->mapFromScene(item->mapToScene(QPointF(60, 10))));
        QTRY_COMPARE(editor->scene()->selectedNodeIds(), QStringList{node.id});
        QTRY_VERIFY(editor->inspector()->findChild<QLineEdit *>("nodeId"));
        look(window.findChild<QDockWidget *>("routerDock"), "router/" + node.id);
    }

    WaveformDesigner *designer = window.waveformDesigner();
    QVERIFY(raiseTab(window, window.findChild<QDockWidget *>("patternsDock")->windowTitle()));
    QTRY_VERIFY(designer->isVisible());
    auto *library = designer->findChild<QListWidget *>("library");
    for (int row = 0; row < library->count(); ++row) {
        library->scrollToItem(library->item(row));
        QTest::mouseClick(library->viewport(), Qt::LeftButton, {},
                          library->visualItemRect(library->item(row)).center());
        QTreeWidget *tree = designer->tree();
        QTRY_VERIFY(tree->topLevelItemCount() > 0);
        for (QTreeWidgetItemIterator it(tree); *it; ++it) {
            tree->scrollToItem(*it);
            QTest::mouseClick(tree->viewport(), Qt::LeftButton, {},
                              tree->visualItemRect(*it).center());
            look(window.findChild<QDockWidget *>("patternsDock"),
                 library->item(row)->text() + "/" + (*it)->text(0).section(' ', 0, 0));
        }
    }
    QVERIFY2(clipped.isEmpty(), qPrintable(clipped.join("\n")));
}

void TestStudio::toolbarsFitAt1280_data()
{
    languageRows();
}

// At 1280×800, in either language, every toolbar of the window and its docks shows all of
// its buttons and fields (none in the "»" overflow menu, no field squeezed), and the
// editors' Undo and Redo stay in sight after an edit (their names no longer grow with it).
void TestStudio::toolbarsFitAt1280()
{
    QFETCH(QString, language);
    StudioOptions o = options();
    o.autoRun = false;
    Studio studio(o);
    MainWindow &window = startIn(studio, language);
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // An edit in each editor: what Undo would undo has a name now.
    window.routerEditor()->setParam("right.force", "grasp", 25);
    window.waveformDesigner()->findChild<QAction *>("duplicatePattern")->trigger();
    window.waveformDesigner()->document()->setValue("/description", QJsonValue("a copy"));
    QVERIFY(window.routerEditor()->undoStack()->canUndo());
    QVERIFY(window.waveformDesigner()->document()->undoStack()->canUndo());

    for (const QString dock : {"plotsDock", "routerDock", "patternsDock"}) {
        QVERIFY(raiseTab(window, window.findChild<QDockWidget *>(dock)->windowTitle()));
        QTest::qWait(100);
        for (QToolBar *bar : window.findChildren<QToolBar *>()) {
            if (!bar->isVisible() || !showsIn(bar, &window))
                continue;
            auto *more = bar->findChild<QToolButton *>("qt_toolbar_ext_button");
            QVERIFY2(more && !more->isVisible(),
                     qPrintable(QString("%1: the toolbar %2 overflows (%3 px for %4 px)")
                                    .arg(dock, bar->objectName())
                                    .arg(bar->width())
                                    .arg(bar->sizeHint().width())));
            const QStringList clipped = clippedTexts(bar);
            QVERIFY2(clipped.isEmpty(), qPrintable(dock + ": " + clipped.join("; ")));
        }
    }
    for (QWidget *editor : {static_cast<QWidget *>(window.routerEditor()),
                            static_cast<QWidget *>(window.waveformDesigner())}) {
        QVERIFY(raiseTab(window, qobject_cast<QDockWidget *>(editor->parentWidget())
                                     ? editor->parentWidget()->windowTitle()
                                     : QString()));
        QTest::qWait(100);
        auto *bar = editor->findChild<QToolBar *>();
        for (QAction *action : editor->actions()) {
            if (action->shortcut() != QKeySequence(QKeySequence::Undo) &&
                action->shortcuts() != QKeySequence::keyBindings(QKeySequence::Redo))
                continue;
            QWidget *button = bar->widgetForAction(action);
            QVERIFY2(button && button->isVisible(),
                     qPrintable(action->text() + " is not in sight in " + editor->objectName()));
        }
    }
    // Run and Pause take the same room: what follows on the toolbar stands still (it moved
    // by 13 px as the run started).
    auto *speed = window.findChild<QWidget *>("speedPicker");
    const int x = speed->mapTo(&window, QPoint()).x();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(window.engine().isRunning());
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QCOMPARE(speed->mapTo(&window, QPoint()).x(), x);
    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(!window.engine().isRunning());
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QCOMPARE(speed->mapTo(&window, QPoint()).x(), x);
}

void TestStudio::screenshotsOfEveryPanel_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("router");
    QTest::addColumn<QString>("language");
    QTest::newRow("1280x800") << QSize(1280, 800) << "box_and_block"
                              << "C3"
                              << "en";
    QTest::newRow("1920x1080") << QSize(1920, 1080) << "bimanual_sorting"
                               << "C3"
                               << "en";
    QTest::newRow("1280x800-de") << QSize(1280, 800) << "bimanual_sorting"
                                 << "C3"
                                 << "de";
    QTest::newRow("1280x800-de-usb") << QSize(1280, 800) << "usb_insertion"
                                     << "usb"
                                     << "de";
    // Both hands, a signal plot and seven devices' plots in one dock.
    QTest::newRow("1280x800-wipe") << QSize(1280, 800) << "dish_wiping"
                                   << "wipe"
                                   << "en";
    // The largest preset: its nodes must still read at 1280×800.
    QTest::newRow("1280x800-C3p") << QSize(1280, 800) << "bimanual_sorting"
                                  << "C3p"
                                  << "en";
}

// Pictures of the window with each bottom dock (and the patterns tab) raised, to be looked at
// (beside the test binary, or in $SEMHAP_SCREENSHOTS), and checked for what a person would
// notice first: a blank viewport, empty plots, a router drawn outside its view, cut text.
void TestStudio::screenshotsOfEveryPanel()
{
    QFETCH(QSize, size);
    QFETCH(QString, scene);
    QFETCH(QString, router);
    QFETCH(QString, language);
    StudioOptions o = options();
    o.size = size;
    o.run.scene = scene;
    o.run.router = router;
    o.speed = 2.0;
    Studio studio(o);
    studio.start();
    if (language != "en")
        studio.setLanguage(language);
    MainWindow &window = *studio.window();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_VERIFY_WITH_TIMEOUT(window.engine().simTime() > 12.0, 30000);
    const QString dir = qEnvironmentVariableIsSet("SEMHAP_SCREENSHOTS")
                            ? qEnvironmentVariable("SEMHAP_SCREENSHOTS")
                            : QCoreApplication::applicationDirPath();
    for (const QString dock : {"eventsDock", "devicesDock", "metricsDock", "patternsDock"}) {
        window.findChild<QDockWidget *>(dock)->raise();
        QTest::qWait(300);
        const QString path =
            QString("%1/studio-%2-%3.png").arg(dir, QTest::currentDataTag(), dock.chopped(4));
        QString error;
        QVERIFY2(Studio::screenshot(&window, path, &error), qPrintable(error));
        QCOMPARE(QImage(path).size(), size);
        const QStringList clipped = clippedTexts(&window);
        QVERIFY2(clipped.isEmpty(), qPrintable(dock + ": " + clipped.join("; ")));
    }

    // The viewport shows the scene.
    auto *viewport = window.findChild<SimViewport *>();
    QVERIFY(viewport && viewport->isVisible());
    QString why;
    QVERIFY2(looksDrawn(viewport->grabFramebuffer(), &why), qPrintable(why));

    // The plots show the run: at least one force and one device graph have data, and each
    // graph with data in view puts its colour on screen.
    window.findChild<QDockWidget *>("plotsDock")->raise();
    QTest::qWait(500);
    auto *plot = window.findChild<QDockWidget *>("plotsDock")->findChild<QCustomPlot *>();
    QVERIFY(plot && plot->isVisible());
    const QImage picture = plot->grab().toImage();
    int drawn = 0;
    for (int g = 0; g < plot->graphCount(); ++g) {
        QCPGraph *graph = plot->graph(g);
        bool found = false;
        const QCPRange keys = graph->keyAxis()->range();
        const QCPRange values = graph->valueAxis()->range();
        for (auto it = graph->data()->findBegin(keys.lower); it != graph->data()->end(); ++it)
            found = found || (keys.contains(it->key) && values.contains(it->value));
        if (!found || !graph->visible() || graph->pen().style() == Qt::NoPen)
            continue;
        QVERIFY2(pixelsOfColour(picture, graph->pen().color()) > 20,
                 qPrintable(graph->name() + " has data in view but is not drawn"));
        ++drawn;
    }
    QVERIFY2(drawn >= 2, qPrintable(QString("only %1 graph(s) drawn").arg(drawn)));
    // Messages and levels are named as the log and the router files name them, in every
    // language (the German plots said "Griff" where the log said "grasp").
    QStringList texts;
    for (int i = 0; i < plot->itemCount(); ++i) {
        if (auto *text = qobject_cast<QCPItemText *>(plot->item(i)))
            texts.append(text->text());
    }
    QVERIFY2(texts.contains("grasp") || texts.contains("grasp 20 N") ||
                 texts.contains("right.engaged"), // the wipe preset's confirmation
             qPrintable(texts.join("|")));
    for (const char *translated : {"Griff", "Bruch", "Rutschen"})
        QVERIFY2(!texts.join("|").contains(translated), qPrintable(texts.join("|")));
    // Each plot keeps room for two value labels at least: the panel scrolls instead (with
    // both hands, a signal and seven devices at 1280x800 a device's plot showed only "0").
    for (int i = 0; i < plot->axisRectCount(); ++i) {
        const int labels = valueLabelsInView(plot->axisRect(i));
        QVERIFY2(labels >= 2, qPrintable(QString("plot %1: %2 value label(s) in %3 px")
                                             .arg(i)
                                             .arg(labels)
                                             .arg(plot->axisRect(i)->height())));
    }

    // The router fits its view, every node inside it, and shows what the running router
    // passes on: the detector of a hand that holds something is lit.
    window.findChild<QDockWidget *>("routerDock")->raise();
    QTest::qWait(200);
    QVERIFY(!window.engine().history().activity().isEmpty());
    const auto lit = [&window] {
        for (const char *id : {"right.force", "left.slip", "right.engaged", "left.holding"}) {
            const auto *node = window.routerEditor()->scene()->nodeItem(id);
            if (node && !node->state().isEmpty())
                return true;
        }
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(lit(), 20000);
    const QStringList outside = nodesOutsideTheView(window.routerEditor());
    QVERIFY2(outside.isEmpty(), qPrintable(outside.join(", ") + " outside the router's view"));
    QString error;
    QVERIFY2(
        Studio::screenshot(
            &window, QString("%1/studio-%2-router.png").arg(dir, QTest::currentDataTag()), &error),
        qPrintable(error));
    const QStringList clipped = clippedTexts(&window);
    QVERIFY2(clipped.isEmpty(), qPrintable("router: " + clipped.join("; ")));
}

void TestStudio::saysWhenTheTaskIsDone_data()
{
    addWindowRows();
}

void TestStudio::saysWhenTheTaskIsDone()
{
    // A pile of one cube, which the scripted operator carries over the partition (seed 1,
    // in 5.3 s): the viewport says the task is done and stays saying so while the run goes
    // on, the metrics give the time, and a reset takes the notice away.
    QFETCH(QString, language);
    StudioOptions o = options();
    o.speed = 8.0;
    o.run.sceneOptions.cubes = 1;
    o.run.seed = 1;
    o.autoRun = false;
    const std::unique_ptr<Studio> studio = startStudio(o);
    MainWindow &window = *studio->window();
    QVERIFY(window.isActiveWindow());
    window.findChild<QDockWidget *>("metricsDock")->raise();
    QLabel *time = nullptr;
    QTRY_VERIFY((time = window.metricsPanel()->findChild<QLabel *>("completion_time")));
    const QString notYet = MetricsPanel::format("completion_time", QJsonValue());
    QCOMPARE(time->text(), notYet);
    // Hovered, a metric says what it means and its unit, not just its key.
    const QString tip = time->toolTip();
    QCOMPARE(tip, MetricsPanel::tooltip("completion_time"));
    QVERIFY2(tip.size() > 40 && tip.endsWith("completion_time") &&
                 tip.contains(language == "de" ? "Sekunden" : "seconds"),
             qPrintable(tip));
    QCOMPARE(window.viewport()->notice(), QString());
    QTest::qWait(300);
    const int greenBefore = pixelsOfColour(window.viewport()->grabFramebuffer(), colors::Ok, 16);

    QTest::keyClick(&window, Qt::Key_F5);
    QVERIFY(window.engine().isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(!window.viewport()->notice().isEmpty(), 60000);
    const double done = window.engine().history().metrics().value("completion_time").toDouble();
    QVERIFY2(done > 4.0 && done < 7.0, qPrintable(QString::number(done)));
    QCOMPARE(time->text(), MetricsPanel::format("completion_time", done));
    QVERIFY2(window.viewport()->notice().contains(QLocale().toString(done, 'f', 1)),
             qPrintable(window.viewport()->notice()));
    QTest::qWait(300);
    savePicture(&window, "taskdone");
    // On screen: the notice's green rim over the picture.
    const QImage picture = window.viewport()->grabFramebuffer();
    QVERIFY2(pixelsOfColour(picture, colors::Ok, 16) > greenBefore + 200,
             qPrintable(QString("%1 green pixels, %2 before")
                            .arg(pixelsOfColour(picture, colors::Ok, 16))
                            .arg(greenBefore)));
    const QStringList clipped = clippedTexts(&window);
    QVERIFY2(clipped.isEmpty(), qPrintable(clipped.join("; ")));

    // The run goes on (the box is refilled); the notice stays, in a window rebuilt in the
    // other language too, until a reset.
    const double t = window.engine().simTime();
    QTRY_VERIFY(window.engine().simTime() > t + 2.0);
    QVERIFY(!window.viewport()->notice().isEmpty());
    window.engine().pause();
    studio->setLanguage(language == "en" ? "de" : "en");
    MainWindow &rebuilt = *studio->window();
    QVERIFY(openWindow(rebuilt));
    QVERIFY2(rebuilt.viewport()->notice().contains(QLocale().toString(done, 'f', 1)),
             qPrintable(rebuilt.viewport()->notice()));
    QTest::keyClick(&rebuilt, Qt::Key_R, Qt::ControlModifier);
    QTRY_COMPARE(rebuilt.viewport()->notice(), QString());
    QTRY_COMPARE(rebuilt.metricsPanel()->findChild<QLabel *>("completion_time")->text(),
                 MetricsPanel::format("completion_time", QJsonValue()));
}

void TestStudio::keyMapAndManual_data()
{
    addWindowRows();
}

void TestStudio::keyMapAndManual()
{
    // Help → Key map (Ctrl+/) lists every shortcut of the window's actions and the drive
    // keys, in the interface language; Help → Documentation (F1) opens the manual.
    QFETCH(QString, language);
    // What three rows say, in the interface language.
    const bool de = language == "de";
    const QString stopAll = de ? "Alles stoppen" : "Stop all";
    const QString preferences = de ? "Einstellungen" : "Preferences";
    const QString away =
        de ? "Das Handgelenk von Ihnen weg bewegen" : "Move the wrist away from you";
    const std::unique_ptr<Studio> studio = startStudio(options());
    MainWindow &window = *studio->window();
    QVERIFY(window.isActiveWindow());
    QTest::keyClick(&window, Qt::Key_Slash, Qt::ControlModifier);
    KeyMapDialog *map = nullptr;
    QTRY_VERIFY((map = window.findChild<KeyMapDialog *>()) && map->isVisible());

    // Over the window and on its screen (it opened wherever the window manager chose).
    QVERIFY(QTest::qWaitForWindowExposed(map));
    QTRY_VERIFY(window.screen()->availableGeometry().contains(map->frameGeometry()));
    QVERIFY(window.geometry().contains(map->geometry().center()));

    QMultiHash<QString, QString> rows;                      // keys -> what they do
    std::map<QString, QMultiHash<QString, QString>> groups; // heading -> its rows
    for (int g = 0; g < map->tree()->topLevelItemCount(); ++g) {
        const QTreeWidgetItem *group = map->tree()->topLevelItem(g);
        for (int r = 0; r < group->childCount(); ++r) {
            rows.insert(group->child(r)->text(0), group->child(r)->text(1));
            groups[group->text(0)].insert(group->child(r)->text(0), group->child(r)->text(1));
        }
    }
    const auto keys = [](const QKeySequence &key) {
        return key.toString(QKeySequence::NativeText);
    };
    // Undo as its portable key only (it showed "Ctrl+Z, F14"); the Router's redo has Ctrl+Y
    // as the manual says, and the map says so for each editor.
    const QString undo = window.findChild<QAction *>("routerUndo")->iconText();
    const QString redo = window.findChild<QAction *>("routerRedo")->iconText();
    for (const QString &dock : {QString("routerDock"), QString("patternsDock")}) {
        const QString heading = de ? QString("Im Bereich %1") : QString("In the %1 panel");
        const auto &group =
            groups[heading.arg(window.findChild<QDockWidget *>(dock)->windowTitle())];
        QCOMPARE(group.value(keys(QKeySequence(Qt::CTRL | Qt::Key_Z))), undo);
        QCOMPARE(group.key(redo), keys(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)) + ", " +
                                      keys(QKeySequence(Qt::CTRL | Qt::Key_Y)));
    }
    // A standard key's other bindings on this platform (F14 for Undo) are left out.
    const auto platformExtra = [](const QKeySequence &key) {
        const QMetaEnum standard = QMetaEnum::fromType<QKeySequence::StandardKey>();
        for (int i = 0; i < standard.keyCount(); ++i) {
            if (QKeySequence::keyBindings(QKeySequence::StandardKey(standard.value(i)))
                    .indexOf(key) > 0)
                return true;
        }
        return false;
    };
    QCOMPARE(rows.value(keys(Qt::Key_Escape)), stopAll);
    QVERIFY2(rows.value(keys(QKeySequence(Qt::CTRL | Qt::Key_Comma))).startsWith(preferences),
             qPrintable(rows.value(keys(QKeySequence(Qt::CTRL | Qt::Key_Comma)))));
    QCOMPARE(rows.value(keys(Qt::Key_W)), away);
    for (const Qt::Key key : {Qt::Key_A, Qt::Key_S, Qt::Key_D})
        QVERIFY2(rows.contains(keys(key)), qPrintable(keys(key)));
    // Every action's shortcut is there with its action, wherever the action lives.
    for (const QAction *action : window.findChildren<QAction *>()) {
        for (const QKeySequence &shortcut : action->shortcuts()) {
            bool listed = false;
            for (auto it = rows.begin(); it != rows.end() && !listed; ++it)
                listed = it.key().split(", ").contains(keys(shortcut)) &&
                         action->iconText().startsWith(it.value());
            QVERIFY2(listed != platformExtra(shortcut),
                     qPrintable(keys(shortcut) + " " + action->iconText()));
        }
    }
    savePicture(map, "keymap");
    QVERIFY2(clippedTexts(map).isEmpty(), qPrintable(clippedTexts(map).join("; ")));
    // Every row reads whole: nothing to scroll sideways to, no text elided in its column.
    QVERIFY(!map->tree()->horizontalScrollBar()->isVisible());
    const QFontMetrics metrics(map->tree()->font());
    for (QTreeWidgetItemIterator it(map->tree()); *it; ++it) {
        if (!(*it)->parent())
            continue;
        for (int column : {0, 1}) {
            const QRect cell = map->tree()->visualItemRect(*it);
            const int room =
                map->tree()->columnWidth(column) -
                (column == 0 ? cell.left() - map->tree()->columnViewportPosition(0) : 0);
            QVERIFY2(metrics.horizontalAdvance((*it)->text(column)) < room,
                     qPrintable((*it)->text(column)));
        }
    }
    map->close();

    // F1: the manual, read in the studio (a desktop with no program for .md opened nothing).
    UrlCatcher catcher;
    QDesktopServices::setUrlHandler("https", &catcher, "open");
    const auto unset = qScopeGuard([] { QDesktopServices::unsetUrlHandler("https"); });
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QTest::keyClick(&window, Qt::Key_F1);
    ManualWindow *manual = nullptr;
    QTRY_VERIFY((manual = window.findChild<ManualWindow *>()) && manual->isVisible());
    QVERIFY(QTest::qWaitForWindowExposed(manual));
    QTextBrowser *page = manual->browser();
    const QString file = page->source().toLocalFile();
    QVERIFY2(file.endsWith("/studio.md") && QFileInfo(file).isFile(), qPrintable(file));
    QVERIFY(page->toPlainText().contains("Help → Key map"));
    QVERIFY(!QApplication::activeModalWidget()); // the window stays in reach
    // The search field finds as it is typed, and Enter goes on to the next match. The
    // manual takes the keys once it is the active window: on a busy machine that comes late.
    manual->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(manual));
    QTest::keyClick(manual, Qt::Key_F, Qt::ControlModifier);
    QTRY_VERIFY(manual->searchField()->hasFocus());
    QTest::keyClicks(manual->searchField(), "stop all");
    QCOMPARE(page->textCursor().selectedText().toLower(), QString("stop all"));
    const int first = page->textCursor().position();
    QTest::keyClick(manual->searchField(), Qt::Key_Return);
    QVERIFY(page->textCursor().position() > first);
    savePicture(manual, "manual");
    QTest::keyClicks(manual->searchField(), "zzqx");
    QCOMPARE(manual->findChild<QLabel *>("manualFound")->text(),
             QString(de ? "Nicht gefunden" : "Not found"));
    // A link to another page of the manual, clicked, opens it here; Back returns.
    const auto clickLink = [&](const QString &ending) {
        QTextCursor cursor(page->document());
        for (QTextBlock block = page->document()->begin(); block.isValid(); block = block.next()) {
            for (auto it = block.begin(); !it.atEnd(); ++it) {
                const QTextFragment fragment = it.fragment();
                if (fragment.charFormat().isAnchor() &&
                    fragment.charFormat().anchorHref().endsWith(ending)) {
                    cursor.setPosition(fragment.position() + 1);
                    page->setTextCursor(cursor);
                    page->ensureCursorVisible();
                    QTest::mouseClick(page->viewport(), Qt::LeftButton, {},
                                      page->cursorRect(cursor).center());
                    return true;
                }
            }
        }
        return false;
    };
    QVERIFY(clickLink("studies.md"));
    QTRY_VERIFY2(page->source().toLocalFile().endsWith("/studies.md"),
                 qPrintable(page->source().toString()));
    QVERIFY(page->toPlainText().contains("semhap.study/1"));
    QTest::mouseClick(manual->findChild<QToolButton *>("manualBack"), Qt::LeftButton);
    QTRY_VERIFY(page->source().toLocalFile().endsWith("/studio.md"));
    // A link to a heading of the page scrolls to it.
    const auto headingShown = [page](const QString &heading) {
        for (QTextBlock block = page->document()->begin(); block.isValid(); block = block.next()) {
            if (block.blockFormat().headingLevel() == 0 || block.text() != heading)
                continue;
            const int y = int(page->document()->documentLayout()->blockBoundingRect(block).y());
            const int top = page->verticalScrollBar()->value();
            return y >= top && y < top + page->viewport()->height();
        }
        return false;
    };
    page->verticalScrollBar()->setValue(0);
    QVERIFY(!headingShown("Running a study"));
    QVERIFY(clickLink("#running-a-study"));
    QTRY_VERIFY(headingShown("Running a study"));
    // The web goes to the desktop's browser.
    QVERIFY(clickLink("https://spacenav.sourceforge.net/"));
    QCOMPARE(catcher.urls.size(), 1);
    manual->close();
}

void TestStudio::fileDialogsStartWhereTheirKindLives_data()
{
    QTest::addColumn<QString>("how");
    QTest::addColumn<QString>("folder"); ///< sessions, patterns or documents
    QTest::newRow("open session") << "key:Ctrl+Alt+O"
                                  << "sessions";
    QTest::newRow("open scene") << "key:Ctrl+O"
                                << "documents";
    QTest::newRow("open router") << "key:Ctrl+Shift+O"
                                 << "documents";
    QTest::newRow("designer: open pattern") << "designer:openPattern"
                                            << "patterns";
    QTest::newRow("designer: save as") << "designer:saveAsPattern"
                                       << "patterns";
    QTest::newRow("designer: import") << "designer:importPattern"
                                      << "documents";
    QTest::newRow("designer: export") << "designer:exportPattern"
                                      << "documents";
    QTest::newRow("router editor: open") << "router:Open…"
                                         << "documents";
    QTest::newRow("router editor: save") << "router:Save…"
                                         << "documents";
    QTest::newRow("plots: CSV") << "plots:exportCsv"
                                << "documents";
    QTest::newRow("plots: PNG") << "plots:exportPng"
                                << "documents";
    QTest::newRow("gripper: other file") << "gripper:Other file…"
                                         << "documents";
}

namespace {

/**
 * Opens the toolbar's Gripper menu under its button and clicks its entry `text` (which may
 * open a file dialog: no waiting in between, a caller may have its answer queued).
 */
void chooseGripper(MainWindow &window, const QString &text)
{
    auto *button = window.findChild<QToolButton *>("gripperButton");
    auto *menu = window.findChild<QMenu *>("gripperMenu");
    QVERIFY(button && button->isVisible() && menu);
    menu->popup(button->mapToGlobal(button->rect().bottomLeft()));
    QAction *entry = nullptr;
    for (QAction *action : menu->actions()) {
        if (action->text() == text)
            entry = action;
    }
    QVERIFY2(entry, qPrintable(text + " is not in the Gripper menu"));
    QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(entry).center());
}

/** The Gripper menu's checked entry, as a person sees it when opening the menu. */
QString checkedGripper(MainWindow &window)
{
    auto *button = window.findChild<QToolButton *>("gripperButton");
    auto *menu = window.findChild<QMenu *>("gripperMenu");
    menu->popup(button->mapToGlobal(button->rect().bottomLeft()));
    QStringList checked;
    for (QAction *action : menu->actions()) {
        if (action->isChecked())
            checked.append(action->text());
    }
    menu->hide();
    return checked.join(", ");
}

/** The message the window shows in a box (which does not block it), closed; else empty. */
QString shownMessage(MainWindow &window)
{
    for (QMessageBox *box : window.findChildren<QMessageBox *>()) {
        if (box->isVisible()) {
            const QString text = box->text() + "\n" + box->informativeText();
            box->close();
            return text;
        }
    }
    return QString();
}

/** Writes `content` to `path` (its folder made); false when it could not. */
bool writeFile(const QString &path, const QByteArray &content)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
}

/** A studio started as `semhap-studio ARGS --pose-port 0 --size 1280x800`, its window shown. */
std::unique_ptr<Studio> startFromCommandLine(const QStringList &args)
{
    StudioOptions o;
    QString text;
    bool help = false;
    if (!StudioOptions::parse(args + QStringList{"--pose-port", "0", "--size", "1280x800"}, &o,
                              &text, &help))
        qWarning("%s", qPrintable(text));
    auto studio = std::make_unique<Studio>(o);
    studio->start();
    if (!QTest::qWaitForWindowExposed(studio->window()))
        qWarning("the window did not show");
    return studio;
}

/**
 * A row per way a scene fails to load, in column `file`: an <include> that does not
 * resolve, an XML syntax error, grips by position servos.
 */
void badSceneRows()
{
    QTest::addColumn<QString>("file");
    static QTemporaryDir dir;
    const QString include = dir.filePath("include.xml");
    writeFile(include, R"(<mujoco model="include"><include file="missing_part.xml"/>
<worldbody/></mujoco>)");
    QTest::newRow("include that does not resolve") << include;
    const QString syntax = dir.filePath("syntax.xml");
    writeFile(syntax, "<mujoco model=\"syntax\"><worldbody><body></worldbody></mujoco>\n");
    QTest::newRow("syntax error") << syntax;
    QFile bundled(":/semhap/scenes/box_and_block.xml");
    QVERIFY(bundled.open(QIODevice::ReadOnly));
    QByteArray servo = bundled.readAll();
    servo.replace(R"(<motor name="right.grip.left" joint="right.slide.left" gear="1")",
                  R"(<position name="right.grip.left" joint="right.slide.left" kp="100")");
    const QString servoFile = dir.filePath("servo.xml");
    writeFile(servoFile, servo);
    QTest::newRow("grips by position servos") << servoFile;
}

/** Opens the file dialog `how` names: a shortcut, a designer action, a router editor menu
 * entry, a plots button or the Gripper menu's entry. */
void openDialog(MainWindow &window, const QString &how)
{
    const QString what = how.section(':', 1);
    if (how.startsWith("key:")) {
        const QKeySequence key(what);
        QTest::keyClick(&window, key[0].key(), key[0].keyboardModifiers());
    } else if (how.startsWith("designer:")) {
        clickDesignerAction(window, what);
    } else if (how.startsWith("gripper:")) {
        chooseGripper(window, what);
    } else if (how.startsWith("router:")) {
        window.findChild<QDockWidget *>("routerDock")->raise();
        for (QAction *action : window.routerEditor()->findChild<QMenu *>("routerMenu")->actions())
            if (action->text() == what)
                action->trigger();
    } else {
        window.findChild<QDockWidget *>("plotsDock")->raise();
        QTest::mouseClick(window.plots()->findChild<QToolButton *>(what), Qt::LeftButton);
    }
}

} // namespace

void TestStudio::fileDialogsStartWhereTheirKindLives()
{
    QFETCH(QString, how);
    QFETCH(QString, folder);
    OwnHome home;
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    window.engine().pause();
    const QString expected = folder == "sessions"   ? PreferencesDialog::sessionsFolder()
                             : folder == "patterns" ? userPatternFolder()
                                                    : home.documents();
    QCOMPARE(dialogFolder([&] { openDialog(window, how); }), QDir(expected).absolutePath());
}

void TestStudio::fileDialogsRememberTheirKindsFolder()
{
    // The folder a kind of file was last saved to is where its next dialog starts, in the
    // next window too; other kinds keep theirs.
    OwnHome home;
    QTemporaryDir exports;
    {
        Workspace workspace;
        MainWindow window(workspace, options());
        QVERIFY(openWindow(window));
        window.engine().pause();
        dialogFolder([&] { openDialog(window, "plots:exportCsv"); }, exports.filePath("a.csv"));
        QVERIFY(QFileInfo::exists(exports.filePath("a.csv")));
        QCOMPARE(dialogFolder([&] { openDialog(window, "plots:exportPng"); }), exports.path());
    }
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    window.engine().pause();
    QCOMPARE(dialogFolder([&] { openDialog(window, "plots:exportCsv"); }), exports.path());
    QCOMPARE(dialogFolder([&] { openDialog(window, "key:Ctrl+Shift+O"); }), home.documents());
    QCOMPARE(dialogFolder([&] { openDialog(window, "designer:importPattern"); }),
             home.documents());
}

void TestStudio::routerFollowsARenamedPattern_data()
{
    addWindowRows();
}

void TestStudio::routerFollowsARenamedPattern()
{
    // A router node plays one of the user's patterns, listed by its name; renamed in the
    // Patterns dock (a taken name refused first), the node follows the file, the inspector
    // shows the new name and the graph still compiles.
    OwnHome home; // the user pattern folder is in it
    StudioOptions o = options();
    o.autoRun = false;
    const std::unique_ptr<Studio> studio = startStudio(o);
    MainWindow &window = *studio->window();
    QVERIFY(window.isActiveWindow());
    WaveformDesigner *designer = window.waveformDesigner();
    QCOMPARE(designer->userFolder(), userPatternFolder());
    window.findChild<QDockWidget *>("patternsDock")->raise();
    designer->openBuiltin("air.squeeze");
    designer->duplicate();
    clickDesignerAction(window, "savePattern"); // air.squeeze.copy: a name to collide with
    designer->openBuiltin("vib.geiger");
    designer->duplicate();
    clickDesignerAction(window, "savePattern");
    const QString old = designer->document()->path();
    QVERIFY(QFileInfo::exists(old));
    RouterEditor *editor = window.routerEditor();
    editor->setParam("right.geiger", "pattern", old);
    QCOMPARE(editor->validate(), QStringList());
    QVERIFY(editor->apply()); // the run plays it too

    designer->document()->setValue("/name", "air.squeeze.copy");
    clickDesignerAction(window, "savePattern");
    QVERIFY(QFileInfo::exists(old));
    QVERIFY2(window.statusBar()->currentMessage().contains("air.squeeze.copy"),
             qPrintable(window.statusBar()->currentMessage()));
    QTest::qWait(100); // the inspector rebuilds queued
    savePicture(&window, "pattern-rename-refused");

    designer->document()->setValue("/name", "my.warning");
    clickDesignerAction(window, "savePattern");
    const QString renamed = userPatternPath(userPatternFolder(), "my.warning");
    QVERIFY(QFileInfo::exists(renamed));
    QVERIFY(!QFileInfo::exists(old));
    const RouterGraph &graph = editor->graph();
    const auto pattern = [&graph] {
        return graph.nodes[size_t(graph.nodeIndex("right.geiger"))]
            .params.value("pattern")
            .toString();
    };
    QCOMPARE(pattern(), renamed);
    QCOMPARE(editor->validate(), QStringList());

    // The inspector shows the node's pattern by its name.
    window.findChild<QDockWidget *>("routerDock")->raise();
    editor->scene()->clearSelection();
    editor->scene()->nodeItem("right.geiger")->setSelected(true);
    QComboBox *picker = nullptr;
    QTRY_VERIFY((picker = editor->inspector()->findChild<QComboBox *>("param:pattern")));
    QTRY_COMPARE(picker->currentText(), QString("my.warning"));
    editor->view()->centerOn(editor->scene()->nodeItem("right.geiger"));
    QTest::qWait(200);
    savePicture(&window, "router-user-pattern");

    // One step back in the editor names the old file again.
    editor->undoStack()->undo();
    QCOMPARE(pattern(), old);

    // The run names the file where it is now: Reset loads it again.
    const RouterGraph &running = window.engine().routerGraph();
    QCOMPARE(running.nodes[size_t(running.nodeIndex("right.geiger"))].params.value("pattern"),
             QJsonValue(renamed));
    QString error;
    QVERIFY2(window.engine().reset(&error), qPrintable(error));
    QCOMPARE(window.routerPicker()->currentText(), QString("C3*"));
}

void TestStudio::buildsAnAlignmentConfirmationByMouse_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QSize>("size");
    QTest::newRow("en-1280x800") << "en" << QSize(1280, 800);
    QTest::newRow("en-1920x1080") << "en" << QSize(1920, 1080);
    QTest::newRow("de-1280x800") << "de" << QSize(1280, 800);
}

// The issue's walk-through: on usb_insertion with C3, a user builds "aligned" (the plug's
// angle to the port within 0.05 rad) by mouse in the router editor, routes it to the filter
// that plays air.squeeze on the right pneumatic band (the squeeze that confirms grasps),
// applies it and runs: the plug.angle plot shows the levels and shades the aligned span,
// and the right band plays the squeeze for it.
void TestStudio::buildsAnAlignmentConfirmationByMouse()
{
    QFETCH(QString, language);
    QFETCH(QSize, size);
    StudioOptions o = options();
    o.size = size;
    o.run.scene = "usb_insertion";
    o.run.router = "C3";
    o.run.operatorName = "reactive";
    o.autoRun = false;
    Studio studio(o);
    MainWindow &window = startIn(studio, language);
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    RouterEditor *editor = window.routerEditor();
    QVERIFY(raiseTab(window, window.findChild<QDockWidget *>("routerDock")->windowTitle()));
    QTRY_VERIFY(editor->view()->isVisible());
    QVERIFY(editor->graph().nodeIndex("right.confirm") >= 0); // C3's, before right.squeeze
    const size_t links = editor->graph().links.size();

    EditorDriver user(editor);
    const QString signal = user.addFromPalette("signal");
    QVERIFY(!signal.isEmpty());
    QVERIFY(user.pick("param:gripper", "right"));
    QVERIFY(user.pick("param:quantity", "plug.angle")); // offered: the scene declares it
    const QString threshold = user.addFromPalette("threshold");
    QVERIFY(!threshold.isEmpty());
    QVERIFY(user.pick("param:gripper", "right"));
    user.type("param:message", "aligned");
    QVERIFY(user.pick("param:category", "confirmation"));
    QVERIFY(user.pick("param:condition", "inside"));
    user.type("param:begin", language == "de" ? "-0,05; 0,05" : "[-0.05, 0.05]");
    const RouterNode &made = editor->graph().nodes[size_t(editor->graph().nodeIndex(threshold))];
    QCOMPARE(made.params.value("begin"), QJsonValue(QJsonArray{-0.05, 0.05}));
    QCOMPARE(made.params.value("message"), "aligned");

    // Laid out and fitted with the toolbar's buttons, then wired port to port.
    for (const QString &button : {RouterEditor::tr("Arrange"), RouterEditor::tr("Fit")}) {
        QToolButton *found = nullptr;
        for (QToolButton *b : editor->findChildren<QToolButton *>()) {
            if (b->text() == button)
                found = b;
        }
        QVERIFY2(found, qPrintable(button));
        QTest::mouseClick(found, Qt::LeftButton);
        user.settle();
    }
    user.wire(signal, "value", threshold, "in");
    user.wire(threshold, "events", "right.confirm", "in");
    QCOMPARE(editor->graph().links.size(), links + 2);
    QTRY_VERIFY2(editor->errors().isEmpty(), qPrintable(editor->errors().join("; ")));
    auto *apply = editor->findChild<QWidget *>("applyButton");
    QVERIFY(apply && apply->isEnabled());
    QTest::mouseClick(apply, Qt::LeftButton);
    QTRY_VERIFY(window.engine().routerGraph().nodeIndex(threshold) >= 0);

    // Run until the operator has the plug aligned over the port.
    window.engine().run();
    const auto alignedSpan = [&window] {
        for (const MessageSpan &span : window.engine().history().spans()) {
            if (messageName(span.message) == "aligned")
                return true;
        }
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(alignedSpan(), 120000);
    // The squeeze node plays for it, and the right band's meter shows it.
    auto *meter = window.findChild<LevelMeter *>("levels:right.air");
    QVERIFY(meter);
    QTRY_VERIFY_WITH_TIMEOUT(
        editor->scene()->nodeItem("right.squeeze")->state().contains("aligned") &&
            *std::max_element(meter->values().begin(), meter->values().end()) > 0.0,
        30000);
    // A few seconds more, so the plots show the run around it.
    QTRY_VERIFY_WITH_TIMEOUT(window.engine().simTime() > 8.0, 60000);
    window.engine().pause();

    // The plug.angle plot: its levels and the aligned span shaded on it.
    const QString dir = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    QString error;
    if (!dir.isEmpty())
        QVERIFY2(Studio::screenshot(
                     &window,
                     QString("%1/walkthrough-router-%2.png").arg(dir, QTest::currentDataTag()),
                     &error),
                 qPrintable(error));
    QVERIFY(raiseTab(window, window.findChild<QDockWidget *>("plotsDock")->windowTitle()));
    auto *plot = window.plots()->findChild<QCustomPlot *>();
    QCPGraph *angle = nullptr;
    for (int g = 0; g < plot->graphCount(); ++g) {
        if (plot->graph(g)->objectName() == "right.plug.angle")
            angle = plot->graph(g);
    }
    QVERIFY(angle);
    QVERIFY(angle->dataCount() > 0);
    QCPAxisRect *rect = angle->keyAxis()->axisRect();
    QStringList levels;
    int shades = 0;
    for (int i = 0; i < plot->itemCount(); ++i) {
        QCPAbstractItem *item = plot->item(i);
        if (item->clipAxisRect() != rect)
            continue;
        if (auto *line = qobject_cast<QCPItemStraightLine *>(item);
            line && line->objectName().startsWith("right.plug.angle/" + threshold))
            levels << QString::number(line->point1->coords().y());
        if (qobject_cast<QCPItemRect *>(item) &&
            item->objectName() == "span.right.aligned/" + threshold)
            ++shades;
    }
    levels.sort();
    QCOMPARE(levels, (QStringList{"-0.05", "0.05"}));
    QVERIFY(shades >= 1);
    if (!dir.isEmpty()) {
        QTest::qWait(300);
        QVERIFY2(Studio::screenshot(
                     &window,
                     QString("%1/walkthrough-plots-%2.png").arg(dir, QTest::currentDataTag()),
                     &error),
                 qPrintable(error));
    }
}

void TestStudio::aSceneThatDoesNotLoadLeavesTheRun_data()
{
    badSceneRows();
}

// A scene file that does not load, opened as a person does it (Ctrl+O, the file dialog), is
// reported in the loader's own words, and the run that was there goes on: its world in the
// viewport, its name in the scene picker and the title, running as before.
void TestStudio::aSceneThatDoesNotLoadLeavesTheRun()
{
    QFETCH(QString, file);
    QString error;
    QVERIFY(!World::load(file, SceneOptions(), &error));
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    Engine &engine = window.engine();
    QComboBox *scene = window.scenePicker();
    scene->setFocus();
    const int bimanual = scene->findData("bimanual_sorting");
    while (scene->currentIndex() != bimanual)
        QTest::keyClick(scene, bimanual > scene->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QTRY_COMPARE(engine.options().scene, QString("bimanual_sorting"));
    QVERIFY(engine.isRunning());
    const World *world = engine.world();

    dialogFolder([&] { openDialog(window, "key:Ctrl+O"); }, file);
    QTRY_VERIFY(window.findChild<QMessageBox *>());
    // The message leaves the window free: nothing modal stands between it and the user.
    QVERIFY(!QApplication::activeModalWidget());
    QCOMPARE(window.findChild<QMessageBox *>()->windowModality(), Qt::NonModal);
    QCOMPARE(shownMessage(window), QString("Could not load scene %1\n%2").arg(file, error));
    QVERIFY2(window.statusBar()->currentMessage().endsWith(error),
             qPrintable(window.statusBar()->currentMessage()));
    QCOMPARE(engine.world(), world);
    QCOMPARE(engine.options().scene, QString("bimanual_sorting"));
    QCOMPARE(scene->currentText(), QString("bimanual_sorting"));
    QVERIFY(window.windowTitle().contains("bimanual_sorting"));
    QVERIFY(engine.isRunning());
    QVERIFY(window.findChild<QAction *>("runAction")->isChecked());
    const double time = engine.simTime();
    QTRY_VERIFY(engine.simTime() > time);
    QString why;
    QVERIFY2(looksDrawn(window.viewport()->grabFramebuffer(), &why), qPrintable(why));

    // A router file that does not load is named as the router, not as the scene.
    dialogFolder([&] { openDialog(window, "key:Ctrl+Shift+O"); }, "/etc/passwd");
    QTRY_VERIFY(window.findChild<QMessageBox *>());
    QVERIFY(!QApplication::activeModalWidget());
    QVERIFY2(shownMessage(window).startsWith("Could not load router /etc/passwd\n/etc/passwd"),
             qPrintable(window.statusBar()->currentMessage()));
    QCOMPARE(engine.options().router, QString("C3"));

    // A scene file that loads takes over, and the run goes on with it, as a picked one does.
    QTemporaryDir dir;
    QFile bundled(":/semhap/scenes/box_and_block.xml");
    QVERIFY(bundled.open(QIODevice::ReadOnly));
    const QString mine = dir.filePath("mine.xml");
    QVERIFY(writeFile(mine, bundled.readAll()));
    dialogFolder([&] { openDialog(window, "key:Ctrl+O"); }, mine);
    QTRY_COMPARE(engine.options().scene, mine);
    QCOMPARE(scene->currentText(), QString("mine.xml"));
    QVERIFY(engine.isRunning());
}

// A scene made for its own router comes with it: dish_wiping with wipe (with C3 its
// plate-holding hand chattered), and back on box_and_block with C3. A router you picked
// stays, and the status bar says which the scene would take.
void TestStudio::eachSceneComesWithItsRouter()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    Engine &engine = window.engine();
    QComboBox *scene = window.scenePicker();
    const auto pick = [&](const QString &name) {
        scene->setFocus();
        const int index = scene->findData(name);
        QVERIFY(index >= 0);
        for (int k = 0; k < 10 && scene->currentIndex() != index; ++k)
            QTest::keyClick(scene, index > scene->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
        QTRY_COMPARE(engine.options().scene, name);
    };
    QCOMPARE(engine.options().router, QString("C3"));
    pick("dish_wiping");
    QTRY_COMPARE(engine.options().router, QString("wipe"));
    QCOMPARE(window.routerPicker()->currentText(), QString("wipe"));
    QVERIFY(engine.isRunning());
    QVERIFY2(window.statusBar()->currentMessage().contains("wipe"),
             qPrintable(window.statusBar()->currentMessage()));
    pick("usb_insertion");
    QTRY_COMPARE(engine.options().router, QString("usb"));
    pick("box_and_block");
    QTRY_COMPARE(engine.options().router, QString("C3"));

    // C1 picked by hand stays with the next scene.
    QComboBox *router = window.routerPicker();
    router->setFocus();
    const int c1 = router->findText("C1");
    QVERIFY(c1 >= 0);
    for (int k = 0; k < 20 && router->currentIndex() != c1; ++k)
        QTest::keyClick(router, c1 > router->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QTRY_COMPARE(engine.options().router, QString("C1"));
    pick("dish_wiping");
    QCOMPARE(engine.options().router, QString("C1"));
    QVERIFY2(window.statusBar()->currentMessage().contains("router of its own, wipe"),
             qPrintable(window.statusBar()->currentMessage()));
}

void TestStudio::aRunThatDoesNotLoadAtTheStartLeavesTheDefaults_data()
{
    badSceneRows();
}

// A scene named on the command line that does not load is reported the same way, and the
// studio opens on the default run, paused, rather than on no scene under a picker naming one.
void TestStudio::aRunThatDoesNotLoadAtTheStartLeavesTheDefaults()
{
    QFETCH(QString, file);
    QString error;
    QVERIFY(!World::load(file, SceneOptions(), &error));
    const std::unique_ptr<Studio> studio = startFromCommandLine({"--scene", file});
    MainWindow *window = studio->window();
    QTRY_VERIFY(window->findChild<QMessageBox *>());
    QCOMPARE(shownMessage(*window),
             QString("Could not load scene %1 with router C3\n%2").arg(file, error));
    Engine &engine = window->engine();
    QVERIFY(engine.isLoaded());
    QCOMPARE(engine.options().scene, QString("box_and_block"));
    QCOMPARE(window->scenePicker()->currentText(), QString("box_and_block"));
    QVERIFY(window->windowTitle().contains("box_and_block"));
    QVERIFY(!engine.isRunning());
    QVERIFY(!window->findChild<QAction *>("runAction")->isChecked());
    QString why;
    QTRY_VERIFY2(looksDrawn(window->viewport()->grabFramebuffer(), &why), qPrintable(why));
}

namespace {

/** The user's gripper folder, where GripperLibrary finds adapters by name. */
QString userGripperFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           "/semhap/grippers";
}

/** The test gripper `slider`'s adapter in the sources (tests/grippers). */
QString sliderAdapter()
{
    return QDir::cleanPath(SEMHAP_TEST_DATA "/../grippers/slider/slider.json");
}

/** Copies the test gripper `slider` (its adapter, its MJCF) into the user's gripper folder. */
bool addSlider()
{
    const QDir slider = QFileInfo(sliderAdapter()).dir();
    QDir().mkpath(userGripperFolder());
    for (const QString &file : slider.entryList(QDir::Files)) {
        if (!QFile::copy(slider.filePath(file), userGripperFolder() + "/" + file))
            return false;
    }
    return true;
}

/**
 * Fills the user's gripper folder: `slider`, which loads; `nomodel` (the slider's adapter
 * naming a model that is not there, as a shipped adapter's before it is downloaded) and
 * `broken` (its JSON breaks off), which do not.
 */
bool addTestGrippers()
{
    QFile slider(sliderAdapter());
    if (!addSlider() || !slider.open(QIODevice::ReadOnly))
        return false;
    // Its model where a download would put it: a folder that is not there.
    const QByteArray noModel =
        slider.readAll().replace("\"slider.xml\"", "\"nomodel/slider.xml\"");
    return writeFile(userGripperFolder() + "/nomodel.json", noModel) &&
           writeFile(userGripperFolder() + "/broken.json", "{\"format\": \"semhap.gripper/1\",\n");
}

} // namespace

void TestStudio::gripperMenuPicksAnAdapter_data()
{
    QTest::addColumn<QString>("entry");   // what the user picks in the Gripper menu
    QTest::addColumn<QString>("gripper"); // what that is: a name, or the file chosen
    QTest::addColumn<bool>("loads");
    QTest::newRow("an adapter of the gripper folder, by name") << "slider"
                                                               << "slider" << true;
    QTest::newRow("another file") << "Other file…" << sliderAdapter() << true;
    QTest::newRow("a model not downloaded") << "nomodel"
                                            << "nomodel" << false;
    QTest::newRow("a broken adapter") << "broken"
                                      << "broken" << false;
}

// The Gripper menu beside the scene picker lists the scene's own, the gripper folders'
// adapters by name and another file. A choice loads the scene with it, the run going on, and
// the menu's check, the title, the tooltip and the icon say so; one that does not load is
// reported in the loader's words, and the run, the world and all of these stay as they were.
void TestStudio::gripperMenuPicksAnAdapter()
{
    QFETCH(QString, entry);
    QFETCH(QString, gripper);
    QFETCH(bool, loads);
    OwnHome home;
    QVERIFY(addTestGrippers());
    QString error;
    QCOMPARE(World::load("box_and_block", SceneOptions{-1, gripper}, &error) != nullptr, loads);
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    Engine &engine = window.engine();
    QCOMPARE(checkedGripper(window), QString("Scene's own"));
    auto *button = window.findChild<QToolButton *>("gripperButton");
    // The button's jaws are blue while an adapter's gripper is in the scene.
    const auto blueJaws = [button] {
        return pixelsOfColour(button->icon().pixmap(32).toImage(), colors::Confirmation) > 0;
    };
    QVERIFY(!blueJaws());
    const World *world = engine.world();
    QVERIFY(!world->gripperMount());

    if (entry == "Other file…")
        QCOMPARE(dialogFolder([&] { chooseGripper(window, entry); }, gripper), home.documents());
    else
        chooseGripper(window, entry);
    const QString shown = QFileInfo(gripper).fileName();
    if (loads) {
        QTRY_COMPARE(engine.options().sceneOptions.gripper, gripper);
        QVERIFY(engine.world()->gripperMount()); // the adapter's model is in the wrist
        QCOMPARE(checkedGripper(window), shown);
        QVERIFY2(window.windowTitle().contains("box_and_block with " +
                                               QFileInfo(gripper).completeBaseName()),
                 qPrintable(window.windowTitle()));
        QVERIFY2(button->toolTip().startsWith("Gripper: " + shown), qPrintable(button->toolTip()));
        QVERIFY(blueJaws());
    } else {
        QTRY_VERIFY(window.findChild<QMessageBox *>());
        QCOMPARE(
            shownMessage(window),
            QString("Could not load gripper %1 into scene box_and_block\n%2").arg(gripper, error));
        QVERIFY2(window.statusBar()->currentMessage().endsWith(error),
                 qPrintable(window.statusBar()->currentMessage()));
        QCOMPARE(engine.world(), world);
        QVERIFY(engine.options().sceneOptions.gripper.isEmpty());
        QCOMPARE(checkedGripper(window), QString("Scene's own"));
        QVERIFY(!window.windowTitle().contains(" with "));
        QVERIFY2(button->toolTip().startsWith("Gripper: the scene's own"),
                 qPrintable(button->toolTip()));
        QVERIFY(!blueJaws());
    }
    QVERIFY(engine.isRunning());
    QCOMPARE(window.scenePicker()->currentText(), QString("box_and_block"));

    // Another scene keeps the gripper; the scene's own brings the scene's back.
    QComboBox *scene = window.scenePicker();
    scene->setFocus();
    QTest::keyClick(scene, Qt::Key_Down);
    QTRY_VERIFY(engine.options().scene != "box_and_block");
    QCOMPARE(engine.options().sceneOptions.gripper, loads ? gripper : QString());
    QCOMPARE(bool(engine.world()->gripperMount()), loads);
    chooseGripper(window, "Scene's own");
    QTRY_VERIFY(engine.options().sceneOptions.gripper.isEmpty());
    QVERIFY(!engine.world()->gripperMount());
    QCOMPARE(checkedGripper(window), QString("Scene's own"));
    QVERIFY(!window.windowTitle().contains(" with "));
    QVERIFY(!blueJaws());
    QVERIFY(engine.isRunning());
}

// The gripper is part of the run: a language switch keeps it, the next start opens it again
// (the workspace file has it), and `--gripper NAME` opens it.
void TestStudio::gripperIsKept()
{
    OwnHome home;
    QVERIFY(addTestGrippers());
    const auto hasSlider = [](MainWindow &window) {
        return window.engine().options().sceneOptions.gripper == "slider" &&
               window.engine().world()->gripperMount() && checkedGripper(window) == "slider";
    };
    {
        Studio studio(options());
        studio.start();
        MainWindow *window = studio.window();
        QVERIFY(QTest::qWaitForWindowExposed(window));
        chooseGripper(*window, "slider");
        QTRY_VERIFY(hasSlider(*window));
        pickLanguage(studio, "de");
        QVERIFY(QTest::qWaitForWindowExposed(studio.window()));
        QVERIFY(hasSlider(*studio.window()));
        QVERIFY(studio.window()->windowTitle().contains("box_and_block mit slider"));
        QVERIFY(studio.window()->engine().isRunning());
        pickLanguage(studio, "en"); // for the next start
        studio.window()->close();
    }
    {
        Studio studio(options());
        studio.start();
        QVERIFY(QTest::qWaitForWindowExposed(studio.window()));
        QVERIFY(hasSlider(*studio.window()));
        QVERIFY(studio.window()->engine().isRunning());
        studio.window()->close();
    }
    QFile::remove(Workspace::defaultFile());
    const std::unique_ptr<Studio> studio = startFromCommandLine({"--gripper", "slider"});
    QVERIFY(hasSlider(*studio->window()));
    QVERIFY(studio->window()->engine().isRunning());
}

// A gripper that does not load at the start — named on the command line, or kept in the
// workspace from the last time — is said in the loader's words, and the studio opens on the
// default run with the scene's own gripper.
void TestStudio::aGripperThatDoesNotLoadAtTheStartIsReported()
{
    OwnHome home;
    QVERIFY(addTestGrippers());
    QString error;
    QVERIFY(!World::load("box_and_block", SceneOptions{-1, "nomodel"}, &error));
    {
        const std::unique_ptr<Studio> studio = startFromCommandLine({"--gripper", "nomodel"});
        MainWindow *window = studio->window();
        QTRY_VERIFY(window->findChild<QMessageBox *>());
        QCOMPARE(shownMessage(*window),
                 "Could not load scene box_and_block with gripper nomodel and router C3\n" +
                     error);
        QVERIFY(window->engine().world());
        QVERIFY(!window->engine().world()->gripperMount());
        QVERIFY(!window->engine().isRunning());
        QCOMPARE(checkedGripper(*window), QString("Scene's own"));
        window->close();
    }

    const QString file = Workspace::defaultFile();
    QVERIFY(writeFile(file, R"({"format": "semhap.workspace/1", "simulation": {
        "scene": "bimanual_sorting", "gripper": "nomodel", "router": "C3"}})"));
    QVERIFY(!World::load("bimanual_sorting", SceneOptions{-1, "nomodel"}, &error));
    Studio studio(options());
    studio.start();
    MainWindow *window = studio.window();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    const QString message = window->statusBar()->currentMessage();
    QVERIFY2(message.contains(file + ": /simulation: " + error), qPrintable(message));
    QVERIFY(window->engine().world());
    QVERIFY(!window->engine().world()->gripperMount());
    QCOMPARE(checkedGripper(*window), QString("Scene's own"));
}

void TestStudio::gripperMenuScreenshots_data()
{
    addWindowRows();
}

// The Gripper menu open under its button with the test gripper picked, as the screen shows
// it (the menu is a window of its own), to be looked at: it lists the scene's own, every
// adapter of the gripper folders (the shipped ones too) and another file, and lies on the
// screen whole; its button is in the toolbar, not in its overflow.
void TestStudio::gripperMenuScreenshots()
{
    OwnHome home;
    QVERIFY(addSlider());
    const QStringList names = GripperLibrary::names();
    for (const QString name : {"franka_hand", "robotiq_2f85", "slider"})
        QVERIFY2(names.contains(name), qPrintable(names.join(", ")));
    StudioOptions o = options();
    o.autoRun = false;
    auto studio = startStudio(o);
    MainWindow *window = studio->window();
    auto *button = window->findChild<QToolButton *>("gripperButton");
    QVERIFY(button && button->isVisible());
    chooseGripper(*window, "slider");
    QTRY_COMPARE(window->engine().options().sceneOptions.gripper, QString("slider"));
    auto *menu = window->findChild<QMenu *>("gripperMenu");
    menu->popup(button->mapToGlobal(button->rect().bottomLeft()));
    QVERIFY(QTest::qWaitForWindowExposed(menu));
    QStringList entries;
    for (QAction *action : menu->actions())
        entries.append(action->text());
    const QStringList expected =
        QStringList{MainWindow::tr("Gripper"), MainWindow::tr("Scene's own")} + names +
        QStringList{QString(), MainWindow::tr("Other file…")};
    QCOMPARE(entries, expected);
    QVERIFY(window->screen()->availableGeometry().contains(menu->geometry()));
    QTest::qWait(200);
    const QString folder = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    if (!folder.isEmpty()) {
        const QRect frame = window->frameGeometry();
        const QPixmap picture =
            window->screen()->grabWindow(0, frame.x(), frame.y(), frame.width(), frame.height());
        QVERIFY(picture.save(
            QString("%1/gripper-menu-%2.png").arg(folder, QTest::currentDataTag()), "PNG"));
    }
    menu->hide();
}

QTEST_MAIN(TestStudio)
#include "tst_studio.moc"
