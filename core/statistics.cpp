// SPDX-License-Identifier: MIT
#include "statistics.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>

namespace semhap {

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/**
 * `differences` of values no larger than `scale`, with those in the values' last digits made
 * 0 (means of the same numbers summed in another order): no difference, as the signed-rank
 * test takes it.
 */
std::vector<double> withoutRounding(std::vector<double> differences, double scale)
{
    for (double &d : differences) {
        if (std::abs(d) <= 1e-12 * scale)
            d = 0.0;
    }
    return differences;
}

/**
 * GSL's default error handler aborts the process on a domain error (an F distribution with
 * astronomic degrees of freedom, from a hostile measures CSV); with it off, the function
 * returns NaN, which the tests report as no result. Set once, as the core library loads;
 * GSL is the core's own (private) dependency.
 */
gsl_error_handler_t *const gslDefaultHandler = gsl_set_error_handler_off();

/** P(W+ <= w) under the null for n untied ranks: the rank sums of all 2^n sign patterns. */
double exactLowerTail(int n, double w)
{
    const int total = n * (n + 1) / 2;
    std::vector<double> ways(size_t(total) + 1, 0.0);
    ways[0] = 1.0;
    for (int rank = 1; rank <= n; ++rank) {
        for (int sum = total; sum >= rank; --sum)
            ways[size_t(sum)] += ways[size_t(sum - rank)];
    }
    double below = 0.0;
    for (int sum = 0; sum <= total && sum <= w + 1e-9; ++sum)
        below += ways[size_t(sum)];
    return below / std::ldexp(1.0, n);
}

/**
 * The Shapiro–Wilk coefficients for n sorted values, Royston (1992, 1995): normal scores m
 * scaled to unit length, the outer one (two from n = 6 on) replaced by Royston's polynomials
 * in 1 / sqrt(n), the rest rescaled so that the coefficients keep unit length.
 */
std::vector<double> shapiroWilkCoefficients(int n)
{
    std::vector<double> a(size_t(n), 0.0);
    if (n == 3) {
        a[0] = -M_SQRT1_2;
        a[2] = M_SQRT1_2;
        return a;
    }
    std::vector<double> m(a.size());
    double mm = 0.0;
    for (int i = 0; i < n; ++i) {
        m[size_t(i)] = gsl_cdf_ugaussian_Pinv((i + 1 - 0.375) / (n + 0.25));
        mm += m[size_t(i)] * m[size_t(i)];
    }
    const double u = 1.0 / std::sqrt(double(n));
    const size_t last = size_t(n) - 1;
    const double outer[6] = {
        m[last] / std::sqrt(mm), 0.221157, -0.147981, -2.071190, 4.434685, -2.706056};
    a[last] = gsl_poly_eval(outer, 6, u);
    double phi = (mm - 2 * m[last] * m[last]) / (1 - 2 * a[last] * a[last]);
    size_t edge = 1; // coefficients fixed at each end
    if (n > 5) {
        const double second[6] = {
            m[last - 1] / std::sqrt(mm), 0.042981, -0.293762, -1.752461, 5.682633, -3.582633};
        a[last - 1] = gsl_poly_eval(second, 6, u);
        phi = (mm - 2 * m[last] * m[last] - 2 * m[last - 1] * m[last - 1]) /
              (1 - 2 * a[last] * a[last] - 2 * a[last - 1] * a[last - 1]);
        edge = 2;
    }
    for (size_t i = edge; i + edge < size_t(n); ++i)
        a[i] = m[i] / std::sqrt(phi);
    for (size_t i = 0; i < edge; ++i)
        a[i] = -a[last - i];
    return a;
}

/**
 * The p of a Shapiro–Wilk W from n values: exact for n = 3 (Shapiro and Wilk 1965), else the
 * upper tail of Royston's normalising transformation of log(1 - W), with its mean and sd
 * polynomials in n for 4 ≤ n ≤ 11 and in log n from 12 on.
 */
double shapiroWilkP(double w, int n)
{
    if (n == 3) {
        const double p = 6.0 / M_PI * (std::asin(std::sqrt(w)) - std::asin(std::sqrt(0.75)));
        return std::clamp(p, 0.0, 1.0);
    }
    const double y = std::log1p(-w);
    double z;
    if (n <= 11) {
        const double gamma = -2.273 + 0.459 * n;
        if (y >= gamma) // beyond the transformation's range: far out in the lower tail of W
            return 0.0;
        const double meanCoefficients[4] = {0.5440, -0.39978, 0.025054, -6.714e-4};
        const double sdCoefficients[4] = {1.3822, -0.77857, 0.062767, -0.0020322};
        z = (-std::log(gamma - y) - gsl_poly_eval(meanCoefficients, 4, n)) /
            std::exp(gsl_poly_eval(sdCoefficients, 4, n));
    } else {
        const double meanCoefficients[4] = {-1.5861, -0.31082, -0.083751, 0.0038915};
        const double sdCoefficients[3] = {-0.4803, -0.082676, 0.0030302};
        const double ln = std::log(double(n));
        z = (y - gsl_poly_eval(meanCoefficients, 4, ln)) /
            std::exp(gsl_poly_eval(sdCoefficients, 3, ln));
    }
    return gsl_cdf_ugaussian_Q(z);
}

} // namespace

