// SPDX-License-Identifier: MIT
#include "studyanalysis.h"

#include <QJsonArray>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** A number as APA tables print it: `digits` decimals. */
QString fixed(double value, int digits = 2)
{
    return std::isfinite(value) ? QString::number(value, 'f', digits) : QStringLiteral("–");
}

/** A value bounded by 1 (p, η², W) without its leading zero: `.043`. */
QString unit(double value)
{
    QString text = fixed(value, 3);
    if (text.startsWith(QLatin1String("0.")))
        text.remove(0, 1);
    else if (text.startsWith(QLatin1String("-0.")))
        text.remove(1, 1);
    return text;
}

/** A p in a table's cell: `.004`, or `< .001`. */
QString pCell(double p)
{
    return p < 0.001 ? QStringLiteral("< .001") : unit(p);
}

QString pText(double p)
{
    return p < 0.001 ? QStringLiteral("p < .001") : QStringLiteral("p = %1").arg(unit(p));
}

/** A degrees of freedom: whole, or with two decimals once corrected. */
QString dfText(double df)
{
    return df == std::floor(df) ? QString::number(df, 'f', 0) : fixed(df, 2);
}

QJsonValue number(double value)
{
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

QJsonObject effectJson(const WithinEffect &e)
{
    return {{QStringLiteral("tested"), e.tested},
            {QStringLiteral("df1"), e.df1},
            {QStringLiteral("df2"), e.df2},
            {QStringLiteral("f"), number(e.f)},
            {QStringLiteral("p"), number(e.p)},
            {QStringLiteral("partial_eta_squared"), number(e.partialEtaSquared)},
            {QStringLiteral("mauchly"),
             QJsonObject{{QStringLiteral("tested"), e.sphericity.tested},
                         {QStringLiteral("w"), number(e.sphericity.w)},
                         {QStringLiteral("chi_squared"), number(e.sphericity.chiSquared)},
                         {QStringLiteral("df"), e.sphericity.df},
                         {QStringLiteral("p"), number(e.sphericity.p)}}},
            {QStringLiteral("greenhouse_geisser"),
             QJsonObject{{QStringLiteral("epsilon"), number(e.sphericity.greenhouseGeisser)},
                         {QStringLiteral("df1"), number(e.greenhouseGeisser.df1)},
                         {QStringLiteral("df2"), number(e.greenhouseGeisser.df2)},
                         {QStringLiteral("p"), number(e.greenhouseGeisser.p)}}},
            {QStringLiteral("huynh_feldt"),
             QJsonObject{{QStringLiteral("epsilon"), number(e.sphericity.huynhFeldt)},
                         {QStringLiteral("p"), number(e.huynhFeldt.p)}}}};
}

/** `F(3, 57) = 0.82, p = .489, η²p = .043`, Greenhouse–Geisser-corrected when it applies. */
QString effectText(const WithinEffect &e)
{
    if (!e.tested)
        return QStringLiteral("not tested");
    const bool corrected = StudyAnalysis::Measure::sphericityViolated(e);
    const double df1 = corrected ? e.greenhouseGeisser.df1 : e.df1;
    const double df2 = corrected ? e.greenhouseGeisser.df2 : e.df2;
    QString text =
        QStringLiteral("F(%1, %2) = %3, %4, η²p = %5")
            .arg(dfText(df1), dfText(df2), fixed(e.f),
                 pText(corrected ? e.greenhouseGeisser.p : e.p), unit(e.partialEtaSquared));
    if (!e.sphericity.tested && e.df1 > 1)
        text += QStringLiteral("; Mauchly's test not computable (too few participants, or "
                               "conditions that differ by a constant)");
    if (e.sphericity.tested)
        text += QStringLiteral("; Mauchly W = %1, %2%3")
                    .arg(unit(e.sphericity.w), pText(e.sphericity.p),
                         corrected ? QStringLiteral(", Greenhouse–Geisser ε = %1")
                                         .arg(unit(e.sphericity.greenhouseGeisser))
                                   : QString());
    return text;
}

QString friedmanText(const FriedmanTest &f)
{
    if (f.df == 0)
        return QStringLiteral("not tested");
    return QStringLiteral("χ²(%1) = %2, %3, Kendall's W = %4")
        .arg(f.df)
        .arg(fixed(f.chiSquared), pText(f.p), unit(f.kendallW));
}

/** A Markdown table cell's text: no pipe breaks the table. */
QString cell(QString text)
{
    return text.replace(QLatin1Char('|'), QLatin1String("\\|"));
}

QString xml(QString text)
{
    return text.replace(QLatin1Char('&'), QLatin1String("&amp;"))
        .replace(QLatin1Char('<'), QLatin1String("&lt;"))
        .replace(QLatin1Char('>'), QLatin1String("&gt;"))
        .replace(QLatin1Char('"'), QLatin1String("&quot;"));
}

/** A tick step of 1, 2 or 5 × 10^k that splits `span` into about five parts. */
double tickStep(double span)
{
    const double raw = span / 5.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (m * power >= raw)
            return m * power;
    }
    return 10.0 * power;
}

} // namespace

