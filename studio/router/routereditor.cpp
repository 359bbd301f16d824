// SPDX-License-Identifier: MIT
#include "routereditor.h"

#include "colors.h"
#include "distinctivenessview.h"
#include "filedialogs.h"
#include "router.h"
#include "routercommands.h"
#include "routerdocument.h"
#include "routerinspector.h"
#include "routerpalette.h"
#include "routerscene.h"
#include "routerwireitem.h"
#include "runhistory.h"
#include "undoactions.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QDir>
#include <QFileInfo>
#include <QGraphicsView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMimeData>
#include <QScrollBar>
#include <QSplitter>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QToolTip>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <optional>

namespace semhap {

namespace {

constexpr char RouterMime[] = "application/x-semhap-router";

} // namespace

RouterEditor::RouterEditor(RouterDocument *document, QWidget *parent)
    : QWidget(parent), m_document(document ? document : new RouterDocument(this))
{
    setObjectName(QStringLiteral("routerEditor"));
    m_undo = m_document->undoStack();
    m_scene = new RouterScene(*m_document, this);
    m_view = new QGraphicsView(m_scene, this);
    m_view->setObjectName(QStringLiteral("routerView"));
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setDragMode(QGraphicsView::RubberBandDrag);
    m_view->setAcceptDrops(true);
    m_view->setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    // Hidden behind another tab, the view has no size of its own to fit the graph to.
    m_view->viewport()->installEventFilter(this);
    for (QScrollBar *bar : {m_view->horizontalScrollBar(), m_view->verticalScrollBar()})
        connect(bar, &QScrollBar::actionTriggered, this, [this] { m_fitted = false; });

    // What is edited, and whether it is saved: the run's router is the toolbar's to name.
    m_documentLabel = new QLabel(this);
    m_documentLabel->setObjectName(QStringLiteral("routerDocument"));
    m_documentLabel->setTextFormat(Qt::PlainText);
    connect(m_document, &RouterDocument::graphReset, this, &RouterEditor::showDocument);
    connect(m_undo, &QUndoStack::cleanChanged, this, &RouterEditor::showDocument);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("routerStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_errorList = new QListWidget(this);
    m_errorList->setObjectName(QStringLiteral("routerErrors"));
    m_errorList->setWordWrap(true);
    m_inspector = new RouterInspector(*this, this);
    connect(m_inspector, &RouterInspector::status, this, &RouterEditor::showStatus);
    m_palette = new RouterPalette(this);
    m_autoApply = new QCheckBox(tr("Auto-apply"), this);
    m_autoApply->setObjectName(QStringLiteral("autoApply"));
    m_autoApply->setToolTip(tr("Send every edit that compiles to the running session"));

    auto *toolbar = new QToolBar(this);
    toolbar->setObjectName(QStringLiteral("routerToolBar"));
    toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    // The selected node's parameters, and how far apart the router's messages feel.
    m_distinct = new DistinctivenessView(this);
    m_distinct->setObjectName(QStringLiteral("routerDistinct"));
    m_sideTabs = new QTabWidget(this);
    m_sideTabs->setObjectName(QStringLiteral("routerSideTabs"));
    m_sideTabs->setDocumentMode(true);
    m_sideTabs->addTab(m_inspector, tr("Node"));
    m_sideTabs->addTab(m_distinct, tr("Distinctiveness"));
    m_sideTabs->setTabToolTip(1, tr("How far apart the messages on each band feel, in "
                                    "just-noticeable differences"));
    auto *bottom = new QSplitter(Qt::Horizontal, this);
    bottom->addWidget(m_palette);
    bottom->addWidget(m_sideTabs);
    // The palette's two columns of names; the rest is the inspector's.
    bottom->setStretchFactor(0, 1);
    bottom->setStretchFactor(1, 3);
    bottom->setSizes({200, 600});
    auto *canvas = new QWidget(this);
    auto *canvasLayout = new QVBoxLayout(canvas);
    canvasLayout->setContentsMargins(0, 0, 0, 0);
    canvasLayout->setSpacing(2);
    canvasLayout->addWidget(m_documentLabel);
    canvasLayout->addWidget(m_view, 1);
    canvasLayout->addWidget(m_status);
    // The problems take room from the canvas, never from the palette and the inspector
    // (the palette reflowed under the mouse as they came and went).
    m_errorList->setMaximumHeight(5 * m_errorList->fontMetrics().lineSpacing());
    canvasLayout->addWidget(m_errorList);
    auto *split = new QSplitter(Qt::Vertical, this);
    split->setObjectName(QStringLiteral("routerSplit"));
    split->addWidget(canvas);
    split->addWidget(bottom);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    split->setSizes({540, 190});
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(toolbar);
    layout->addWidget(split, 1);

    m_validateTimer = new QTimer(this);
    m_validateTimer->setSingleShot(true);
    m_validateTimer->setInterval(150);
    connect(m_validateTimer, &QTimer::timeout, this, [this] {
        validate();
        if (m_autoApply->isChecked() && m_errors.isEmpty() && m_apply)
            apply();
    });

    const QList<QAction *> tools = createActions();
    toolbar->addAction(tools.front());
    if (auto *button = qobject_cast<QToolButton *>(toolbar->widgetForAction(tools.front())))
        button->setPopupMode(QToolButton::InstantPopup);
    toolbar->addSeparator();
    for (QAction *action : tools.mid(1))
        toolbar->addAction(action);
    auto *spacer = new QWidget(toolbar);
    spacer->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    toolbar->addWidget(spacer);
    toolbar->addWidget(m_autoApply);
    toolbar->addAction(m_applyAction);
    if (QWidget *button = toolbar->widgetForAction(m_applyAction))
        button->setObjectName(QStringLiteral("applyButton"));

    connect(m_document, &RouterDocument::changed, this, &RouterEditor::onGraphChanged);
    connect(m_scene, &QGraphicsScene::selectionChanged, m_inspector, &RouterInspector::schedule);
    // A node picked on the canvas shows its parameters, wherever the side was.
    connect(m_scene, &QGraphicsScene::selectionChanged, this, [this] {
        if (!m_scene->selectedNodeIds().isEmpty())
            m_sideTabs->setCurrentWidget(m_inspector);
    });
    connect(m_scene, &RouterScene::connectRequested, this, [this](const RouterLink &link) {
        QString reason;
        connectPorts(link, &reason);
    });
    connect(m_scene, &RouterScene::connectRefused, this,
            [this](const QString &reason, const QPointF &scenePos) {
                showStatus(tr("Not connected: %1").arg(reason), true);
                const QPoint at = m_view->viewport()->mapToGlobal(m_view->mapFromScene(scenePos));
                QToolTip::showText(at, reason, m_view);
            });
    connect(m_scene, &RouterScene::nodesMoved, this,
            [this](const QStringList &ids, const QList<QPointF> &from, const QList<QPointF> &to) {
                m_undo->push(new MoveNodesCommand(m_document, ids, from, to));
            });
    connect(m_scene, &RouterScene::nodeDropped, this,
            [this](const QString &type, const QPointF &pos) { addNode(type, pos); });
    connect(m_palette, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem *item) {
        // In free space, as near the view's centre as there is any.
        const QPointF centre = m_view->mapToScene(m_view->viewport()->rect().center()) -
                               QPointF(RouterNodeItem::Width / 2, RouterScene::NewNodeHeight / 2);
        const QRectF visible = m_view->mapToScene(m_view->viewport()->rect()).boundingRect();
        const QString id =
            addNode(item->data(Qt::UserRole).toString(), m_scene->freePlace(centre, visible));
        if (RouterNodeItem *node = m_scene->nodeItem(id))
            m_view->ensureVisible(node);
    });
    connect(m_errorList, &QListWidget::itemActivated, this, [this](QListWidgetItem *item) {
        const QString id = item->data(Qt::UserRole).toString();
        if (RouterNodeItem *node = m_scene->nodeItem(id)) {
            m_scene->clearSelection();
            node->setSelected(true);
            m_view->centerOn(node);
            m_fitted = false;
        }
    });
    connect(m_errorList, &QListWidget::itemClicked, m_errorList, &QListWidget::itemActivated);

    if (document) {
        // An editor built again over a document shows it as it is, edits and undo kept.
        fitView();
        validate();
        showDocument();
    } else {
        setGraph(RouterGraph());
    }
}

RouterEditor::~RouterEditor()
{
    // Our own document dies with our children, after this editor's members: its undo stack,
    // left not clean, says it is clean again as it is destroyed, and showDocument() then ran
    // on a half-destroyed editor (free(): invalid pointer, once in a CI run).
    m_undo->disconnect(this);
    m_document->disconnect(this);
    // And the scene, whose items say the selection changed as they go.
    m_scene->disconnect(this);
}

QList<QAction *> RouterEditor::createActions()
{
    // The document menu: new, templates, open, save.
    auto *fileAction = new QAction(tr("Router"), this);
    fileAction->setObjectName(QStringLiteral("routerMenuAction"));
    auto *menu = new QMenu(this);
    menu->setObjectName(QStringLiteral("routerMenu"));
    fileAction->setMenu(menu);
    const auto item = [this](QMenu *into, const QString &text, std::function<void()> slot) {
        QAction *action = into->addAction(text);
        connect(action, &QAction::triggered, this, std::move(slot));
        return action;
    };
    item(menu, tr("New (empty)"), [this] {
        QString error;
        newFromPreset(QString(), &error);
    });
    QMenu *presets = menu->addMenu(tr("New from preset"));
    presets->setObjectName(QStringLiteral("presetMenu"));
    for (const QString &name : RouterPresets::names()) {
        item(presets, name, [this, name] {
            QString error;
            if (!newFromPreset(name, &error))
                showStatus(error, true);
        });
    }
    menu->addSeparator();
    item(menu, tr("Open…"), [this] {
        const QString path = FileDialogs::openFile(this, FileKind::Router, tr("Open router"),
                                                   tr("semhap routers (*.json)"));
        QString error;
        if (!path.isEmpty() && !openFile(path, &error))
            showStatus(error, true);
    });
    QAction *save = item(menu, tr("Save…"), [this] { exportDialog(false); });
    save->setShortcut(QKeySequence::Save);
    save->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(save);
    item(menu, tr("Save self-contained…"), [this] { exportDialog(true); });
    addAction(fileAction);

    QAction *undo = UndoActions::undo(m_undo, this);
    undo->setObjectName(QStringLiteral("routerUndo"));
    QAction *redo = UndoActions::redo(m_undo, this);
    redo->setObjectName(QStringLiteral("routerRedo"));
    auto *arrangeAction = new QAction(tr("Arrange"), this);
    arrangeAction->setToolTip(tr("Lay the nodes out in columns: detectors, logic, patterns, "
                                 "devices"));
    connect(arrangeAction, &QAction::triggered, this, &RouterEditor::arrange);
    addAction(arrangeAction);
    auto *fit = new QAction(tr("Fit"), this);
    fit->setToolTip(tr("Show the whole graph"));
    connect(fit, &QAction::triggered, this, &RouterEditor::fitView);
    addAction(fit);

    // Canvas keys: only while the canvas has the focus, so text fields keep theirs.
    const auto canvasAction = [this](const QString &text, const QKeySequence &key,
                                     void (RouterEditor::*slot)()) {
        auto *action = new QAction(text, m_view);
        action->setShortcut(key);
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        connect(action, &QAction::triggered, this, slot);
        m_view->addAction(action);
    };
    canvasAction(tr("Delete"), QKeySequence::Delete, &RouterEditor::deleteSelection);
    canvasAction(tr("Delete"), QKeySequence(Qt::Key_Backspace), &RouterEditor::deleteSelection);
    canvasAction(tr("Copy"), QKeySequence::Copy, &RouterEditor::copySelection);
    canvasAction(tr("Paste"), QKeySequence::Paste, &RouterEditor::paste);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);

