// SPDX-License-Identifier: MIT
// The router node editor driven like a user: nodes from the palette, names and parameters
// typed into the inspector, wires dragged between ports; the graph it makes must route the
// bundled trace exactly like the C3 preset. Also: refused links say why, undo and redo
// restore the exact graph, files round-trip, and the engine swaps routers while running.
#include "contactframereader.h"
#include "devicemanager.h"
#include "distinctivenessview.h"
#include "editordriver.h"
#include "engine.h"
#include "gatedrouter.h"
#include "mainwindow.h"
#include "pipeline.h"
#include "routercommands.h"
#include "routerdocument.h"
#include "routereditor.h"
#include "routernodeitem.h"
#include "routerscene.h"
#include "routerwireitem.h"
#include "runhistory.h"
#include "studio.h"
#include "studiofolders.h"
#include "userpatterns.h"
#include "workspace.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGraphicsView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>

using namespace semhap;

namespace {

const QString Trace = QStringLiteral(SEMHAP_RESOURCES "/traces/demo.jsonl");

RouterGraph preset(const QString &name)
{
    RouterGraph graph;
    LoadError error;
    if (!RouterPresets::preset(name, &graph, &error))
        qFatal("%s", qPrintable(error.toString()));
    return graph;
}

/** Nodes and links only, without editor positions: what decides how a graph routes. */
QJsonObject routing(const RouterGraph &graph)
{
    QJsonObject json = graph.toJson();
    QJsonArray nodes;
    for (const QJsonValue &node : json.value("nodes").toArray()) {
        QJsonObject o = node.toObject();
        o.remove("ui");
        nodes.append(o);
    }
    return {{"nodes", nodes}, {"links", json.value("links")}};
}

struct Routed
{
    std::vector<SemanticEvent> events;
    std::vector<DeviceFrame> frames;
    QStringList devices;
};

class Recorder : public PipelineSink
{
public:
    explicit Recorder(Routed &r) : m_r(r) {}
    void onEvent(const SemanticEvent &e) override { m_r.events.push_back(e); }
    void onDeviceFrame(const DeviceFrame &f) override { m_r.frames.push_back(f); }

private:
    Routed &m_r;
};

/** Routes the demo trace through `graph`, as `semhap route` does. */
Routed route(const RouterGraph &graph)
{
    LoadError error;
    std::unique_ptr<Router> router = Router::compile(graph, &error);
    if (!router)
        qFatal("%s", qPrintable(error.toString()));
    Routed routed;
    for (int d = 0; d < router->player().deviceCount(); ++d)
        routed.devices.append(router->player().deviceName(d));
    Pipeline pipeline(std::move(router));
    QFile file(Trace);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read the trace");
    ContactFrameReader reader(&file, Trace);
    Recorder sink(routed);
    ContactFrame frame;
    while (reader.next(&frame))
        pipeline.process(frame, sink);
    pipeline.flush(sink);
    return routed;
}

/** The editor in a window of its own, laid out and shown. */
struct Fixture : EditorDriver
{
    Fixture()
    {
        setEditor(&editor);
        editor.resize(1100, 900);
        editor.show();
        editor.activateWindow();
        // Shortcuts (undo, delete, copy) need the active window.
        if (!QTest::qWaitForWindowActive(&editor))
            qFatal("the editor did not show");
    }

    RouterEditor editor;
};

QString text(const QJsonValue &value)
{
    if (value.isString())
        return value.toString();
    if (value.isDouble())
        return QLocale().toString(value.toDouble(), 'g', 12);
    return QString::fromUtf8(QJsonDocument(value.toArray()).toJson(QJsonDocument::Compact));
}

} // namespace

class TestRouterEditor : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void buildsC3ByMouse();
    void refusedLinkSaysWhy_data();
    void refusedLinkSaysWhy();
    void undoRedoRestoresTheExactGraph();
    void deleteCopyPaste();
    void marksValidationErrors();
    void comfortableInALaptopWindow();
    void presetsLaidOutInColumns();
    void saveOpenRoundTrip();
    void namesItsDocument();
    void selfContainedEmbedsUserPatterns();
    void selfContainedKeepsPatternsOfOneName();
    void documentDrivesItsViews();
    void failedSaveKeepsTheFile();
    void opensAnOldSpelling();
    void offersTheDesignersPatterns();
    void followsARenamedPattern();
    void inspectorShowsTheNodeTypeTable();
    void engineSwapsWhileRunning();
    void liveActivityLightsWires();
    void signalPickerOffersTheSourcesSignals();
    void messageFieldsOfferNewMessages();
    void levelsAreTypedAsNumbersOrRanges_data();
    void levelsAreTypedAsNumbersOrRanges();
    void distinctivenessFollowsTheRouter();
    void screenshot();
};

void TestRouterEditor::initTestCase()
{
    QCoreApplication::setOrganizationName("semhap");
    QCoreApplication::setApplicationName("semhap-routereditor-test");
}

void TestRouterEditor::buildsC3ByMouse()
{
    Fixture f;
    const RouterGraph c3 = preset("C3");
    // Every node from the palette, named and set up in the inspector with the keyboard.
    for (const RouterNode &node : c3.nodes) {
        const QString id = f.addFromPalette(node.type);
        QVERIFY2(!id.isEmpty(), qPrintable(node.type));
        QCOMPARE(f.editor.inspector()->findChild<QLineEdit *>("nodeId")->text(), id);
        f.type("nodeId", node.id);
        QVERIFY2(f.editor.graph().nodeIndex(node.id) >= 0, qPrintable(node.id));
        for (auto it = node.params.begin(); it != node.params.end(); ++it)
            f.type("param:" + it.key(), text(it.value()));
    }
    // Arranged with the toolbar button, then every wire dragged from port to port.
    QToolButton *arrange = nullptr;
    for (QToolButton *button : f.editor.findChildren<QToolButton *>()) {
        if (button->text() == RouterEditor::tr("Arrange"))
            arrange = button;
    }
    QVERIFY(arrange);
    QTest::mouseClick(arrange, Qt::LeftButton);
    Fixture::settle();
    for (const RouterLink &link : c3.links) {
        RouterScene *scene = f.editor.scene();
        f.wire(link.from, scene->nodeItem(link.from)->outputs().front().name, link.to,
               scene->nodeItem(link.to)->inputs().front().name);
    }
    // Wires between default ports keep them implicit, as the preset writes them.
    QCOMPARE(f.editor.graph().links.size(), c3.links.size());

    QCOMPARE(f.editor.validate(), QStringList());
    QCOMPARE(QJsonDocument(routing(f.editor.graph())).toJson(),
             QJsonDocument(routing(c3)).toJson());

    const Routed built = route(f.editor.graph());
    const Routed expected = route(c3);
    QVERIFY(expected.events.size() > 10);
    QCOMPARE(built.devices, expected.devices);
    QCOMPARE(built.events.size(), expected.events.size());
    for (size_t i = 0; i < built.events.size(); ++i) {
        const SemanticEvent &a = built.events[i];
        const SemanticEvent &e = expected.events[i];
        QVERIFY(a.t == e.t && a.node == e.node && a.message == e.message && a.phase == e.phase &&
                a.intensity == e.intensity && a.gripper == e.gripper);
    }
    QCOMPARE(built.frames.size(), expected.frames.size());
    for (size_t i = 0; i < built.frames.size(); ++i) {
        QCOMPARE(built.frames[i].t, expected.frames[i].t);
        QCOMPARE(built.frames[i].device, expected.frames[i].device);
        QVERIFY(built.frames[i].values == expected.frames[i].values);
    }
}

