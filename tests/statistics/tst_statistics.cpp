// SPDX-License-Identifier: MIT
// The statistics module: the Wilcoxon signed-rank test against published values and exact
// enumeration, the bootstrap interval, paired comparisons of seeds, and the study analysis's
// tests (Shapiro–Wilk, paired t, repeated-measures ANOVA, Bonferroni-corrected pairs), each
// against published worked examples to the digits they were published with.
#include "repeatedmeasures.h"
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

/**
 * Whether `actual` rounds to `published`, to the digits printed there: within half a unit of
 * its last digit ("0.0387" allows 0.00005, "6.2e-09" allows 0.05e-09).
 */
bool agrees(double actual, QStringView published)
{
    const qsizetype e = published.indexOf(u'e');
    const QStringView mantissa = e < 0 ? published : published.left(e);
    const int exponent = e < 0 ? 0 : published.mid(e + 1).toInt();
    const qsizetype dot = mantissa.indexOf(u'.');
    const int decimals = dot < 0 ? 0 : int(mantissa.size() - dot - 1);
    const double halfUnit = 0.5 * std::pow(10.0, exponent - decimals);
    return std::abs(actual - published.toDouble()) <= halfUnit * (1 + 1e-9);
}

/** Empty when `actual` agrees with `published`, else what `what` was instead. */
QString mismatch(const QString &what, double actual, QStringView published)
{
    if (agrees(actual, published))
        return {};
    return QStringLiteral("%1 = %2, published %3")
        .arg(what, QString::number(actual, 'g', 10), published.toString());
}

