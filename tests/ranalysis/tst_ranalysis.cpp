// SPDX-License-Identifier: MIT
// `semhap study export --r` checked by R itself (docs/science.md): a simulated two-factor
// study's analysis.R, run with Debian's R, afex and emmeans, prints every statistic semhap
// computed, each within 1e-6 of `study analyze --json`.
#include "clirun.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <map>

namespace {

/** The value at a JSON pointer (`/anova/f`, `/pairwise/3/p`) in `object`; undefined if none. */
QJsonValue at(const QJsonObject &object, const QString &pointer)
{
    QJsonValue value = object;
    for (const QString &part : pointer.split(QLatin1Char('/'), Qt::SkipEmptyParts)) {
        if (value.isArray())
            value = value.toArray().at(part.toInt());
        else
            value = value.toObject().value(part);
    }
    return value;
}

} // namespace

class TestRAnalysis : public QObject
{
    Q_OBJECT

private slots:
    void rReproducesEveryStatistic();
};

void TestRAnalysis::rReproducesEveryStatistic()
{
    const QString rscript = QStandardPaths::findExecutable(QStringLiteral("Rscript"));
    QVERIFY2(!rscript.isEmpty(), "Rscript is not installed (scripts/deps.sh installs "
                                 "r-base-core, r-cran-afex and r-cran-emmeans)");
    QTemporaryDir dir;
    const QString study = dir.filePath("comparison.db");
    // Two factors of two levels: the one-way and the two-way ANOVA, both kinds of pairwise
    // test, Friedman's, and Mauchly's where a measure's spread calls for it.
    CliResult r = semhapRun({"study", "simulate", SEMHAP_RESOURCES "/studies/comparison.json",
                             "--participants", "6", "--trial-seconds", "10", "--out", study});
    QVERIFY2(r.code == 0, r.err.constData());
    const QString folder = dir.filePath("r");
    r = semhapRun({"study", "export", study, "--r", folder});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(QFileInfo(folder + "/measures.csv").isFile());
    r = semhapRun({"study", "analyze", study, "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    std::map<QString, QJsonObject> measures;
    for (const QJsonValue &m : QJsonDocument::fromJson(r.out).object().value("measures").toArray())
        measures[m.toObject().value("measure").toString()] = m.toObject();

    QProcess rProcess;
    rProcess.setWorkingDirectory(folder); // the script reads measures.csv beside it
    rProcess.start(rscript, {"analysis.R"});
    QVERIFY(rProcess.waitForFinished(120000));
    QVERIFY2(rProcess.exitStatus() == QProcess::NormalExit && rProcess.exitCode() == 0,
             rProcess.readAllStandardError().constData());

    std::map<QString, int> compared; ///< by statistic, the measures' indices left out
    int lines = 0;
    for (const QByteArray &line : rProcess.readAllStandardOutput().trimmed().split('\n')) {
        const QList<QByteArray> fields = line.split('\t');
        QVERIFY2(fields.size() == 3, line.constData());
        const QString name = QString::fromUtf8(fields[0]);
        const QString pointer = QString::fromUtf8(fields[1]);
        QVERIFY2(measures.count(name), line.constData());
        const QJsonValue semhap = at(measures[name], pointer);
        QVERIFY2(semhap.isDouble(), line.constData());
        bool ok = false;
        const double value = fields[2].toDouble(&ok);
        QVERIFY2(ok, line.constData());
        QVERIFY2(std::abs(value - semhap.toDouble()) <= 1e-6,
                 qPrintable(QString("%1: R %2, semhap %3")
                                .arg(QString::fromUtf8(line))
                                .arg(value, 0, 'g', 12)
                                .arg(semhap.toDouble(), 0, 'g', 12)));
        ++lines;
        QString statistic = pointer;
        statistic.replace(QRegularExpression("/[0-9]+/"), "/N/");
        ++compared[statistic];
    }
    // Every test semhap ran has its numbers from R.
    int anovas = 0, friedmans = 0, pairs = 0, twoWay = 0;
    for (const auto &[name, m] : measures) {
        anovas += m.value("anova").toObject().value("tested").toBool();
        friedmans += m.value("friedman").toObject().value("df").toInt() > 0;
        for (const QJsonValue &pair : m.value("pairwise").toArray())
            pairs += pair.toObject().value("tested").toBool();
        const QJsonObject effects = m.value("two_way_anova").toObject();
        for (const QString &effect : effects.keys())
            twoWay += effects.value(effect).toObject().value("tested").toBool();
    }
    QVERIFY(anovas > 0 && friedmans > 0 && pairs > 0 && twoWay > 0);
    QCOMPARE(compared["/anova/f"], anovas);
    QCOMPARE(compared["/friedman/chi_squared"], friedmans);
    QCOMPARE(compared["/pairwise/N/statistic"], pairs);
    int twoWayCompared = 0;
    for (const auto &[statistic, count] : compared)
        twoWayCompared +=
            statistic.startsWith("/two_way_anova/") && statistic.endsWith("/f") ? count : 0;
    QCOMPARE(twoWayCompared, twoWay);
    qInfo("%d statistics within 1e-6 of R's: %d ANOVAs (%d with Greenhouse-Geisser), %d "
          "two-way effects, %d Friedman tests, %d pairwise tests",
          lines, anovas, compared["/anova/greenhouse_geisser/p"], twoWay, friedmans, pairs);
}

QTEST_GUILESS_MAIN(TestRAnalysis)
#include "tst_ranalysis.moc"