    m_applyAction = new QAction(tr("Apply"), this);
    m_applyAction->setObjectName(QStringLiteral("applyAction"));
    m_applyAction->setToolTip(tr("Make this graph the running router"));
    m_applyAction->setEnabled(false);
    connect(m_applyAction, &QAction::triggered, this, &RouterEditor::apply);
    return {fileAction, undo, redo, arrangeAction, fit};
}

void RouterEditor::setGraph(const RouterGraph &graph, const QString &path)
{
    m_document->reset(RouterScene::placed(graph), path);
    m_inspector->forget();
    fitView();
    validate();
}

QWidget *RouterEditor::inspector() const
{
    return m_inspector;
}

const RouterGraph &RouterEditor::graph() const
{
    return m_document->graph();
}

QString RouterEditor::addNode(const QString &type, const QPointF &scenePos)
{
    if (!routerNodeType(type))
        return QString();
    RouterNode node;
    node.id = m_document->uniqueId(type);
    node.type = type;
    node.ui = {{QStringLiteral("x"), scenePos.x()}, {QStringLiteral("y"), scenePos.y()}};
    m_undo->push(new AddNodeCommand(m_document, node));
    m_scene->clearSelection();
    m_scene->nodeItem(node.id)->setSelected(true);
    return node.id;
}

