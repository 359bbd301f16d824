// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h" // isPlainName: the form of the names

#include <QHash>
#include <QMutex>
#include <QString>
#include <QStringList>

namespace semhap {

/**
 * Interns names as small integers, process-wide and thread-safe, for names that frames and
 * events carry by id across threads and modules: the frames' signals (signalNames()) and
 * the messages (messageNames()). A parser, the simulation and a router compiled anywhere
 * then agree on an id without handing a table around. Bounded: input cannot grow it past
 * Capacity names.
 */
class NameTable
{
public:
    /** The most names a table holds; interning more fails. */
    static constexpr int Capacity = 4096;

    /** Starts with `builtins` at ids 0, 1, ... */
    explicit NameTable(const QStringList &builtins = {});
    /** The id of `name`, added when new; -1 when the table is full. */
    int intern(const QString &name);
    /** The id of `name`, or -1 when it was never interned. */
    int find(const QString &name) const;
    /** The name of `id`; a null string for an id never given. */
    QString name(int id) const;

private:
    mutable QMutex m_mutex;
    QHash<QString, int> m_ids;
    QStringList m_names;
};

/** The table of the frames' signal names. */
NameTable &signalNames();

} // namespace semhap
