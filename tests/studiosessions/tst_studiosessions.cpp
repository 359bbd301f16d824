// SPDX-License-Identifier: MIT
// Sessions in the studio: the engine records what it runs, the window records, reopens and
// scrubs a session, and re-routing a recording through the editor's router gives what a
// pipeline gives for the same frames.
#include "eventlogmodel.h"
#include "eventlogpanel.h"
#include "foxglovepeers.h"
#include "liverigdialog.h"
#include "mainwindow.h"
#include "openwindow.h"
#include "pipeline.h"
#include "plotpanel.h"
#include "preferencesdialog.h"
#include "replaybar.h"
#include "router.h"
#include "routereditor.h"
#include "routergraph.h"
#include "runtoolbar.h"
#include "sessionblocks.h"
#include "sessionreader.h"
#include "sessionreplay.h"
#include "simviewport.h"
#include "statusbar.h"
#include "studiofolders.h"
#include "widgetchecks.h"
#include "workspace.h"
#include "world.h"

#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QHelpEvent>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProcess>
#include <QRadioButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QToolTip>
#include <QTranslator>
#include <QUdpSocket>

#include <qcustomplot.h>

#include <cmath>
#include <limits>

using namespace semhap;

class TestStudioSessions : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void engineRecordsWhatTheHistorySees();
    void windowRecordsReopensAndScrubs();
    void reroutesThroughTheEditorsRouter();
    void replaySaysWhichRowsItSkipped();
    void windowListensToALiveRig();
    void aLiveRigFollowsARobot();
    void closingAReplayBringsTheRunBack();
    void exportsTheReplayedSession();
    void opensARobotRecording();
    void replayNamesAnEditedRouter();
    void recordingMidGraspShowsTheGraspFromItsStart();
    void untitledRerouteLeavesNoPickerEntry();
    void routerStatusTellsTheReplayFromTheRun();
    void replayWordsFitTheWindow_data();
    void replayWordsFitTheWindow();
    void statusBarKeepsItsWordsApart_data();
    void statusBarKeepsItsWordsApart();
    void routerStatusGoesWithAnotherRouter_data();
    void routerStatusGoesWithAnotherRouter();
    void routerPickerShowsTheWholeName_data();
    void routerPickerShowsTheWholeName();
    void cleanupTestCase();

private:
    /** Records about `seconds` of simulated C3 from an engine into a new file. */
    QString recordFromEngine(double seconds, qint64 *frames, qint64 *events);

    QTemporaryDir m_dir;
};

namespace {

StudioOptions studioOptions()
{
    StudioOptions o;
    QString message;
    bool help = false;
    StudioOptions::parse(
        {"--speed", "4", "--pose-port", "0", "--size", "1280x800", "--default-layout"}, &o,
        &message, &help);
    return o;
}

/** Events compared by value. */
bool sameEvents(const std::vector<SemanticEvent> &a, const std::vector<SemanticEvent> &b)
{
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](const auto &x, const auto &y) {
               return x.t == y.t && x.node == y.node && x.message == y.message &&
                      x.phase == y.phase && x.intensity == y.intensity;
           });
}

/**
 * Opens `path` as a person does: the shortcut (Ctrl+Alt+O a session, Ctrl+Shift+O a router
 * with `modifiers`), the file typed into the dialog, Return.
 */
void openWithKeys(MainWindow &window, const QString &path, Qt::KeyboardModifiers modifiers)
{
    QTimer::singleShot(0, [path] {
        QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()));
        auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        dialog->selectFile(path);
        QTest::keyClick(dialog->focusWidget() ? dialog->focusWidget() : dialog, Qt::Key_Return);
    });
    QTest::keyClick(&window, Qt::Key_O, modifiers);
}

/** Opens the session at `path` with Ctrl+Alt+O. */
void openSessionWithKeys(MainWindow &window, const QString &path)
{
    openWithKeys(window, path, Qt::ControlModifier | Qt::AltModifier);
}

/** Records from now until the run's time passed `seconds` more, with Ctrl+Shift+R. */
QString recordWithKeys(MainWindow &window, double seconds)
{
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    const QString path = window.engine().recordingPath();
    const double from = window.engine().simTime();
    if (!QTest::qWaitFor([&] { return window.engine().simTime() > from + seconds; }, 30000))
        return QString();
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    return window.engine().isRecording() ? QString() : path;
}

/** Router → New ("untitled", no file) in `editor`, filled with C1's graph. */
bool buildUntitledRouter(RouterEditor *editor)
{
    QString error;
    RouterGraph c1;
    LoadError loadError;
    if (!editor->newFromPreset(QString(), &error) || !RouterPresets::preset("C1", &c1, &loadError))
        return false;
    c1.name = editor->graph().name;
    c1.file.clear();
    editor->setGraph(c1);
    return true;
}

/** The latest time any of the plot's graphs holds; -1 when none holds anything. */
double lastPlotted(const QCustomPlot *plot, double *first = nullptr)
{
    double last = -1.0;
    double earliest = std::numeric_limits<double>::infinity();
    for (int g = 0; g < plot->graphCount(); ++g) {
        bool found = false;
        const QCPRange keys = plot->graph(g)->getKeyRange(found);
        if (found) {
            last = std::max(last, keys.upper);
            earliest = std::min(earliest, keys.lower);
        }
    }
    if (first)
        *first = earliest;
    return last;
}

/** The studio's strings in `language` ("en" or "de") while it lives. */
struct Speaking
{
    explicit Speaking(const QString &language)
    {
        if (language != "de")
            return;
        loaded = german.load(QLocale(QLocale::German), "semhap", "_", ":/i18n");
        QCoreApplication::installTranslator(&german);
    }
    ~Speaking() { QCoreApplication::removeTranslator(&german); }
    QTranslator german;
    bool loaded = true;
};

} // namespace

void TestStudioSessions::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    // Recordings go to the default folder unless a test chooses another.
    QSettings().remove("sessions/folder");
    QVERIFY(m_dir.isValid());
}

QString TestStudioSessions::recordFromEngine(double seconds, qint64 *frames, qint64 *events)
{
    Engine engine;
    RunOptions options;
    options.duration = 3600.0;
    QString error;
    if (!engine.load(options, &error))
        return {};
    const QString path = m_dir.filePath(QStringLiteral("engine-%1.db").arg(seconds));
    if (!engine.startRecording(path, QStringLiteral("from the test"), &error))
        return {};
    engine.setSpeed(8.0);
    engine.run();
    if (!QTest::qWaitFor([&] { return engine.simTime() >= seconds; }, 30000))
        return {};
    engine.pause();
    engine.stopRecording();
    QTest::qWait(100); // the last values drain into the history
    const RunHistory &history = engine.history();
    *frames = history.frames(Gripper::Left).end() + history.frames(Gripper::Right).end();
    *events = history.events().end();
    return path;
}