bool RouterEditor::connectPorts(const RouterLink &link, QString *reason)
{
    if (!graph().checkLink(link, reason)) {
        showStatus(tr("Not connected: %1").arg(*reason), true);
        return false;
    }
    m_undo->push(new ConnectCommand(m_document, link));
    showStatus(tr("Connected %1 to %2").arg(link.from, link.to), false);
    return true;
}

void RouterEditor::setParam(const QString &id, const QString &key, const QJsonValue &value)
{
    const int index = graph().nodeIndex(id);
    if (index < 0)
        return;
    const QJsonObject &params = graph().nodes[size_t(index)].params;
    if (params.value(key) == value)
        return;
    m_undo->push(new SetParamCommand(m_document, id, key, value));
}

void RouterEditor::followRenamedPattern(const QString &from, const QString &to)
{
    const QStringList ids = graph().nodesPlayingFile(from);
    if (ids.isEmpty())
        return;
    m_undo->beginMacro(tr("Rename pattern"));
    for (const QString &id : ids)
        setParam(id, QStringLiteral("pattern"), to);
    m_undo->endMacro();
}

bool RouterEditor::renameNode(const QString &id, const QString &newId, QString *reason)
{
    if (newId == id)
        return true;
    if (newId.isEmpty() || newId.contains(QLatin1Char(':')) ||
        std::any_of(newId.begin(), newId.end(), [](QChar c) { return c.isSpace(); })) {
        *reason = tr("'%1' is not a valid id (non-empty, no ':' or spaces)").arg(newId);
        return false;
    }
    if (graph().nodeIndex(newId) >= 0) {
        *reason = tr("there is already a node '%1'").arg(newId);
        return false;
    }
    m_undo->push(new RenameNodeCommand(m_document, id, newId));
    return true;
}