void TestRouterEditor::refusedLinkSaysWhy_data()
{
    QTest::addColumn<QString>("from");
    QTest::addColumn<QString>("fromPort");
    QTest::addColumn<QString>("to");
    QTest::addColumn<QString>("toPort");
    QTest::addColumn<bool>("toOutput");
    QTest::addColumn<QString>("reason");
    QTest::newRow("event into a device") << "right.force"
                                         << "events"
                                         << "right.air"
                                         << "in" << false
                                         << "port type mismatch: 'right.force:events' sends "
                                            "event, 'right.air:in' takes voice";
    QTest::newRow("voice into a filter")
        << "right.squeeze"
        << "out"
        << "left.warn"
        << "in" << false
        << "port type mismatch: 'right.squeeze:out' sends voice, 'left.warn:in' takes event";
    QTest::newRow("output to output") << "right.force"
                                      << "events"
                                      << "right.confirm"
                                      << "out" << true << "an output connects to an input";
    QTest::newRow("itself") << "right.confirm"
                            << "out"
                            << "right.confirm"
                            << "in" << false << "node 'right.confirm' (filter) cannot feed itself";
    QTest::newRow("twice") << "right.force"
                           << "events"
                           << "right.confirm"
                           << "in" << false
                           << "'right.force:events' already feeds 'right.confirm:in'";
    QTest::newRow("cycle") << "right.warn"
                           << "out"
                           << "right.confirm"
                           << "in" << false << "";
}

void TestRouterEditor::refusedLinkSaysWhy()
{
    QFETCH(QString, from);
    QFETCH(QString, fromPort);
    QFETCH(QString, to);
    QFETCH(QString, toPort);
    QFETCH(bool, toOutput);
    QFETCH(QString, reason);
    Fixture f;
    f.editor.setGraph(preset("C3"));
    if (reason.isEmpty()) {
        // right.confirm -> right.warn first; then right.warn -> right.confirm closes a loop.
        f.wire("right.confirm", "out", "right.warn", "in");
        reason = "this link would make a cycle: 'right.confirm' already leads to 'right.warn'";
    }
    const QJsonObject before = f.editor.graph().toJson();
    f.wire(from, fromPort, to, toPort, toOutput);
    QCOMPARE(f.editor.graph().toJson(), before);
    const QString status = f.editor.statusLabel()->text();
    QVERIFY2(status.contains(reason), qPrintable(status));
}

void TestRouterEditor::undoRedoRestoresTheExactGraph()
{
    Fixture f;
    f.editor.setGraph(preset("C3"));
    std::vector<QJsonObject> states{f.editor.graph().toJson()};
    const auto record = [&] {
        QVERIFY(f.editor.graph().toJson() != states.back());
        states.push_back(f.editor.graph().toJson());
    };
    const QString gate = f.addFromPalette("gate");
    record();
    f.type("param:mode", "open");
    record();
    f.type("nodeId", "right.gate");
    record();
    f.wire("right.force", "events", "right.gate", "in");
    record();
    f.select("right.squeeze");
    f.type("param:pattern", "air.pulse5hz");
    record();
    // Moving a node by its title.
    RouterNodeItem *item = f.editor.scene()->nodeItem("left.slip");
    const QPoint grab = f.at(item->mapToScene(QPointF(80, 8)));
    QTest::mousePress(f.canvas(), Qt::LeftButton, {}, grab);
    QTest::mouseMove(f.canvas(), grab + QPoint(20, 20));
    QTest::mouseMove(f.canvas(), grab + QPoint(60, 45));
    QTest::mouseRelease(f.canvas(), Qt::LeftButton, {}, grab + QPoint(60, 45));
    Fixture::settle();
    record();
    // Deleting a node with the Delete key takes its links along.
    f.select("right.warn");
    f.editor.view()->setFocus();
    QTest::keyClick(f.editor.view(), Qt::Key_Delete);
    Fixture::settle();
    record();
    QCOMPARE(f.editor.graph().nodeIndex("right.warn"), -1);

    QUndoStack *undo = f.editor.undoStack();
    QCOMPARE(undo->count(), int(states.size()) - 1);
    for (size_t k = states.size() - 1; k > 0; --k) {
        f.editor.setFocus();
        QTest::keyClick(&f.editor, Qt::Key_Z, Qt::ControlModifier);
        Fixture::settle();
        QCOMPARE(f.editor.graph().toJson(), states[k - 1]);
    }
    for (size_t k = 1; k < states.size(); ++k) {
        undo->redo();
        QCOMPARE(f.editor.graph().toJson(), states[k]);
    }
}

void TestRouterEditor::deleteCopyPaste()
{
    Fixture f;
    f.editor.setGraph(preset("C3"));
    const size_t nodes = f.editor.graph().nodes.size();
    const size_t links = f.editor.graph().links.size();
    // Two linked nodes, selected with Ctrl+click, copied and pasted with the keyboard.
    f.select("right.confirm");
    RouterNodeItem *squeeze = f.editor.scene()->nodeItem("right.squeeze");
    QTest::mouseClick(f.canvas(), Qt::LeftButton, Qt::ControlModifier,
                      f.at(squeeze->mapToScene(QPointF(60, 10))));
    QCOMPARE(f.editor.scene()->selectedNodeIds(), QStringList({"right.confirm", "right.squeeze"}));
    f.editor.view()->setFocus();
    QTest::keyClick(f.editor.view(), Qt::Key_C, Qt::ControlModifier);
    QTest::keyClick(f.editor.view(), Qt::Key_V, Qt::ControlModifier);
    Fixture::settle();
    QCOMPARE(f.editor.graph().nodes.size(), nodes + 2);
    QCOMPARE(f.editor.graph().links.size(), links + 1);
    QCOMPARE(f.editor.scene()->selectedNodeIds(),
             QStringList({"right.confirm2", "right.squeeze2"}));
    const RouterLink &pasted = f.editor.graph().links.back();
    QCOMPARE(pasted.from, "right.confirm2");
    QCOMPARE(pasted.to, "right.squeeze2");
    // One undo takes the whole paste back.
    f.editor.undoStack()->undo();
    QCOMPARE(f.editor.graph().nodes.size(), nodes);
    QCOMPARE(f.editor.graph().links.size(), links);
}