void TestStudioSessions::engineRecordsWhatTheHistorySees()
{
    qint64 frames = 0;
    qint64 events = 0;
    const QString path = recordFromEngine(2.5, &frames, &events);
    QVERIFY(!path.isEmpty());
    QString error;
    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    QVERIFY(frames > 1000);
    QCOMPARE(reader->contactFrameCount(), frames);
    QVERIFY(events > 0);
    QCOMPARE(reader->eventCount(), events);
    QCOMPARE(reader->info().source, QString("studio"));
    QCOMPARE(reader->info().notes, QString("from the test"));
    QVERIFY(reader->info().ended.isValid());
    QVERIFY(reader->deviceFrameCount() > 0);
}

void TestStudioSessions::windowRecordsReopensAndScrubs()
{
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    QVERIFY(window.engine().isRunning());
    // Where recordings go: File → Preferences, typed into the sessions folder field.
    const QString folder = m_dir.filePath("my sessions");
    QTimer::singleShot(0, this, [folder] {
        auto *dialog = qobject_cast<PreferencesDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        QLineEdit *edit = dialog->sessionsFolderEdit();
        QCOMPARE(edit->text(), QDir::toNativeSeparators(StudioFolders::sessions()));
        edit->setFocus();
        edit->selectAll();
        QTest::keyClicks(edit, folder);
        dialog->grab().save(QCoreApplication::applicationDirPath() + "/preferences.png");
        QTest::keyClick(edit, Qt::Key_Return);
    });
    window.findChild<QAction *>("preferencesAction")->trigger();
    QCOMPARE(StudioFolders::sessions(), folder);

    QTest::keyClicks(window.runToolBar()->sessionNameEdit(), "p07/baseline");
    QTest::keyClicks(window.runToolBar()->notesEdit(), "participant 7");
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(window.engine().isRecording());
    const QString path = window.engine().recordingPath();
    QCOMPARE(QFileInfo(path).absolutePath(), folder);
    QVERIFY2(QFileInfo(path).fileName().startsWith("p07_baseline-"), qPrintable(path));
    QVERIFY(path.endsWith(".db"));
    QTRY_VERIFY(window.findChild<QLabel *>("recordLabel")->text().contains("dropped"));
    const double from = window.engine().simTime();
    QTRY_VERIFY_WITH_TIMEOUT(window.engine().simTime() > from + 6.0, 30000);
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(!window.engine().isRecording());

    QString error;
    QVERIFY(window.openSession(path));
    QVERIFY(!window.engine().isRunning());
    SessionReplay *replay = window.replay();
    QVERIFY(replay->isOpen());
    QVERIFY(window.replayBar()->isVisible());
    // The run's controls are off while a replay owns the window.
    for (const char *name : {"runAction", "stepAction", "driveAction", "recordAction"})
        QVERIFY2(!window.findChild<QAction *>(name)->isEnabled(), name);
    QVERIFY(replay->endTime() > replay->startTime() + 3.0);
    // The bar says what the session was: its scene, and on hover its notes and dates.
    auto *about = window.replayBar()->findChild<QLabel *>("replayAbout");
    QCOMPARE(about->text(), QString("box_and_block"));
    QVERIFY(about->toolTip().contains("Started: "));
    QVERIFY2(about->toolTip().contains("Notes: participant 7"), qPrintable(about->toolTip()));
    QVERIFY(about->toolTip().contains("Recorded by: studio"));
    QCOMPARE(window.replayBar()->findChild<QLabel *>("replaySource")->text(),
             QString("Showing: recorded with C3"));
    // The viewport shows the recorded scene (schema 2 keeps its states at display rate).
    QVERIFY2(replay->world(), qPrintable(replay->sceneNote()));
    QCOMPARE(window.viewport()->placeholder(), QString());
    QCOMPARE(window.viewport()->caption(), QString("Replay"));
    const std::vector<double> atStart = replay->world()->sceneState();
    const quint64 drawn = window.viewport()->renderedFrames();
    QTRY_VERIFY(window.viewport()->renderedFrames() > drawn);
    // At 1280 px the bar's words all fit.
    QTest::qWait(100);
    QCOMPARE(clippedTexts(window.replayBar()), QStringList());

    // Scrub from the keyboard: to the end, then one page (1 s) back.
    QSlider *slider = window.replayBar()->slider();
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_End);
    QTest::keyClick(slider, Qt::Key_PageDown);
    const double t = replay->time();
    QVERIFY(std::abs(t - (replay->endTime() - 1.0)) < 1e-3);
    // The bodies moved with the scrubber: the session's state at t, not the start's.
    QVERIFY(replay->world()->sceneState() != atStart);
    // The picture for the manual: scrubbed in, the plots show the session (replotted, and
    // the status bar's 250 ms timer wrote the time scrubbed to).
    if (const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !shots.isEmpty()) {
        QTest::qWait(300);
        window.grab().save(shots + "/replay-1280x800.png");
    }
    std::unique_ptr<SessionReader> recorded = SessionReader::open(path, &error);
    QVERIFY(recorded);
    SceneState stateAtT;
    QVERIFY(recorded->readSceneState(t, &stateAtT, &error));
    QVERIFY(stateAtT.t <= t && stateAtT.t > t - 0.05);
    // As recorded, up to MuJoCo renormalising the quaternions when the pose is shown: a
    // state recorded mid-step is off unit length by ~1e-10, depending on the machine's load.
    const std::vector<double> shown = replay->world()->sceneState();
    QCOMPARE(shown.size(), stateAtT.pose.size());
    for (size_t i = 0; i < shown.size(); ++i)
        QVERIFY2(std::abs(shown[i] - stateAtT.pose[i]) <= 1e-9,
                 qPrintable(QString("pose[%1]: %2 vs %3")
                                .arg(i)
                                .arg(shown[i], 0, 'g', 17)
                                .arg(stateAtT.pose[i], 0, 'g', 17)));
    QTRY_VERIFY(window.eventLog()->model()->rowCount() > 0);
    const EventLogModel *log = window.eventLog()->model();
    for (int row = 0; row < log->rowCount(); ++row)
        QVERIFY(log->index(row, 0).data(EventLogModel::TimeRole).toDouble() <= t);
    auto *plot = window.plots()->findChild<QCustomPlot *>();
    QTRY_VERIFY(plot->graphCount() > 0 && plot->graph(0)->dataCount() > 0);
    double last = -1.0;
    for (int g = 0; g < plot->graphCount(); ++g) {
        bool found = false;
        const QCPRange keys = plot->graph(g)->getKeyRange(found);
        if (found)
            last = std::max(last, keys.upper);
    }
    QVERIFY2(last <= t + 1e-9 && last > t - 0.05, qPrintable(QString::number(last)));
    // The documentation's screenshot: SEMHAP_REPLAY_SCREENSHOT=FILE.png.
    if (qEnvironmentVariableIsSet("SEMHAP_REPLAY_SCREENSHOT")) {
        QTest::qWait(500); // the plots and the viewport repaint on the event loop
        window.grab().save(qEnvironmentVariable("SEMHAP_REPLAY_SCREENSHOT"));
    }

    // A click on the groove jumps there (it paged 1 s), and a click near its left end
    // shows less.
    const QPoint start = slider->rect().center();
    const double span = replay->endTime() - replay->startTime();
    const auto fraction = [&] { return (replay->time() - replay->startTime()) / span; };
    QTest::mouseClick(slider, Qt::LeftButton, {}, QPoint(slider->width() / 4, start.y()));
    QVERIFY2(std::abs(fraction() - 0.25) < 0.1, qPrintable(QString::number(fraction())));
    QTest::mouseClick(slider, Qt::LeftButton, {}, QPoint(4, start.y()));
    QVERIFY2(fraction() < 0.05, qPrintable(QString::number(fraction())));
    QVERIFY(replay->time() < t);
    // ... in the plots too: nothing after the new time, whatever the run left behind.
    QTest::qWait(300);
    double latest = -1.0;
    for (int g = 0; g < plot->graphCount(); ++g) {
        bool found = false;
        const QCPRange keys = plot->graph(g)->getKeyRange(found);
        if (found)
            latest = std::max(latest, keys.upper);
    }
    QVERIFY2(latest <= replay->time() + 1e-9, qPrintable(QString::number(latest)));

    // Playing moves on; closing brings the simulation back.
    QTest::mouseClick(window.replayBar()->playButton(), Qt::LeftButton);
    const double before = replay->time();
    QTRY_VERIFY(replay->time() > before + 0.2);
    QTest::mouseClick(window.replayBar()->closeButton(), Qt::LeftButton);
    QVERIFY(!replay->isOpen());
    QVERIFY(window.engine().world());
    QVERIFY(!window.replayBar()->isVisible());
}

