// SPDX-License-Identifier: MIT
// The studio's files as a user meets them: each file dialog starts where its kind lives and
// remembers it, the router follows a renamed pattern, a confirmation is built by mouse, a
// scene, run or gripper that does not load is reported and leaves the work as it was.

#include "colors.h"
#include "editordriver.h"
#include "gripperlibrary.h"
#include "imagechecks.h"
#include "levelmeter.h"
#include "mainwindow.h"
#include "openwindow.h"
#include "patterndocument.h"
#include "plotpanel.h"
#include "preferencesdialog.h"
#include "routereditor.h"
#include "runtoolbar.h"
#include "simviewport.h"
#include "studio.h"
#include "studiofolders.h"
#include "studiotesting.h"
#include "userpatterns.h"
#include "waveformdesigner.h"
#include "widgetchecks.h"
#include "windowpictures.h"
#include "workspace.h"
#include "world.h"

#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <qcustomplot.h>

#include <memory>

using namespace semhap;

class TestStudioFiles : public StudioTestCase
{
    Q_OBJECT

private slots:
    void initTestCase() { setUp(); }
    void init() { reset(); }
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
};

void TestStudioFiles::fileDialogsStartWhereTheirKindLives_data()
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

void TestStudioFiles::fileDialogsStartWhereTheirKindLives()
{
    QFETCH(QString, how);
    QFETCH(QString, folder);
    OwnHome home;
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    window.engine().pause();
    const QString expected = folder == "sessions"   ? StudioFolders::sessions()
                             : folder == "patterns" ? StudioFolders::patterns()
                                                    : home.documents();
    QCOMPARE(dialogFolder([&] { openDialog(window, how); }), QDir(expected).absolutePath());
}

void TestStudioFiles::fileDialogsRememberTheirKindsFolder()
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

void TestStudioFiles::routerFollowsARenamedPattern_data()
{
    addWindowRows();
}

void TestStudioFiles::routerFollowsARenamedPattern()
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
    QCOMPARE(designer->userFolder(), StudioFolders::patterns());
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
    const QString renamed = userPatternPath(StudioFolders::patterns(), "my.warning");
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
    QCOMPARE(window.runToolBar()->routerPicker()->currentText(), QString("C3*"));
}

void TestStudioFiles::buildsAnAlignmentConfirmationByMouse_data()
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
void TestStudioFiles::buildsAnAlignmentConfirmationByMouse()
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

void TestStudioFiles::aSceneThatDoesNotLoadLeavesTheRun_data()
{
    badSceneRows();
}

// A scene file that does not load, opened as a person does it (Ctrl+O, the file dialog), is
// reported in the loader's own words, and the run that was there goes on: its world in the
// viewport, its name in the scene picker and the title, running as before.
void TestStudioFiles::aSceneThatDoesNotLoadLeavesTheRun()
{
    QFETCH(QString, file);
    QString error;
    QVERIFY(!World::load(file, SceneOptions(), &error));
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    Engine &engine = window.engine();
    QComboBox *scene = window.runToolBar()->scenePicker();
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
void TestStudioFiles::eachSceneComesWithItsRouter()
{
    Workspace workspace;
    MainWindow window(workspace, options());
    QVERIFY(openWindow(window));
    Engine &engine = window.engine();
    QComboBox *scene = window.runToolBar()->scenePicker();
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
    QCOMPARE(window.runToolBar()->routerPicker()->currentText(), QString("wipe"));
    QVERIFY(engine.isRunning());
    QVERIFY2(window.statusBar()->currentMessage().contains("wipe"),
             qPrintable(window.statusBar()->currentMessage()));
    pick("usb_insertion");
    QTRY_COMPARE(engine.options().router, QString("usb"));
    pick("box_and_block");
    QTRY_COMPARE(engine.options().router, QString("C3"));

    // C1 picked by hand stays with the next scene.
    QComboBox *router = window.runToolBar()->routerPicker();
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

void TestStudioFiles::aRunThatDoesNotLoadAtTheStartLeavesTheDefaults_data()
{
    badSceneRows();
}

// A scene named on the command line that does not load is reported the same way, and the
// studio opens on the default run, paused, rather than on no scene under a picker naming one.
void TestStudioFiles::aRunThatDoesNotLoadAtTheStartLeavesTheDefaults()
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
    QCOMPARE(window->runToolBar()->scenePicker()->currentText(), QString("box_and_block"));
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
    return QDir::cleanPath(SEMHAP_GRIPPERS "/slider/slider.json");
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

void TestStudioFiles::gripperMenuPicksAnAdapter_data()
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
void TestStudioFiles::gripperMenuPicksAnAdapter()
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
    QCOMPARE(window.runToolBar()->scenePicker()->currentText(), QString("box_and_block"));

    // Another scene keeps the gripper; the scene's own brings the scene's back.
    QComboBox *scene = window.runToolBar()->scenePicker();
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
void TestStudioFiles::gripperIsKept()
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
void TestStudioFiles::aGripperThatDoesNotLoadAtTheStartIsReported()
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

void TestStudioFiles::gripperMenuScreenshots_data()
{
    addWindowRows();
}

// The Gripper menu open under its button with the test gripper picked, as the screen shows
// it (the menu is a window of its own), to be looked at: it lists the scene's own, every
// adapter of the gripper folders (the shipped ones too) and another file, and lies on the
// screen whole; its button is in the toolbar, not in its overflow.
void TestStudioFiles::gripperMenuScreenshots()
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
        QStringList{RunToolBar::tr("Gripper"), RunToolBar::tr("Scene's own")} + names +
        QStringList{QString(), RunToolBar::tr("Other file…")};
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

QTEST_MAIN(TestStudioFiles)
#include "tst_studiofiles.moc"