void TestRouterEditor::marksValidationErrors()
{
    Fixture f;
    RouterGraph graph = preset("C3");
    graph.nodes[size_t(graph.nodeIndex("right.force"))].params.insert("grasp", 90);
    graph.nodes[size_t(graph.nodeIndex("left.geiger"))].params.insert("pattern", "no.such");
    f.editor.setGraph(graph);
    const QStringList errors = f.editor.errors();
    QCOMPARE(errors.size(), 2);
    QVERIFY2(errors[0].contains("right.force"), qPrintable(errors[0]));
    QVERIFY2(errors[1].contains("unknown pattern 'no.such'"), qPrintable(errors[1]));
    RouterNodeItem *force = f.editor.scene()->nodeItem("right.force");
    QCOMPARE(force->error(), errors[0]);
    QCOMPARE(force->toolTip(), errors[0]);
    QVERIFY(f.editor.scene()->nodeItem("left.slip")->error().isEmpty());
    // Fixing it in the inspector clears the mark.
    f.select("right.force");
    f.type("param:grasp", "20");
    QTRY_VERIFY(force->error().isEmpty());
    QCOMPARE(f.editor.errors().size(), 1);
}

void TestRouterEditor::comfortableInALaptopWindow()
{
    // The room the Router tab has in a 1280×800 window. C3p's words were 6 px high, new
    // nodes landed on others, the inspector jumped to its top after each edit, and the
    // palette reflowed under the mouse when the problem list came.
    Fixture f;
    f.editor.resize(665, 690);
    QTest::qWait(50);
    f.editor.setGraph(preset("C3p"));
    QVERIFY2(f.editor.view()->transform().m11() >= RouterEditor::MinReadableScale - 1e-9,
             qPrintable(QString::number(f.editor.view()->transform().m11())));

    // New nodes, double-clicked in the palette, each in free space.
    f.editor.setGraph(preset("C3"));
    for (int k = 0; k < 3; ++k) {
        const QString id = f.addFromPalette("threshold");
        QVERIFY(!id.isEmpty());
        const QRectF box = f.editor.scene()->nodeItem(id)->sceneBoundingRect();
        for (const RouterNode &node : f.editor.graph().nodes) {
            QVERIFY2(node.id == id ||
                         !box.intersects(f.editor.scene()->nodeItem(node.id)->sceneBoundingRect()),
                     qPrintable(id + " lands on " + node.id));
        }
    }
    f.editor.setGraph(preset("C3"));

    // The palette stays where it is when problems show.
    QListWidget *palette = f.editor.palette();
    QListWidgetItem *threshold = palette->findItems("threshold", Qt::MatchExactly).front();
    const QRect before = palette->visualItemRect(threshold);
    f.select("right.force");
    f.type("param:grasp", "90");
    QTRY_VERIFY(f.editor.findChild<QListWidget *>("routerErrors")->isVisible());
    QTest::qWait(50);
    QCOMPARE(palette->visualItemRect(threshold), before);

    // The inspector keeps its place: scrolled to the last field, an edit there leaves it
    // there, with the keyboard still in that field.
    f.type("param:grasp", "20");
    auto *scroll = f.editor.inspector()->findChild<QScrollArea *>("inspectorScroll");
    QVERIFY(scroll->verticalScrollBar()->maximum() > 0); // more fields than room
    scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());
    const int kept = scroll->verticalScrollBar()->value();
    f.type("param:max", "110");
    QCOMPARE(f.editor.graph().nodes[size_t(f.editor.graph().nodeIndex("right.force"))]
                 .params.value("max")
                 .toDouble(),
             110.0);
    QCOMPARE(scroll->verticalScrollBar()->value(), kept);
    QVERIFY(QApplication::focusWidget());
    QCOMPARE(QApplication::focusWidget()->objectName(), QString("param:max"));
}

void TestRouterEditor::presetsLaidOutInColumns()
{
    Fixture f;
    f.editor.setGraph(preset("C3"));
    const auto x = [&](const QString &id) { return f.editor.scene()->nodeItem(id)->pos().x(); };
    QVERIFY(x("right.force") < x("right.confirm"));
    QVERIFY(x("right.confirm") < x("right.squeeze"));
    QVERIFY(x("right.squeeze") < x("right.air"));
    // No two nodes overlap.
    const auto &nodes = f.editor.graph().nodes;
    for (size_t i = 0; i < nodes.size(); ++i) {
        for (size_t j = i + 1; j < nodes.size(); ++j) {
            const RouterNodeItem *a = f.editor.scene()->nodeItem(nodes[i].id);
            const RouterNodeItem *b = f.editor.scene()->nodeItem(nodes[j].id);
            QVERIFY2(!a->sceneBoundingRect()
                          .adjusted(6, 3, -6, -3)
                          .intersects(b->sceneBoundingRect().adjusted(6, 3, -6, -3)),
                     qPrintable(nodes[i].id + " " + nodes[j].id));
        }
    }
    // Positions go into the document, so a saved file keeps them.
    for (const RouterNode &node : nodes)
        QVERIFY(node.ui.contains("x") && node.ui.contains("y"));
}

void TestRouterEditor::saveOpenRoundTrip()
{
    QTemporaryDir dir;
    Fixture f;
    f.editor.setGraph(preset("C2"));
    const QJsonObject saved = f.editor.graph().toJson();
    QString error;
    QVERIFY2(f.editor.saveFile(dir.filePath("mine.json"), false, &error), qPrintable(error));
    f.editor.setGraph(preset("C3"));
    QVERIFY2(f.editor.openFile(dir.filePath("mine.json"), &error), qPrintable(error));
    QCOMPARE(f.editor.graph().toJson(), saved);
    QCOMPARE(f.editor.graph().file, dir.filePath("mine.json"));
    QVERIFY(!f.editor.openFile(dir.filePath("missing.json"), &error));
    QVERIFY2(error.contains("missing.json"), qPrintable(error));
}