void TestStudioSessions::reroutesThroughTheEditorsRouter()
{
    qint64 frames = 0;
    qint64 events = 0;
    const QString path = recordFromEngine(3.0, &frames, &events);
    QVERIFY(!path.isEmpty());

    // The reference: the recorded frames through a pipeline with C1.
    QString error;
    std::unique_ptr<SessionReader> reader = SessionReader::open(path, &error);
    QVERIFY2(reader, qPrintable(error));
    RouterGraph c1;
    LoadError loadError;
    QVERIFY(RouterPresets::preset("C1", &c1, &loadError));
    std::unique_ptr<Router> router = Router::compile(c1, &loadError);
    QVERIFY(router);
    Pipeline pipeline(std::move(router));
    struct : PipelineSink
    {
        void onEvent(const SemanticEvent &event) override { events.push_back(event); }
        std::vector<SemanticEvent> events;
    } expected;
    QVERIFY(reader->readContactFrames(
        [&](const ContactFrame &frame, double) {
            pipeline.process(frame, expected);
            return true;
        },
        &error));
    pipeline.flush(expected);
    QVERIFY(!expected.events.empty());

    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    QVERIFY(window.openSession(path));
    SessionReplay *replay = window.replay();
    QCOMPARE(qint64(replay->events().size()), reader->eventCount());
    window.routerEditor()->setGraph(c1);
    QTest::mouseClick(window.replayBar()->rerouteButton(), Qt::LeftButton);
    QVERIFY(replay->isRerouted());
    QCOMPARE(window.replayBar()->findChild<QLabel *>("replaySource")->text(),
             QString("Showing: re-routed through C1"));
    QVERIFY(sameEvents(replay->events(), expected.events));
    QVERIFY(window.replayBar()->recordedButton()->isEnabled());
    QTest::mouseClick(window.replayBar()->recordedButton(), Qt::LeftButton);
    QVERIFY(!replay->isRerouted());
    QCOMPARE(qint64(replay->events().size()), reader->eventCount());
}

void TestStudioSessions::replaySaysWhichRowsItSkipped()
{
    // Rows a program wrote wrong are skipped, and the window says so instead of showing them.
    qint64 frames = 0;
    qint64 events = 0;
    const QString path = recordFromEngine(4.0, &frames, &events);
    QVERIFY(!path.isEmpty());
    QVERIFY2(events > 0, "the run must have had a message to damage");
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "damage");
        db.setDatabaseName(path);
        QVERIFY(db.open());
        QSqlQuery query(db);
        std::vector<double> rows = emptyContactRow(0.5, 0);
        rows[3] = -1; // a negative force, twice
        rows.insert(rows.end(), rows.begin(), rows.end());
        rows[SessionSchema::ContactColumns] = 0.6;
        QVERIFY(query.exec(insertBlock(SessionSchema::Stream::ContactFrames, rows,
                                       SessionSchema::ContactColumns)));
        QVERIFY(query.exec("UPDATE events SET message = 'Shout!' WHERE rowid = 1"));
        db.close();
    }
    QSqlDatabase::removeDatabase("damage");
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    QVERIFY(window.openSession(path));
    QCOMPARE(window.replay()->skippedRows(), qint64(3));
    QCOMPARE(qint64(window.replay()->events().size()), events - 1);
    QCOMPARE(window.statusBar()->currentMessage(),
             QString("3 row(s) of the session break the stream rules and were skipped (semhap "
                     "replay lists them)"));
    if (const QByteArray dir = qgetenv("SEMHAP_SCREENSHOTS"); !dir.isEmpty())
        window.grab().save(QString::fromLocal8Bit(dir) + "/replay-skipped-rows.png");
}