#define COMPARE_PUBLISHED(actual, published)                                                      \
    do {                                                                                          \
        const QString difference = mismatch(QStringLiteral(#actual), (actual), (published));      \
        QVERIFY2(difference.isEmpty(), qPrintable(difference));                                   \
    } while (false)

/**
 * Field, Miles & Field, Discovering Statistics Using R (2012), chapter 13: the time in seconds
 * eight celebrities took to retch eating each of four bushtucker foods (Bushtucker.dat; stick
 * insect, kangaroo testicle, fish eye, witchetty grub).
 */
const std::vector<std::vector<double>> bushtucker{
    {8, 7, 1, 6}, {9, 5, 2, 5}, {6, 2, 3, 8},  {5, 3, 1, 9},
    {8, 4, 5, 8}, {7, 5, 6, 7}, {10, 2, 7, 2}, {12, 6, 8, 1},
};

/**
 * The same book's 3 x 3 within-subjects example (Attitude.dat): 20 participants' ratings
 * (-100 to 100) of adverts for beer, wine and water (drink, factor A), each shown with
 * positive, negative and neutral imagery (factor B); columns beerpos, beerneg, beerneut,
 * winepos, ..., waterneu, so A varies slowest.
 */
const std::vector<std::vector<double>> attitude{
    {1, 6, 5, 38, -5, 4, 10, -14, -2},     {43, 30, 8, 20, -12, 4, 9, -10, -13},
    {15, 15, 12, 20, -15, 6, 6, -16, 1},   {40, 30, 19, 28, -4, 0, 20, -10, 2},
    {8, 12, 8, 11, -2, 6, 27, 5, -5},      {17, 17, 15, 17, -6, 6, 9, -6, -13},
    {30, 21, 21, 15, -2, 16, 19, -20, 3},  {34, 23, 28, 27, -7, 7, 12, -12, 2},
    {34, 20, 26, 24, -10, 12, 12, -9, 4},  {26, 27, 27, 23, -15, 14, 21, -6, 0},
    {1, -19, -10, 28, -13, 13, 33, -2, 9}, {7, -18, 6, 26, -16, 19, 23, -17, 5},
    {22, -8, 4, 34, -23, 14, 21, -19, 0},  {30, -6, 3, 32, -22, 21, 17, -11, 4},
    {40, -6, 0, 24, -9, 19, 15, -10, 2},   {15, -9, 4, 29, -18, 7, 13, -17, 8},
    {20, -17, 9, 30, -17, 12, 16, -4, 10}, {9, -12, -5, 24, -15, 18, 17, -4, 8},
    {14, -11, 7, 34, -14, 20, 19, -1, 12}, {15, -6, 13, 23, -15, 15, 29, -1, 10},
};

/** Leukocytes of six animals before and after surgery (see pairedT). */
const std::vector<double> beforeSurgery{10.8, 12.9, 9.59, 8.81, 12, 6.07};
const std::vector<double> afterSurgery{10.6, 16.6, 17.2, 14, 10.6, 8.6};

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
    void shapiroWilk_data();
    void shapiroWilk();
    void shapiroWilkExactForThree();
    void shapiroWilkNothingToTest();
    void pairedT_data();
    void pairedT();
    void pairedTNothingToTest();
    void oneWayAsField();
    void twoLevelsAsPairedT();
    void twoWay_data();
    void twoWay();
    void oneDfEffectsAreSpherical();
    void anovaNothingToTest();
    void pairwiseTAsR();
    void pairwiseTFactorialCells();
    void pairwiseSignedRank();
    void pairwiseNothingToTest();
    void boxPlotAsGgplot();
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
    // Runs that differ in their values' last digits only: no difference for the test.
    const double third = 0.1 + 0.2; // 0.30000000000000004
    const PairedComparison rounding = comparePaired({0.3, 0.3, third}, {third, third, 0.3});
    QCOMPARE(rounding.pairs, 3);
    QCOMPARE(rounding.test.n, 0);
    QCOMPARE(rounding.test.p, 1.0);
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

void TestStatistics::shapiroWilk_data()
{
    QTest::addColumn<std::vector<double>>("values");
    QTest::addColumn<QString>("w");
    QTest::addColumn<QString>("p");
    // R's shapiro.test as printed in github.com/s4rduk4r/R-examples (R 3.6.1): notebook 06,
    // leukocytes before and after surgery (n = 6, Royston's small-sample branch, a tie after).
    QTest::newRow("before surgery, n = 6") << beforeSurgery << "0.96736"
                                           << "0.8742";
    QTest::newRow("after surgery, n = 6") << afterSurgery << "0.90401"
                                          << "0.3982";
    // Notebook 10: body mass changes of mice on three supplements (n = 9, ties).
    QTest::newRow("supplement F1, n = 9")
        << std::vector<double>{7.1, 7.0, 7.0, 8.6, 8.2, 6.6, 6.8, 6.7, 7.7} << "0.86142"
        << "0.09936";
    QTest::newRow("supplement F2, n = 9")
        << std::vector<double>{7.6, 7.3, 7.3, 8.3, 7.6, 6.6, 6.7, 6.8, 7.0} << "0.93473"
        << "0.5277";
    QTest::newRow("supplement F3, n = 9")
        << std::vector<double>{9.2, 8.3, 9.1, 9.0, 8.9, 9.0, 9.2, 7.6, 8.1} << "0.82447"
        << "0.0387";
    // Notebook 09: HDL of infants on three milk regimes (n = 10).
    QTest::newRow("human milk, n = 10")
        << std::vector<double>{56, 63, 45, 41, 71, 60, 78, 50, 68, 62} << "0.97975"
        << "0.9638";
    QTest::newRow("formula, n = 10")
        << std::vector<double>{40, 48, 60, 38, 28, 44, 66, 22, 45, 54} << "0.9826"
        << "0.9775";
    QTest::newRow("supplemented formula, n = 10")
        << std::vector<double>{71, 57, 64, 44, 73, 50, 79, 67, 84, 61} << "0.98636"
        << "0.9901";
    // R's ToothGrowth$len (n = 60, the large-sample branch): shapiro.test gives W = 0.96743,
    // p-value = 0.1091 (r-stats-lightbridge.netlify.app/stats/normality-test.html).
    QTest::newRow("ToothGrowth, n = 60")
        << std::vector<double>{4.2,  11.5, 7.3,  5.8,  6.4,  10.0, 11.2, 11.2, 5.2,  7.0,
                               16.5, 16.5, 15.2, 17.3, 22.5, 17.3, 13.6, 14.5, 18.8, 15.5,
                               23.6, 18.5, 33.9, 25.5, 26.4, 32.5, 26.7, 21.5, 23.3, 29.5,
                               15.2, 21.5, 17.6, 9.7,  14.5, 10.0, 8.2,  9.4,  16.5, 9.7,
                               19.7, 23.3, 23.6, 26.4, 20.0, 25.2, 25.8, 21.2, 14.5, 27.3,
                               25.5, 26.4, 22.4, 24.5, 24.8, 30.9, 26.4, 27.3, 29.4, 23.0}
        << "0.96743"
        << "0.1091";
    // Field's RExam.dat exam marks (n = 100): scipy.stats.shapiro (the same AS R94, in single
    // precision) gives (0.96130979, 0.00499133) in github.com/snehilk1312/AppliedStatistics,
    // Python/statistics_with_Python/05_Exploring_Assumptions (02_..._normality.ipynb); taken
    // to the digits single precision supports.
    QTest::newRow("RExam, n = 100")
        << std::vector<double>{18, 30, 40, 30, 40, 15, 36, 40, 63, 31, 22, 47, 38, 34, 54, 35, 33,
                               38, 29, 36, 59, 31, 34, 28, 50, 59, 33, 57, 25, 53, 65, 47, 28, 43,
                               47, 60, 45, 22, 39, 43, 66, 36, 26, 58, 53, 37, 48, 32, 42, 34, 56,
                               76, 72, 77, 77, 66, 62, 86, 97, 72, 69, 87, 88, 72, 75, 74, 68, 81,
                               77, 71, 60, 74, 80, 68, 64, 94, 65, 72, 75, 92, 89, 83, 80, 95, 99,
                               80, 81, 75, 78, 65, 80, 86, 73, 81, 69, 60, 69, 71, 82, 58}
        << "0.96131"
        << "0.004991";
}

void TestStatistics::shapiroWilk()
{
    QFETCH(std::vector<double>, values);
    const ShapiroWilkTest test = shapiroWilkTest(values);
    QVERIFY(test.tested);
    QCOMPARE(test.n, int(values.size()));
    QFETCH(QString, w);
    QFETCH(QString, p);
    COMPARE_PUBLISHED(test.w, w);
    COMPARE_PUBLISHED(test.p, p);
    // The order of the values does not matter, a NaN is left out.
    std::vector<double> shuffled(values.rbegin(), values.rend());
    shuffled.insert(shuffled.begin() + 1, qQNaN());
    const ShapiroWilkTest again = shapiroWilkTest(shuffled);
    QCOMPARE(again.n, test.n);
    QCOMPARE(again.w, test.w);
}

void TestStatistics::shapiroWilkExactForThree()
{
    // For n = 3 the coefficients are -1/sqrt 2, 0, 1/sqrt 2 and the null distribution of W is
    // known exactly (Shapiro & Wilk 1965, Biometrika 52, p. 596): P(W <= w) =
    // 6/pi (asin sqrt w - asin sqrt 3/4). For 1, 2, 4: W = (3/sqrt 2)^2 / (42/9) = 27/28.
    const ShapiroWilkTest test = shapiroWilkTest({4, 1, 2});
    QVERIFY(test.tested);
    QVERIFY(std::abs(test.w - 27.0 / 28.0) < 1e-12);
    const double p = 6 / M_PI * (std::asin(std::sqrt(27.0 / 28.0)) - M_PI / 3);
    QVERIFY2(std::abs(test.p - p) < 1e-12, qPrintable(QString::number(test.p)));
    // Equally spaced: W = 1, the largest p there is.
    QCOMPARE(shapiroWilkTest({1, 2, 3}).p, 1.0);
    // Two equal values and one apart: the smallest W, 3/4, p = 0.
    const ShapiroWilkTest lowest = shapiroWilkTest({5, 5, 8});
    QVERIFY(std::abs(lowest.w - 0.75) < 1e-12);
    QVERIFY(lowest.p < 1e-6);
}

void TestStatistics::shapiroWilkNothingToTest()
{
    const auto untested = [](const std::vector<double> &values) {
        const ShapiroWilkTest test = shapiroWilkTest(values);
        return !test.tested && test.p == 1.0 && test.w == 1.0;
    };
    QVERIFY(untested({}));
    QVERIFY(untested({1.0, 2.0}));
    QVERIFY(untested({1.0, qQNaN(), 2.0, qInf()})); // two values left
    QVERIFY(untested({3.0, 3.0, 3.0, 3.0}));        // all equal: no spread to judge
    QVERIFY(untested(std::vector<double>(5001, 1.0)));
    std::vector<double> ramp(5001);
    for (size_t i = 0; i < ramp.size(); ++i)
        ramp[i] = double(i);
    QVERIFY(untested(ramp)); // past Royston's 5000
    ramp.pop_back();
    QVERIFY(shapiroWilkTest(ramp).tested);
    QCOMPARE(shapiroWilkTest({3.0, 3.0, 3.0, 3.0}).n, 4);
}

void TestStatistics::pairedT_data()
{
    QTest::addColumn<std::vector<double>>("baseline");
    QTest::addColumn<std::vector<double>>("other");
    QTest::addColumn<QString>("mean");
    QTest::addColumn<QString>("t");
    QTest::addColumn<int>("df");
    QTest::addColumn<QString>("p");
    // R's t.test(before, after, paired = TRUE) in github.com/s4rduk4r/R-examples, notebook 06:
    // t = -2.1205, df = 5, p-value = 0.08745, mean of the differences -2.905.
    QTest::newRow("leukocytes") << afterSurgery << beforeSurgery << "-2.905"
                                << "-2.1205" << 5 << "0.08745";
    // STHDA's mice weights, t.test(after, before, paired = TRUE) as printed at
    // rstudio-pubs-static.s3.amazonaws.com/805708_042b43ff85154c5187e66d2eba2f0cd5.html:
    // t = 20.883, df = 9, p-value = 6.2e-09, mean of the differences 194.49.
    QTest::newRow("mice weights") << std::vector<double>{200.1, 190.9, 192.7, 213,   241.4,
                                                         196.9, 172.2, 185.5, 205.2, 193.7}
                                  << std::vector<double>{392.9, 393.2, 345.1, 393,   434,
                                                         427.9, 422,   383.9, 392.3, 352.2}
                                  << "194.49"
                                  << "20.883" << 9 << "6.2e-09";
}

void TestStatistics::pairedT()
{
    QFETCH(std::vector<double>, baseline);
    QFETCH(std::vector<double>, other);
    QFETCH(QString, mean);
    QFETCH(QString, t);
    QFETCH(int, df);
    QFETCH(QString, p);
    const PairedTTest test = pairedTTest(baseline, other);
    QVERIFY(test.tested);
    QCOMPARE(test.n, df + 1);
    QCOMPARE(test.df, df);
    COMPARE_PUBLISHED(test.meanDifference, mean);
    COMPARE_PUBLISHED(test.t, t);
    COMPARE_PUBLISHED(test.p, p);
    // The other way round: the same test, t negated.
    const PairedTTest reversed = pairedTTest(other, baseline);
    QCOMPARE(reversed.t, -test.t);
    QCOMPARE(reversed.p, test.p);
}

void TestStatistics::pairedTNothingToTest()
{
    const auto untested = [](const PairedTTest &test) {
        return !test.tested && test.p == 1.0 && test.df == 0;
    };
    QVERIFY(untested(pairedTTest({}, {})));
    QVERIFY(untested(pairedTTest({1.0}, {2.0})));
    QVERIFY(untested(pairedTTest({1.0, 2.0, 3.0}, {1.0, 2.0})));              // unequal lengths
    QVERIFY(untested(pairedTTest({1.0, 2.0, 3.0}, {3.0, 4.0, 5.0})));         // all differ by 2
    QVERIFY(untested(pairedTTest({1.0, qQNaN(), 3.0}, {2.0, 5.0, qQNaN()}))); // one pair left
    const PairedTTest twoLeft = pairedTTest({1.0, 2.0, qQNaN(), 4.0}, {2.0, 5.0, 3.0, 4.5});
    QVERIFY(twoLeft.tested);
    QCOMPARE(twoLeft.n, 3);
}

void TestStatistics::oneWayAsField()
{
    // Field, Miles & Field (2012), chapter 13, ezANOVA on the bushtucker data as printed in
    // github.com/snehilk1312/AppliedStatistics, R/statistics_with_R/13_GLM4_RepeatedMeasures
    // Designs/Markdown_notebook/01_RepeatedMeasuresAnova.md: Animal DFn 3, DFd 21, SSn 83.125,
    // SSd 153.375, F 3.793806, p 2.557030e-02; Mauchly W 0.136248, p 0.04684581; GGe
    // 0.5328456, p[GG] 0.06258412; HFe 0.6657636, p[HF] 0.04833061. Field's SPSS output in
    // the book: Mauchly's W .136, GG .533, HF .666, F(3, 21) = 3.79, p = .026.
    const WithinEffect anova = repeatedMeasuresAnova(bushtucker);
    QVERIFY(anova.tested);
    QCOMPARE(anova.df1, 3);
    QCOMPARE(anova.df2, 21);
    COMPARE_PUBLISHED(anova.ssEffect, u"83.125");
    COMPARE_PUBLISHED(anova.ssError, u"153.375");
    COMPARE_PUBLISHED(anova.f, u"3.793806");
    COMPARE_PUBLISHED(anova.p, u"2.557030e-02");
    // pingouin's rm_anova in the Python twin of that notebook: np2 0.35148.
    COMPARE_PUBLISHED(anova.partialEtaSquared, u"0.35148");
    QVERIFY(anova.sphericity.tested);
    COMPARE_PUBLISHED(anova.sphericity.w, u"0.136248");
    QCOMPARE(anova.sphericity.df, 5);
    COMPARE_PUBLISHED(anova.sphericity.p, u"0.04684581");
    COMPARE_PUBLISHED(anova.sphericity.greenhouseGeisser, u"0.5328456");
    COMPARE_PUBLISHED(anova.greenhouseGeisser.p, u"0.06258412");
    COMPARE_PUBLISHED(anova.sphericity.huynhFeldt, u"0.6657636");
    COMPARE_PUBLISHED(anova.huynhFeldt.p, u"0.04833061");
    // The corrected dfs are the dfs times epsilon (SPSS: 1.60 and 11.19).
    COMPARE_PUBLISHED(anova.greenhouseGeisser.df1, u"1.60");
    COMPARE_PUBLISHED(anova.greenhouseGeisser.df2, u"11.19");
    // The conditions in another order: the same ANOVA.
    std::vector<std::vector<double>> swapped = bushtucker;
    for (std::vector<double> &row : swapped)
        std::swap(row[0], row[3]);
    const WithinEffect again = repeatedMeasuresAnova(swapped);
    QVERIFY(std::abs(again.f - anova.f) < 1e-9);
    QVERIFY(std::abs(again.sphericity.w - anova.sphericity.w) < 1e-9);
}

void TestStatistics::twoLevelsAsPairedT()
{
    // With two conditions the ANOVA is the paired t test: F = t^2 with the same p (the
    // leukocytes' published t = -2.1205, p = 0.08745), and sphericity holds trivially.
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < beforeSurgery.size(); ++i)
        rows.push_back({beforeSurgery[i], afterSurgery[i]});
    const WithinEffect anova = repeatedMeasuresAnova(rows);
    QVERIFY(anova.tested);
    QCOMPARE(anova.df1, 1);
    QCOMPARE(anova.df2, 5);
    QVERIFY2(std::abs(anova.f - 2.1205 * 2.1205) < 2 * 2.1205 * 0.00005,
             qPrintable(QString::number(anova.f)));
    COMPARE_PUBLISHED(anova.p, u"0.08745");
    QVERIFY(!anova.sphericity.tested);
    QCOMPARE(anova.sphericity.w, 1.0);
    QCOMPARE(anova.sphericity.greenhouseGeisser, 1.0);
    QCOMPARE(anova.greenhouseGeisser.p, anova.p);
    QCOMPARE(anova.huynhFeldt.p, anova.p);
}

void TestStatistics::twoWay_data()
{
    QTest::addColumn<int>("effect"); // 0 drink (A), 1 imagery (B), 2 interaction
    QTest::addColumn<int>("df1");
    QTest::addColumn<QString>("ssEffect");
    QTest::addColumn<QString>("ssError");
    QTest::addColumn<QString>("f");
    QTest::addColumn<QString>("p");
    QTest::addColumn<QString>("w");
    QTest::addColumn<QString>("mauchlyP");
    QTest::addColumn<QString>("gg");
    QTest::addColumn<QString>("ggP");
    QTest::addColumn<QString>("hf");
    QTest::addColumn<QString>("hfP");
    // Field, Miles & Field (2012), chapter 13, ezANOVA(within = .(atd, drink), type = 3) on
    // Attitude.dat as printed in github.com/snehilk1312/AppliedStatistics, R/statistics_with_R/
    // 13_GLM4_RepeatedMeasuresDesigns/Markdown_notebook/03_FactorialRepeatedMeasureAnova.md.
    // The book's SPSS output agrees: drink F(1.15, 21.93) = 5.11 with GG, imagery F(2, 38) =
    // 122.56, interaction F(4, 76) = 17.16.
    QTest::newRow("drink") << 0 << 2 << "2092.344"
                           << "7785.878"
                           << "5.105981"
                           << "1.086293e-02"
                           << "0.2672411"
                           << "6.952302e-06"
                           << "0.5771143"
                           << "2.976868e-02"
                           << "0.5907442"
                           << "2.881391e-02";
    QTest::newRow("imagery") << 1 << 2 << "21628.678"
                             << "3352.878"
                             << "122.564825"
                             << "2.680197e-17"
                             << "0.6621013"
                             << "2.445230e-02"
                             << "0.7474407"
                             << "1.757286e-13"
                             << "0.7968420"
                             << "3.142804e-14";
    QTest::newRow("drink x imagery") << 2 << 4 << "2624.422"
                                     << "2906.689"
                                     << "17.154922"
                                     << "4.589040e-10"
                                     << "0.5950440"
                                     << "4.356587e-01"
                                     << "0.7983979"
                                     << "1.900249e-08"
                                     << "0.9785878"
                                     << "6.809640e-10";
}

void TestStatistics::twoWay()
{
    QFETCH(int, effect);
    QFETCH(int, df1);
    QFETCH(QString, ssEffect);
    QFETCH(QString, ssError);
    QFETCH(QString, f);
    QFETCH(QString, p);
    QFETCH(QString, w);
    QFETCH(QString, mauchlyP);
    QFETCH(QString, gg);
    QFETCH(QString, ggP);
    QFETCH(QString, hf);
    QFETCH(QString, hfP);
    const TwoWayWithinEffects anova = twoWayRepeatedMeasuresAnova(attitude, 3, 3);
    const WithinEffect &e = effect == 0 ? anova.a : effect == 1 ? anova.b : anova.interaction;
    QVERIFY(e.tested);
    QCOMPARE(e.df1, df1);
    QCOMPARE(e.df2, df1 * 19);
    COMPARE_PUBLISHED(e.ssEffect, ssEffect);
    COMPARE_PUBLISHED(e.ssError, ssError);
    COMPARE_PUBLISHED(e.f, f);
    COMPARE_PUBLISHED(e.p, p);
    COMPARE_PUBLISHED(e.sphericity.w, w);
    COMPARE_PUBLISHED(e.sphericity.p, mauchlyP);
    COMPARE_PUBLISHED(e.sphericity.greenhouseGeisser, gg);
    COMPARE_PUBLISHED(e.greenhouseGeisser.p, ggP);
    COMPARE_PUBLISHED(e.sphericity.huynhFeldt, hf);
    COMPARE_PUBLISHED(e.huynhFeldt.p, hfP);
    QCOMPARE(e.sphericity.df, df1 * (df1 + 1) / 2 - 1);
    // Partial eta squared from the published sums of squares.
    QVERIFY(std::abs(e.partialEtaSquared -
                     ssEffect.toDouble() / (ssEffect.toDouble() + ssError.toDouble())) < 1e-6);
}

void TestStatistics::oneDfEffectsAreSpherical()
{
    // A 2 x 2 (beer and wine with positive and negative imagery): every effect has 1 df, so
    // Mauchly's test has nothing to test and the corrections change nothing. Each effect is
    // then the paired t test of its contrast: A's of the subjects' means per drink.
    std::vector<std::vector<double>> cells;
    std::vector<double> beer, wine;
    for (const std::vector<double> &row : attitude) {
        cells.push_back({row[0], row[1], row[3], row[4]});
        beer.push_back((row[0] + row[1]) / 2);
        wine.push_back((row[3] + row[4]) / 2);
    }
    const TwoWayWithinEffects anova = twoWayRepeatedMeasuresAnova(cells, 2, 2);
    for (const WithinEffect *e : {&anova.a, &anova.b, &anova.interaction}) {
        QVERIFY(e->tested);
        QCOMPARE(e->df1, 1);
        QCOMPARE(e->df2, 19);
        QVERIFY(!e->sphericity.tested);
        QCOMPARE(e->sphericity.greenhouseGeisser, 1.0);
        QCOMPARE(e->greenhouseGeisser.p, e->p);
        QCOMPARE(e->huynhFeldt.df2, 19.0);
    }
    const PairedTTest drink = pairedTTest(beer, wine);
    QVERIFY(std::abs(anova.a.f - drink.t * drink.t) < 1e-9 * anova.a.f);
    QVERIFY(std::abs(anova.a.p - drink.p) < 1e-12);
}

void TestStatistics::anovaNothingToTest()
{
    const auto untested = [](const WithinEffect &e) {
        return !e.tested && e.p == 1.0 && e.df1 == 0 && !e.sphericity.tested;
    };
    QVERIFY(untested(repeatedMeasuresAnova({})));
    QVERIFY(untested(repeatedMeasuresAnova({{1, 2, 3}})));                  // one subject
    QVERIFY(untested(repeatedMeasuresAnova({{1}, {2}, {3}})));              // one condition
    QVERIFY(untested(repeatedMeasuresAnova({{1, 2, 3}, {1, qQNaN(), 3}}))); // a NaN
    QVERIFY(untested(repeatedMeasuresAnova({{1, 2, 3}, {1, 2}})));          // a short row
    // Every subject shifted alike: no error variance, F undefined.
    QVERIFY(untested(repeatedMeasuresAnova({{1, 2, 4}, {11, 12, 14}, {-1, 0, 2}})));
    QVERIFY(untested(repeatedMeasuresAnova({{5, 5}, {5, 5}})));
    // Conditions that differ only in the values' last digits (means of the same numbers
    // summed in another order): effect and error are rounding alike, F would be their ratio.
    const double ulp = 1.4210854715202004e-14; // one step of a double near 62
    QVERIFY(untested(repeatedMeasuresAnova({{62.2266400068458, 62.2266400068458 + ulp},
                                            {38.08202, 38.08202},
                                            {59.8075, 59.8075},
                                            {53.7274816, 53.7274816 + ulp},
                                            {71.3998766, 71.3998766 - ulp}})));
    // The same where every value is one number but for its last digits.
    const double third = 0.1 + 0.2; // 0.30000000000000004
    QVERIFY(untested(repeatedMeasuresAnova(
        {{third, 0.3, 0.3}, {0.3, third, 0.3}, {0.3, 0.3, third}, {third, third, 0.3}})));
    // Two-way: rows that do not hold a x b cells, or a factor with one level.
    const auto untestedTwoWay = [&](const TwoWayWithinEffects &anova) {
        return untested(anova.a) && untested(anova.b) && untested(anova.interaction);
    };
    QVERIFY(untestedTwoWay(twoWayRepeatedMeasuresAnova(attitude, 3, 2)));
    QVERIFY(untestedTwoWay(twoWayRepeatedMeasuresAnova(attitude, 1, 9)));
    QVERIFY(untestedTwoWay(twoWayRepeatedMeasuresAnova({attitude[0]}, 3, 3)));
    // Fewer subjects than the effect has df: the F test stands, Mauchly's test cannot be had
    // (a singular covariance), the epsilons stay within their bounds.
    const WithinEffect few =
        repeatedMeasuresAnova({{1, 4, 2, 8, 5}, {2, 3, 7, 1, 1}, {0, 5, 5, 2, 9}});
    QVERIFY(few.tested);
    QVERIFY(!few.sphericity.tested);
    QCOMPARE(few.sphericity.p, 1.0);
    QVERIFY(few.sphericity.greenhouseGeisser >= 0.25 && few.sphericity.greenhouseGeisser <= 1);
    QVERIFY(few.sphericity.huynhFeldt >= 0.25 && few.sphericity.huynhFeldt <= 1);
    QVERIFY(few.greenhouseGeisser.p >= 0 && few.greenhouseGeisser.p <= 1);
    QVERIFY(few.huynhFeldt.p >= 0 && few.huynhFeldt.p <= 1);
}

void TestStatistics::pairwiseTAsR()
{
    // pairwise.t.test(paired = TRUE, p.adjust.method = "bonferroni") on the bushtucker data,
    // printed in the notebook of oneWayAsField; the t and unadjusted p from statsmodels'
    // allpairtest(ttest_rel, method = "bonf") in its Python twin.
    const std::vector<PairwiseComparison> pairs = pairwiseComparisons(bushtucker, PairedTest::T);
    QCOMPARE(pairs.size(), size_t(6));
    const struct
    {
        int first, second;
        const char16_t *t, *p, *adjusted;
    } published[] = {
        {0, 1, u"-4.7753", u"0.002", u"0.0121"},  {0, 2, u"-5.465", u"0.0009", u"0.0056"},
        {0, 3, u"-1.3252", u"0.2267", u"1.0000"}, {1, 2, u"-0.104", u"0.9201", u"1.0000"},
        {1, 3, u"1.1225", u"0.2987", u"1.0000"},  {2, 3, u"0.8919", u"0.402", u"1.0000"},
    };
    for (size_t i = 0; i < pairs.size(); ++i) {
        const PairwiseComparison &pair = pairs[i];
        QCOMPARE(pair.first, published[i].first);
        QCOMPARE(pair.second, published[i].second);
        QVERIFY(pair.tested);
        const QString where = QStringLiteral("pair %1-%2 ").arg(pair.first).arg(pair.second);
        const QString differences =
            mismatch(where + u't', pair.statistic, published[i].t) +
            mismatch(where + u'p', pair.p, published[i].p) +
            mismatch(where + QStringLiteral("adjusted p"), pair.pAdjusted, published[i].adjusted);
        QVERIFY2(differences.isEmpty(), qPrintable(differences));
        QCOMPARE(pair.pAdjusted, std::min(1.0, 6 * pair.p));
    }
    QCOMPARE(pairs[0].meanDifference, 4.25 - 8.125); // kangaroo testicle - stick insect
}

void TestStatistics::pairwiseTFactorialCells()
{
    // The nine attitude cells as conditions: 36 pairs, Bonferroni times 36. R's matrix, as
    // printed in the notebook of twoWay (row: later cell, column: earlier), read by row.
    const char16_t *published[9][8] = {
        {},
        {u"0.00217"},
        {u"0.01982", u"1.00000"},
        {u"1.00000", u"0.01105", u"0.00310"},
        {u"5.6e-08", u"0.00265", u"2.0e-07", u"1.9e-10"},
        {u"0.39905", u"1.00000", u"1.00000", u"2.2e-05", u"2.3e-07"},
        {u"1.00000", u"0.47584", u"1.00000", u"0.07300", u"1.3e-09", u"0.10547"},
        {u"2.9e-06", u"0.18860", u"0.00010", u"3.2e-10", u"1.00000", u"1.1e-07", u"4.9e-11"},
        {u"0.00212", u"1.00000", u"0.74838", u"4.3e-10", u"0.00041", u"8.1e-05", u"9.0e-07",
         u"0.00068"},
    };
    const std::vector<PairwiseComparison> pairs = pairwiseComparisons(attitude, PairedTest::T);
    QCOMPARE(pairs.size(), size_t(36));
    for (const PairwiseComparison &pair : pairs) {
        const QString difference =
            mismatch(QStringLiteral("cells %1-%2 adjusted p").arg(pair.first).arg(pair.second),
                     pair.pAdjusted, published[pair.second][pair.first]);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }
}

void TestStatistics::pairwiseSignedRank()
{
    // Three conditions built on Hollander & Wolfe's depression scores (R's wilcox.test example:
    // V = 40 for x - y, p-value = 0.03906): y - x has W+ = 45 - 40 = 5 and the same exact p,
    // times the 3 comparisons. The third condition lies above x in every subject: W+ = 45,
    // the most extreme of 2^9 sign patterns, p = 2 / 512.
    const std::vector<double> x{1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
    const std::vector<double> y{0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < x.size(); ++i)
        rows.push_back({x[i], y[i], x[i] + 0.1 * double(i + 1)});
    const std::vector<PairwiseComparison> pairs =
        pairwiseComparisons(rows, PairedTest::SignedRank);
    QCOMPARE(pairs.size(), size_t(3));
    QCOMPARE(pairs[0].statistic, 5.0);
    QVERIFY(std::abs(pairs[0].p - 0.0390625) < 1e-12);
    QVERIFY(std::abs(pairs[0].pAdjusted - 3 * 0.0390625) < 1e-12);
    QCOMPARE(pairs[1].statistic, 45.0);
    QVERIFY(std::abs(pairs[1].pAdjusted - 3 * 2.0 / 512) < 1e-12);
    std::vector<double> yToZ;
    for (const std::vector<double> &row : rows)
        yToZ.push_back(row[2] - row[1]);
    QCOMPARE(pairs[2].p, signedRankTest(yToZ).p);
    // A pair with no differences: untested, p 1 before and after the correction.
    for (std::vector<double> &row : rows)
        row[2] = row[1];
    const PairwiseComparison same = pairwiseComparisons(rows, PairedTest::SignedRank)[2];
    QVERIFY(!same.tested);
    QCOMPARE(same.pAdjusted, 1.0);
}

void TestStatistics::pairwiseNothingToTest()
{
    QVERIFY(pairwiseComparisons({}, PairedTest::T).empty());
    QVERIFY(pairwiseComparisons({{1, 2, 3}}, PairedTest::T).empty());
    QVERIFY(pairwiseComparisons({{1}, {2}}, PairedTest::SignedRank).empty());
    QVERIFY(pairwiseComparisons({{1, 2}, {2, qQNaN()}}, PairedTest::T).empty());
    QVERIFY(pairwiseComparisons({{1, 2, 3}, {2, 3}}, PairedTest::SignedRank).empty());
    // Constant differences: the t test has nothing to test, p stays 1 after the correction.
    const std::vector<PairwiseComparison> constant =
        pairwiseComparisons({{1, 3}, {2, 4}, {5, 7}}, PairedTest::T);
    QCOMPARE(constant.size(), size_t(1));
    QVERIFY(!constant[0].tested);
    QCOMPARE(constant[0].pAdjusted, 1.0);
    QCOMPARE(constant[0].meanDifference, 2.0);
    // Differences in the values' last digits are none: nothing for the t test, and zeros the
    // signed-rank test drops.
    const double ulp = 1.4210854715202004e-14; // one step of a double near 62
    const std::vector<std::vector<double>> rounding{{62.2266400068458, 62.2266400068458 + ulp},
                                                    {38.08202, 38.08202},
                                                    {53.7274816, 53.7274816 + ulp},
                                                    {71.3998766, 71.3998766 - ulp}};
    QVERIFY(!pairwiseComparisons(rounding, PairedTest::T)[0].tested);
    QVERIFY(!pairwiseComparisons(rounding, PairedTest::SignedRank)[0].tested);
}

void TestStatistics::boxPlotAsGgplot()
{
    // R: quantile(1:10) is 1, 3.25, 5.5, 7.75, 10 (type 7, R's default and ggplot2's).
    std::vector<double> values{10, 9, 8, 7, 6, 5, 4, 3, 2, 1};
    BoxPlot box = boxPlot(values);
    QCOMPARE(box.q1, 3.25);
    QCOMPARE(box.median, 5.5);
    QCOMPARE(box.q3, 7.75);
    QCOMPARE(box.low, 1.0);
    QCOMPARE(box.high, 10.0);
    QVERIFY(box.outliers.empty());
    // quantile(c(1:10, 30)): 3.5, 6, 8.5; 30 lies beyond q3 + 1.5 IQR = 16, the whisker
    // ends at 10. A NaN is no value.
    values.push_back(30);
    values.push_back(qQNaN());
    box = boxPlot(values);
    QCOMPARE(box.q1, 3.5);
    QCOMPARE(box.median, 6.0);
    QCOMPARE(box.q3, 8.5);
    QCOMPARE(box.high, 10.0);
    QCOMPARE(box.outliers, std::vector<double>{30});
    QVERIFY(std::isnan(boxPlot({}).median));
}

QTEST_GUILESS_MAIN(TestStatistics)
#include "tst_statistics.moc"