void TestRouterEditor::namesItsDocument()
{
    // The editor names what it edits and whether it is saved, above the canvas: after
    // Router → New from preset → C1 the line under the canvas still named the file opened
    // before, and nothing said the graph was not saved.
    QTemporaryDir dir;
    Fixture f;
    auto *document = f.editor.findChild<QLabel *>("routerDocument");
    auto *status = f.editor.findChild<QLabel *>("routerStatus");
    f.editor.setGraph(preset("C2"));
    QString error;
    QVERIFY2(f.editor.saveFile(dir.filePath("mine.json"), false, &error), qPrintable(error));
    QVERIFY2(f.editor.openFile(dir.filePath("mine.json"), &error), qPrintable(error));
    QCOMPARE(document->text(), QString("mine.json"));
    QCOMPARE(document->toolTip(), QDir::toNativeSeparators(dir.filePath("mine.json")));
    // An edit marks it.
    f.editor.setParam("right.force", "grasp", 25.0);
    QCOMPARE(document->text(), QString("* mine.json — changed since it was saved"));
    f.editor.undoStack()->undo();
    QCOMPARE(document->text(), QString("mine.json"));

    // Router → New from preset → C1, through the menus.
    auto *bar = f.editor.findChild<QToolBar *>("routerToolBar");
    auto *button = qobject_cast<QToolButton *>(
        bar->widgetForAction(f.editor.findChild<QAction *>("routerMenuAction")));
    QVERIFY(button);
    QMenu *presets = f.editor.findChild<QMenu *>("presetMenu");
    QVERIFY(presets);
    QTimer::singleShot(0, [presets] {
        QMenu *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
        QVERIFY(menu);
        menu->setActiveAction(presets->menuAction());
        QTest::keyClick(menu, Qt::Key_Right); // opens the submenu
        QTRY_VERIFY(presets->isVisible());
        for (QAction *action : presets->actions()) {
            if (action->text() == "C1") {
                presets->setActiveAction(action);
                QTest::keyClick(presets, Qt::Key_Return);
                return;
            }
        }
        QFAIL("no C1 in the preset menu");
    });
    QTest::mouseClick(button, Qt::LeftButton);
    QTRY_COMPARE(f.editor.graph().name, QString("C1"));
    QCOMPARE(document->text(), QString("C1 — preset"));
    f.editor.setParam("right.force", "grasp", 25.0);
    QCOMPARE(document->text(), QString("* C1 — changed from the preset, not saved to a file"));
    QCOMPARE(status->text(), QString("New router from the preset C1."));
    QVERIFY(!status->text().contains("mine.json"));
}

void TestRouterEditor::selfContainedEmbedsUserPatterns()
{
    QTemporaryDir dir;
    QFile builtin(SEMHAP_RESOURCES "/patterns/vib.geiger.json");
    QVERIFY(builtin.open(QIODevice::ReadOnly));
    QJsonObject pattern = QJsonDocument::fromJson(builtin.readAll()).object();
    pattern.insert("name", "my.warning");
    QFile user(dir.filePath("my.warning.json"));
    QVERIFY(user.open(QIODevice::WriteOnly));
    user.write(QJsonDocument(pattern).toJson());
    user.close();

    Fixture f;
    f.editor.setGraph(preset("C3"));
    f.editor.setParam("right.geiger", "pattern", user.fileName());
    QCOMPARE(f.editor.validate(), QStringList());
    QString error;
    QVERIFY2(f.editor.saveFile(dir.filePath("portable.json"), true, &error), qPrintable(error));
    QVERIFY(QFile::remove(user.fileName()));
    RouterGraph loaded;
    LoadError loadError;
    QVERIFY(RouterGraph::fromFile(dir.filePath("portable.json"), &loaded, &loadError));
    QCOMPARE(loaded.patterns.size(), size_t(1));
    QCOMPARE(loaded.patterns.front()->name(), "my.warning");
    QCOMPARE(loaded.nodes[size_t(loaded.nodeIndex("right.geiger"))].params.value("pattern"),
             "my.warning");
    QVERIFY2(Router::compile(loaded, &loadError), qPrintable(loadError.toString()));
    // The editor offers the embedded pattern by name.
    QVERIFY(f.editor.openFile(dir.filePath("portable.json"), &error));
    f.select("right.geiger");
    auto *combo = f.editor.inspector()->findChild<QComboBox *>("param:pattern");
    QVERIFY(combo);
    QVERIFY(combo->findText("my.warning") >= 0);
}

void TestRouterEditor::inspectorShowsTheNodeTypeTable()
{
    // The fields come from the core's specs: defaults, units and help as the compiler has
    // them, choices for every choice parameter, and a pattern's own parameters.
    Fixture f;
    f.editor.setGraph(preset("C3p"));
    f.select("right.break");
    const RouterNodeType &threshold = *routerNodeType("threshold");
    auto *minDuration = f.editor.inspector()->findChild<QLineEdit *>("param:minDuration");
    QVERIFY(minDuration);
    QCOMPARE(minDuration->toolTip(), threshold.param("minDuration")->help);
    QVERIFY2(minDuration->placeholderText().contains("0"),
             qPrintable(minDuration->placeholderText()));
    auto *message = f.editor.inspector()->findChild<QComboBox *>("param:message");
    QVERIFY(message);
    for (const QString &choice : threshold.param("message")->choices)
        QVERIFY2(message->findData(choice) >= 0, qPrintable(choice));

    const RouterGraph &graph = f.editor.graph();
    for (const RouterNode &node : graph.nodes) {
        if (node.type != "predict")
            continue;
        f.select(node.id);
        auto *tau = f.editor.inspector()->findChild<QLineEdit *>("param:tau");
        QVERIFY(tau);
        QVERIFY2(tau->placeholderText().contains(QLocale().toString(DefaultSlopeTau)),
                 qPrintable(tau->placeholderText()));
        break;
    }
    // A pattern with parameters of its own: one field each, with the pattern's default.
    f.select("right.squeeze");
    f.type("param:pattern", "air.proportional");
    const PatternPtr played =
        graph.playedPattern(graph.nodes[size_t(graph.nodeIndex("right.squeeze"))]);
    QVERIFY(played && played->params().size() > 1);
    for (int p = 0; p < played->params().size(); ++p) {
        auto *field =
            f.editor.inspector()->findChild<QLineEdit *>("param:" + played->params().name(p));
        QVERIFY2(field, qPrintable(played->params().name(p)));
        QVERIFY(field->placeholderText().contains(
            QLocale().toString(played->params().defaultValue(p))));
    }
}

void TestRouterEditor::selfContainedKeepsPatternsOfOneName()
{
    // Two user files that both call their pattern "mine": the editor used to embed one and
    // point both nodes at it, so the second node played the first file.
    QTemporaryDir dir;
    const auto write = [&](const QString &file, double value) {
        const QJsonObject pattern{
            {"format", "semhap.pattern/1"},
            {"name", "mine"},
            {"model", "lra4"},
            {"tracks", QJsonArray{QJsonObject{
                           {"channels", QJsonArray{"*"}},
                           {"sustain", QJsonObject{{"type", "const"}, {"value", value}}}}}}};
        QFile out(dir.filePath(file));
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(pattern).toJson());
    };
    write("soft.json", 0.3);
    write("hard.json", 0.9);
    Fixture f;
    f.editor.setGraph(preset("C3"));
    f.editor.setParam("right.geiger", "pattern", dir.filePath("soft.json"));
    f.editor.setParam("left.geiger", "pattern", dir.filePath("hard.json"));
    QCOMPARE(f.editor.validate(), QStringList());
    QString error;
    QVERIFY2(f.editor.saveFile(dir.filePath("portable.json"), true, &error), qPrintable(error));

    RouterGraph loaded;
    LoadError loadError;
    QVERIFY(RouterGraph::fromFile(dir.filePath("portable.json"), &loaded, &loadError));
    QCOMPARE(loaded.patterns.size(), size_t(2));
    const auto played = [&](const QString &node) {
        const QString name =
            loaded.nodes[size_t(loaded.nodeIndex(node))].params.value("pattern").toString();
        QString reason;
        const PatternPtr pattern = loaded.pattern(name, &reason);
        return pattern ? pattern->toJson()["tracks"][0]["sustain"]["value"].toDouble() : -1.0;
    };
    QCOMPARE(played("right.geiger"), 0.3);
    QCOMPARE(played("left.geiger"), 0.9);
    QCOMPARE(loaded.nodes[size_t(loaded.nodeIndex("left.geiger"))].params.value("pattern"),
             "mine~2");
    QVERIFY2(Router::compile(loaded, &loadError), qPrintable(loadError.toString()));
}