bool StudyAnalysis::Measure::sphericityViolated(const WithinEffect &effect)
{
    return effect.sphericity.tested && effect.sphericity.p < Alpha;
}

StudyAnalysis StudyAnalysis::run(const StudyTable &table, const QStringList &measures)
{
    StudyAnalysis analysis;
    analysis.conditions = table.conditions();
    analysis.factors = table.factors();
    const size_t conditionCount = size_t(analysis.conditions.size());
    // The two-way ANOVA takes the cells factor A first: condition of levels (a_i, b_j) at
    // column i * |B| + j.
    std::vector<int> cells;
    if (analysis.factors.size() == 2) {
        const StudyProtocol::Factor &a = analysis.factors[0];
        const StudyProtocol::Factor &b = analysis.factors[1];
        for (const QString &levelA : a.levels) {
            for (const QString &levelB : b.levels) {
                for (int c = 0; c < int(conditionCount); ++c) {
                    if (table.levels(c) == QStringList{levelA, levelB})
                        cells.push_back(c);
                }
            }
        }
    }
    for (const QString &name : measures.isEmpty() ? table.measures() : measures) {
        Measure m;
        m.name = name;
        const StudyTable::Matrix matrix = table.matrix(name);
        m.participants = matrix.participants;
        m.excluded = matrix.incomplete;
        // An item asked after some conditions only is compared over those.
        const size_t k = matrix.conditions.size();
        for (size_t c = 0; c < k; ++c) {
            std::vector<double> column;
            for (const std::vector<double> &row : matrix.rows)
                column.push_back(row[c]);
            Condition condition;
            condition.id = analysis.conditions[matrix.conditions[c]];
            condition.summary = summarise(column);
            condition.box = boxPlot(column);
            condition.normality = shapiroWilkTest(column);
            m.conditions.push_back(condition);
        }
        m.normal =
            k > 0 && std::all_of(m.conditions.begin(), m.conditions.end(), [](const Condition &c) {
                return c.normality.tested && c.normality.p >= Alpha;
            });
        // Each participant's values a permutation of 1..k: a ranking, which only rank tests
        // may take, whatever Shapiro-Wilk says.
        m.ranking = !matrix.rows.empty() && std::all_of(matrix.rows.begin(), matrix.rows.end(),
                                                        [k](std::vector<double> r) {
                                                            std::sort(r.begin(), r.end());
                                                            for (size_t i = 0; i < k; ++i) {
                                                                if (r[i] != double(i + 1))
                                                                    return false;
                                                            }
                                                            return true;
                                                        });
        if (m.ranking)
            m.normal = false;
        m.anova = repeatedMeasuresAnova(matrix.rows);
        if (cells.size() == k && k == size_t(analysis.conditions.size()) && k > 0) {
            m.twoWay = true;
            std::vector<std::vector<double>> ordered;
            for (const std::vector<double> &row : matrix.rows) {
                std::vector<double> cellRow;
                for (int c : cells)
                    cellRow.push_back(row[size_t(c)]);
                ordered.push_back(cellRow);
            }
            m.twoWayAnova =
                twoWayRepeatedMeasuresAnova(ordered, int(analysis.factors[0].levels.size()),
                                            int(analysis.factors[1].levels.size()));
        }
        m.friedman = friedmanTest(matrix.rows);
        m.pairedTest = m.normal ? PairedTest::T : PairedTest::SignedRank;
        m.pairwise = pairwiseComparisons(matrix.rows, m.pairedTest);
        analysis.measures.push_back(m);
    }
    return analysis;
}

