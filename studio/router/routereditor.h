// SPDX-License-Identifier: MIT
#pragma once

#include "paneldock.h"
#include "routercontext.h"
#include "routergraph.h"

#include <QHash>
#include <QWidget>

#include <functional>

class QAction;
class QCheckBox;
class QFormLayout;
class QGraphicsView;
class QLabel;
class QListWidget;
class QListWidgetItem;
class QTabWidget;
class QTimer;
class QUndoStack;
class QWidget;

namespace semhap {

class DistinctivenessView;
class RunHistory;
class RouterDocument;
class RouterInspector;
class RouterScene;

/**
 * The router node editor: a palette of node types, the graph on a canvas (drag from a port
 * to a port to link, with the reason shown when a link is refused), an inspector for the
 * selected node's parameters, the compiler's errors marked on the nodes and listed, undo and
 * redo of every edit, copy and paste, open and save (optionally self-contained), the presets
 * as templates, and Apply to the running session with its live activity shown on the wires.
 */
class RouterEditor : public QWidget
{
    Q_OBJECT

public:
    /** Where the main window docks it by default (PanelDock). */
    static PanelDock dock();
    /** Sends a graph to the running session; false with a one-line error. */
    using ApplyFunction = std::function<bool(const RouterGraph &graph, QString *error)>;
    /**
     * What the running source compiles routers for (its signals): the graph is checked
     * against it, and the signal picker offers its signals.
     */
    using ContextFunction = std::function<RouterContext()>;

    /** Edits `document` (null: a document of the editor's own); it must outlive the editor. */
    explicit RouterEditor(RouterDocument *document = nullptr, QWidget *parent = nullptr);
    ~RouterEditor() override;

    /**
     * Shows `graph`, from file `path` (empty: none), as a fresh document (the undo history
     * starts again); nodes without a position are laid out.
     */
    void setGraph(const RouterGraph &graph, const QString &path = QString());
    /** The document being edited. */
    const RouterGraph &graph() const;

    /** Adds a node of `type` at `scenePos` (the palette's drop, double-click); its id. */
    QString addNode(const QString &type, const QPointF &scenePos);
    /** Links two ports if the compiler's rules allow it, else false with the reason. */
    bool connectPorts(const RouterLink &link, QString *reason);
    /** Sets a node parameter (undefined: back to the default), as the inspector does. */
    void setParam(const QString &id, const QString &key, const QJsonValue &value);
    /**
     * Points the pattern nodes that name the user's pattern file `from` at `to`, as one
     * undoable step: the designer renamed it. Embedded patterns keep their names.
     */
    void followRenamedPattern(const QString &from, const QString &to);
    /** Renames a node, keeping its links; false with the reason when the id is not free. */
    bool renameNode(const QString &id, const QString &newId, QString *reason);
    /** Deletes the selected nodes (with their links) and wires. */
    void deleteSelection();
    /** Copies the selected nodes and the links among them to the clipboard as JSON. */
    void copySelection();
    /** Pastes nodes copied from a router (ids made unique, shifted so they show). */
    void paste();
    /** Lays the nodes out in columns by kind, as one undoable move. */
    void arrange();
    /**
     * Zooms the view to show the whole graph, and keeps it so as the view is shown and
     * resized until the user scrolls.
     */
    void fitView();

    /** Opens a `semhap.router/1` file as a fresh document. */
    bool openFile(const QString &path, QString *error);
    /**
     * Saves the document with node positions; self-contained embeds the user patterns and
     * device models it uses (not the built-ins), so it runs the same elsewhere.
     */
    bool saveFile(const QString &path, bool selfContained, QString *error);
    /** Starts a fresh document from a preset (`C3`), or an empty one for an empty name. */
    bool newFromPreset(const QString &name, QString *error);

    /** Compiles the graph now and marks what is wrong; the list of problems, first first. */
    QStringList validate();
    QStringList errors() const { return m_errors; }

    /**
     * Where the source's context comes from (none: any signal name is taken and only the
     * built-in quantities are offered); checks the graph again.
     */
    void setContextFunction(ContextFunction context);
    /** The source changed (another scene, a rig): checks the graph and the picker again. */
    void updateContext();
    /**
     * The messages the graph's nodes name (threshold, compose, filter) that are not built
     * in, sorted: what the message fields offer besides grasp, break and slip.
     */
    QStringList newMessageNames() const;
    /** The context the source compiles for (a default one without a context function). */
    RouterContext context() const;

    /** Where Apply sends the graph; without one Apply is disabled. */
    void setApplyFunction(ApplyFunction apply);
    /** Sends the graph to the session; false (with the reason shown) when it cannot. */
    bool apply();
    /** Applies every edit that compiles, shortly after it is made. */
    void setAutoApply(bool on);
    /**
     * Whether a session replay is shown: Apply re-routes it, and what the status line says
     * Apply did names the replay or the run waiting behind it.
     */
    void setReplaying(bool replaying);
    /**
     * The session loaded its router afresh (another router, scene or rig), dropping what
     * was applied: the status line stops saying what Apply did.
     */
    void forgetApplied();
    /** Shows the live activity of the session in `history` (null: none). */
    void setHistory(RunHistory *history);

    RouterDocument *document() const { return m_document; }
    RouterScene *scene() const { return m_scene; }
    QGraphicsView *view() const { return m_view; }
    /** The smallest zoom Fit goes to: node words at 8–9 px, read without leaning in. */
    static constexpr double MinReadableScale = 0.7;
    QListWidget *palette() const { return m_palette; }
    QUndoStack *undoStack() const { return m_undo; }
    /** The form of the selected node's parameters. */
    QWidget *inspector() const;
    /** The line that says why a link was refused, or what Apply did. */
    QLabel *statusLabel() const { return m_status; }

signals:
    /** The graph was applied to the session. */
    void applied();

protected:
    /** The view's first show (a tab raised) and its resizes fit the graph again. */
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    /** Makes the editor's actions; returns the toolbar's, in order. */
    QList<QAction *> createActions();
    void showStatus(const QString &text, bool warning);
    /** Names the document above the canvas: its file or name, and whether it is saved. */
    void showDocument();
    /** Says what Apply did, the run's or the replay's router (`to`), as is true now. */
    enum class Applied
    {
        None,
        Run,
        Replay
    };
    void showApplied(Applied to);
    void onGraphChanged();
    void onHistoryUpdated();
    void exportDialog(bool selfContained);

    RouterDocument *m_document = nullptr;
    RouterScene *m_scene = nullptr;
    QGraphicsView *m_view = nullptr;
    QListWidget *m_palette = nullptr;
    QTabWidget *m_sideTabs = nullptr;
    DistinctivenessView *m_distinct = nullptr;
    RouterInspector *m_inspector = nullptr;
    QListWidget *m_errorList = nullptr;
    QLabel *m_documentLabel = nullptr;
    QLabel *m_status = nullptr;
    QCheckBox *m_autoApply = nullptr;
    QUndoStack *m_undo = nullptr; ///< the document's
    QAction *m_applyAction = nullptr;
    QTimer *m_validateTimer = nullptr;

    ApplyFunction m_apply;
    ContextFunction m_context;
    /** What the status line says Apply went to; None once it says anything else. */
    Applied m_applied = Applied::None;
    bool m_replaying = false;
    RunHistory *m_history = nullptr;
    qint64 m_nextActivity = 0;
    QStringList m_errors;
    bool m_fitted = true;   ///< the view shows the whole graph and follows its size
    bool m_fitting = false; ///< inside fitView (its scroll bars resize the view)
};

} // namespace semhap