void TestRouterEditor::documentDrivesItsViews()
{
    // The document is edited; two scenes on it follow, each from its signals alone.
    RouterDocument document;
    RouterScene first(document);
    RouterScene second(document);
    QSignalSpy changed(&document, &RouterDocument::changed);
    QSignalSpy inserted(&document, &RouterDocument::nodeInserted);
    QSignalSpy params(&document, &RouterDocument::nodeParamsChanged);
    QSignalSpy links(&document, &RouterDocument::linksChanged);
    const RouterGraph c3 = RouterScene::placed(preset("C3"));
    document.reset(c3);
    QVERIFY(!document.isModified());
    const auto inStep = [&](const RouterScene &scene) {
        const RouterGraph &graph = document.graph();
        for (const RouterNode &node : graph.nodes) {
            const RouterNodeItem *item = scene.nodeItem(node.id);
            if (!item || item->pos() != RouterDocument::nodePos(node))
                return false;
        }
        for (size_t j = 0; j < graph.links.size(); ++j) {
            if (!scene.wireItem(int(j)))
                return false;
        }
        return scene.items().size() >= qsizetype(graph.nodes.size() + graph.links.size());
    };
    QVERIFY(inStep(first) && inStep(second));

    QUndoStack &undo = *document.undoStack();
    RouterNode filter{document.uniqueId("right.confirm"), "filter",
                      QJsonObject{{"category", "confirmation"}},
                      QJsonObject{{"x", 40.0}, {"y", 900.0}}};
    QCOMPARE(filter.id, QString("right.confirm2"));
    undo.push(new AddNodeCommand(&document, filter));
    QCOMPARE(inserted.count(), 1);
    QCOMPARE(changed.count(), 2); // the reset, then the one edit
    undo.push(new ConnectCommand(&document, RouterLink{"right.force", {}, filter.id, {}}));
    QCOMPARE(links.count(), 1);
    undo.push(new SetParamCommand(&document, filter.id, "category", "exception"));
    QCOMPARE(params.count(), 1);
    undo.push(new RenameNodeCommand(&document, filter.id, "right.other"));
    undo.push(
        new MoveNodesCommand(&document, {"right.other"}, {QPointF(40, 900)}, {QPointF(80, 950)}));
    QVERIFY(document.isModified());
    QVERIFY(inStep(first) && inStep(second));
    QVERIFY(first.nodeItem("right.other") && !first.nodeItem(filter.id));
    QCOMPARE(second.nodeItem("right.other")->pos(), QPointF(80, 950));
    undo.push(new RemoveCommand(&document, {"right.force"}, {}));
    QVERIFY(inStep(first) && inStep(second));
    QVERIFY(!second.nodeItem("right.force"));

    // Undoing everything gives back the graph exactly, and the views with it.
    undo.setIndex(0);
    QCOMPARE(document.graph().toJson(), c3.toJson());
    QVERIFY(!document.isModified());
    QVERIFY(inStep(first) && inStep(second));
}

void TestRouterEditor::failedSaveKeepsTheFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("router.json");
    QFile existing(path);
    QVERIFY(existing.open(QIODevice::WriteOnly));
    existing.write("what was there");
    existing.close();
    RouterDocument document;
    document.reset(preset("C3"));
    document.undoStack()->push(
        new SetParamCommand(&document, "right.geiger", "pattern", dir.filePath("missing.json")));
    QString error;
    // Self-contained, the missing pattern file stops the save before anything is written.
    QVERIFY(!document.save(path, true, &error));
    QVERIFY2(error.contains("missing.json"), qPrintable(error));
    QVERIFY(existing.open(QIODevice::ReadOnly));
    QCOMPARE(existing.readAll(), QByteArray("what was there"));
    existing.close();
    QVERIFY(document.isModified());
    QVERIFY(document.path().isEmpty());
    // A folder that does not exist: the reason, and nothing left behind.
    QVERIFY(!document.save(dir.filePath("no/such/folder/router.json"), false, &error));
    QVERIFY2(error.contains("cannot write"), qPrintable(error));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"router.json"});
    QVERIFY(document.save(path, false, &error));
    QVERIFY(!document.isModified());
    QCOMPARE(document.path(), path);
}

void TestRouterEditor::opensAnOldSpelling()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("old.json");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "semhap.router/1", "nodes": [
        {"id": "h", "type": "hysteresis", "params": {"hold": 0.1}}]})");
    file.close();
    Fixture f;
    QString error;
    QVERIFY2(f.editor.openFile(path, &error), qPrintable(error));
    QVERIFY2(f.editor.statusLabel()->text().contains("deprecated"),
             qPrintable(f.editor.statusLabel()->text()));
    QCOMPARE(f.editor.graph().nodes[0].type, QString("debounce"));
    QVERIFY(f.editor.saveFile(path, false, &error));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray saved = file.readAll();
    QVERIFY(saved.contains("\"debounce\"") && !saved.contains("hysteresis"));
}

