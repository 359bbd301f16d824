// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace semhap {

/**
 * Mauchly's test of sphericity for one within-subject effect, and the epsilons that correct
 * its F test's degrees of freedom when sphericity does not hold.
 */
struct Sphericity
{
    /// False for an effect of 1 df (two levels: sphericity holds trivially, W = 1, both
    /// epsilons 1) and when the subjects are too few for Mauchly's test (fewer than df + 1, or
    /// a singular covariance); the epsilons are still estimated when there are df > 1.
    bool tested = false;
    double w = 1.0; ///< Mauchly's W, 0 to 1: 1 when the contrasts' covariance is spherical
    double chiSquared = 0.0; ///< -(n - 1 - (2d² + d + 2) / 6d) ln W for an effect of d df
    int df = 0;              ///< d (d + 1) / 2 - 1
    double p = 1.0;          ///< of chiSquared with the second-order term R adds; 1 when untested
    double greenhouseGeisser = 1.0; ///< epsilon, 1 / d to 1
    /// Huynh–Feldt's epsilon (n d GG - 2) / (d (n - 1 - d GG)) within 1 / d to 1 (1 where the
    /// denominator is not positive)
    double huynhFeldt = 1.0;
};

/** An F test's degrees of freedom multiplied by an epsilon, and its p on them. */
struct CorrectedTest
{
    double df1 = 0.0;
    double df2 = 0.0;
    double p = 1.0;
};

/** One within-subject effect of a repeated-measures ANOVA. */
struct WithinEffect
{
    bool tested = false; ///< false: fewer than 2 subjects or levels, a NaN, or no error variance
    int df1 = 0;         ///< the effect's degrees of freedom
    int df2 = 0;         ///< its error's: df1 (n - 1)
    double ssEffect = 0.0;
    double ssError = 0.0; ///< the effect × subjects interaction, its error term
    double f = 0.0;
    double p = 1.0;                 ///< assuming sphericity; 1 when untested
    double partialEtaSquared = 0.0; ///< ssEffect / (ssEffect + ssError)
    Sphericity sphericity;
    CorrectedTest greenhouseGeisser; ///< the F test on dfs times the Greenhouse–Geisser epsilon
    CorrectedTest huynhFeldt;        ///< the F test on dfs times the Huynh–Feldt epsilon
};

/**
 * The one-way repeated-measures ANOVA of `rows` (one row per subject, one value per
 * condition, all complete): the conditions' F against the conditions × subjects error, with
 * Mauchly's test and the Greenhouse–Geisser and Huynh–Feldt corrections, computed from the
 * orthonormal contrasts of the conditions. Fewer than 2 subjects or conditions, a NaN or a
 * short row, or no error variance at all: nothing tested.
 */
WithinEffect repeatedMeasuresAnova(const std::vector<std::vector<double>> &rows);

/** The three effects of a two-way within-subjects ANOVA. */
struct TwoWayWithinEffects
{
    WithinEffect a;
    WithinEffect b;
    WithinEffect interaction; ///< A × B
};

/**
 * The two-way repeated-measures ANOVA of a fully crossed `levelsA` × `levelsB` design. Each
 * row is one subject's levelsA · levelsB cell values with factor A varying slowest: the cell
 * (A level i, B level j) is row[i * levelsB + j], as in columns a1b1, a1b2, ..., a2b1, ...
 * Each effect is tested against its own interaction with subjects, with Mauchly's test and
 * the corrections where it has more than 1 df. Fewer than 2 levels of a factor, fewer than 2
 * subjects, a NaN or a row of another length: nothing tested.
 */
TwoWayWithinEffects twoWayRepeatedMeasuresAnova(const std::vector<std::vector<double>> &rows,
                                                int levelsA, int levelsB);

} // namespace semhap
