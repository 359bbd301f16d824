// SPDX-License-Identifier: MIT
#include "rostypes.h"

#include "msgschema.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>

namespace semhap {

namespace {

/** `package/msg/Type` → the built-in resource of its .msg text. */
QByteArray text(const QString &type)
{
    const QStringList parts = type.split(QLatin1Char('/'));
    if (parts.size() != 3)
        return QByteArray();
    QFile file(QStringLiteral(":/semhap/ros/%1/msg/%2.msg").arg(parts[0], parts[2]));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/** The message types a .msg text uses, as package/msg/Type, in the order met. */
QStringList uses(const QString &type, const QByteArray &msg)
{
    static const QRegularExpression word(QStringLiteral("^\\s*([A-Za-z][A-Za-z0-9_/]*)"));
    const QString package = type.section(QLatin1Char('/'), 0, 0);
    QStringList out;
    for (const QString &line : QString::fromUtf8(msg).split(QLatin1Char('\n'))) {
        const QRegularExpressionMatch m = word.match(line);
        if (!m.hasMatch())
            continue;
        const QString base = m.captured(1);
        if (MsgSchema::isBuiltin(base.section(QLatin1Char('<'), 0, 0)))
            continue;
        const QStringList parts = base.split(QLatin1Char('/'));
        const QString used = parts.size() == 1
                                 ? package + QStringLiteral("/msg/") + base
                                 : parts.first() + QStringLiteral("/msg/") + parts.last();
        if (!out.contains(used))
            out << used;
    }
    return out;
}

} // namespace

QByteArray RosTypes::schema(const QString &type)
{
    const QByteArray own = text(type);
    if (own.isEmpty())
        return QByteArray();
    QByteArray out = own.trimmed();
    // Each type it uses, depth first, once.
    QStringList done{type};
    QStringList pending = uses(type, own);
    while (!pending.isEmpty()) {
        const QString next = pending.takeFirst();
        if (done.contains(next))
            continue;
        done << next;
        const QByteArray msg = text(next);
        out += "\n" + QByteArray(80, '=') +
               "\nMSG: " + next.section(QLatin1Char('/'), 0, 0).toUtf8() + '/' +
               next.section(QLatin1Char('/'), 2, 2).toUtf8() + '\n' + msg.trimmed();
        pending = uses(next, msg) + pending;
    }
    return out + '\n';
}

QStringList RosTypes::names()
{
    QStringList out;
    const QDir root(QStringLiteral(":/semhap/ros"));
    for (const QString &package : root.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        for (const QString &file : QDir(root.filePath(package + QStringLiteral("/msg")))
                                       .entryList({QStringLiteral("*.msg")}, QDir::Files))
            out << package + QStringLiteral("/msg/") + file.chopped(4);
    }
    return out;
}

} // namespace semhap