void TestStudioSessions::windowListensToALiveRig()
{
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    int port = 0;
    {
        QUdpSocket probe; // a port free right now
        QVERIFY(probe.bind(QHostAddress::LocalHost, 0));
        port = probe.localPort();
    }

    // File → Listen for a live rig (Ctrl+L): type the port, keep it on this machine, Listen.
    QTimer::singleShot(0, this, [port] {
        auto *dialog = qobject_cast<LiveRigDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        QVERIFY(!dialog->networkCheck()->isChecked());
        QRadioButton *udp = dialog->udpChoice();
        QTest::mouseClick(udp, Qt::LeftButton, {}, QPoint(8, udp->height() / 2));
        QSpinBox *edit = dialog->portEdit();
        edit->setFocus();
        edit->selectAll();
        QTest::keyClicks(edit, QString::number(port));
        QTest::keyClick(edit, Qt::Key_Return);
    });
    QTest::keyClick(&window, Qt::Key_L, Qt::ControlModifier);
    QVERIFY(window.engine().isLive());
    QVERIFY(window.engine().isRunning());
    QCOMPARE(window.engine().liveUri(), QStringLiteral("udp:127.0.0.1:%1").arg(port));
    QVERIFY(window.windowTitle().contains("live rig"));
    QCOMPARE(window.runToolBar()->scenePicker()->currentText(), QString("Live rig…"));
    QVERIFY(window.viewport()->placeholder().startsWith("Live rig on udp:127.0.0.1"));
    // What only the simulation has is off: stepping, pacing, driving.
    for (const char *name : {"stepAction", "driveAction", "fasterAction", "slowerAction"})
        QVERIFY2(!window.findChild<QAction *>(name)->isEnabled(), name);
    QVERIFY(!window.runToolBar()->speedPicker()->isEnabled());
    QVERIFY(window.findChild<QAction *>("recordAction")->isEnabled());

    // Record while the rig sends a few seconds of the trace and some garbage.
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(window.engine().isRecording());
    const QString path = window.engine().recordingPath();
    QVERIFY2(QFileInfo(path).fileName().startsWith("live-C3-"), qPrintable(path));
    QCOMPARE(QFileInfo(path).absolutePath(), StudioFolders::sessions());
    QFile trace(SEMHAP_RESOURCES "/traces/demo.jsonl");
    QVERIFY(trace.open(QIODevice::ReadOnly));
    QUdpSocket sender;
    for (int line = 0; line < 1400 && !trace.atEnd(); ++line) {
        sender.writeDatagram(trace.readLine(), QHostAddress::LocalHost, quint16(port));
        // At most a few dozen unread: loopback drops what the socket's buffer cannot hold.
        if (line % 32 == 31)
            QVERIFY(QTest::qWaitFor(
                [&] { return window.engine().liveStats().datagrams + 64 > quint64(line); },
                10000));
    }
    sender.writeDatagram("{\"t\": oops", QHostAddress::LocalHost, quint16(port));
    QTRY_COMPARE(window.engine().liveStats().frames + window.engine().liveStats().rejected,
                 quint64(1401));
    QTRY_VERIFY(window.eventLog()->model()->rowCount() > 0);
    auto *rate = window.findChild<QLabel *>("rateLabel");
    QTRY_VERIFY2(rate->text().contains("1 malformed"), qPrintable(rate->text()));
    QTRY_VERIFY(window.statusBar()->currentMessage().contains("invalid JSON"));
    // Once the message has gone (or a narrow window cut it), the count still says why.
    QVERIFY2(rate->toolTip().contains("invalid JSON"), qPrintable(rate->toolTip()));
    QVERIFY(window.findChild<QLabel *>("operatorLabel")->text().contains("Live rig"));
    // The rig's second hand came after the plots were built for the scene's one: its rects
    // are added and every rect keeps its readable height, the panel scrolling instead.
    auto *plot = window.plots()->findChild<QCustomPlot *>();
    QTRY_COMPARE(plot->axisRectCount(), 11); // two hands' force and contacts, seven devices
    plot->replot();
    for (QCPAxisRect *rect : plot->axisRects())
        QVERIFY2(rect->rect().height() >= rect->minimumSize().height() - 1,
                 qPrintable(QString("%1 px high, %2 wanted")
                                .arg(rect->rect().height())
                                .arg(rect->minimumSize().height())));
    if (qEnvironmentVariableIsSet("SEMHAP_LIVE_SCREENSHOT")) {
        QTest::qWait(500);
        window.grab().save(qEnvironmentVariable("SEMHAP_LIVE_SCREENSHOT"));
    }
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(!window.engine().isRecording());
    QString error;
    std::unique_ptr<SessionReader> session = SessionReader::open(path, &error);
    QVERIFY2(session, qPrintable(error));
    QCOMPARE(session->contactFrameCount(), qint64(1400));
    QVERIFY(session->eventCount() > 0);

    // Stop all holds the rig's frames back: nothing reaches the devices until Run.
    QTest::keyClick(&window, Qt::Key_Escape);
    QVERIFY(!window.engine().isRunning());
    sender.writeDatagram(trace.readLine(), QHostAddress::LocalHost, quint16(port));
    QTRY_COMPARE(window.engine().liveStats().held, quint64(1));

    // Picking a scene goes back to the simulation.
    QComboBox *scene = window.runToolBar()->scenePicker();
    scene->setFocus();
    const int bimanual = scene->findData("bimanual_sorting");
    while (scene->currentIndex() != bimanual)
        QTest::keyClick(scene, bimanual > scene->currentIndex() ? Qt::Key_Down : Qt::Key_Up);
    QVERIFY(!window.engine().isLive());
    QVERIFY(window.engine().world());
    QVERIFY(window.viewport()->placeholder().isEmpty());
    QVERIFY(window.findChild<QAction *>("stepAction")->isEnabled());

    // The picker's "Live rig" entry asks where to listen; cancelled, the scene stays.
    const int live = scene->findData("semhap:live-rig");
    QCOMPARE(live, scene->count() - 1);
    while (scene->currentIndex() != live - 1)
        QTest::keyClick(scene, Qt::Key_Down);
    const QString before = scene->currentData().toString();
    bool asked = false;
    QTimer::singleShot(0, this, [&asked] {
        auto *dialog = qobject_cast<LiveRigDialog *>(QApplication::activeModalWidget());
        asked = dialog != nullptr;
        if (dialog)
            dialog->reject();
    });
    QTest::keyClick(scene, Qt::Key_Down);
    QVERIFY(asked);
    QVERIFY(!window.engine().isLive());
    QCOMPARE(scene->currentData().toString(), before);
}

void TestStudioSessions::aLiveRigFollowsARobot()
{
    // The reference robot (tests/interop/foxglove-robot.mjs) plays its grasp once asked.
    QProcess robot;
    const int port = startRobot(robot, {"--hold"});
    QVERIFY(port > 0);
    const QString url = QStringLiteral("ws://127.0.0.1:%1").arg(port);
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));

    // File → Listen for a live rig (Ctrl+L): a robot's Foxglove server, its address and map.
    QTimer::singleShot(0, this, [url] {
        auto *dialog = qobject_cast<LiveRigDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        QVERIFY(!dialog->robotUrlEdit()->isEnabled());
        QRadioButton *robotChoice = dialog->robotChoice();
        QTest::mouseClick(robotChoice, Qt::LeftButton, {}, QPoint(8, robotChoice->height() / 2));
        QVERIFY(dialog->robotUrlEdit()->isEnabled());
        QVERIFY(!dialog->portEdit()->isEnabled());
        for (QLineEdit *edit : {dialog->robotUrlEdit(), dialog->topicsEdit()}) {
            edit->setFocus();
            edit->selectAll();
            QTest::keyClicks(edit, edit == dialog->topicsEdit()
                                       ? QStringLiteral(SEMHAP_INTEROP_DIR "/grasp.topics.json")
                                       : url);
        }
        const QString folder = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
        if (!folder.isEmpty())
            dialog->grab().save(folder + "/liverig-robot.png");
        QTest::keyClick(dialog->topicsEdit(), Qt::Key_Return);
    });
    QTest::keyClick(&window, Qt::Key_L, Qt::ControlModifier);
    QVERIFY(window.engine().isLive());
    QCOMPARE(window.engine().liveUri(), url);
    QVERIFY(window.engine().isRunning());
    robot.write("go\n");
    QVERIFY(robot.waitForBytesWritten(10000));
    QTRY_COMPARE_WITH_TIMEOUT(window.engine().liveStats().frames, quint64(1000), 30000);
    // The grasp is confirmed in the log, as from a recording of it.
    QTRY_VERIFY(window.eventLog()->model()->rowCount() > 5);
    QTRY_COMPARE(window.findChild<QLabel *>("operatorLabel")->text(), "Live rig on " + url);
    robot.waitForFinished(10000);
    QSettings().remove("liveRig"); // the dialog remembers the robot: the other tests start on UDP

    // The next start follows the same robot, through the same map.
    QTemporaryDir dir;
    const QString saved = dir.filePath("workspace.json");
    workspace.autosaveTo(saved);
    QString error;
    QVERIFY2(workspace.autosave(&error), qPrintable(error));
    Workspace again;
    MainWindow next(again, studioOptions());
    QStringList problems;
    QVERIFY(again.restore(saved, studioOptions(), &problems));
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
    QCOMPARE(next.engine().liveUri(), url);
    QCOMPARE(next.engine().liveOptions().topics,
             QStringLiteral(SEMHAP_INTEROP_DIR "/grasp.topics.json"));
}

