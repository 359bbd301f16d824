// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QString>
#include <QStringList>

namespace semhap {

/**
 * Interns actor (body) names as small integers, so frames carry no strings and
 * detectors compare actors by id on the hot path.
 */
class ActorTable
{
public:
    /** The id of `name`, added when new. A null or empty name is "no actor" (-1). */
    int intern(const QString &name);
    /** The id of `name`, or -1 when unknown. */
    int find(const QString &name) const;
    /** The name of `id`; a null string for -1 or an unknown id. */
    QString name(int id) const;
    int size() const { return int(m_names.size()); }

private:
    QHash<QString, int> m_ids;
    QStringList m_names;
};

} // namespace semhap
