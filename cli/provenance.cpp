// SPDX-License-Identifier: MIT
#include "provenance.h"

#include "semhaprevision.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QSysInfo>

namespace semhap {

Provenance::Provenance() : m_started(QDateTime::currentDateTimeUtc()) {}

QJsonObject Provenance::toJson(bool ended) const
{
    QJsonObject json{
        {QStringLiteral("semhap"), QStringLiteral(SEMHAP_VERSION " (" SEMHAP_REVISION ")")},
        {QStringLiteral("command"), QJsonArray::fromStringList(QCoreApplication::arguments())},
        {QStringLiteral("host"), QSysInfo::machineHostName()},
        {QStringLiteral("started"), m_started.toString(Qt::ISODateWithMs)}};
    if (ended)
        json.insert(QStringLiteral("ended"),
                    QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    return json;
}

} // namespace semhap