void TestStudioSessions::closingAReplayBringsTheRunBack()
{
    // A person records, drives, pauses, looks at the session and closes it: the paused run
    // is back where it was — time, bodies, driving, plots — not started again.
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    const QString path = recordWithKeys(window, 1.0);
    QVERIFY(!path.isEmpty());
    const double recorded = window.engine().simTime();
    QTRY_VERIFY_WITH_TIMEOUT(window.engine().simTime() > std::max(3.0, recorded + 1.0), 30000);
    QTest::keyClick(&window, Qt::Key_T, Qt::ControlModifier); // Drive
    QVERIFY(window.engine().isDriving());
    QTest::keyClick(&window, Qt::Key_F5); // Pause
    QVERIFY(!window.engine().isRunning());
    QTest::qWait(300); // the plots catch up
    auto *operatorLabel = window.findChild<QLabel *>("operatorLabel");
    QCOMPARE(operatorLabel->text(), QString("You are driving"));
    const double t = window.engine().simTime();
    const std::vector<double> bodies = window.engine().world()->sceneState();
    auto *plot = window.plots()->findChild<QCustomPlot *>();
    double firstPlotted = 0.0;
    QVERIFY(std::abs(lastPlotted(plot, &firstPlotted) - t) < 0.05);
    const int logRows = window.eventLog()->model()->rowCount();
    QVERIFY(logRows > 0);

    openSessionWithKeys(window, path);
    QVERIFY(window.engine().isReplaying());
    QTRY_COMPARE(operatorLabel->text(), QString("Replay: nobody drives"));
    QVERIFY(!window.findChild<QAction *>("driveAction")->isChecked());
    QTRY_VERIFY(lastPlotted(plot) <= window.replay()->startTime()); // the session's start

    const quint64 drawn = window.viewport()->renderedFrames();
    QTest::mouseClick(window.replayBar()->closeButton(), Qt::LeftButton);
    QVERIFY(!window.engine().isReplaying());
    QVERIFY(!window.replayBar()->isVisible());
    QVERIFY(!window.engine().isRunning());
    QCOMPARE(window.engine().simTime(), t);
    QCOMPARE(window.engine().world()->sceneState(), bodies);
    QVERIFY(window.engine().isDriving());
    QVERIFY(window.findChild<QAction *>("driveAction")->isChecked());
    QTRY_COMPARE(operatorLabel->text(), QString("You are driving"));
    QCOMPARE(window.findChild<QLabel *>("timeLabel")->text(),
             QStringLiteral("t = %1 s").arg(QLocale().toString(t, 'f', 2)));
    // The plots and the log show the run's history again, and the paused world is drawn.
    double firstAgain = 0.0;
    QTRY_VERIFY(std::abs(lastPlotted(plot, &firstAgain) - t) < 0.05);
    QCOMPARE(firstAgain, firstPlotted);
    QTRY_COMPARE(window.eventLog()->model()->rowCount(), logRows);
    QTRY_VERIFY(window.viewport()->renderedFrames() > drawn);
    QCOMPARE(window.viewport()->caption(), QString());

    // Run goes on from there; Reset still starts again.
    QTest::keyClick(&window, Qt::Key_F5);
    QTRY_VERIFY(window.engine().simTime() > t + 0.1);
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier);
    QVERIFY(window.engine().simTime() < t);
}

void TestStudioSessions::exportsTheReplayedSession()
{
    // File → Export session… on the session replayed: as XDF, which says that a run at 4×
    // cannot be lined up with an LSL recording, then as MCAP, picked by its file type.
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    const QString path = recordWithKeys(window, 1.0);
    QVERIFY(!path.isEmpty());
    openSessionWithKeys(window, path);
    QVERIFY(window.engine().isReplaying());
    auto *exportAction = window.findChild<QAction *>("exportSessionAction");
    QVERIFY(exportAction && exportAction->isEnabled());
    const auto exportAs = [&](const QString &target, const QString &fileType) {
        QTimer::singleShot(0, [target, fileType] {
            QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()));
            auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
            QCOMPARE(dialog->nameFilters().size(), 3);
            const QStringList types = dialog->nameFilters().filter(fileType);
            QCOMPARE(types.size(), 1);
            dialog->selectNameFilter(types.first());
            dialog->selectFile(target);
            QTest::keyClick(dialog->focusWidget() ? dialog->focusWidget() : dialog,
                            Qt::Key_Return);
        });
        exportAction->trigger();
    };
    const QString xdf = m_dir.filePath("exported.xdf");
    // The export's note comes in a message box once the file is written; the box runs its
    // own event loop, so a timer answers it from inside.
    QString note;
    QTimer closer;
    connect(&closer, &QTimer::timeout, [&note] {
        if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
            note = box->text();
            box->accept();
        }
    });
    closer.start(20);
    exportAs(xdf, "session time");
    QTRY_VERIFY_WITH_TIMEOUT(exportAction->isEnabled(), 30000);
    closer.stop();
    QVERIFY2(note.contains("cannot be lined up with an LSL recording"), qPrintable(note));
    QFile file(xdf);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.read(4), QByteArray("XDF:"));
    QVERIFY(window.statusBar()->currentMessage().startsWith("Exported "));

    // The file type picked decides, and a name typed without its suffix gets it.
    const QString mcap = m_dir.filePath("exported.mcap");
    exportAs(m_dir.filePath("exported"), "MCAP");
    QTRY_VERIFY_WITH_TIMEOUT(exportAction->isEnabled(), 30000);
    QFile recording(mcap);
    QVERIFY(recording.open(QIODevice::ReadOnly));
    QCOMPARE(recording.read(8), QByteArray("\x89MCAP0\r\n"));
    // Nothing but the two files: the temporaries were renamed into place.
    QCOMPARE(QDir(m_dir.path()).entryList({"exported*"}, QDir::Files),
             QStringList({"exported.mcap", "exported.xdf"}));
}

