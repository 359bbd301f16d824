// SPDX-License-Identifier: MIT
#pragma once

#include "repeatedmeasures.h"
#include "statistics.h"
#include "studytable.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace semhap {

/**
 * The paper's analysis of a within-subject study, measure by measure (docs/studies.md,
 * "Analysis"), on each participant's mean over trials per condition: descriptives and
 * Shapiro–Wilk per condition; the repeated-measures ANOVA (two-way when the protocol
 * declares two factors) with Mauchly's test and the Greenhouse–Geisser correction; Friedman's
 * test with Kendall's W; Bonferroni-corrected pairwise paired t tests, or Wilcoxon
 * signed-rank tests where normality fails.
 */
struct StudyAnalysis
{
    /** The significance level of every decision. */
    static constexpr double Alpha = 0.05;

    /** One condition of one measure. */
    struct Condition
    {
        QString id;
        Summary summary;
        BoxPlot box;
        ShapiroWilkTest normality;
    };

    /** One measure's analysis. */
    struct Measure
    {
        QString name;
        QStringList participants; ///< those in the analysis (a value in every condition)
        QStringList excluded;     ///< those left out: a condition missing
        std::vector<Condition> conditions;
        /** Every condition's Shapiro–Wilk test ran and kept p >= Alpha (never a ranking). */
        bool normal = false;
        /** Each participant's values are a permutation of 1..k: rank tests only. */
        bool ranking = false;
        bool twoWay = false;
        WithinEffect anova;              ///< one-way, over the conditions
        TwoWayWithinEffects twoWayAnova; ///< when twoWay
        FriedmanTest friedman;
        PairedTest pairedTest = PairedTest::T; ///< t when normal, else signed-rank
        std::vector<PairwiseComparison> pairwise;

        /** Whether the primary test (the ANOVA when normal, else Friedman's) could run. */
        bool tested() const { return normal ? anova.tested : friedman.df > 0; }
        /** Whether Mauchly's test rejected sphericity for `effect`, so GG applies. */
        static bool sphericityViolated(const WithinEffect &effect);
    };

    QString source; ///< the study or CSV analysed
    QString name;   ///< the study's name (a CSV: its file name)
    QStringList conditions;
    std::vector<StudyProtocol::Factor> factors;
    std::vector<Measure> measures;

    /** Analyses each of `measures` of `table` (all of them when empty). */
    static StudyAnalysis run(const StudyTable &table, const QStringList &measures = {});

    /** Everything computed, as JSON (`semhap study analyze --json`). */
    QJsonObject toJson() const;
    /** The report, in Markdown; box plots linked as `MEASURE.svg` beside it. */
    QByteArray markdown() const;
    /** Measure `m`'s box plot per condition, as SVG. */
    QByteArray boxPlotSvg(const Measure &m) const;
    /** The file name of a measure's box plot. */
    static QString plotFile(const QString &measure);
};

} // namespace semhap