bool isCompleteTable(const std::vector<std::vector<double>> &rows, size_t columns)
{
    return std::all_of(rows.begin(), rows.end(), [columns](const std::vector<double> &row) {
        return row.size() == columns &&
               std::all_of(row.begin(), row.end(), [](double v) { return std::isfinite(v); });
    });
}

/**
 * The ranks of `values` from 1, tied values sharing their mid-rank; `ties` gets the sum of
 * t^3 - t over the groups of t tied values (what tie corrections subtract).
 */
std::vector<double> midRanks(const std::vector<double> &values, double *ties)
{
    std::vector<size_t> order(values.size());
    gsl_sort_index(order.data(), values.data(), 1, values.size());
    std::vector<double> ranks(values.size());
    *ties = 0.0;
    for (size_t i = 0; i < order.size();) {
        size_t j = i;
        while (j + 1 < order.size() && values[order[j + 1]] == values[order[i]])
            ++j;
        const double midRank = (double(i) + double(j)) / 2.0 + 1.0;
        for (size_t k = i; k <= j; ++k)
            ranks[order[k]] = midRank;
        const double t = double(j - i + 1);
        *ties += t * t * t - t;
        i = j + 1;
    }
    return ranks;
}

SignedRankTest signedRankTest(const std::vector<double> &differences)
{
    SignedRankTest test;
    std::vector<double> magnitudes;
    std::vector<size_t> positive; // indices into magnitudes of the positive differences
    for (double d : differences) {
        if (std::isnan(d) || d == 0.0)
            continue;
        if (d > 0)
            positive.push_back(magnitudes.size());
        magnitudes.push_back(std::abs(d));
    }
    test.n = int(magnitudes.size());
    if (test.n == 0)
        return test;

    // Mid-ranks of the magnitudes, and the tie groups' sizes for the variance.
    double tieCorrection = 0.0;
    const std::vector<double> ranks = midRanks(magnitudes, &tieCorrection);
    for (size_t index : positive)
        test.w += ranks[index];

    const double n = test.n;
    if (test.n <= ExactLimit && tieCorrection == 0.0) {
        test.exact = true;
        const double lower = exactLowerTail(test.n, test.w);
        // P(W+ >= w) = P(W+ <= total - w) by the symmetry of the null distribution.
        const double upper = exactLowerTail(test.n, n * (n + 1) / 2.0 - test.w);
        test.p = std::min(1.0, 2.0 * std::min(lower, upper));
        return test;
    }
    const double mean = n * (n + 1) / 4.0;
    const double variance = n * (n + 1) * (2 * n + 1) / 24.0 - tieCorrection / 48.0;
    if (variance <= 0.0)
        return test;
    const double offset = test.w - mean;
    const double corrected = offset - (offset > 0 ? 0.5 : offset < 0 ? -0.5 : 0.0);
    const double z = corrected / std::sqrt(variance);
    test.p = std::min(1.0, 2.0 * std::min(gsl_cdf_ugaussian_P(z), gsl_cdf_ugaussian_Q(z)));
    return test;
}

