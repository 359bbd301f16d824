// SPDX-License-Identifier: MIT
#pragma once

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
 * it. Fewer than 2 subjects or conditions, a NaN or a short row: nothing tested (p = 1).
 */
FriedmanTest friedmanTest(const std::vector<std::vector<double>> &rows);

/** The mean of the values that are not NaN, and their sample standard deviation. */
struct Summary
{
    int n = 0;
    double mean = 0.0;
    double sd = 0.0;
};
Summary summarise(const std::vector<double> &values);

} // namespace semhap
