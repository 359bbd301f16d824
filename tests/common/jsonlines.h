// SPDX-License-Identifier: MIT
#pragma once

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QList>
#include <QTest>

#include <algorithm>
#include <cmath>

/** The JSON objects of a JSON Lines file, blank lines skipped. */
inline QList<QJsonObject> readLines(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    QList<QJsonObject> lines;
    while (!file.atEnd()) {
        const QByteArray line = file.readLine().trimmed();
        if (!line.isEmpty())
            lines.append(QJsonDocument::fromJson(line).object());
    }
    return lines;
}

inline bool sameValue(const QJsonValue &a, const QJsonValue &b)
{
    if (a.isDouble() && b.isDouble())
        return std::abs(a.toDouble() - b.toDouble()) <=
               1e-9 * std::max(1.0, std::abs(a.toDouble()));
    if (a.isArray() && b.isArray()) {
        const QJsonArray x = a.toArray();
        const QJsonArray y = b.toArray();
        if (x.size() != y.size())
            return false;
        for (int i = 0; i < x.size(); ++i) {
            if (!sameValue(x[i], y[i]))
                return false;
        }
        return true;
    }
    return a == b;
}

/** Compares parsed lines key by key, numbers to 1e-9; names the first difference. */
inline void compareLines(const QList<QJsonObject> &actual, const QList<QJsonObject> &expected)
{
    const int n = int(std::min(actual.size(), expected.size()));
    for (int i = 0; i < n; ++i) {
        const QJsonObject &a = actual[i];
        const QJsonObject &e = expected[i];
        bool same = a.keys() == e.keys();
        for (auto it = e.begin(); same && it != e.end(); ++it)
            same = sameValue(a.value(it.key()), it.value());
        if (!same)
            QFAIL(qPrintable(
                QString("line %1 differs:\n  actual:   %2\n  expected: %3")
                    .arg(i + 1)
                    .arg(QString::fromUtf8(QJsonDocument(a).toJson(QJsonDocument::Compact)),
                         QString::fromUtf8(QJsonDocument(e).toJson(QJsonDocument::Compact)))));
    }
    QCOMPARE(actual.size(), expected.size());
}