QString StudyAnalysis::plotFile(const QString &measure)
{
    QString name = measure;
    static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9_.-]"));
    name.replace(unsafe, QStringLiteral("_"));
    // A name changed to be a file name gets its hash, so "a b" and "a_b" keep two plots; a
    // leading dot would hide the file.
    if (name != measure || name.startsWith(QLatin1Char('.')))
        name = QStringLiteral("%1-%2")
                   .arg(name.left(60))
                   .arg(qHash(measure, 0) % 100000u, 5, 10, QLatin1Char('0'));
    return name + QStringLiteral(".svg");
}

QJsonObject StudyAnalysis::toJson() const
{
    QJsonArray measureList;
    for (const Measure &m : measures) {
        QJsonArray conditionList;
        for (const Condition &c : m.conditions) {
            conditionList.append(
                QJsonObject{{QStringLiteral("condition"), c.id},
                            {QStringLiteral("n"), c.summary.n},
                            {QStringLiteral("mean"), number(c.summary.mean)},
                            {QStringLiteral("sd"), number(c.summary.sd)},
                            {QStringLiteral("median"), number(c.box.median)},
                            {QStringLiteral("q1"), number(c.box.q1)},
                            {QStringLiteral("q3"), number(c.box.q3)},
                            {QStringLiteral("shapiro_wilk"),
                             QJsonObject{{QStringLiteral("tested"), c.normality.tested},
                                         {QStringLiteral("w"), number(c.normality.w)},
                                         {QStringLiteral("p"), number(c.normality.p)}}}});
        }
        QJsonArray pairs;
        for (const PairwiseComparison &p : m.pairwise) {
            pairs.append(QJsonObject{{QStringLiteral("first"), m.conditions[p.first].id},
                                     {QStringLiteral("second"), m.conditions[p.second].id},
                                     {QStringLiteral("tested"), p.tested},
                                     {QStringLiteral("mean_difference"), number(p.meanDifference)},
                                     {QStringLiteral("statistic"), number(p.statistic)},
                                     {QStringLiteral("p"), number(p.p)},
                                     {QStringLiteral("p_bonferroni"), number(p.pAdjusted)}});
        }
        QJsonObject measure{
            {QStringLiteral("measure"), m.name},
            {QStringLiteral("participants"), m.participants.size()},
            {QStringLiteral("excluded"), QJsonArray::fromStringList(m.excluded)},
            {QStringLiteral("conditions"), conditionList},
            {QStringLiteral("normal"), m.normal},
            {QStringLiteral("ranking"), m.ranking},
            {QStringLiteral("primary"),
             m.normal ? QStringLiteral("anova") : QStringLiteral("friedman")},
            {QStringLiteral("anova"), effectJson(m.anova)},
            {QStringLiteral("friedman"),
             QJsonObject{{QStringLiteral("df"), m.friedman.df},
                         {QStringLiteral("chi_squared"), number(m.friedman.chiSquared)},
                         {QStringLiteral("p"), number(m.friedman.p)},
                         {QStringLiteral("kendall_w"), number(m.friedman.kendallW)}}},
            {QStringLiteral("pairwise_test"), m.pairedTest == PairedTest::T
                                                  ? QStringLiteral("paired_t")
                                                  : QStringLiteral("wilcoxon_signed_rank")},
            {QStringLiteral("pairwise"), pairs}};
        if (m.twoWay) {
            measure.insert(QStringLiteral("two_way_anova"),
                           QJsonObject{{factors[0].id, effectJson(m.twoWayAnova.a)},
                                       {factors[1].id, effectJson(m.twoWayAnova.b)},
                                       {factors[0].id + QStringLiteral(":") + factors[1].id,
                                        effectJson(m.twoWayAnova.interaction)}});
        }
        measureList.append(measure);
    }
    QJsonArray factorList;
    for (const StudyProtocol::Factor &f : factors)
        factorList.append(
            QJsonObject{{QStringLiteral("id"), f.id},
                        {QStringLiteral("levels"), QJsonArray::fromStringList(f.levels)}});
    return {{QStringLiteral("source"), source},
            {QStringLiteral("name"), name},
            {QStringLiteral("alpha"), Alpha},
            {QStringLiteral("conditions"), QJsonArray::fromStringList(conditions)},
            {QStringLiteral("factors"), factorList},
            {QStringLiteral("measures"), measureList}};
}

