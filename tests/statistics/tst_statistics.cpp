// SPDX-License-Identifier: MIT
// The statistics module: the Wilcoxon signed-rank test against published values and exact
// enumeration, the bootstrap interval, and paired comparisons of seeds.
#include "statistics.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace semhap;

namespace {

/**
 * The two-sided p of W+ by brute force: every sign pattern of the magnitudes, equally likely
 * under the null, counted (the exact permutation distribution, ties and all).
 */
double bruteForceP(const std::vector<double> &differences)
{
    const SignedRankTest observed = signedRankTest(differences);
    std::vector<double> magnitudes;
    for (double d : differences) {
        if (d != 0.0)
            magnitudes.push_back(std::abs(d));
    }
    const double n = double(magnitudes.size());
    const double mean = n * (n + 1) / 4.0;
    const unsigned patterns = 1u << magnitudes.size();
    unsigned asExtreme = 0;
    for (unsigned bits = 0; bits < patterns; ++bits) {
        std::vector<double> flipped;
        for (size_t i = 0; i < magnitudes.size(); ++i)
            flipped.push_back(bits & (1u << i) ? magnitudes[i] : -magnitudes[i]);
        if (std::abs(signedRankTest(flipped).w - mean) >= std::abs(observed.w - mean) - 1e-9)
            ++asExtreme;
    }
    return double(asExtreme) / patterns;
}

} // namespace

class TestStatistics : public QObject
{
    Q_OBJECT

private slots:
    void friedmanAsR();
    void friedmanAgreement();
    void exactSignedRank_data();
    void exactSignedRank();
    void normalApproximationWithTies();
    void nothingToTest();
    void bootstrapInterval();
    void pairsBySeed();
    void summary();
};