void RouterEditor::deleteSelection()
{
    const QStringList ids = m_scene->selectedNodeIds();
    const std::vector<int> links = m_scene->selectedLinks();
    if (ids.isEmpty() && links.empty())
        return;
    m_undo->push(new RemoveCommand(m_document, ids, links));
}

void RouterEditor::copySelection()
{
    const QStringList ids = m_scene->selectedNodeIds();
    if (ids.isEmpty())
        return;
    RouterGraph copy;
    for (const RouterNode &node : graph().nodes) {
        if (ids.contains(node.id))
            copy.nodes.push_back(node);
    }
    for (const RouterLink &link : graph().links) {
        if (ids.contains(link.from) && ids.contains(link.to))
            copy.links.push_back(link);
    }
    const QByteArray json = QJsonDocument(copy.toJson()).toJson(QJsonDocument::Indented);
    auto *mime = new QMimeData;
    mime->setData(QLatin1String(RouterMime), json);
    mime->setText(QString::fromUtf8(json));
    QApplication::clipboard()->setMimeData(mime);
    showStatus(tr("Copied %n node(s)", nullptr, int(ids.size())), false);
}

void RouterEditor::paste()
{
    const QMimeData *mime = QApplication::clipboard()->mimeData();
    if (!mime)
        return;
    const QByteArray json = mime->hasFormat(QLatin1String(RouterMime))
                                ? mime->data(QLatin1String(RouterMime))
                                : mime->text().toUtf8();
    RouterGraph pasted;
    LoadError error;
    if (!RouterGraph::fromJson(QJsonDocument::fromJson(json).object(), tr("clipboard"), &pasted,
                               &error)) {
        showStatus(tr("Nothing to paste: %1").arg(error.toString()), true);
        return;
    }
    QHash<QString, QString> ids;
    m_undo->beginMacro(tr("Paste"));
    for (RouterNode node : pasted.nodes) {
        const QString id = m_document->uniqueId(node.id);
        ids.insert(node.id, id);
        node.id = id;
        const QPointF pos = RouterDocument::nodePos(node) + QPointF(40, 40);
        node.ui.insert(QStringLiteral("x"), pos.x());
        node.ui.insert(QStringLiteral("y"), pos.y());
        m_undo->push(new AddNodeCommand(m_document, node));
    }
    for (RouterLink link : pasted.links) {
        link.from = ids.value(link.from, link.from);
        link.to = ids.value(link.to, link.to);
        m_undo->push(new ConnectCommand(m_document, link));
    }
    m_undo->endMacro();
    m_scene->clearSelection();
    for (const QString &id : ids) {
        if (RouterNodeItem *item = m_scene->nodeItem(id))
            item->setSelected(true);
    }
}