QByteArray StudyAnalysis::markdown() const
{
    QString md = QStringLiteral("# Analysis: %1\n\n").arg(name);
    md += QStringLiteral(
              "Source: `%1`. Conditions: %2. Each participant's mean over trials per condition; "
              "α = .05. Per measure: Shapiro–Wilk per condition; where every condition passes, "
              "the repeated-measures ANOVA (Greenhouse–Geisser-corrected when Mauchly's test "
              "rejects sphericity) and Bonferroni-corrected paired t tests; otherwise "
              "Friedman's test with Kendall's W and Bonferroni-corrected Wilcoxon signed-rank "
              "tests. Both omnibus tests are listed for every measure.\n\n")
              .arg(source, conditions.join(QStringLiteral(", ")));
    // The summary: the primary test of each measure.
    md += QStringLiteral("## Summary\n\n| measure | n | test | result | pairs differing "
                         "(Bonferroni) |\n|---|---|---|---|---|\n");
    for (const Measure &m : measures) {
        QStringList differing;
        for (const PairwiseComparison &p : m.pairwise) {
            if (p.tested && p.pAdjusted < Alpha)
                differing.append(QStringLiteral("%1–%2 (%3)")
                                     .arg(cell(m.conditions[p.first].id),
                                          cell(m.conditions[p.second].id), pText(p.pAdjusted)));
        }
        QString test, result;
        if (!m.tested()) {
            test = QStringLiteral("—");
            result = QStringLiteral("not tested: no variance, no differences to rank, or too few "
                                    "participants");
        } else if (m.normal) {
            test = m.twoWay ? QStringLiteral("RM-ANOVA, two-way") : QStringLiteral("RM-ANOVA");
            result = m.twoWay ? QStringLiteral("%1: %2; %3: %4; %1 × %3: %5")
                                    .arg(factors[0].id, effectText(m.twoWayAnova.a), factors[1].id,
                                         effectText(m.twoWayAnova.b),
                                         effectText(m.twoWayAnova.interaction))
                              : effectText(m.anova);
        } else {
            test = QStringLiteral("Friedman");
            result = friedmanText(m.friedman);
        }
        md += QStringLiteral("| %1 | %2 | %3 | %4 | %5 |\n")
                  .arg(cell(m.name))
                  .arg(m.participants.size())
                  .arg(test, cell(result),
                       differing.isEmpty() ? QStringLiteral("none")
                                           : differing.join(QStringLiteral(", ")));
    }
    for (const Measure &m : measures) {
        md += QStringLiteral("\n## %1\n\n").arg(m.name);
        md += QStringLiteral("%1 participants").arg(m.participants.size());
        if (!m.excluded.isEmpty())
            md += QStringLiteral("; left out for a missing condition: %1")
                      .arg(m.excluded.join(QStringLiteral(", ")));
        md += QStringLiteral(".\n\n![%1 per condition](%2)\n\n").arg(m.name, plotFile(m.name));
        md += QStringLiteral("| condition | mean | SD | median | IQR | Shapiro–Wilk |\n"
                             "|---|---|---|---|---|---|\n");
        for (const Condition &c : m.conditions) {
            const bool none = c.summary.n == 0;
            md += QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 |\n")
                      .arg(cell(c.id), none ? QStringLiteral("–") : fixed(c.summary.mean),
                           none ? QStringLiteral("–") : fixed(c.summary.sd), fixed(c.box.median),
                           none ? QStringLiteral("–")
                                : QStringLiteral("%1–%2").arg(fixed(c.box.q1), fixed(c.box.q3)),
                           c.normality.tested ? QStringLiteral("W = %1, %2")
                                                    .arg(unit(c.normality.w), pText(c.normality.p))
                                              : QStringLiteral("not tested"));
        }
        md += QStringLiteral("\n- Normality: %1.\n")
                  .arg(m.ranking ? QStringLiteral("a ranking (each participant's values are 1 "
                                                  "to %1): Friedman's test is primary")
                                       .arg(m.conditions.size())
                       : m.normal ? QStringLiteral("every condition passes")
                                  : QStringLiteral("fails in a condition (or untestable): "
                                                   "Friedman's test is primary"));
        md += QStringLiteral("- Repeated-measures ANOVA: %1.\n").arg(effectText(m.anova));
        if (m.twoWay) {
            md += QStringLiteral("- Two-way: %1: %2; %3: %4; %1 × %3: %5.\n")
                      .arg(factors[0].id, effectText(m.twoWayAnova.a), factors[1].id,
                           effectText(m.twoWayAnova.b), effectText(m.twoWayAnova.interaction));
        }
        md += QStringLiteral("- Friedman: %1.\n").arg(friedmanText(m.friedman));
        if (m.pairwise.empty())
            continue;
        const bool t = m.pairedTest == PairedTest::T;
        md += QStringLiteral("\n%1, Bonferroni-corrected (%2 pairs):\n\n"
                             "| pair | mean difference | %3 | p | p (Bonferroni) |\n"
                             "|---|---|---|---|---|\n")
                  .arg(t ? QStringLiteral("Paired t tests")
                         : QStringLiteral("Wilcoxon signed-rank tests"))
                  .arg(m.pairwise.size())
                  .arg(t ? QStringLiteral("t") : QStringLiteral("W+"));
        for (const PairwiseComparison &p : m.pairwise) {
            md += QStringLiteral("| %1 – %2 | %3 | %4 | %5 | %6 |\n")
                      .arg(cell(m.conditions[p.second].id), cell(m.conditions[p.first].id),
                           fixed(p.meanDifference),
                           p.tested ? fixed(p.statistic) : QStringLiteral("—"),
                           p.tested ? pCell(p.p) : QStringLiteral("—"),
                           p.tested ? pCell(p.pAdjusted) : QStringLiteral("—"));
        }
    }
    return md.toUtf8();
}