void TestStatistics::exactSignedRank_data()
{
    QTest::addColumn<std::vector<double>>("differences");
    QTest::addColumn<double>("w");
    QTest::addColumn<double>("p");
    // Hollander & Wolfe's depression scores (R's wilcox.test example): V = 40, p = 0.03906.
    const std::vector<double> x{1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
    const std::vector<double> y{0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
    std::vector<double> d;
    for (size_t i = 0; i < x.size(); ++i)
        d.push_back(x[i] - y[i]);
    QTest::newRow("Hollander & Wolfe") << d << 40.0 << 0.0390625;
    // All ten differences positive: the most extreme of 2^10 patterns, twice.
    QTest::newRow("all positive, n = 10")
        << std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10} << 55.0 << 2.0 / 1024;
    QTest::newRow("all negative, n = 10")
        << std::vector<double>{-1, -2, -3, -4, -5, -6, -7, -8, -9, -10} << 0.0 << 2.0 / 1024;
    // Balanced: W+ at the centre of the distribution, p capped at 1.
    QTest::newRow("balanced") << std::vector<double>{1, -2, -3, 4} << 5.0 << 1.0;
    // Zeros are dropped before ranking (Wilcoxon's convention).
    QTest::newRow("zeros dropped") << std::vector<double>{0, 0, 1, 2, 3} << 6.0 << 0.25;
}

void TestStatistics::exactSignedRank()
{
    QFETCH(std::vector<double>, differences);
    QFETCH(double, w);
    QFETCH(double, p);
    const SignedRankTest test = signedRankTest(differences);
    QVERIFY(test.exact);
    QCOMPARE(test.w, w);
    QVERIFY2(std::abs(test.p - p) < 1e-12, qPrintable(QString::number(test.p, 'g', 12)));
    QVERIFY(std::abs(test.p - std::min(1.0, bruteForceP(differences))) < 1e-12);
}

void TestStatistics::normalApproximationWithTies()
{
    // With ties the exact table does not apply: the normal approximation (tie-corrected
    // variance, continuity correction) must stay close to the exact permutation p.
    const std::vector<std::vector<double>> samples{
        {1, 1, 2, 2, 2, 3, -1, 4, 4, 5, -2, 6, 6, 7},
        {0.5, -0.5, 1, 1, 1, -1, 2, 2, 3, 3, 3, 3, -3, 4},
        {2, 2, 2, 2, -2, 1, 1, -1, 3, 3, 3, 4, 4, 5, 5},
    };
    for (const std::vector<double> &sample : samples) {
        const SignedRankTest test = signedRankTest(sample);
        QVERIFY(!test.exact);
        const double exact = bruteForceP(sample);
        QVERIFY2(std::abs(test.p - exact) < 0.015,
                 qPrintable(QString("normal %1, exact %2").arg(test.p).arg(exact)));
    }
    // Past ExactLimit, untied: approximate. 1..30, every third negative: W+ = 465 - 165 =
    // 300 against a mean of 232.5 and a variance of 30 * 31 * 61 / 24, so
    // z = (300 - 232.5 - 0.5) / 48.618 = 1.378 and p = 2 (1 - Phi(z)) = 0.168.
    std::vector<double> many;
    for (int i = 1; i <= 30; ++i)
        many.push_back(i % 3 == 0 ? -i : i);
    const SignedRankTest test = signedRankTest(many);
    QVERIFY(!test.exact);
    QCOMPARE(test.n, 30);
    QCOMPARE(test.w, 300.0);
    QVERIFY2(std::abs(test.p - 0.1682) < 0.001, qPrintable(QString::number(test.p)));
}

void TestStatistics::nothingToTest()
{
    QCOMPARE(signedRankTest({}).p, 1.0);
    QCOMPARE(signedRankTest({0.0, 0.0}).n, 0);
    QCOMPARE(signedRankTest({0.0, 0.0}).p, 1.0);
    // One difference: at best 2 / 2 = 1.
    QCOMPARE(signedRankTest({3.0}).p, 1.0);
}

void TestStatistics::bootstrapInterval()
{
    std::mt19937_64 random(7);
    std::normal_distribution<double> normal(2.0, 1.0);
    std::vector<double> small;
    std::vector<double> large;
    for (int i = 0; i < 400; ++i)
        (i < 20 ? small : large).push_back(normal(random));
    const auto mean = [](const std::vector<double> &v) {
        double sum = 0;
        for (double x : v)
            sum += x;
        return sum / double(v.size());
    };
    const Interval a = bootstrapMeanInterval(small);
    const Interval b = bootstrapMeanInterval(large);
    QVERIFY(a.low < mean(small) && mean(small) < a.high);
    QVERIFY(b.low < mean(large) && mean(large) < b.high);
    // Narrower with more values: about 1 / sqrt(n), here sqrt(380 / 20) = 4.4 times.
    const double ratio = (a.high - a.low) / (b.high - b.low);
    QVERIFY2(ratio > 3.0 && ratio < 6.0, qPrintable(QString::number(ratio)));
    // About +-1.96 sd / sqrt(n) for the larger sample.
    QVERIFY(std::abs((b.high - b.low) / 2 - 1.96 / std::sqrt(380.0)) < 0.03);
    // Deterministic with the seed; another seed, another (close) interval.
    const Interval again = bootstrapMeanInterval(small);
    QCOMPARE(again.low, a.low);
    QCOMPARE(again.high, a.high);
    const Interval other = bootstrapMeanInterval(small, 0.95, 10000, 2);
    QVERIFY(other.low != a.low && std::abs(other.low - a.low) < 0.1);
    // Constant values: a point.
    const Interval point = bootstrapMeanInterval({1.5, 1.5, 1.5});
    QCOMPARE(point.low, 1.5);
    QCOMPARE(point.high, 1.5);
    QVERIFY(std::isnan(bootstrapMeanInterval({}).low));
}

void TestStatistics::pairsBySeed()
{
    // Seeds with a value on both sides pair; a null (NaN) on either side leaves the seed out.
    const double nan = std::nan("");
    const std::vector<double> baseline{4, 5, nan, 6, 3, 5};
    const std::vector<double> other{2, 3, 1, nan, 1, 2};
    const PairedComparison c = comparePaired(baseline, other);
    QCOMPARE(c.pairs, 4);
    QCOMPARE(c.meanDifference, -2.25);
    QVERIFY(c.interval.low <= -2.0 && c.interval.high >= -2.5);
    QVERIFY(!c.test.exact); // the differences -2, -2, -2, -3 are tied
    QCOMPARE(c.test.w, 0.0);
    const PairedComparison none = comparePaired({nan}, {1.0});
    QCOMPARE(none.pairs, 0);
    QVERIFY(std::isnan(none.meanDifference));
    QCOMPARE(none.test.p, 1.0);
}

void TestStatistics::friedmanAsR()
{
    // R's friedman.test example (Hollander & Wolfe's rounding first base, 22 players x 3
    // methods): Friedman chi-squared = 11.143, df = 2, p-value = 0.003805; ties in 9 rows.
    const std::vector<double> times{
        5.40, 5.50, 5.55, 5.85, 5.70, 5.75, 5.20, 5.60, 5.50, 5.55, 5.50, 5.40, 5.90, 5.85,
        5.70, 5.45, 5.55, 5.60, 5.40, 5.40, 5.35, 5.45, 5.50, 5.35, 5.25, 5.15, 5.00, 5.85,
        5.80, 5.70, 5.25, 5.20, 5.10, 5.65, 5.55, 5.45, 5.60, 5.35, 5.45, 5.05, 5.00, 4.95,
        5.50, 5.50, 5.40, 5.45, 5.55, 5.50, 5.55, 5.55, 5.35, 5.45, 5.50, 5.55, 5.50, 5.45,
        5.25, 5.65, 5.60, 5.40, 5.70, 5.65, 5.55, 6.30, 6.30, 6.25};
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < times.size(); i += 3)
        rows.push_back({times[i], times[i + 1], times[i + 2]});
    const FriedmanTest test = friedmanTest(rows);
    QCOMPARE(test.n, 22);
    QCOMPARE(test.df, 2);
    QCOMPARE(qRound(test.chiSquared * 1000), 11143);
    QCOMPARE(qRound(test.p * 1e6), 3805);
    // W = chi-squared / (n (k - 1)) = 11.1429 / 44.
    QVERIFY(std::abs(test.kendallW - 0.253247) < 1e-6);
}

void TestStatistics::friedmanAgreement()
{
    // Every subject ranks the conditions alike: W = 1, chi-squared = n (k - 1).
    const FriedmanTest same = friedmanTest({{1, 2, 3, 4}, {10, 20, 30, 40}, {0, 5, 6, 9}});
    QCOMPARE(same.chiSquared, 9.0);
    QCOMPARE(same.kendallW, 1.0);
    // Nothing to test: one subject, a missing value, every value tied.
    QCOMPARE(friedmanTest({{1, 2, 3}}).df, 0);
    QCOMPARE(friedmanTest({{1, 2, 3}, {1, qQNaN(), 3}}).p, 1.0);
    QCOMPARE(friedmanTest({{1, 1}, {2, 2}}).df, 0);
}

void TestStatistics::summary()
{
    const Summary s = summarise({2, 4, std::nan(""), 4, 5, 5, 7, 9, 4});
    QCOMPARE(s.n, 8);
    QCOMPARE(s.mean, 5.0);
    QVERIFY(std::abs(s.sd - std::sqrt(32.0 / 7.0)) < 1e-12);
    QCOMPARE(summarise({}).n, 0);
    QCOMPARE(summarise({3.0}).sd, 0.0);
}

QTEST_GUILESS_MAIN(TestStatistics)
#include "tst_statistics.moc"