void RouterEditor::arrange()
{
    QStringList ids;
    QList<QPointF> from;
    QList<QPointF> to;
    for (const auto &[id, pos] : RouterScene::arrangedPositions(graph())) {
        const QPointF now = RouterDocument::nodePos(graph().nodes[size_t(graph().nodeIndex(id))]);
        if (now != pos) {
            ids.append(id);
            from.append(now);
            to.append(pos);
        }
    }
    if (ids.isEmpty())
        return;
    auto *command = new MoveNodesCommand(m_document, ids, from, to);
    command->setText(tr("Arrange"));
    m_undo->push(command);
    fitView();
}

void RouterEditor::fitView()
{
    m_fitted = true;
    m_fitting = true;
    const QRectF bounds = m_scene->itemsBoundingRect().adjusted(-16, -16, 16, 16);
    if (bounds.isEmpty()) {
        m_view->resetTransform();
        m_fitting = false;
        return;
    }
    m_view->setSceneRect(bounds.united(m_view->sceneRect()));
    m_view->fitInView(bounds, Qt::KeepAspectRatio);
    // Small graphs stay at their natural size rather than blown up; large ones no smaller
    // than their words can be read at, from their sources on the left (scroll for the rest).
    const double scale = m_view->transform().m11();
    if (scale > 1.0) {
        m_view->resetTransform();
        m_view->centerOn(bounds.center());
    } else if (scale < MinReadableScale) {
        m_view->setTransform(QTransform::fromScale(MinReadableScale, MinReadableScale));
        const double halfWidth = m_view->viewport()->width() / MinReadableScale / 2;
        m_view->centerOn(bounds.left() + halfWidth, bounds.center().y());
    }
    m_fitting = false;
}

bool RouterEditor::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_view->viewport() && event->type() == QEvent::Resize && m_fitted && !m_fitting)
        fitView();
    return QWidget::eventFilter(watched, event);
}

bool RouterEditor::openFile(const QString &path, QString *error)
{
    RouterGraph graph;
    LoadError loadError;
    if (!RouterGraph::fromFile(path, &graph, &loadError)) {
        *error = loadError.toString();
        return false;
    }
    setGraph(graph, path);
    // An old spelling was read; saving writes the new one.
    QStringList warnings;
    for (const LoadError &warning : graph.warnings)
        warnings.append(warning.toString());
    showStatus(warnings.isEmpty() ? tr("Opened %1").arg(QDir::toNativeSeparators(path))
                                  : warnings.join(QLatin1Char('\n')),
               !warnings.isEmpty());
    return true;
}

bool RouterEditor::saveFile(const QString &path, bool selfContained, QString *error)
{
    if (!m_document->save(path, selfContained, error))
        return false;
    showDocument(); // saved under another name, it was clean already
    showStatus(tr("Saved %1").arg(QDir::toNativeSeparators(path)), false);
    return true;
}

void RouterEditor::exportDialog(bool selfContained)
{
    // A router opened from a file is offered back to its file.
    const QString path =
        FileDialogs::saveFile(this, FileKind::Router,
                              selfContained ? tr("Save self-contained router") : tr("Save router"),
                              !m_document->path().isEmpty() ? m_document->path()
                              : graph().name.isEmpty()      ? QString()
                                                       : graph().name + QStringLiteral(".json"),
                              tr("semhap routers (*.json)"));
    QString error;
    if (!path.isEmpty() && !saveFile(path, selfContained, &error))
        showStatus(error, true);
}

bool RouterEditor::newFromPreset(const QString &name, QString *error)
{
    RouterGraph graph;
    if (!name.isEmpty()) {
        LoadError loadError;
        if (!RouterPresets::preset(name, &graph, &loadError)) {
            *error = loadError.toString();
            return false;
        }
    } else {
        graph.name = tr("untitled");
    }
    setGraph(graph);
    // The line under the canvas no longer speaks of the file edited before.
    showStatus(name.isEmpty() ? tr("New router.") : tr("New router from the preset %1.").arg(name),
               false);
    return true;
}

