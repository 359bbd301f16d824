// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>

namespace semhap {

struct StudyAnalysis;
class StudyTable;

/**
 * `analysis.R` (`semhap study export --r`, docs/science.md): R code that reads
 * `measures.csv` from the folder it runs in and computes `study analyze`'s tests with R's
 * own: afex's aov_ez (uncorrected, with Mauchly's test and the Greenhouse-Geisser figures
 * where semhap applies them), emmeans' pairwise paired t tests from the multivariate model,
 * friedman.test and wilcox.test, Bonferroni-corrected. It runs the tests semhap ran, measure
 * by measure in its order, and prints each statistic with `sprintf('%.10f')` beside where
 * `study analyze --json` has it, so a reader can check every number.
 */
class StudyRScript
{
public:
    /**
     * The script for `analysis`'s measures of `table` (semhap's decisions, which tests ran
     * and how, written into it).
     */
    static QByteArray script(const StudyAnalysis &analysis, const StudyTable &table);
};

} // namespace semhap