Interval bootstrapMeanInterval(const std::vector<double> &values, double level, int resamples,
                               std::uint64_t seed)
{
    if (values.empty() || resamples < 1)
        return {NaN, NaN};
    const std::unique_ptr<gsl_rng, void (*)(gsl_rng *)> rng(gsl_rng_alloc(gsl_rng_mt19937),
                                                            gsl_rng_free);
    gsl_rng_set(rng.get(), static_cast<unsigned long>(seed));
    std::vector<double> means(static_cast<size_t>(resamples));
    const unsigned long n = values.size();
    for (double &mean : means) {
        double sum = 0.0;
        for (unsigned long k = 0; k < n; ++k)
            sum += values[gsl_rng_uniform_int(rng.get(), n)];
        mean = sum / double(n);
    }
    gsl_sort(means.data(), 1, means.size());
    const double tail = (1.0 - level) / 2.0;
    return {gsl_stats_quantile_from_sorted_data(means.data(), 1, means.size(), tail),
            gsl_stats_quantile_from_sorted_data(means.data(), 1, means.size(), 1.0 - tail)};
}

PairedComparison comparePaired(const std::vector<double> &baseline,
                               const std::vector<double> &other)
{
    PairedComparison comparison;
    std::vector<double> differences;
    for (size_t i = 0; i < std::min(baseline.size(), other.size()); ++i) {
        if (!std::isnan(baseline[i]) && !std::isnan(other[i]))
            differences.push_back(other[i] - baseline[i]);
    }
    comparison.pairs = int(differences.size());
    comparison.meanDifference =
        differences.empty() ? NaN : gsl_stats_mean(differences.data(), 1, differences.size());
    comparison.interval = bootstrapMeanInterval(differences);
    double scale = 0.0;
    for (size_t i = 0; i < std::min(baseline.size(), other.size()); ++i) {
        if (!std::isnan(baseline[i]) && !std::isnan(other[i]))
            scale = std::max({scale, std::abs(baseline[i]), std::abs(other[i])});
    }
    comparison.test = signedRankTest(withoutRounding(differences, scale));
    return comparison;
}

FriedmanTest friedmanTest(const std::vector<std::vector<double>> &rows)
{
    FriedmanTest test;
    test.n = int(rows.size());
    test.k = rows.empty() ? 0 : int(rows.front().size());
    if (test.n < 2 || test.k < 2 || !isCompleteTable(rows, size_t(test.k)))
        return test;
    // Ranks within each subject; the conditions' rank sums against what chance gives.
    std::vector<double> sums(size_t(test.k), 0.0);
    double ties = 0.0;
    for (const std::vector<double> &row : rows) {
        double rowTies = 0.0;
        const std::vector<double> ranks = midRanks(row, &rowTies);
        ties += rowTies;
        for (size_t j = 0; j < ranks.size(); ++j)
            sums[j] += ranks[j];
    }
    const double n = test.n, k = test.k;
    double spread = 0.0;
    for (double sum : sums)
        spread += (sum - n * (k + 1) / 2) * (sum - n * (k + 1) / 2);
    const double denominator = n * k * (k + 1) - ties / (k - 1);
    if (denominator <= 0.0) // every subject ranked every condition alike: nothing to test
        return test;
    test.df = test.k - 1;
    test.chiSquared = 12.0 * spread / denominator;
    test.p = gsl_cdf_chisq_Q(test.chiSquared, double(test.df));
    test.kendallW = test.chiSquared / (n * (k - 1));
    return test;
}

ShapiroWilkTest shapiroWilkTest(const std::vector<double> &values)
{
    ShapiroWilkTest test;
    std::vector<double> x;
    std::copy_if(values.begin(), values.end(), std::back_inserter(x),
                 [](double v) { return std::isfinite(v); });
    test.n = int(x.size());
    if (test.n < 3 || test.n > 5000)
        return test;
    gsl_sort(x.data(), 1, x.size());
    const double mean = gsl_stats_mean(x.data(), 1, x.size());
    double squares = 0.0;
    for (double v : x)
        squares += (v - mean) * (v - mean);
    if (x.front() == x.back())
        return test;
    const std::vector<double> a = shapiroWilkCoefficients(test.n);
    double b = 0.0;
    for (size_t i = 0; i < x.size(); ++i)
        b += a[i] * x[i];
    test.tested = true;
    test.w = std::min(1.0, b * b / squares); // rounding can carry a perfect fit past 1
    test.p = shapiroWilkP(test.w, test.n);
    return test;
}

