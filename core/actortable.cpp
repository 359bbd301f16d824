// SPDX-License-Identifier: MIT
#include "actortable.h"

namespace semhap {

int ActorTable::intern(const QString &name)
{
    if (name.isEmpty())
        return -1;
    const auto it = m_ids.constFind(name);
    if (it != m_ids.cend())
        return it.value();
    const int id = int(m_names.size());
    m_names.append(name);
    m_ids.insert(name, id);
    return id;
}

int ActorTable::find(const QString &name) const
{
    return name.isEmpty() ? -1 : m_ids.value(name, -1);
}

QString ActorTable::name(int id) const
{
    if (id < 0 || id >= int(m_names.size()))
        return QString();
    return m_names.at(id);
}

} // namespace semhap
