// SPDX-License-Identifier: MIT
#include "repeatedmeasures.h"

#include "statistics.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace semhap {

namespace {

using Matrix = std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)>;
using Vector = std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)>;

Matrix zeroMatrix(size_t rows, size_t columns)
{
    return Matrix(gsl_matrix_calloc(rows, columns), gsl_matrix_free);
}

Vector zeroVector(size_t size)
{
    return Vector(gsl_vector_calloc(size), gsl_vector_free);
}

/**
 * k × (k - 1) orthonormal contrasts of k levels: columns of unit length, orthogonal to each
 * other and to the constant. They are Q's columns after the first in the QR decomposition of
 * [1 | e1 ... e(k-1)], whose first column is the constant.
 */
Matrix contrasts(size_t k)
{
    Matrix basis = zeroMatrix(k, k);
    for (size_t i = 0; i < k; ++i)
        gsl_matrix_set(basis.get(), i, 0, 1.0);
    for (size_t j = 1; j < k; ++j)
        gsl_matrix_set(basis.get(), j - 1, j, 1.0);
    Vector tau = zeroVector(k);
    gsl_linalg_QR_decomp(basis.get(), tau.get());
    Matrix q = zeroMatrix(k, k);
    Matrix r = zeroMatrix(k, k);
    gsl_linalg_QR_unpack(basis.get(), tau.get(), q.get(), r.get());
    Matrix result = zeroMatrix(k, k - 1);
    gsl_matrix_const_view rest = gsl_matrix_const_submatrix(q.get(), 0, 1, k, k - 1);
    gsl_matrix_memcpy(result.get(), &rest.matrix);
    return result;
}

/** The k × 1 average of k levels, scaled to unit length: the factor an effect leaves out. */
Matrix average(size_t k)
{
    Matrix result = zeroMatrix(k, 1);
    gsl_matrix_set_all(result.get(), 1.0 / std::sqrt(double(k)));
    return result;
}

/** The Kronecker product a ⊗ b: the contrasts of a crossed design, a's factor the slower. */
Matrix kronecker(const gsl_matrix *a, const gsl_matrix *b)
{
    Matrix result = zeroMatrix(a->size1 * b->size1, a->size2 * b->size2);
    for (size_t i = 0; i < a->size1; ++i) {
        for (size_t j = 0; j < a->size2; ++j) {
            gsl_matrix_view block =
                gsl_matrix_submatrix(result.get(), i * b->size1, j * b->size2, b->size1, b->size2);
            gsl_matrix_memcpy(&block.matrix, b);
            gsl_matrix_scale(&block.matrix, gsl_matrix_get(a, i, j));
        }
    }
    return result;
}

/**
 * Mauchly's test and the epsilons from the d × d covariance of an effect's contrasts of
 * `cells` cells over n subjects, all from its eigenvalues: W = det / (trace / d)^d,
 * GG = trace² / (d trace(S²)).
 */
Sphericity sphericity(const gsl_matrix *covariance, int n, size_t cells)
{
    Sphericity result;
    const size_t d = covariance->size1;
    if (d < 2)
        return result;
    Matrix copy = zeroMatrix(d, d);
    gsl_matrix_memcpy(copy.get(), covariance); // gsl_eigen_symm destroys its input
    Vector eigenvalues = zeroVector(d);
    const std::unique_ptr<gsl_eigen_symm_workspace, decltype(&gsl_eigen_symm_free)> workspace(
        gsl_eigen_symm_alloc(d), gsl_eigen_symm_free);
    gsl_eigen_symm(copy.get(), eigenvalues.get(), workspace.get());
    double trace = 0.0, squares = 0.0, largest = 0.0, smallest = HUGE_VAL, logDeterminant = 0.0;
    for (size_t i = 0; i < d; ++i) {
        const double lambda = gsl_vector_get(eigenvalues.get(), i);
        trace += lambda;
        squares += lambda * lambda;
        largest = std::max(largest, lambda);
        smallest = std::min(smallest, lambda);
        logDeterminant += std::log(std::max(lambda, 0.0));
    }
    const double dd = double(d);
    result.greenhouseGeisser = trace * trace / (dd * squares);
    // Huynh–Feldt's estimate grows past every bound as its denominator falls to 0 (as few
    // subjects as the effect has df): it stays 1 there, and within [1 / d, 1] elsewhere.
    const double hfDenominator = dd * (n - 1 - dd * result.greenhouseGeisser);
    if (hfDenominator > 0.0) {
        const double hf = (n * dd * result.greenhouseGeisser - 2) / hfDenominator;
        result.huynhFeldt = std::clamp(hf, 1.0 / dd, 1.0);
    }
    const double factor = n - 1 - (2 * dd * dd + dd + 2) / (6 * dd);
    if (n - 1 < int(d) || factor <= 0.0 || !(smallest > 1e-12 * largest))
        return result; // a singular covariance: too few subjects for Mauchly's test
    result.tested = true;
    const double logW = logDeterminant - dd * std::log(trace / dd);
    result.w = std::exp(logW);
    result.chiSquared = -factor * logW;
    result.df = int(d * (d + 1) / 2 - 1);
    // The chi-squared distribution with the next term of its asymptotic expansion (Anderson,
    // An Introduction to Multivariate Statistical Analysis, the sphericity test), which R's
    // mauchly.test, car and ez add: small samples would otherwise get too small a p. Their
    // term has 3 k where Anderson's has 3 d (k the cells, d the contrasts); it is kept, so
    // that the p is the one those print and studies publish (it moves the third digit).
    const double cubic = 2 * dd * dd * dd + 6 * dd * dd + 3 * double(cells) + 2;
    const double omega =
        (dd + 2) * (dd - 1) * (dd - 2) * cubic / (288 * dd * dd * factor * factor);
    const double first = gsl_cdf_chisq_Q(result.chiSquared, double(result.df));
    const double next = gsl_cdf_chisq_Q(result.chiSquared, double(result.df + 4));
    result.p = std::clamp(first + omega * (next - first), 0.0, 1.0);
    return result;
}

