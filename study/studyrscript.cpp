// SPDX-License-Identifier: MIT
#include "studyrscript.h"

#include "studyanalysis.h"
#include "studytable.h"

#include <QFile>

namespace semhap {

namespace {

/** A string as an R literal. */
QByteArray literal(const QString &text)
{
    QByteArray quoted = text.toUtf8();
    quoted.replace('\\', "\\\\").replace('"', "\\\"");
    return '"' + quoted + '"';
}

QByteArray vector(const QStringList &texts)
{
    QByteArray v = "c(";
    for (int i = 0; i < texts.size(); ++i)
        v += (i ? ", " : "") + literal(texts[i]);
    return v + ')';
}

QByteArray logical(bool value)
{
    return value ? "TRUE" : "FALSE";
}

QByteArray logicals(const std::vector<bool> &values)
{
    QByteArray v = "c(";
    for (size_t i = 0; i < values.size(); ++i)
        v += (i ? ", " : "") + logical(values[i]);
    return v + ')';
}

} // namespace

QByteArray StudyRScript::script(const StudyAnalysis &analysis, const StudyTable &table)
{
    QByteArray r = "# " + analysis.name.toUtf8() +
                   ": the statistics of `semhap study analyze`, computed by R.\n"
                   "# Written by semhap " SEMHAP_VERSION
                   ". Run it in its folder, beside measures.csv:\n"
                   "#   Rscript analysis.R\n"
                   "# It needs R's afex and emmeans (Debian: r-cran-afex, r-cran-emmeans).\n\n";
    r += "conditions <- " + vector(analysis.conditions) + "\n";
    if (analysis.factors.size() == 2) {
        // Each condition's level of the two factors, which R calls A and B (a factor's id
        // may be a word R keeps for itself, such as `break`).
        QStringList a, b;
        for (int c = 0; c < analysis.conditions.size(); ++c) {
            const QStringList levels = table.levels(c);
            a.append(levels.value(0));
            b.append(levels.value(1));
        }
        const StudyProtocol::Factor &fa = analysis.factors[0];
        const StudyProtocol::Factor &fb = analysis.factors[1];
        r += "level_a <- " + vector(a) + "\nlevel_b <- " + vector(b) + "\n";
        r += "effects <- " + vector({fa.id, fb.id, fa.id + QLatin1Char(':') + fb.id}) + "\n";
    }
    QFile common(QStringLiteral(":/semhap/r/analysis.R"));
    if (common.open(QIODevice::ReadOnly))
        r += '\n' + common.readAll();
    for (const StudyAnalysis::Measure &m : analysis.measures) {
        std::vector<bool> tested;
        for (const PairwiseComparison &p : m.pairwise)
            tested.push_back(p.tested);
        r += "\nmeasure(" + literal(m.name) + ", anova = " + logical(m.anova.tested) +
             ", sphericity = " + logical(m.anova.sphericity.tested) +
             ", gg = " + logical(StudyAnalysis::Measure::sphericityViolated(m.anova)) +
             ",\n        friedman = " + logical(m.friedman.df > 0) +
             ", pairwise = " + (m.pairedTest == PairedTest::T ? "\"t\"" : "\"wilcoxon\"") +
             ", tested = " + logicals(tested);
        if (m.twoWay) {
            const WithinEffect *effects[] = {&m.twoWayAnova.a, &m.twoWayAnova.b,
                                             &m.twoWayAnova.interaction};
            std::vector<bool> effectTested, sphericity, gg;
            for (const WithinEffect *e : effects) {
                effectTested.push_back(e->tested);
                sphericity.push_back(e->sphericity.tested);
                gg.push_back(StudyAnalysis::Measure::sphericityViolated(*e));
            }
            r += ",\n        two_way = list(tested = " + logicals(effectTested) +
                 ", sphericity = " + logicals(sphericity) + ", gg = " + logicals(gg) + ')';
        }
        r += ")\n";
    }
    return r;
}

} // namespace semhap