void TestStudioSessions::opensARobotRecording()
{
    // File → Open session (Ctrl+Alt+O) on a rosbag2 recording: a second dialog asks for its
    // topic map; the recording becomes a session in the sessions folder and opens for replay.
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    const QString recording = QStringLiteral(SEMHAP_INTEROP_DIR "/grasp-zstd.mcap");
    const QString map = QStringLiteral(SEMHAP_INTEROP_DIR "/grasp.topics.json");
    const QString session = QDir(StudioFolders::sessions()).filePath("grasp-zstd.db");
    QFile::remove(session);
    bool askedForTheMap = false;
    QTimer::singleShot(0, [&] {
        QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()));
        auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        QTimer::singleShot(0, [&] {
            // The map's dialog follows once the recording's has closed.
            QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()) &&
                        QApplication::activeModalWidget()->windowTitle().startsWith("Topic map"));
            auto *mapDialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
            QCOMPARE(mapDialog->windowTitle(), QString("Topic map of grasp-zstd.mcap"));
            askedForTheMap = true;
            mapDialog->selectFile(map);
            QTest::keyClick(mapDialog->focusWidget() ? mapDialog->focusWidget() : mapDialog,
                            Qt::Key_Return);
        });
        dialog->selectFile(recording);
        QTest::keyClick(dialog->focusWidget() ? dialog->focusWidget() : dialog, Qt::Key_Return);
    });
    QTest::keyClick(&window, Qt::Key_O, Qt::ControlModifier | Qt::AltModifier);
    QVERIFY(askedForTheMap);
    QTRY_VERIFY_WITH_TIMEOUT(window.engine().isReplaying(), 30000);
    QCOMPARE(window.replay()->path(), session);
    QVERIFY(window.statusBar()->currentMessage().contains("1000 frame(s)"));
    // The session is the recording routed: the grasp and its break warning, as route gives.
    QString error;
    auto reader = SessionReader::open(session, &error);
    QVERIFY2(reader, qPrintable(error));
    QCOMPARE(reader->info().source, QString("import"));
    int events = 0;
    QVERIFY(reader->readEvents(
        [&](const SemanticEvent &) {
            ++events;
            return true;
        },
        &error));
    QCOMPARE(events, 38);
    QFile::remove(session);
}

void TestStudioSessions::replayNamesAnEditedRouter()
{
    // Recorded with C3 whose break was raised to 100 N: the replay bar and the router
    // picker say C3*, and a re-routing says whether the editor's graph is its preset.
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    RouterEditor *editor = window.routerEditor();
    window.findChild<QDockWidget *>("routerDock")->raise();
    editor->setParam("right.force", "break", 100.0);
    QTest::mouseClick(editor->findChild<QWidget *>("applyButton"), Qt::LeftButton);
    QTRY_COMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C3*"));
    const QString path = recordWithKeys(window, 0.5);
    QVERIFY(!path.isEmpty());

    // The run goes on with an edit of C1; the picker shows what the replay shows.
    RouterGraph c1;
    LoadError loadError;
    QVERIFY(RouterPresets::preset("C1", &c1, &loadError));
    editor->setGraph(c1);
    editor->setParam("right.force", "grasp", 25.0);
    QTest::mouseClick(editor->findChild<QWidget *>("applyButton"), Qt::LeftButton);
    QTRY_COMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C1*"));
    const QJsonObject running = window.engine().routerGraph().toJson();
    openSessionWithKeys(window, path);
    QVERIFY(window.engine().isReplaying());
    auto *source = window.replayBar()->findChild<QLabel *>("replaySource");
    QCOMPARE(source->text(), QString("Showing: recorded with C3*"));
    QCOMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C3*"));
    auto *about = window.replayBar()->findChild<QLabel *>("replayAbout");
    QVERIFY2(about->toolTip().contains("Router: C3, edited"), qPrintable(about->toolTip()));
    QCOMPARE(clippedTexts(window.replayBar()), QStringList()); // the star fits at 1280 px
    if (const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !shots.isEmpty())
        window.grab().save(shots + "/replay-edited-1280x800.png");
    // What the studio keeps for its next start is the run behind the replay, edit and all.
    QCOMPARE(workspace.toJson().value("router").toObject().value("graph").toObject(), running);

    // Re-routed through the editor's C1 with its edit, then through C1 as it is.
    QTest::mouseClick(window.replayBar()->rerouteButton(), Qt::LeftButton);
    QCOMPARE(source->text(), QString("Showing: re-routed through C1*"));
    QCOMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C1*"));
    editor->setGraph(c1);
    QTest::mouseClick(window.replayBar()->rerouteButton(), Qt::LeftButton);
    QCOMPARE(source->text(), QString("Showing: re-routed through C1"));
    QCOMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C1"));
    QTest::mouseClick(window.replayBar()->recordedButton(), Qt::LeftButton);
    QCOMPARE(source->text(), QString("Showing: recorded with C3*"));
    QCOMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C3*"));

    // Closed, the picker names the run's router again.
    QTest::mouseClick(window.replayBar()->closeButton(), Qt::LeftButton);
    QCOMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C1*"));
    QCOMPARE(window.engine().routerGraph().toJson(), running);
}

void TestStudioSessions::untitledRerouteLeavesNoPickerEntry()
{
    // Re-routed through a graph built in the editor (no file): the picker names it while
    // the replay shows it, offers it to no one, and forgets it when the replay stops
    // showing it. Before, "untitled" stayed in the picker, and picking it failed to load.
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    QComboBox *picker = window.runToolBar()->routerPicker();
    QStringList entries;
    for (int i = 0; i < picker->count(); ++i)
        entries << picker->itemText(i);
    const QString path = recordWithKeys(window, 0.5);
    QVERIFY(!path.isEmpty());
    openSessionWithKeys(window, path);
    QVERIFY(window.engine().isReplaying());

    QVERIFY(buildUntitledRouter(window.routerEditor()));
    for (int round = 0; round < 2; ++round) {
        QTest::mouseClick(window.replayBar()->rerouteButton(), Qt::LeftButton);
        QCOMPARE(picker->currentText(), QString("untitled"));
        const auto *model = qobject_cast<QStandardItemModel *>(picker->model());
        QVERIFY(!model->item(picker->currentIndex())->isEnabled());
        const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
        if (round == 0 && !shots.isEmpty()) {
            picker->showPopup();
            window.grab().save(shots + "/replay-untitled-1280x800.png");
            picker->view()->window()->grab().save(shots + "/replay-untitled-picker.png");
            picker->hidePopup();
        }
        // Back to the recorded router, then (second round) out of the replay.
        QTest::mouseClick(round == 0 ? window.replayBar()->recordedButton()
                                     : window.replayBar()->closeButton(),
                          Qt::LeftButton);
        QCOMPARE(picker->findText("untitled"), -1);
    }
    QVERIFY(!window.engine().isReplaying());
    QStringList after;
    for (int i = 0; i < picker->count(); ++i)
        after << picker->itemText(i);
    QCOMPARE(after, entries);
}

void TestStudioSessions::routerStatusTellsTheReplayFromTheRun()
{
    // The router editor's line after Apply said "the running session uses this router now"
    // all through a replay, where nothing runs and Apply re-routes the replay instead.
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    window.findChild<QDockWidget *>("routerDock")->raise();
    RouterEditor *editor = window.routerEditor();
    QWidget *apply = editor->findChild<QWidget *>("applyButton");
    const QLabel *status = editor->statusLabel();
    editor->setParam("right.force", "break", 100.0);
    QTest::mouseClick(apply, Qt::LeftButton);
    QCOMPARE(status->text(), QString("Applied: the running session uses this router now."));
    const QString path = recordWithKeys(window, 0.5);
    QVERIFY(!path.isEmpty());

    openSessionWithKeys(window, path);
    QVERIFY(window.engine().isReplaying());
    QCOMPARE(status->text(), QString("Applied: the run waiting behind the replay uses this "
                                     "router."));
    QTest::mouseClick(apply, Qt::LeftButton);
    QVERIFY(window.engine().replay().isRerouted());
    QCOMPARE(status->text(), QString("Applied: the replay was re-routed through this router."));
    if (const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !shots.isEmpty())
        window.grab().save(shots + "/replay-router-applied-1280x800.png");
    // Closed, the re-routing is gone with the replay: the line says nothing of it.
    QTest::mouseClick(window.replayBar()->closeButton(), Qt::LeftButton);
    QVERIFY(!window.engine().isReplaying());
    QCOMPARE(status->text(), QString());
    // Applied to the run before the replay, it is the run's again after.
    QTest::mouseClick(apply, Qt::LeftButton);
    openSessionWithKeys(window, path);
    QTest::mouseClick(window.replayBar()->closeButton(), Qt::LeftButton);
    QCOMPARE(status->text(), QString("Applied: the running session uses this router now."));
}