/** The F test on epsilon times the dfs. */
CorrectedTest corrected(double f, int df1, int df2, double epsilon)
{
    return {df1 * epsilon, df2 * epsilon, gsl_cdf_fdist_Q(f, df1 * epsilon, df2 * epsilon)};
}

/**
 * The effect that `contrast` (cells × d, orthonormal columns orthogonal to the constant)
 * picks out of `y` (subjects × cells): the subjects' scores on the contrasts, their means
 * (the effect) and their spread around them (the effect × subjects error).
 */
WithinEffect effect(const gsl_matrix *y, const gsl_matrix *contrast)
{
    const size_t n = y->size1, d = contrast->size2;
    Matrix scores = zeroMatrix(n, d);
    gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, y, contrast, 0.0, scores.get());
    WithinEffect result;
    for (size_t j = 0; j < d; ++j) {
        gsl_vector_view column = gsl_matrix_column(scores.get(), j);
        const double mean = gsl_stats_mean(column.vector.data, column.vector.stride, n);
        result.ssEffect += double(n) * mean * mean;
        gsl_vector_add_constant(&column.vector, -mean);
    }
    Matrix crossProducts = zeroMatrix(d, d);
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, scores.get(), scores.get(), 0.0,
                   crossProducts.get());
    for (size_t j = 0; j < d; ++j)
        result.ssError += gsl_matrix_get(crossProducts.get(), j, j);
    // No error variance (every subject shifted alike, rounding aside): F is not defined.
    // Rounding is judged against the effect and against the values' own size: values that
    // differ only in their last digits (means of the same numbers summed in another order)
    // have an effect and an error of rounding alike, whose ratio means nothing.
    double squares = 0.0;
    for (size_t i = 0; i < y->size1; ++i) {
        for (size_t j = 0; j < y->size2; ++j)
            squares += gsl_matrix_get(y, i, j) * gsl_matrix_get(y, i, j);
    }
    if (!(result.ssError > 1e-12 * (result.ssEffect + result.ssError)) ||
        !(result.ssError > 1e-20 * squares))
        return WithinEffect();
    result.tested = true;
    result.df1 = int(d);
    result.df2 = int(d * (n - 1));
    result.f = (result.ssEffect / result.df1) / (result.ssError / result.df2);
    result.p = gsl_cdf_fdist_Q(result.f, result.df1, result.df2);
    result.partialEtaSquared = result.ssEffect / (result.ssEffect + result.ssError);
    gsl_matrix_scale(crossProducts.get(), 1.0 / double(n - 1));
    result.sphericity = sphericity(crossProducts.get(), int(n), y->size2);
    result.greenhouseGeisser =
        corrected(result.f, result.df1, result.df2, result.sphericity.greenhouseGeisser);
    result.huynhFeldt = corrected(result.f, result.df1, result.df2, result.sphericity.huynhFeldt);
    return result;
}

/** `rows` as a subjects × cells matrix. */
Matrix table(const std::vector<std::vector<double>> &rows)
{
    Matrix y = zeroMatrix(rows.size(), rows.front().size());
    for (size_t i = 0; i < rows.size(); ++i) {
        for (size_t j = 0; j < rows[i].size(); ++j)
            gsl_matrix_set(y.get(), i, j, rows[i][j]);
    }
    return y;
}

} // namespace

WithinEffect repeatedMeasuresAnova(const std::vector<std::vector<double>> &rows)
{
    const size_t k = rows.empty() ? 0 : rows.front().size();
    if (rows.size() < 2 || k < 2 || !isCompleteTable(rows, k))
        return {};
    return effect(table(rows).get(), contrasts(k).get());
}

TwoWayWithinEffects twoWayRepeatedMeasuresAnova(const std::vector<std::vector<double>> &rows,
                                                int levelsA, int levelsB)
{
    if (levelsA < 2 || levelsB < 2 || rows.size() < 2 ||
        !isCompleteTable(rows, size_t(levelsA) * size_t(levelsB)))
        return {};
    const Matrix y = table(rows);
    const Matrix contrastsA = contrasts(size_t(levelsA));
    const Matrix contrastsB = contrasts(size_t(levelsB));
    TwoWayWithinEffects result;
    result.a = effect(y.get(), kronecker(contrastsA.get(), average(size_t(levelsB)).get()).get());
    result.b = effect(y.get(), kronecker(average(size_t(levelsA)).get(), contrastsB.get()).get());
    result.interaction = effect(y.get(), kronecker(contrastsA.get(), contrastsB.get()).get());
    return result;
}

} // namespace semhap