void RouterEditor::showDocument()
{
    const QString &path = m_document->path();
    const bool modified = m_document->isModified();
    QString text;
    if (path.isEmpty() && RouterPresets::names().contains(graph().name)) {
        text = modified ? tr("%1 — changed from the preset, not saved to a file").arg(graph().name)
                        : tr("%1 — preset").arg(graph().name);
    } else if (path.isEmpty()) {
        const QString name = graph().name.isEmpty() ? tr("untitled") : graph().name;
        text = tr("%1 — not saved to a file").arg(name);
    } else if (modified) {
        text = tr("%1 — changed since it was saved").arg(QFileInfo(path).fileName());
    } else {
        text = QFileInfo(path).fileName();
    }
    m_documentLabel->setText((modified ? QStringLiteral("* ") : QString()) + text);
    m_documentLabel->setToolTip(path.isEmpty() ? tr("Save or Save as… writes it to a file")
                                               : QDir::toNativeSeparators(path));
}

QStringList RouterEditor::validate()
{
    // The compiler stops at the first problem; taking the culprit out and compiling again
    // finds the next, so every broken node is marked at once.
    RouterGraph graph = this->graph();
    std::vector<int> linkIndex(graph.links.size());
    for (size_t j = 0; j < linkIndex.size(); ++j)
        linkIndex[j] = int(j);
    QHash<QString, QString> nodeErrors;
    QHash<int, QString> linkErrors;
    const RouterContext source = context();
    m_errors.clear();
    m_errorList->clear();
    std::unique_ptr<Router> compiled;
    for (int round = 0; round < 32; ++round) {
        LoadError error;
        compiled = Router::compile(graph, &error, source);
        if (compiled)
            break;
        const QStringList tokens = error.pointer.split(QLatin1Char('/'));
        const int index = tokens.size() > 2 ? tokens[2].toInt() : -1;
        auto *item = new QListWidgetItem(error.reason, m_errorList);
        item->setForeground(colors::ErrorDark);
        m_errors.append(error.reason);
        if (tokens.value(1) == QLatin1String("nodes") && index >= 0 &&
            size_t(index) < graph.nodes.size()) {
            const QString id = graph.nodes[size_t(index)].id;
            nodeErrors.insert(id, error.reason);
            item->setData(Qt::UserRole, id);
            graph.nodes.erase(graph.nodes.begin() + index);
            for (size_t j = graph.links.size(); j-- > 0;) {
                if (graph.links[j].from == id || graph.links[j].to == id) {
                    graph.links.erase(graph.links.begin() + long(j));
                    linkIndex.erase(linkIndex.begin() + long(j));
                }
            }
        } else if (tokens.value(1) == QLatin1String("links") && index >= 0 &&
                   size_t(index) < graph.links.size()) {
            linkErrors.insert(linkIndex[size_t(index)], error.reason);
            item->setData(Qt::UserRole, graph.links[size_t(index)].to);
            graph.links.erase(graph.links.begin() + index);
            linkIndex.erase(linkIndex.begin() + index);
        } else {
            break;
        }
    }
    m_scene->setErrors(nodeErrors, linkErrors);
    m_errorList->setVisible(!m_errors.isEmpty());
    m_distinct->setRouter(m_errors.isEmpty() ? compiled.get() : nullptr);
    m_applyAction->setEnabled(m_apply && m_errors.isEmpty());
    return m_errors;
}

void RouterEditor::setApplyFunction(ApplyFunction apply)
{
    m_apply = std::move(apply);
    m_applyAction->setEnabled(m_apply && m_errors.isEmpty());
}

bool RouterEditor::apply()
{
    if (!m_apply)
        return false;
    m_validateTimer->stop();
    if (!validate().isEmpty()) {
        showStatus(tr("Not applied: %1").arg(m_errors.front()), true);
        return false;
    }
    QString error;
    if (!m_apply(graph(), &error)) {
        showStatus(tr("Not applied: %1").arg(error), true);
        return false;
    }
    showApplied(m_replaying ? Applied::Replay : Applied::Run);
    emit applied();
    return true;
}