void TestRouterEditor::offersTheDesignersPatterns()
{
    QStandardPaths::setTestModeEnabled(true);
    QVERIFY(QDir().mkpath(StudioFolders::patterns()));
    const QString path = StudioFolders::patterns() + "/my.slipwarning.json";
    QFile::remove(path);
    QVERIFY(QFile::copy(SEMHAP_RESOURCES "/patterns/vib.geiger.json", path));
    Fixture f;
    f.editor.setGraph(preset("C3"));
    f.select("left.geiger");
    auto *combo = f.editor.inspector()->findChild<QComboBox *>("param:pattern");
    QVERIFY(combo);
    // Listed by name; the node stores the file, as the core reads it.
    const int at = combo->findData(path);
    QVERIFY2(at >= 0, qPrintable(path));
    QCOMPARE(combo->itemText(at), QString("my.slipwarning"));
    for (int i = 0; i < combo->count(); ++i)
        QVERIFY2(!combo->itemText(i).contains('/'), qPrintable(combo->itemText(i)));
    combo->setFocus();
    while (combo->currentIndex() != at)
        QTest::keyClick(combo, combo->currentIndex() < at ? Qt::Key_Down : Qt::Key_Up);
    const auto stored = [&f] {
        return f.editor.graph()
            .nodes[size_t(f.editor.graph().nodeIndex("left.geiger"))]
            .params.value("pattern")
            .toString();
    };
    QTRY_COMPARE(stored(), path);
    QCOMPARE(f.editor.validate(), QStringList());
    // The inspector, built again, shows the node's pattern by its name.
    QTRY_VERIFY(f.editor.inspector()->findChild<QComboBox *>("param:pattern") != combo);
    combo = f.editor.inspector()->findChild<QComboBox *>("param:pattern");
    QCOMPARE(combo->currentText(), QString("my.slipwarning"));

    // Typing a name picks what it names: a built-in by name, the user's pattern by its file.
    for (const QString &name : {QString("vib.geiger"), QString("my.slipwarning")}) {
        combo = f.editor.inspector()->findChild<QComboBox *>("param:pattern");
        combo->lineEdit()->selectAll();
        QTest::keyClicks(combo->lineEdit(), name);
        QTest::keyClick(combo->lineEdit(), Qt::Key_Return);
        QTRY_COMPARE(stored(), name == "vib.geiger" ? name : path);
        QCoreApplication::processEvents(); // the inspector rebuilds queued
    }

    // Saved, the router names the file, as the core reads it (self-contained embeds it).
    QTemporaryDir dir;
    QString error;
    QVERIFY2(f.editor.saveFile(dir.filePath("plain.json"), false, &error), qPrintable(error));
    RouterGraph plain;
    LoadError loadError;
    QVERIFY(RouterGraph::fromFile(dir.filePath("plain.json"), &plain, &loadError));
    QCOMPARE(plain.nodes[size_t(plain.nodeIndex("left.geiger"))].params.value("pattern"), path);
    QFile::remove(path);
}

void TestRouterEditor::followsARenamedPattern()
{
    // The designer renamed a user pattern: the nodes that name its file name the new one, as
    // one undoable step; nodes naming other patterns are left alone.
    Fixture f;
    f.editor.setGraph(preset("C3"));
    const QString from = "/tmp/patterns/mine.json";
    const QString to = "/tmp/patterns/yours.json";
    f.editor.setParam("left.geiger", "pattern", from);
    f.editor.setParam("right.geiger", "pattern", from);
    const QString squeeze = f.editor.graph()
                                .nodes[size_t(f.editor.graph().nodeIndex("right.squeeze"))]
                                .params.value("pattern")
                                .toString();
    const int steps = f.editor.undoStack()->count();
    f.editor.followRenamedPattern(from, to);
    const auto pattern = [&f](const char *id) {
        return f.editor.graph()
            .nodes[size_t(f.editor.graph().nodeIndex(id))]
            .params.value("pattern")
            .toString();
    };
    QCOMPARE(pattern("left.geiger"), to);
    QCOMPARE(pattern("right.geiger"), to);
    QCOMPARE(pattern("right.squeeze"), squeeze);
    QCOMPARE(f.editor.undoStack()->count(), steps + 1);
    f.editor.undoStack()->undo();
    QCOMPARE(pattern("left.geiger"), from);
    QCOMPARE(pattern("right.geiger"), from);
    // Nothing names the file: no step.
    f.editor.followRenamedPattern("/tmp/patterns/other.json", to);
    QCOMPARE(f.editor.undoStack()->index(), steps);
}

void TestRouterEditor::engineSwapsWhileRunning()
{
    Engine engine;
    RunOptions options;
    options.duration = 3600.0;
    QString error;
    QVERIFY2(engine.load(options, &error), qPrintable(error));
    engine.setSpeed(8.0);
    engine.run();
    QTRY_VERIFY_WITH_TIMEOUT(!engine.history().events().isEmpty(), 30000);
    const RunHistory &history = engine.history();
    const qint64 firstFrame = history.frames(Gripper::Right).begin();
    const qint64 framesBefore = history.frames(Gripper::Right).end();
    const qint64 eventsBefore = history.events().end();
    QSignalSpy reset(&engine.history(), &RunHistory::reset);
    QSignalSpy changed(&engine.history(), &RunHistory::routerChanged);
    QSignalSpy routerChanged(&engine, &Engine::routerChanged);

    // A broken graph is refused and the run keeps its router.
    RouterGraph broken = preset("C4");
    broken.nodes[0].params.insert("grasp", "lots");
    QVERIFY(!engine.setRouter(broken, &error));
    QVERIFY2(error.contains("grasp"), qPrintable(error));
    QCOMPARE(engine.routerGraph().name, "C3");

    RouterGraph c4 = preset("C4");
    QVERIFY2(engine.setRouter(c4, &error), qPrintable(error));
    QCOMPARE(engine.routerGraph().name, "C4");
    QCOMPARE(engine.options().router, "C4");
    QCOMPARE(changed.count(), 1);
    QCOMPARE(routerChanged.count(), 1);
    QVERIFY(engine.isRunning());
    // The run goes on: frames keep their history, new events come.
    QTRY_VERIFY_WITH_TIMEOUT(history.events().end() > eventsBefore + 2, 30000);
    QVERIFY(history.frames(Gripper::Right).end() > framesBefore);
    QCOMPARE(history.frames(Gripper::Right).begin(), firstFrame);
    QCOMPARE(reset.count(), 0);
    for (const RunDevice &device : history.devices())
        QVERIFY2(engine.devices().transport(device.name), qPrintable(device.name));
    // Every event after the swap names a detector of C4.
    for (qint64 i = eventsBefore; i < history.events().end(); ++i)
        QVERIFY(c4.nodeIndex(history.nodeName(history.events().at(i).node)) >= 0);
    // The preset as it is, laid out by the editor, is not an edit; a changed parameter is,
    // and stays one over a reset (the toolbar says C4*).
    QVERIFY(!engine.isRouterEdited());
    QVERIFY(engine.setRouter(RouterScene::placed(c4), &error));
    QVERIFY(!engine.isRouterEdited());
    RouterGraph edited = c4;
    edited.nodes[0].params.insert("grasp", 25);
    QVERIFY2(engine.setRouter(edited, &error), qPrintable(error));
    QCOMPARE(engine.options().router, "C4");
    QVERIFY(engine.isRouterEdited());
    // Reset runs the applied graph again.
    QVERIFY(engine.reset(&error));
    QCOMPARE(engine.routerGraph().name, "C4");
    QVERIFY(engine.isRouterEdited());
    engine.pause();
}