void TestStudioSessions::statusBarKeepsItsWordsApart_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QSize>("size");
    QTest::newRow("de-1280x800") << "de" << QSize(1280, 800);
    QTest::newRow("en-1280x800") << "en" << QSize(1280, 800);
    QTest::newRow("de-1920x1080") << "de" << QSize(1920, 1080);
}

// Issue 33, D12: while recording, the recording's readout leaves a message a third of the
// bar, and a longer message ran into it, cut mid-letter against "Aufnahme nach …".
void TestStudioSessions::statusBarKeepsItsWordsApart()
{
    QFETCH(QString, language);
    QFETCH(QSize, size);
    const Speaking speaking(language);
    QVERIFY(speaking.loaded);
    Workspace workspace;
    StudioOptions options = studioOptions();
    options.size = size;
    MainWindow window(workspace, options);
    QVERIFY(openWindow(window));
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(window.engine().isRecording());
    auto *recording = window.findChild<QLabel *>("recordLabel");
    QTRY_VERIFY(!recording->text().isEmpty());
    auto *bar = qobject_cast<StatusBar *>(window.statusBar());
    QVERIFY(bar);

    // A short message whole; a long one (an error's, say) ends in "…" a space before the
    // readouts, the whole of it in the tooltip.
    QTest::keyClick(&window, Qt::Key_Escape); // Stop all says so in the bar
    QVERIFY(bar->currentMessage().startsWith(language == "de" ? "Gestoppt" : "Stopped"));
    QCOMPARE(bar->shownMessage(), bar->currentMessage());
    const QString error = QString("/home/experimenter/studies/%1: cannot write: ").arg(
                              QString(40, QChar('x'))) +
                          "No space left on device";
    bar->showMessage(error, 10000);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    const QRect room = bar->messageRect();
    const QRect readout(recording->mapTo(bar, QPoint(0, 0)), recording->size());
    const int space = bar->fontMetrics().horizontalAdvance("  ");
    QVERIFY2(room.right() < readout.left() - space / 2,
             qPrintable(QString("%1 %2").arg(room.right()).arg(readout.left())));
    QCOMPARE(clippedTexts(bar), QStringList()); // and the readouts whole
    const QString shown = bar->shownMessage();
    QVERIFY(bar->fontMetrics().horizontalAdvance(shown) <= room.width());
    if (bar->fontMetrics().horizontalAdvance(error) > room.width()) {
        QVERIFY2(shown.endsWith(QChar(0x2026)), qPrintable(shown));
        QHelpEvent help(QEvent::ToolTip, room.center(), bar->mapToGlobal(room.center()));
        QCoreApplication::sendEvent(bar, &help);
        QTRY_COMPARE(QToolTip::text(), error);
    } else {
        QCOMPARE(shown, error);
    }
    if (const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !shots.isEmpty()) {
        QTest::qWait(100); // painted, for the picture
        window.grab().save(QString("%1/statusbar-%2.png").arg(shots, QTest::currentDataTag()));
    }
    QToolTip::hideText();
    QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(!window.engine().isRecording());
}

void TestStudioSessions::replayWordsFitTheWindow_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("source"); // what the bar says the replay shows
    QTest::addColumn<QString>("nobody"); // what the status bar says of the operator
    QTest::addColumn<bool>("whole");     // whether the window has room for all of it
    const QString en = "Showing: re-routed through untitled";
    const QString de = "Angezeigt: neu geroutet über unbenannt";
    QTest::newRow("en-1280x800") << "en" << QSize(1280, 800) << en << "Replay: nobody drives"
                                 << true;
    QTest::newRow("de-1280x800") << "de" << QSize(1280, 800) << de << "Wiedergabe: niemand steuert"
                                 << true;
    QTest::newRow("en-1920x1080") << "en" << QSize(1920, 1080) << en << "Replay: nobody drives"
                                  << true;
    // Narrower than the words: the bar gives up "Angezeigt: …", never the router's name.
    QTest::newRow("de-1100x800") << "de" << QSize(1100, 800) << de << "Wiedergabe: niemand steuert"
                                 << false;
}

void TestStudioSessions::replayWordsFitTheWindow()
{
    // Re-routed through an untitled editor graph at 1280x800, the replay bar asked for more
    // than 1280 px in German: the window grew past the screen, cutting the bar and the
    // status bar's "Wiedergabe: niemand steuert".
    QFETCH(QString, language);
    QFETCH(QSize, size);
    QFETCH(QString, source);
    QFETCH(QString, nobody);
    QFETCH(bool, whole);
    const Speaking speaking(language);
    QVERIFY(speaking.loaded);
    Workspace workspace;
    StudioOptions options = studioOptions();
    options.size = size;
    MainWindow window(workspace, options);
    QVERIFY(openWindow(window));
    const QString path = recordWithKeys(window, 0.5);
    QVERIFY(!path.isEmpty());
    openSessionWithKeys(window, path);
    QVERIFY(window.engine().isReplaying());
    QVERIFY(buildUntitledRouter(window.routerEditor()));
    QTest::mouseClick(window.replayBar()->rerouteButton(), Qt::LeftButton);
    QVERIFY(window.engine().replay().isRerouted());
    auto *operatorLabel = window.findChild<QLabel *>("operatorLabel");
    QTRY_COMPARE(operatorLabel->text(), nobody); // the status bar's timer writes it
    QTest::qWait(100);                           // laid out and painted, for the picture
    if (const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !shots.isEmpty())
        window.grab().save(
            QString("%1/replay-rerouted-%2.png").arg(shots, QTest::currentDataTag()));

    // The window keeps the screen's size: nothing of either bar is beyond its edge.
    QCOMPARE(window.size(), size);
    QCOMPARE(clippedTexts(window.replayBar()), QStringList());
    QCOMPARE(clippedTexts(window.statusBar()), QStringList());
    QVERIFY(window.rect().contains(
        QRect(operatorLabel->mapTo(&window, QPoint(0, 0)), operatorLabel->size())));
    auto *shown = window.replayBar()->findChild<QLabel *>("replaySource");
    QVERIFY(window.rect().contains(QRect(shown->mapTo(&window, QPoint(0, 0)), shown->size())));
    if (whole) {
        QCOMPARE(shown->text(), source);
        QCOMPARE(shown->toolTip(), QString());
    } else {
        QVERIFY2(shown->text().startsWith(QString("…")) && shown->text().endsWith("unbenannt"),
                 qPrintable(shown->text()));
        QCOMPARE(shown->toolTip(), source);
    }
}

