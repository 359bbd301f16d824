# What every analysis.R does; `semhap study export --r` writes the study's own lines after it.
suppressPackageStartupMessages({
    library(afex)
    library(emmeans)
})

# Names as they are (a participant `NA`, a condition `T`); an empty value is no observation.
table <- read.csv("measures.csv", na.strings = "",
                  colClasses = c(participant = "character", condition = "character",
                                 trial = "character", measure = "character",
                                 value = "numeric"))

# One line per statistic: the measure, where `semhap study analyze --json` has it (a JSON
# pointer into the measure's object), and R's value.
say <- function(name, statistic, value) {
    cat(sprintf("%s\t%s\t%.10f\n", name, statistic, value))
}

# Each participant's mean over a measure's trials per condition: participants in rows, the
# conditions the measure was asked in as columns, participants without a value in each of
# them left out, as semhap's analysis takes them.
means <- function(name) {
    rows <- table[table$measure == name, ]
    asked <- conditions[conditions %in% rows$condition]
    cells <- aggregate(value ~ participant + condition, data = rows, FUN = mean)
    m <- tapply(cells$value,
                list(cells$participant, factor(cells$condition, levels = asked)), identity)
    m[complete.cases(m), , drop = FALSE]
}

long <- function(m) {
    data.frame(participant = rep(rownames(m), ncol(m)),
               condition = factor(rep(colnames(m), each = nrow(m)), levels = colnames(m)),
               value = as.vector(m))
}

# An effect of an afex fit: F, p and partial eta squared with no correction; Mauchly's test
# where semhap computed it; the Greenhouse-Geisser figures where semhap applies them
# (Mauchly's test rejected sphericity).
effect <- function(name, pointer, fit, row, sphericity, gg) {
    anova <- fit$anova_table
    say(name, paste0(pointer, "/f"), anova[row, "F"])
    say(name, paste0(pointer, "/p"), anova[row, "Pr(>F)"])
    say(name, paste0(pointer, "/partial_eta_squared"), anova[row, "pes"])
    if (sphericity) {
        s <- summary(fit)
        say(name, paste0(pointer, "/mauchly/w"), s$sphericity.tests[row, "Test statistic"])
        say(name, paste0(pointer, "/mauchly/p"), s$sphericity.tests[row, "p-value"])
        if (gg) {
            say(name, paste0(pointer, "/greenhouse_geisser/epsilon"),
                s$pval.adjustments[row, "GG eps"])
            say(name, paste0(pointer, "/greenhouse_geisser/p"),
                s$pval.adjustments[row, "Pr(>F[GG])"])
        }
    }
}

fit_within <- function(data, within) {
    aov_ez("participant", "value", data, within = within,
           anova_table = list(correction = "none", es = "pes"))
}

# One measure, with the tests semhap ran on it: `anova` (and `sphericity`, `gg` as above),
# `friedman`, the pairwise tests ("t": paired t tests from emmeans' multivariate model;
# "wilcoxon": Wilcoxon signed-rank tests, exact up to 25 non-zero differences without ties,
# as semhap decides) of the pairs `tested`, Bonferroni-corrected, and, in a two-factor
# design, `two_way`: for each effect its tested, sphericity and gg.
measure <- function(name, anova, sphericity, gg, friedman, pairwise, tested, two_way = NULL) {
    m <- means(name)
    if (nrow(m) == 0)
        return(invisible())
    fit <- NULL
    if (anova || (pairwise == "t" && any(tested)))
        fit <- fit_within(long(m), "condition")
    if (anova)
        effect(name, "/anova", fit, "condition", sphericity, gg)
    if (!is.null(two_way) && any(two_way$tested)) {
        data <- long(m)
        cell <- match(as.character(data$condition), conditions)
        data$A <- factor(level_a[cell], levels = unique(level_a))
        data$B <- factor(level_b[cell], levels = unique(level_b))
        fit2 <- fit_within(data, c("A", "B"))
        rows <- c("A", "B", "A:B")
        for (e in seq_along(rows)) {
            if (two_way$tested[e])
                effect(name, paste0("/two_way_anova/", effects[e]), fit2, rows[e],
                       two_way$sphericity[e], two_way$gg[e])
        }
    }
    if (friedman) {
        f <- friedman.test(m)
        say(name, "/friedman/chi_squared", f$statistic)
        say(name, "/friedman/p", f$p.value)
    }
    if (!any(tested))
        return(invisible())
    pairs_of <- combn(ncol(m), 2)
    if (pairwise == "t") {
        contrasts <- pairs(emmeans(fit, ~ condition, model = "multivariate"), adjust = "none")
        raw <- summary(contrasts)
        corrected <- summary(contrasts, adjust = "bonferroni")
    }
    for (k in seq_along(tested)) {
        if (!tested[k])
            next
        first <- pairs_of[1, k]
        second <- pairs_of[2, k]
        pointer <- sprintf("/pairwise/%d", k - 1)
        if (pairwise == "t") {
            # emmeans contrasts the earlier condition minus the later; semhap the later
            # minus the earlier.
            say(name, paste0(pointer, "/statistic"), -raw$t.ratio[k])
            say(name, paste0(pointer, "/p"), raw$p.value[k])
            say(name, paste0(pointer, "/p_bonferroni"), corrected$p.value[k])
        } else {
            # The later condition minus the earlier, zeros dropped as semhap drops them (so an
            # exact p stays exact), and so are differences in the values' last digits.
            d <- m[, second] - m[, first]
            d <- d[abs(d) > 1e-12 * max(abs(m[, c(first, second)]))]
            exact <- length(d) <= 25 && !any(duplicated(abs(d)))
            w <- wilcox.test(d, exact = exact, correct = TRUE)
            say(name, paste0(pointer, "/statistic"), w$statistic)
            say(name, paste0(pointer, "/p"), w$p.value)
            say(name, paste0(pointer, "/p_bonferroni"), min(1, w$p.value * ncol(pairs_of)))
        }
    }
}