void TestRouterEditor::liveActivityLightsWires()
{
    // The wires light from what the running router reports, gates included: a break warning
    // held back by a closed gate lights nothing past the gate until its control opens it.
    Fixture f;
    const RouterGraph graph = gatedRouter();
    f.editor.setGraph(graph);
    RunHistory history;
    f.editor.setHistory(&history);
    LoadError error;
    std::unique_ptr<Router> router = Router::compile(graph, &error);
    QVERIFY2(router, qPrintable(error.toString()));
    history.start({}, {}, router->nodeIds());
    Pipeline pipeline(std::move(router));
    struct Sink : PipelineSink
    {
        RunHistory *history;
        void onNodeActivity(const NodeActivity &activity) override { history->append(activity); }
    } sink;
    sink.history = &history;
    const auto feed = [&](double t, Gripper gripper, double force) {
        pipeline.process(forceFrame(t, gripper, force), sink);
        history.commit();
    };
    RouterScene *scene = f.editor.scene();
    const auto wire = [&](const QString &from, const QString &to) {
        for (size_t j = 0; j < graph.links.size(); ++j) {
            if (graph.links[j].from == from && graph.links[j].to == to)
                return scene->wireItem(int(j))->glow();
        }
        return -1.0;
    };
    feed(0.0, Gripper::Right, 100); // grasp and break
    QVERIFY(wire("force", "grasps") > 0.5);
    QVERIFY(wire("force", "breaks") > 0.5);
    QCOMPARE(wire("breaks", "gate"), 0.0); // the gate holds it back
    QCOMPARE(wire("gate", "buzz"), 0.0);
    QVERIFY2(scene->nodeItem("breaks")->state().contains("break"),
             qPrintable(scene->nodeItem("breaks")->state()));
    QVERIFY(scene->nodeItem("gate")->state().isEmpty());
    feed(0.01, Gripper::Left, 30); // the control's grasp opens it
    QVERIFY(wire("breaks", "gate") > 0.5);
    QVERIFY(wire("gate", "buzz") > 0.5);
    QVERIFY(wire("buzz", "right.vibro") > 0.5);
    QVERIFY(scene->nodeItem("buzz")->state().contains("break"));
    QTRY_COMPARE_WITH_TIMEOUT(wire("force", "grasps"), 0.0, 2000);
    feed(0.02, Gripper::Left, 0); // the control lets go: the gate ends what it passed
    QVERIFY(scene->nodeItem("gate")->state().isEmpty());
    QVERIFY(scene->nodeItem("buzz")->state().isEmpty());
    QVERIFY(scene->nodeItem("breaks")->state().contains("break"));
}

void TestRouterEditor::signalPickerOffersTheSourcesSignals()
{
    // The source's context: the picker lists its signals for the node's gripper, the
    // graph is checked against it, and a signal it lacks is refused with the core's reason.
    Fixture f;
    RouterContext source;
    source.knowsSignals = true;
    source.signalNames[size_t(Gripper::Right)] = QStringList{"plug.angle", "plug.depth"};
    source.signalNames[size_t(Gripper::Left)] = QStringList{"wrist.fz"};
    f.editor.setContextFunction([&source] { return source; });
    QString applied;
    f.editor.setApplyFunction([&applied](const RouterGraph &graph, QString *) {
        applied = graph.nodes.front().params.value("quantity").toString();
        return true;
    });
    const QString id = f.addFromPalette("signal");
    QVERIFY(f.pick("param:gripper", "right"));
    QCOMPARE(f.editor.graph().nodes.front().params.value("gripper"), "right");
    auto *quantity = f.editor.inspector()->findChild<QComboBox *>("param:quantity");
    QVERIFY(quantity);
    QVERIFY(quantity->isEditable());
    for (const QString &builtin : routerNodeType("signal")->param("quantity")->choices)
        QVERIFY2(quantity->findText(builtin) >= 0, qPrintable(builtin));
    QVERIFY(quantity->findText("plug.angle") >= 0);
    QVERIFY(quantity->findText("plug.depth") >= 0);
    QCOMPARE(quantity->findText("wrist.fz"), -1); // the left gripper's
    // A signal the source reports later (a live rig's next frames) is offered as the list
    // opens again.
    source.signalNames[size_t(Gripper::Right)].append("plug.force");
    QVERIFY(f.pick("param:quantity", "plug.force"));
    QCOMPARE(f.editor.graph().nodes.front().params.value("quantity"), "plug.force");
    source.signalNames[size_t(Gripper::Right)].removeLast();
    QVERIFY(f.pick("param:quantity", "plug.angle"));
    QCOMPARE(f.editor.graph().nodes.front().params.value("quantity"), "plug.angle");
    QTRY_VERIFY(f.editor.errors().isEmpty());
    QVERIFY(f.editor.apply());
    QCOMPARE(applied, QStringLiteral("plug.angle"));

    // Typed: a name the scene does not declare is marked, and Apply says why.
    f.select(id);
    f.type("param:quantity", "plug.lateral");
    QCOMPARE(f.editor.graph().nodes.front().params.value("quantity"), "plug.lateral");
    QVERIFY(!f.editor.apply());
    const QString reason = "the right gripper's frames carry no signal 'plug.lateral' (they "
                           "carry: plug.angle, plug.depth)";
    QVERIFY2(f.editor.statusLabel()->text().contains(reason),
             qPrintable(f.editor.statusLabel()->text()));
    QVERIFY(f.editor.errors().join("\n").contains(reason));
    // A source that does not know its signals in advance takes any name.
    source.knowsSignals = false;
    f.editor.updateContext();
    QTRY_VERIFY(f.editor.errors().isEmpty());
}

void TestRouterEditor::messageFieldsOfferNewMessages()
{
    // A message typed on one node is offered on the others, besides the built-in ones.
    Fixture f;
    f.addFromPalette("threshold");
    auto *message = f.editor.inspector()->findChild<QComboBox *>("param:message");
    QVERIFY(message);
    QVERIFY(message->isEditable());
    f.type("param:message", "aligned");
    QCOMPARE(f.editor.graph().nodes.front().params.value("message"), "aligned");
    QVERIFY(f.pick("param:category", "confirmation"));
    QCOMPARE(f.editor.newMessageNames(), QStringList{"aligned"});

    f.addFromPalette("compose");
    QVERIFY(f.pick("param:message", "aligned"));
    QCOMPARE(f.editor.graph().nodes.back().params.value("message"), "aligned");
    const QString filter = f.addFromPalette("filter");
    auto *passes = f.editor.inspector()->findChild<QComboBox *>("param:message");
    QVERIFY(passes->findText("aligned") >= 0);
    QVERIFY(passes->findText("grasp") >= 0);
    // A filter passes a list: typed with commas.
    f.type("param:message", "grasp, aligned");
    const int node = f.editor.graph().nodeIndex(filter);
    QCOMPARE(f.editor.graph().nodes[size_t(node)].params.value("message"),
             QJsonArray({"grasp", "aligned"}));
    // Its "(any)" entry clears it again.
    QVERIFY(f.pick("param:message", RouterEditor::tr("(any)")));
    QVERIFY(!f.editor.graph().nodes[size_t(node)].params.contains("message"));
}