void TestStudioSessions::routerStatusGoesWithAnotherRouter_data()
{
    QTest::addColumn<bool>("picker"); // the toolbar's router picker, or File → Open router
    QTest::newRow("picker") << true;
    QTest::newRow("open") << false;
}

void TestStudioSessions::routerStatusGoesWithAnotherRouter()
{
    // After Apply, another router loaded from the toolbar's picker or File → Open runs
    // instead of the applied graph; the router editor's line still said "Applied: the
    // running session uses this router now."
    QFETCH(bool, picker);
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    window.findChild<QDockWidget *>("routerDock")->raise();
    RouterEditor *editor = window.routerEditor();
    const QLabel *status = editor->statusLabel();
    editor->setParam("right.force", "break", 100.0);
    QTest::mouseClick(editor->findChild<QWidget *>("applyButton"), Qt::LeftButton);
    QCOMPARE(status->text(), QString("Applied: the running session uses this router now."));
    if (picker) {
        QVERIFY(choose(window.runToolBar()->routerPicker(), "C1"));
        QTRY_COMPARE(window.engine().options().router, QString("C1"));
    } else {
        const QString file = m_dir.filePath("mine.json");
        QFile::remove(file);
        QVERIFY(QFile::copy(":/semhap/routers/C1.json", file));
        openWithKeys(window, file, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(window.engine().options().router, file);
    }
    QVERIFY(!window.engine().isRouterEdited());
    if (const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !shots.isEmpty())
        window.grab().save(QString("%1/router-loaded-%2.png").arg(shots, QTest::currentDataTag()));
    QCOMPARE(status->text(), QString());
}

void TestStudioSessions::routerPickerShowsTheWholeName_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("file"); // the router file opened; empty: an untitled graph
    QTest::addColumn<QString>("shown");
    const QString longer = "mine-v2.json";
    QTest::newRow("en-file") << "en" << longer << longer;
    QTest::newRow("de-file") << "de" << longer << longer;
    QTest::newRow("de-untitled") << "de" << QString() << "unbenannt";
    // Longer than the toolbar has room for: the picker gives up the middle of the name.
    const QString tooLong = "grasp-confirmations-for-participant-7.json";
    QTest::newRow("en-too-long") << "en" << tooLong << QString();
    QTest::newRow("de-too-long") << "de" << tooLong << QString();
}

void TestStudioSessions::routerPickerShowsTheWholeName()
{
    // The picker kept the width it had when the window first showed: a router opened from a
    // file read "mine.jso", an untitled graph a German replay re-routed through "unbenar".
    QFETCH(QString, language);
    QFETCH(QString, file);
    QFETCH(QString, shown);
    const Speaking speaking(language);
    QVERIFY(speaking.loaded);
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    QComboBox *picker = window.runToolBar()->routerPicker();
    if (file.isEmpty()) {
        const QString path = recordWithKeys(window, 0.5);
        QVERIFY(!path.isEmpty());
        openSessionWithKeys(window, path);
        QVERIFY(buildUntitledRouter(window.routerEditor()));
        QTest::mouseClick(window.replayBar()->rerouteButton(), Qt::LeftButton);
        QVERIFY(window.engine().replay().isRerouted());
    } else {
        const QString path = m_dir.filePath(file);
        QFile::remove(path);
        QVERIFY(QFile::copy(":/semhap/routers/C1.json", path));
        openWithKeys(window, path, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(window.engine().options().router, path);
    }
    if (shown.isEmpty()) {
        QVERIFY2(picker->currentText().contains(QString("…")) &&
                     picker->currentText().endsWith(".json"),
                 qPrintable(picker->currentText()));
        QVERIFY2(picker->toolTip().contains(file), qPrintable(picker->toolTip()));
    } else {
        QCOMPARE(picker->currentText(), shown);
    }
    // The toolbar gives the picker room for its text (laid out on the next passes): the
    // text is no wider than the picker's field (clippedTexts measures it so).
    auto *bar = window.findChild<QToolBar *>("runToolBar");
    QTRY_VERIFY2(clippedTexts(bar).isEmpty(), qPrintable(clippedTexts(bar).join("; ")));
    if (const QString shots = qEnvironmentVariable("SEMHAP_SCREENSHOTS"); !shots.isEmpty())
        window.grab().save(QString("%1/router-picker-%2.png").arg(shots, QTest::currentDataTag()));
    // The window keeps the screen's width, and no top toolbar gives up a button.
    QCOMPARE(window.width(), 1280);
    for (QToolBar *top : window.findChildren<QToolBar *>()) {
        if (!top->isVisible() || window.toolBarArea(top) != Qt::TopToolBarArea)
            continue;
        QVERIFY2(!top->findChild<QToolButton *>("qt_toolbar_ext_button")->isVisible(),
                 qPrintable(top->objectName() + " overflows"));
        QCOMPARE(clippedTexts(top), QStringList());
    }
}

void TestStudioSessions::recordingMidGraspShowsTheGraspFromItsStart()
{
    // Recording starts while the right hand holds a cube: the replay shades the grasp from
    // the session's start, and the log's first row is its begin.
    Workspace workspace;
    MainWindow window(workspace, studioOptions());
    QVERIFY(openWindow(window));
    const RunHistory &history = window.engine().history();
    const auto grasping = [&] {
        return std::any_of(
            history.spans().begin(), history.spans().end(), [](const MessageSpan &span) {
                return span.active && span.message == Message::Grasp && span.node == "right.force";
            });
    };
    QTRY_VERIFY_WITH_TIMEOUT(grasping(), 30000);
    const QString path = recordWithKeys(window, 0.5);
    QVERIFY(!path.isEmpty());

    openSessionWithKeys(window, path);
    SessionReplay *replay = window.replay();
    QVERIFY(replay->isOpen());
    const auto span =
        std::find_if(history.spans().begin(), history.spans().end(), [](const MessageSpan &s) {
            return s.message == Message::Grasp && s.node == "right.force";
        });
    QVERIFY(span != history.spans().end());
    QCOMPARE(span->begin, replay->startTime());
    QVERIFY(span->active);
    const EventLogModel *log = window.eventLog()->model();
    QTRY_VERIFY(log->rowCount() > 0);
    QCOMPARE(log->index(0, EventLogModel::TimeColumn).data(EventLogModel::TimeRole).toDouble(),
             replay->startTime());
    QCOMPARE(log->index(0, EventLogModel::MessageColumn).data().toString(), QString("grasp"));
    QCOMPARE(log->index(0, EventLogModel::PhaseColumn).data(EventLogModel::PhaseRole).toInt(),
             int(EventPhase::Begin));
    QVERIFY(replay->info().extra.value("open_at_start").contains("right.force"));
}

void TestStudioSessions::cleanupTestCase()
{
    QSettings().remove("sessions/folder"); // it named a folder of this run's
}

QTEST_MAIN(TestStudioSessions)
#include "tst_studiosessions.moc"