void RouterEditor::setReplaying(bool replaying)
{
    if (replaying == m_replaying)
        return;
    m_replaying = replaying;
    if (m_applied == Applied::Replay && !replaying) {
        forgetApplied(); // the re-routing closed with the replay; the run kept its router
    } else if (m_applied == Applied::Run) {
        showApplied(Applied::Run); // the run waits behind the replay, or runs again
    }
}

void RouterEditor::forgetApplied()
{
    if (m_applied == Applied::None)
        return; // the line says something else (a refused link, a problem): it stays
    m_status->clear();
    m_applied = Applied::None;
}

void RouterEditor::showApplied(Applied to)
{
    if (to == Applied::Replay)
        showStatus(tr("Applied: the replay was re-routed through this router."), false);
    else if (m_replaying)
        showStatus(tr("Applied: the run waiting behind the replay uses this router."), false);
    else
        showStatus(tr("Applied: the running session uses this router now."), false);
    m_applied = to;
}

void RouterEditor::setAutoApply(bool on)
{
    m_autoApply->setChecked(on);
}

void RouterEditor::setHistory(RunHistory *history)
{
    if (m_history)
        disconnect(m_history, nullptr, this, nullptr);
    m_history = history;
    m_scene->clearActivity();
    if (!history)
        return;
    m_nextActivity = history->activity().end();
    connect(history, &RunHistory::updated, this, &RouterEditor::onHistoryUpdated);
    connect(history, &RunHistory::reset, this, [this] {
        m_nextActivity = m_history->activity().begin();
        m_scene->clearActivity();
    });
}

void RouterEditor::onHistoryUpdated()
{
    // Hidden, the nodes' states still follow (they show when it opens), without flashes.
    const RunSeries<NodeActivity> &activity = m_history->activity();
    for (qint64 i = std::max(m_nextActivity, activity.begin()); i < activity.end(); ++i) {
        const NodeActivity &change = activity.at(i);
        m_scene->showActivity(m_history->nodeName(change.node), change, isVisible());
    }
    m_nextActivity = activity.end();
    const std::vector<RunDevice> &devices = m_history->devices();
    for (size_t d = 0; d < devices.size(); ++d) {
        const RunSeries<DeviceFrame> &frames = m_history->deviceFrames(int(d));
        double level = 0.0;
        if (!frames.isEmpty()) {
            const DeviceFrame &frame = frames.last();
            for (int c = 0; c < frame.channelCount; ++c)
                level = std::max(level, frame.values[size_t(c)]);
        }
        m_scene->setDeviceLevel(devices[d].name, std::clamp(level, 0.0, 1.0));
    }
}

void RouterEditor::showStatus(const QString &text, bool warning)
{
    m_applied = Applied::None;
    m_status->setText(text);
    m_status->setStyleSheet(
        warning ? QStringLiteral("QLabel { color: %1; }").arg(colors::css(colors::ErrorDark))
                : QString());
}

void RouterEditor::onGraphChanged()
{
    m_validateTimer->start();
    m_inspector->schedule();
}

QStringList RouterEditor::newMessageNames() const
{
    QStringList names;
    for (const RouterNode &node : graph().nodes) {
        for (const ParamSpec &spec : graph().paramsOf(node)) {
            if (!spec.openChoices)
                continue;
            // A name beyond the spec's own choices (the built-in messages) is a new one.
            const QJsonValue value = node.params.value(spec.name);
            const QJsonArray list = value.isArray() ? value.toArray() : QJsonArray{value};
            for (const QJsonValue &item : list) {
                const QString name = item.toString();
                if (isPlainName(name) && !spec.choices.contains(name))
                    names.append(name);
            }
        }
    }
    names.removeDuplicates();
    names.sort();
    return names;
}

void RouterEditor::setContextFunction(ContextFunction context)
{
    m_context = std::move(context);
    updateContext();
}

void RouterEditor::updateContext()
{
    m_validateTimer->start();
    m_inspector->refresh(); // the signal picker's choices follow the source
}

RouterContext RouterEditor::context() const
{
    return m_context ? m_context() : RouterContext();
}

PanelDock RouterEditor::dock()
{
    return {QStringLiteral("routerDock"), tr("Router"), PanelDock::Side::Right,
            QStringLiteral("plotsDock")};
}

} // namespace semhap
