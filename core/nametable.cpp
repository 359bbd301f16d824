// SPDX-License-Identifier: MIT
#include "nametable.h"

#include <QMutexLocker>

namespace semhap {

NameTable::NameTable(const QStringList &builtins)
{
    for (const QString &name : builtins)
        intern(name);
}

int NameTable::intern(const QString &name)
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_ids.constFind(name);
    if (it != m_ids.cend())
        return it.value();
    if (m_names.size() >= Capacity)
        return -1;
    const int id = int(m_names.size());
    m_names.append(name);
    m_ids.insert(name, id);
    return id;
}

int NameTable::find(const QString &name) const
{
    QMutexLocker lock(&m_mutex);
    return m_ids.value(name, -1);
}

QString NameTable::name(int id) const
{
    QMutexLocker lock(&m_mutex);
    if (id < 0 || id >= int(m_names.size()))
        return QString();
    return m_names.at(id);
}

NameTable &signalNames()
{
    static NameTable table;
    return table;
}

} // namespace semhap
