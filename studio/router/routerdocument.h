// SPDX-License-Identifier: MIT
#pragma once

#include "routergraph.h"

#include <QObject>
#include <QPointF>
#include <QString>

class QUndoStack;

namespace semhap {

/**
 * The router being edited: its graph (node positions in each node's `ui`), its undo stack
 * and its file. The undo commands and file I/O change it through the functions below and
 * nothing else; every change is announced by a fine-grained signal, so views (the editor's
 * RouterScene) and the editor's inspector and validation follow without reading the whole
 * graph again. Saving goes through the core: RouterGraph::embedFiles for a self-contained
 * file, OutputFile's temporary-and-rename for the write.
 */
class RouterDocument : public QObject
{
    Q_OBJECT

public:
    explicit RouterDocument(QObject *parent = nullptr);
    ~RouterDocument() override;

    const RouterGraph &graph() const { return m_graph; }
    QUndoStack *undoStack() const { return m_undo; }
    /** The file last opened or saved; empty for a new document. */
    const QString &path() const { return m_path; }
    /** Whether there are edits since the document was opened, started or saved. */
    bool isModified() const;

    /** Replaces the document with `graph` from `path` (empty: new); the undo history restarts. */
    void reset(const RouterGraph &graph, const QString &path = QString());
    /**
     * Saves to `path` through a temporary file; self-contained embeds the user patterns and
     * device models the graph uses, each under a name of its own. False with the reason,
     * keeping the file that was there.
     */
    bool save(const QString &path, bool selfContained, QString *error);

    /** `base` if no node has that id, else `base` with the lowest free number appended. */
    QString uniqueId(const QString &base) const;
    /** Where a node is drawn (its `ui` x and y). */
    static QPointF nodePos(const RouterNode &node);

    // The edits, as the undo commands make them.
    void insertNode(int index, const RouterNode &node);
    void removeNode(int index);
    void insertLink(int index, const RouterLink &link);
    void removeLink(int index);
    void setNodeParams(const QString &id, const QJsonObject &params);
    void setNodePos(const QString &id, const QPointF &pos);
    /** Renames a node and the links that name it. */
    void renameNode(const QString &from, const QString &to);

signals:
    /** The whole graph was replaced (reset()). */
    void graphReset();
    /** Node `index` was inserted. */
    void nodeInserted(int index);
    /** Node `index` was removed (its links went before, each with linksChanged()). */
    void nodeRemoved(int index);
    /** Node `index`'s parameters changed: its summary and, for a pattern, its ports. */
    void nodeParamsChanged(int index);
    /** Node `index` moved to nodePos(). */
    void nodeMoved(int index);
    /** Node `index` was renamed from `from` (its links were renamed with it). */
    void nodeRenamed(int index, const QString &from);
    /** A link was inserted, removed or renamed. */
    void linksChanged();
    /** After any of the above: the graph differs from what it was. */
    void changed();

private:
    RouterGraph m_graph;
    QUndoStack *m_undo = nullptr;
    QString m_path;
};

} // namespace semhap