QByteArray StudyAnalysis::boxPlotSvg(const Measure &m) const
{
    const int columnWidth = 110, left = 70, top = 40, plotHeight = 260;
    const int width = left + columnWidth * int(m.conditions.size()) + 20;
    const int height = top + plotHeight + 60;
    double low = INFINITY, high = -INFINITY;
    for (const Condition &c : m.conditions) {
        if (c.summary.n == 0)
            continue;
        low = std::min(low, c.box.low);
        high = std::max(high, c.box.high);
        for (double v : c.box.outliers) {
            low = std::min(low, v);
            high = std::max(high, v);
        }
    }
    if (!std::isfinite(low)) {
        low = 0;
        high = 1;
    }
    // A span too small to split into steps at this magnitude is drawn as one value.
    const double magnitude = std::max({1.0, std::abs(low), std::abs(high)});
    if (high - low < 1e-9 * magnitude) {
        low -= 0.5 * magnitude;
        high += 0.5 * magnitude;
    }
    const double step = tickStep(high - low);
    low = std::floor(low / step) * step;
    high = std::ceil(high / step) * step;
    const int ticks = std::min(20, int(std::lround((high - low) / step)));
    const auto y = [&](double v) { return top + plotHeight * (1.0 - (v - low) / (high - low)); };
    QString svg =
        QStringLiteral("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%1\" height=\"%2\" "
                       "viewBox=\"0 0 %1 %2\" font-family=\"sans-serif\" font-size=\"12\">\n"
                       "<rect width=\"%1\" height=\"%2\" fill=\"white\"/>\n"
                       "<text x=\"%3\" y=\"22\" font-size=\"14\" font-weight=\"bold\">%4 "
                       "(n = %5)</text>\n")
            .arg(width)
            .arg(height)
            .arg(left)
            .arg(xml(m.name))
            .arg(m.participants.size());
    for (int i = 0; i <= ticks; ++i) {
        const double v = low + i * step;
        const double at = y(v);
        svg += QStringLiteral("<line x1=\"%1\" x2=\"%2\" y1=\"%3\" y2=\"%3\" stroke=\"#ddd\"/>"
                              "<text x=\"%4\" y=\"%5\" text-anchor=\"end\">%6</text>\n")
                   .arg(left)
                   .arg(width - 20)
                   .arg(at, 0, 'f', 1)
                   .arg(left - 6)
                   .arg(at + 4, 0, 'f', 1)
                   .arg(QString::number(std::abs(v) < step / 1e6 ? 0.0 : v, 'g', 6));
    }
    for (size_t i = 0; i < m.conditions.size(); ++i) {
        const Condition &c = m.conditions[i];
        const double x = left + columnWidth * (double(i) + 0.5);
        const double half = columnWidth * 0.3;
        svg += QStringLiteral("<text x=\"%1\" y=\"%2\" text-anchor=\"middle\">%3</text>\n")
                   .arg(x, 0, 'f', 1)
                   .arg(top + plotHeight + 20)
                   .arg(xml(c.id));
        if (c.summary.n == 0)
            continue;
        const double q1 = y(c.box.q1), q3 = y(c.box.q3);
        // Whiskers, the box (q3 is the higher value, so the smaller y), the median.
        svg += QStringLiteral("<line x1=\"%1\" x2=\"%1\" y1=\"%2\" y2=\"%3\" stroke=\"black\"/>"
                              "<line x1=\"%1\" x2=\"%1\" y1=\"%4\" y2=\"%5\" stroke=\"black\"/>\n")
                   .arg(x, 0, 'f', 1)
                   .arg(y(c.box.high), 0, 'f', 1)
                   .arg(q3, 0, 'f', 1)
                   .arg(q1, 0, 'f', 1)
                   .arg(y(c.box.low), 0, 'f', 1);
        svg += QStringLiteral("<rect x=\"%1\" y=\"%2\" width=\"%3\" height=\"%4\" "
                              "fill=\"#9ecae1\" stroke=\"black\"/>\n"
                              "<line x1=\"%1\" x2=\"%5\" y1=\"%6\" y2=\"%6\" stroke=\"black\" "
                              "stroke-width=\"2\"/>\n")
                   .arg(x - half, 0, 'f', 1)
                   .arg(q3, 0, 'f', 1)
                   .arg(2 * half, 0, 'f', 1)
                   .arg(q1 - q3, 0, 'f', 1)
                   .arg(x + half, 0, 'f', 1)
                   .arg(y(c.box.median), 0, 'f', 1);
        // The mean as a diamond, the outliers as circles.
        const double mean = y(c.summary.mean);
        svg += QStringLiteral("<path d=\"M %1 %2 l 5 5 l -5 5 l -5 -5 z\" fill=\"#d62728\"/>\n")
                   .arg(x, 0, 'f', 1)
                   .arg(mean - 5, 0, 'f', 1);
        for (double v : c.box.outliers)
            svg += QStringLiteral("<circle cx=\"%1\" cy=\"%2\" r=\"3\" fill=\"none\" "
                                  "stroke=\"black\"/>\n")
                       .arg(x, 0, 'f', 1)
                       .arg(y(v), 0, 'f', 1);
    }
    svg += QStringLiteral("<text x=\"%1\" y=\"%2\" font-size=\"11\" fill=\"#555\">box: quartiles "
                          "and median; whiskers: 1.5 IQR; ◆ mean</text>\n</svg>\n")
               .arg(left)
               .arg(height - 12);
    return svg.toUtf8();
}

} // namespace semhap