PairedTTest pairedTTest(const std::vector<double> &baseline, const std::vector<double> &other)
{
    PairedTTest test;
    if (baseline.size() != other.size())
        return test;
    std::vector<double> differences;
    for (size_t i = 0; i < baseline.size(); ++i) {
        if (!std::isnan(baseline[i]) && !std::isnan(other[i]))
            differences.push_back(other[i] - baseline[i]);
    }
    test.n = int(differences.size());
    if (test.n < 2)
        return test;
    test.meanDifference = gsl_stats_mean(differences.data(), 1, differences.size());
    const double sd =
        gsl_stats_sd_m(differences.data(), 1, differences.size(), test.meanDifference);
    // Equal differences (sd 0, or rounding noise next to the mean or the values themselves)
    // leave nothing to test.
    double scale = std::abs(test.meanDifference);
    for (size_t i = 0; i < baseline.size(); ++i) {
        if (!std::isnan(baseline[i]) && !std::isnan(other[i]))
            scale = std::max({scale, std::abs(baseline[i]), std::abs(other[i])});
    }
    if (!std::isfinite(sd) || !(sd > 1e-12 * scale))
        return test;
    test.tested = true;
    test.df = test.n - 1;
    test.t = test.meanDifference / (sd / std::sqrt(double(test.n)));
    test.p = std::min(1.0, 2.0 * gsl_cdf_tdist_Q(std::abs(test.t), double(test.df)));
    return test;
}

std::vector<PairwiseComparison> pairwiseComparisons(const std::vector<std::vector<double>> &rows,
                                                    PairedTest test)
{
    const size_t k = rows.empty() ? 0 : rows.front().size();
    if (rows.size() < 2 || k < 2 || !isCompleteTable(rows, k))
        return {};
    const double comparisons = double(k * (k - 1) / 2);
    std::vector<PairwiseComparison> pairs;
    for (size_t first = 0; first + 1 < k; ++first) {
        for (size_t second = first + 1; second < k; ++second) {
            std::vector<double> a, b, differences;
            double scale = 0.0;
            for (const std::vector<double> &row : rows) {
                a.push_back(row[first]);
                b.push_back(row[second]);
                differences.push_back(row[second] - row[first]);
                scale = std::max({scale, std::abs(row[first]), std::abs(row[second])});
            }
            differences = withoutRounding(differences, scale);
            PairwiseComparison pair;
            pair.first = int(first);
            pair.second = int(second);
            pair.meanDifference = gsl_stats_mean(differences.data(), 1, differences.size());
            if (test == PairedTest::T) {
                const PairedTTest t = pairedTTest(a, b);
                pair.tested = t.tested;
                pair.statistic = t.t;
                pair.p = t.p;
            } else {
                const SignedRankTest signedRank = signedRankTest(differences);
                pair.tested = signedRank.n > 0;
                pair.statistic = signedRank.w;
                pair.p = signedRank.p;
            }
            pair.pAdjusted = std::min(1.0, pair.p * comparisons);
            pairs.push_back(pair);
        }
    }
    return pairs;
}

namespace {

/** The values that are not NaN. */
std::vector<double> present(const std::vector<double> &values)
{
    std::vector<double> kept;
    std::copy_if(values.begin(), values.end(), std::back_inserter(kept),
                 [](double v) { return !std::isnan(v); });
    return kept;
}

} // namespace

Summary summarise(const std::vector<double> &values)
{
    const std::vector<double> present = semhap::present(values);
    Summary summary;
    summary.n = int(present.size());
    if (present.empty())
        return summary;
    summary.mean = gsl_stats_mean(present.data(), 1, present.size());
    summary.sd =
        present.size() > 1 ? gsl_stats_sd_m(present.data(), 1, present.size(), summary.mean) : 0.0;
    return summary;
}

BoxPlot boxPlot(const std::vector<double> &values)
{
    std::vector<double> sorted = present(values);
    BoxPlot box;
    if (sorted.empty()) {
        box.low = box.q1 = box.median = box.q3 = box.high = NaN;
        return box;
    }
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    box.q1 = gsl_stats_quantile_from_sorted_data(sorted.data(), 1, n, 0.25);
    box.median = gsl_stats_quantile_from_sorted_data(sorted.data(), 1, n, 0.5);
    box.q3 = gsl_stats_quantile_from_sorted_data(sorted.data(), 1, n, 0.75);
    const double reach = 1.5 * (box.q3 - box.q1);
    box.low = box.q1;
    box.high = box.q3;
    for (double v : sorted) {
        if (v < box.q1 - reach || v > box.q3 + reach)
            box.outliers.push_back(v);
        else {
            box.low = std::min(box.low, v);
            box.high = std::max(box.high, v);
        }
    }
    return box;
}

} // namespace semhap
