// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace semhap {

/** A Wilcoxon signed-rank test of paired differences. */
struct SignedRankTest
{
    int n = 0;      ///< the non-zero differences (zeros are dropped, Wilcoxon's way)
    double w = 0.0; ///< W+: the sum of the ranks of the positive differences (mid-ranks on ties)
    double p = 1.0; ///< two-sided p-value; 1 when there is nothing to test
    bool exact = false; ///< from the exact null distribution, else the normal approximation
};

/**
 * The Wilcoxon signed-rank test of `differences` against a median of 0. Zeros are dropped;
 * tied magnitudes share their mid-rank. Exact (the null distribution counted) for at most
 * ExactLimit non-zero differences without ties; otherwise the normal approximation with
 * the tie correction of the variance and a continuity correction of 0.5.
 */
SignedRankTest signedRankTest(const std::vector<double> &differences);

/** Above this many non-zero differences, or with ties, signedRankTest approximates. */
constexpr int ExactLimit = 25;

/** A confidence interval; both ends NaN when it cannot be had (no values). */
struct Interval
{
    double low;
    double high;
};

/**
 * The percentile bootstrap interval of the mean of `values` at `level` (0.95: the 2.5th
 * and 97.5th percentiles of `resamples` means of resamples drawn with replacement). The
 * generator is seeded with `seed`, so the interval is the same on every run.
 */
Interval bootstrapMeanInterval(const std::vector<double> &values, double level = 0.95,
                               int resamples = 10000, std::uint64_t seed = 1);

/** One metric of two conditions run on the same seeds, compared pair by pair. */
struct PairedComparison
{
    int pairs = 0;               ///< seeds with a value under both conditions
    double meanDifference = 0.0; ///< mean of (other - baseline) over the pairs; NaN: none
    Interval interval{};         ///< 95 % bootstrap interval of that mean
    SignedRankTest test;         ///< of the differences
};

/**
 * Compares `other` with `baseline`, both indexed by seed (NaN: no value for that seed):
 * the differences other - baseline of the seeds with both, their mean, its 95 % bootstrap
 * interval and the signed-rank test.
 */
PairedComparison comparePaired(const std::vector<double> &baseline,
                               const std::vector<double> &other);

/** Friedman's rank test of k conditions measured on the same n subjects, and Kendall's W. */
struct FriedmanTest
{
    int n = 0;               ///< subjects
    int k = 0;               ///< conditions
    int df = 0;              ///< k - 1; 0 when there was nothing to test
    double chiSquared = 0.0; ///< the statistic, tie-corrected
    double p = 1.0;          ///< from the chi-squared distribution with df degrees of freedom
    double kendallW = 0.0;   ///< chiSquared / (n (k - 1)): 0 no agreement, 1 complete
};

/**
 * Friedman's test of `rows` (one per subject, one value per condition, all complete):
 * ranks within each subject (mid-ranks on ties), the statistic with the tie correction R's
 * friedman.test applies, its chi-squared p, and Kendall's coefficient of concordance W from
 * it. Fewer than 2 subjects or conditions, a NaN (or infinity) or a short row: nothing tested
 * (p = 1).
 */
FriedmanTest friedmanTest(const std::vector<std::vector<double>> &rows);

/**
 * Whether `rows` form a complete table: every row has exactly `columns` values and none is
 * NaN or infinite (what the tests of subjects × conditions below need).
 */
bool isCompleteTable(const std::vector<std::vector<double>> &rows, size_t columns);

/** The Shapiro–Wilk test of normality. */
struct ShapiroWilkTest
{
    bool tested = false; ///< false: fewer than 3 or more than 5000 values, or all of them equal
    int n = 0;           ///< the values tested (NaN and infinite values are left out)
    double w = 1.0;      ///< W, 0 to 1: 1 when the ordered values lie on a normal's quantiles
    double p = 1.0;      ///< the chance of a W this small from normal data; 1 when untested
};

/**
 * The Shapiro–Wilk W of `values` and its p, by Royston's algorithm (AS R94, 1995): the
 * coefficients from normal scores with Royston's polynomial corrections of the outer two,
 * the p exact for n = 3 and from Royston's normalising transformations for 4 ≤ n ≤ 11 and
 * 12 ≤ n ≤ 5000. NaN and infinite values are left out, as R's shapiro.test drops NA.
 */
ShapiroWilkTest shapiroWilkTest(const std::vector<double> &values);

/** Student's paired t test. */
struct PairedTTest
{
    bool tested = false; ///< false: fewer than 2 pairs, unequal lengths, or constant differences
    int n = 0;           ///< the pairs with both values (a NaN on either side leaves a pair out)
    double meanDifference = 0.0; ///< the mean of other - baseline
    double t = 0.0;
    int df = 0;     ///< n - 1
    double p = 1.0; ///< two-sided, from Student's t distribution; 1 when untested
};

/**
 * The paired t test of `other` against `baseline` (one value each per subject, the same
 * subjects in the same order): the differences other - baseline, their mean, t = mean / (sd /
 * sqrt(n)) on n - 1 degrees of freedom and the two-sided p. Pairs with a NaN are left out.
 */
PairedTTest pairedTTest(const std::vector<double> &baseline, const std::vector<double> &other);

/** Which paired test pairwiseComparisons runs on each pair of conditions. */
enum class PairedTest
{
    T,         ///< Student's paired t test (pairedTTest)
    SignedRank ///< the Wilcoxon signed-rank test (signedRankTest)
};

/** One pair of conditions compared over the same subjects, Bonferroni-corrected. */
struct PairwiseComparison
{
    int first = 0;               ///< the earlier condition's column
    int second = 0;              ///< the later condition's column
    bool tested = false;         ///< false: the differences were all 0 or (t test) all equal
    double meanDifference = 0.0; ///< the mean of second - first
    double statistic = 0.0;      ///< t, or W+ of the signed-rank test
    double p = 1.0;              ///< the test's own two-sided p
    double pAdjusted = 1.0;      ///< Bonferroni's: min(1, p k (k - 1) / 2) for k conditions
};

/**
 * Every pair of the conditions of `rows` (one row per subject, one value per condition, all
 * complete) compared with `test` on the differences second - first, in the order (0, 1),
 * (0, 2), ..., (k - 2, k - 1), each p multiplied by the k (k - 1) / 2 comparisons (capped at
 * 1). Fewer than 2 subjects or conditions, a NaN or a short row: nothing tested, no pairs.
 */
std::vector<PairwiseComparison> pairwiseComparisons(const std::vector<std::vector<double>> &rows,
                                                    PairedTest test);

/** The mean of the values that are not NaN, and their sample standard deviation. */
struct Summary
{
    int n = 0;
    double mean = 0.0;
    double sd = 0.0;
};
Summary summarise(const std::vector<double> &values);

/**
 * What a box plot draws of some values: the quartiles (R's default quantiles, type 7), the
 * whiskers' ends (the most extreme values within 1.5 interquartile ranges of the box, as
 * Tukey drew them) and the values beyond them. All NaN when there are no values.
 */
struct BoxPlot
{
    double low = 0.0;
    double q1 = 0.0;
    double median = 0.0;
    double q3 = 0.0;
    double high = 0.0;
    std::vector<double> outliers;
};
BoxPlot boxPlot(const std::vector<double> &values);

} // namespace semhap
