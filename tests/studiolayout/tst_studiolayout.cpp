// SPDX-License-Identifier: MIT
// The studio's window at the screens people have (1280×800 to 2560×1440), in English and
// German: it fits, its router graph, inspectors and toolbars show whole, every panel is
// photographed, it says when a task is done, and its key map and manual open.

#include "colors.h"
#include "imagechecks.h"
#include "keymapdialog.h"
#include "mainwindow.h"
#include "manualwindow.h"
#include "metricspanel.h"
#include "openwindow.h"
#include "patterndocument.h"
#include "plotchecks.h"
#include "routereditor.h"
#include "routernodeitem.h"
#include "routernodetype.h"
#include "routerscene.h"
#include "simviewport.h"
#include "studio.h"
#include "studiotesting.h"
#include "virtualscreen.h"
#include "waveformdesigner.h"
#include "widgetchecks.h"
#include "windowpictures.h"
#include "workspace.h"

#include <QApplication>
#include <QDesktopServices>
#include <QDockWidget>
#include <QGraphicsView>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProcess>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>

#include <qcustomplot.h>

#include <cmath>
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

/** A row per interface language, "en" and "de", in column `language`. */
static void languageRows()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << "en";
    QTest::newRow("de") << "de";
}

} // namespace

class TestStudioLayout : public StudioTestCase
{
    Q_OBJECT

private slots:
    void initTestCase() { setUp(); }
    void init() { reset(); }
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
};

void TestStudioLayout::firstWindowFitsTheScreen_data()
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
void TestStudioLayout::firstWindowFitsTheScreen()
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

void TestStudioLayout::routerFitsItsGraphWhenRaised_data()
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
void TestStudioLayout::routerFitsItsGraphWhenRaised()
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

void TestStudioLayout::inspectorsShowEveryFieldWhole_data()
{
    languageRows();
}

// At 1280×800, in either language: the router editor's inspector for a node of every type
// and every node of C3p, and the pattern designer's inspector for every node of every
// built-in pattern, show each field whole: none cut by the dock or a scroll area, no text
// or value squeezed.
void TestStudioLayout::inspectorsShowEveryFieldWhole()
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

void TestStudioLayout::toolbarsFitAt1280_data()
{
    languageRows();
}

// At 1280×800, in either language, every toolbar of the window and its docks shows all of
// its buttons and fields (none in the "»" overflow menu, no field squeezed), and the
// editors' Undo and Redo stay in sight after an edit (their names no longer grow with it).
void TestStudioLayout::toolbarsFitAt1280()
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

void TestStudioLayout::screenshotsOfEveryPanel_data()
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
void TestStudioLayout::screenshotsOfEveryPanel()
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

void TestStudioLayout::saysWhenTheTaskIsDone_data()
{
    addWindowRows();
}

void TestStudioLayout::saysWhenTheTaskIsDone()
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

void TestStudioLayout::keyMapAndManual_data()
{
    addWindowRows();
}

void TestStudioLayout::keyMapAndManual()
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
    // manual takes the keys once it is the active window. On a busy X server with no window
    // manager, the main window's late focus event can take that back after the manual had it:
    // Ctrl+F is pressed while the manual is the active window.
    QTRY_VERIFY([manual] {
        if (QApplication::activeWindow() != manual) {
            manual->activateWindow();
            return false;
        }
        QTest::keyClick(manual, Qt::Key_F, Qt::ControlModifier);
        return manual->searchField()->hasFocus();
    }());
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

QTEST_MAIN(TestStudioLayout)
#include "tst_studiolayout.moc"
