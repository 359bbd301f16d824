// SPDX-License-Identifier: MIT
#pragma once

#include "clirun.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <set>

/** A CSV's lines with the columns `dropped` (0-based) taken out. */
inline QStringList withoutColumns(const QByteArray &csv, const std::set<int> &dropped)
{
    QStringList lines;
    for (const QString &line : QString::fromUtf8(csv).split(QLatin1Char('\n'))) {
        QStringList kept;
        const QStringList cells = line.split(QLatin1Char(','));
        for (int c = 0; c < cells.size(); ++c) {
            if (!dropped.count(c))
                kept.append(cells[c]);
        }
        lines.append(kept.join(QLatin1Char(',')));
    }
    return lines;
}

/**
 * Checks that a study merged from shards exports and analyses as the study one machine
 * simulated (docs/cluster.md): measures.csv and answers.csv byte for byte, trials.csv but
 * for when each trial ran and where its session is, `study analyze --json` but for its
 * source. The exports go into `dir`. Fails the running test (check QTest::currentTestFailed).
 */
inline void compareMergedStudy(const QString &merged, const QString &oneMachine,
                               const QString &dir)
{
    const QString studies[2] = {oneMachine, merged};
    QByteArray files[2][3];
    QJsonObject analyses[2];
    for (int i = 0; i < 2; ++i) {
        const QString csv = QDir(dir).filePath(QStringLiteral("export-%1").arg(i));
        CliResult r = semhapRun({"study", "export", studies[i], "--csv", csv});
        QVERIFY2(r.code == 0, r.err.constData());
        int f = 0;
        for (const char *name : {"measures.csv", "answers.csv", "trials.csv"}) {
            QFile file(QDir(csv).filePath(QLatin1String(name)));
            QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
            files[i][f++] = file.readAll();
        }
        r = semhapRun({"study", "analyze", studies[i], "--json"});
        QVERIFY2(r.code == 0, r.err.constData());
        analyses[i] = QJsonDocument::fromJson(r.out).object();
        QVERIFY(analyses[i].contains("source"));
        analyses[i].remove("source");
    }
    QCOMPARE(files[1][0], files[0][0]);
    QCOMPARE(files[1][1], files[0][1]);
    QVERIFY(files[0][2].startsWith("participant,condition,phase,trial,status,reason,seconds,"
                                   "started,ended,session\n"));
    QCOMPARE(withoutColumns(files[1][2], {7, 8, 9}), withoutColumns(files[0][2], {7, 8, 9}));
    QCOMPARE(analyses[1], analyses[0]);
}
