// SPDX-License-Identifier: MIT
#pragma once

#include "pattern.h"

#include <QJsonObject>
#include <QObject>
#include <QUndoStack>

namespace semhap {

/**
 * The pattern being designed, as its `semhap.pattern/1` JSON with an undo stack: every edit
 * (a value at a JSON pointer, or the whole document) is an undoable command, and after
 * each the JSON is parsed again so views can show the pattern or why it does not load.
 * Built-in patterns are opened read-only.
 */
class PatternDocument : public QObject
{
    Q_OBJECT

public:
    explicit PatternDocument(QObject *parent = nullptr);

    /** Starts over with `json` (no undo history): what opening a file or a built-in does. */
    void reset(const QJsonObject &json, const QString &path, bool readOnly);
    const QJsonObject &json() const { return m_json; }
    /** The parsed pattern, or null when the JSON does not load (see error()). */
    const PatternPtr &pattern() const { return m_pattern; }
    const LoadError &error() const { return m_error; }

    /** Where the document is saved; empty for a built-in or a new pattern. */
    const QString &path() const { return m_path; }
    void setPath(const QString &path);
    bool isReadOnly() const { return m_readOnly; }
    bool isModified() const { return !m_undo.isClean(); }
    QUndoStack *undoStack() { return &m_undo; }

    /** Replaces the whole document, undoably (`text` names the step in the Edit menu). */
    void setJson(const QJsonObject &json, const QString &text);
    /**
     * Sets the value at an RFC 6901 `pointer` (an undefined value removes the key or array
     * item; one past an array's end appends), undoably.
     */
    void setValue(const QString &pointer, const QJsonValue &value);
    /** The value at `pointer`; undefined when there is none. */
    QJsonValue value(const QString &pointer) const;

    // Structure edits, each one undoable step; each returns the pointer of the node to show.
    /** Appends a track driving every channel with a constant sustain. */
    QString addTrack();
    /**
     * Gives the track at `track` (`/tracks/N`, or any node inside it) an attack, sustain or
     * release when it has none: a ramp up, a constant, a ramp down. Empty when `track` is
     * not in a track.
     */
    QString addPart(const QString &track, const QString &part);
    /** Appends a constant input to the combinator at `pointer` (its `of`). */
    QString addInput(const QString &pointer);
    /** Removes the node at `pointer`; returns what held it. */
    QString remove(const QString &pointer);
    /** Whether addPart() can work on `pointer`: it is a track or inside one. */
    bool canAddPart(const QString &pointer) const;
    /** Whether addInput() can work on `pointer`: its type takes a list of inputs (`of`). */
    bool canAddInput(const QString &pointer) const;
    /** Whether remove() can take `pointer`: a track but the last, a part, a list's input but the
     * last. */
    bool canRemove(const QString &pointer) const;
    /** The first document of a new pattern `name` on `model`: one track, ramp-hold-release. */
    static QJsonObject newPattern(const QString &name, const QString &model);

    /** Writes the JSON to `path` (making its folder) and marks the document saved there. */
    bool save(const QString &path, QString *error);

    /** The value at `pointer` inside `root`. */
    static QJsonValue valueAt(const QJsonValue &root, const QString &pointer);
    /** `root` with the value at `pointer` replaced (or removed when `value` is undefined). */
    static QJsonValue withValue(const QJsonValue &root, const QString &pointer,
                                const QJsonValue &value);

signals:
    /** The JSON changed (an edit, an undo, a reset); pattern() and error() are current. */
    void changed();
    /** The path, read-only state or saved state changed. */
    void stateChanged();

private:
    class SetJsonCommand;
    friend class SetJsonCommand;
    void apply(const QJsonObject &json);

    QJsonObject m_json;
    PatternPtr m_pattern;
    LoadError m_error;
    QString m_path;
    bool m_readOnly = false;
    QUndoStack m_undo;
};

} // namespace semhap
