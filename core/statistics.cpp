// SPDX-License-Identifier: MIT
#include "statistics.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace semhap {

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

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

} // namespace

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
    comparison.test = signedRankTest(differences);
    return comparison;
}

FriedmanTest friedmanTest(const std::vector<std::vector<double>> &rows)
{
    FriedmanTest test;
    test.n = int(rows.size());
    test.k = rows.empty() ? 0 : int(rows.front().size());
    const auto complete = [&](const std::vector<double> &row) {
        return int(row.size()) == test.k &&
               std::none_of(row.begin(), row.end(), [](double v) { return std::isnan(v); });
    };
    if (test.n < 2 || test.k < 2 || !std::all_of(rows.begin(), rows.end(), complete))
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

Summary summarise(const std::vector<double> &values)
{
    std::vector<double> present;
    for (double v : values) {
        if (!std::isnan(v))
            present.push_back(v);
    }
    Summary summary;
    summary.n = int(present.size());
    if (present.empty())
        return summary;
    summary.mean = gsl_stats_mean(present.data(), 1, present.size());
    summary.sd =
        present.size() > 1 ? gsl_stats_sd_m(present.data(), 1, present.size(), summary.mean) : 0.0;
    return summary;
}

} // namespace semhap