void TestRouterEditor::levelsAreTypedAsNumbersOrRanges_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("shown");
    const QJsonValue range(QJsonArray{0.02, 0.08});
    QTest::newRow("number") << "en_US"
                            << "80" << QJsonValue(80) << "80";
    QTest::newRow("JSON range") << "en_US"
                                << "[0.02, 0.08]" << range << "[0.02, 0.08]";
    QTest::newRow("two numbers") << "en_US"
                                 << "0.02, 0.08" << range << "[0.02, 0.08]";
    QTest::newRow("negative range")
        << "en_US"
        << "-0.05; 0.05" << QJsonValue(QJsonArray{-0.05, 0.05}) << "[-0.05, 0.05]";
    QTest::newRow("German number") << "de_DE"
                                   << "0,5" << QJsonValue(0.5) << "0,5";
    QTest::newRow("German semicolon") << "de_DE"
                                      << "0,02; 0,08" << range << "[0,02; 0,08]";
    QTest::newRow("German brackets") << "de_DE"
                                     << "[0,02; 0,08]" << range << "[0,02; 0,08]";
    QTest::newRow("German comma space") << "de_DE"
                                        << "0,02, 0,08" << range << "[0,02; 0,08]";
    QTest::newRow("German JSON") << "de_DE"
                                 << "[0.02, 0.08]" << range << "[0,02; 0,08]";
    QTest::newRow("not a level") << "en_US"
                                 << "low" << QJsonValue("low") << "low";
}

void TestRouterEditor::levelsAreTypedAsNumbersOrRanges()
{
    QFETCH(QString, locale);
    QFETCH(QString, typed);
    QFETCH(QJsonValue, value);
    QFETCH(QString, shown);
    struct LocaleGuard
    {
        QLocale before;
        ~LocaleGuard() { QLocale::setDefault(before); }
    } guard;
    QLocale::setDefault(QLocale(locale));
    Fixture f;
    f.addFromPalette("threshold");
    f.type("param:begin", typed);
    QCOMPARE(f.editor.graph().nodes.front().params.value("begin"), value);
    QCOMPARE(f.editor.inspector()->findChild<QLineEdit *>("param:begin")->text(), shown);
}

// Issue 34: the open router's messages on each band, as far apart as a person feels them;
// an edit that puts two messages on one pattern shows them confusable at once.
void TestRouterEditor::distinctivenessFollowsTheRouter()
{
    Fixture f;
    f.editor.setGraph(preset("C4"));
    auto *tabs = f.editor.findChild<QTabWidget *>("routerSideTabs");
    QVERIFY(tabs);
    QTest::mouseClick(tabs->tabBar(), Qt::LeftButton, {},
                      tabs->tabBar()->tabRect(1).center());
    auto *view = f.editor.findChild<DistinctivenessView *>("routerDistinct");
    QCOMPARE(tabs->currentWidget(), view);
    auto *band = view->findChild<QComboBox *>("distinctBand");
    auto *matrix = view->findChild<QTableWidget *>("distinctMatrix");
    auto *summary = view->findChild<QLabel *>("distinctSummary");
    QCOMPARE(band->count(), 2); // left.air and right.air: C4 is all pneumatic
    band->setCurrentIndex(band->findData("right.air"));
    QCOMPARE(matrix->rowCount(), 2);
    QCOMPARE(matrix->verticalHeaderItem(0)->text(), QString("right.force:grasp"));
    QCOMPARE(matrix->verticalHeaderItem(1)->text(), QString("right.force:break"));
    QVERIFY(matrix->item(0, 1)->text().toDouble() > 3.0);
    QVERIFY2(summary->text().contains("no two of these messages are closer than 1 JND"),
             qPrintable(summary->text()));

    // The break warning's pulses become the grasp's squeeze: one pattern for both.
    f.select("right.pulse5hz");
    QCOMPARE(tabs->currentWidget(), f.editor.inspector()); // a node picked shows its fields
    f.type("param:pattern", "air.squeeze");
    QTRY_COMPARE(matrix->item(0, 1)->text(), QString("0.00"));
    QCOMPARE(band->currentData().toString(), QString("right.air")); // the band looked at stays
    QVERIFY(matrix->item(0, 1)->font().bold());
    QVERIFY2(summary->text().contains("right.force:grasp and right.force:break (0.00 JND)"),
             qPrintable(summary->text()));

    // A router that does not compile says so instead.
    f.type("param:pattern", "no.such");
    QTRY_VERIFY(summary->text().contains("has problems"));
    QCOMPARE(matrix->rowCount(), 0);
}

void TestRouterEditor::screenshot()
{
    const QString dir = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    if (dir.isEmpty())
        QSKIP("set SEMHAP_SCREENSHOTS=DIR (and run under xvfb with QT_QPA_PLATFORM=xcb)");
    {
        Fixture f;
        f.editor.resize(900, 820);
        f.editor.setGraph(preset("C3"));
        f.select("right.force");
        QTest::qWait(200);
        QVERIFY(f.editor.grab().save(dir + "/routereditor-alone.png"));
    }
    StudioOptions options;
    options.size = QSize(1280, 800);
    options.restoreLayout = false;
    options.posePort = 0;
    options.speed = 4.0;
    Workspace workspace;
    MainWindow window(workspace, options);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.findChild<QDockWidget *>("routerDock")->raise();
    QTest::qWait(6000);
    window.routerEditor()->fitView();
    QTest::qWait(300);
    QVERIFY(window.grab().save(dir + "/routereditor-window.png"));

    // The predictive preset on the bimanual task, English and German, at both sizes.
    for (const QString &language : {QStringLiteral("en"), QStringLiteral("de")}) {
        for (const QSize size : {QSize(1280, 800), QSize(1920, 1080)}) {
            StudioOptions c3p = options;
            c3p.run.scene = "bimanual_sorting";
            c3p.run.router = "C3p";
            c3p.size = size;
            c3p.language = language;
            Studio studio(c3p);
            studio.start();
            QVERIFY(QTest::qWaitForWindowExposed(studio.window()));
            studio.window()->findChild<QDockWidget *>("routerDock")->raise();
            QTest::qWait(4000);
            studio.window()->routerEditor()->fitView();
            QTest::qWait(300);
            QString error;
            QVERIFY2(Studio::screenshot(studio.window(),
                                        QStringLiteral("%1/router-c3p-%2-%3x%4.png")
                                            .arg(dir, language)
                                            .arg(size.width())
                                            .arg(size.height()),
                                        &error),
                     qPrintable(error));
            // And how far apart C1's messages feel on its right vibration band (C3p plays
            // one message per band).
            studio.window()->routerEditor()->setGraph(preset("C1"));
            auto *tabs = studio.window()->routerEditor()->findChild<QTabWidget *>("routerSideTabs");
            tabs->setCurrentIndex(1);
            auto *band = tabs->findChild<QComboBox *>("distinctBand");
            QTRY_VERIFY(band->findData("right.vibro") >= 0);
            band->setCurrentIndex(band->findData("right.vibro"));
            QTest::qWait(300);
            QVERIFY2(Studio::screenshot(studio.window(),
                                        QStringLiteral("%1/router-distinct-%2-%3x%4.png")
                                            .arg(dir, language)
                                            .arg(size.width())
                                            .arg(size.height()),
                                        &error),
                     qPrintable(error));
        }
    }
}

QTEST_MAIN(TestRouterEditor)
#include "tst_routereditor.moc"
