// SPDX-License-Identifier: MIT
#include "comparecommand.h"

#include "metricspec.h"
#include "operator.h"
#include "provenance.h"
#include "simrun.h"
#include "statistics.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <thread>

#include <unistd.h>

namespace semhap {

namespace {

/**
 * The metrics a comparison reports, in the order of their table (MetricSpec): what the runs
 * scored, then the runs' own measures (their times). Inputs come first in the CSV.
 */
const std::vector<const MetricSpec *> &metricSpecs()
{
    static const std::vector<const MetricSpec *> specs = [] {
        std::vector<const MetricSpec *> out = MetricSpec::numbers(MetricRole::Outcome);
        for (const MetricSpec *spec : MetricSpec::numbers(MetricRole::Measure))
            out.push_back(spec);
        return out;
    }();
    return specs;
}

const QStringList &metricKeys()
{
    static const QStringList keys = [] {
        QStringList out;
        for (const MetricSpec *spec : metricSpecs())
            out.append(QLatin1String(spec->name));
        return out;
    }();
    return keys;
}

const QStringList &inputKeys()
{
    static const QStringList keys{QStringLiteral("scene"), QStringLiteral("router"),
                                  QStringLiteral("operator"), QStringLiteral("seed"),
                                  QStringLiteral("duration")};
    return keys;
}

/** One run of the grid: its inputs and its metrics (NaN where a metric is null). */
struct Row
{
    QStringList inputs;
    std::vector<double> metrics;
};

QString csvNumber(double value)
{
    return std::isnan(value) ? QString() : QString::number(value, 'g', 10);
}

QByteArray csvHeader()
{
    return (inputKeys() + metricKeys()).join(QLatin1Char(',')).toUtf8() + '\n';
}

QByteArray csvLine(const Row &row)
{
    QStringList cells = row.inputs;
    for (double value : row.metrics)
        cells.append(csvNumber(value));
    return cells.join(QLatin1Char(',')).toUtf8() + '\n';
}

/**
 * A CSV line back into a row; false with the reason (`expected N cells, found M`, `'x' is
 * not a number`).
 */
bool parseLine(const QByteArray &line, Row *row, QString *reason)
{
    const QStringList cells = QString::fromUtf8(line).trimmed().split(QLatin1Char(','));
    const int width = int(inputKeys().size() + metricKeys().size());
    if (cells.size() != width) {
        *reason = QStringLiteral("expected %1 cells, found %2").arg(width).arg(cells.size());
        return false;
    }
    row->inputs = cells.mid(0, inputKeys().size());
    row->metrics.clear();
    for (int c = int(inputKeys().size()); c < cells.size(); ++c) {
        bool ok = cells[c].isEmpty();
        const double value = ok ? std::nan("") : cells[c].toDouble(&ok);
        if (!ok) {
            *reason = QStringLiteral("'%1' is not a number").arg(cells[c]);
            return false;
        }
        row->metrics.push_back(value);
    }
    return true;
}

/**
 * The runs of a compare whose CSV is not whole yet: `CSV.partial`, the header and then each
 * finished run's line, appended and handed to the disk as the run ends, so that a task
 * killed mid-way keeps every run it finished for `--resume`. It is written directly rather
 * than through an OutputFile because it must be on the disk while the command runs; the
 * CSV itself appears whole at the end, and the journal goes once it has.
 */
class Journal
{
public:
    static QString pathOf(const QString &csv) { return csv + QStringLiteral(".partial"); }

    /**
     * The complete lines of an existing journal or CSV after its header: a last line cut
     * off by a kill (no newline) is dropped. False with `FILE:LINE: reason`.
     */
    static bool read(const QString &path, std::vector<Row> *rows, QString *error)
    {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            *error = QStringLiteral("%1: cannot read: %2").arg(path, file.errorString());
            return false;
        }
        if (file.readLine() != csvHeader()) {
            *error = QStringLiteral("%1:1: not a semhap compare CSV (header differs)").arg(path);
            return false;
        }
        for (int line = 2; !file.atEnd(); ++line) {
            const QByteArray text = file.readLine();
            if (!text.endsWith('\n'))
                break; // cut off: that run is done again
            Row row;
            QString reason;
            if (!parseLine(text, &row, &reason)) {
                *error = QStringLiteral("%1:%2: %3").arg(path).arg(line).arg(reason);
                return false;
            }
            rows->push_back(row);
        }
        return true;
    }

    /** Starts the journal afresh with `rows` (those a resumed run keeps); false with why. */
    bool start(const QString &path, const std::vector<Row> &rows, QString *error)
    {
        m_file.setFileName(path);
        if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
            *error = QStringLiteral("%1: cannot write: %2").arg(path, m_file.errorString());
            return false;
        }
        QByteArray text = csvHeader();
        for (const Row &row : rows)
            text += csvLine(row);
        return write(text, error);
    }

    /** Appends a finished run's line and hands it to the disk; false with why. */
    bool append(const Row &row, QString *error)
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        return write(csvLine(row), error);
    }

private:
    bool write(const QByteArray &text, QString *error)
    {
        if (m_file.write(text) != text.size() || !m_file.flush() ||
            ::fsync(m_file.handle()) != 0) {
            *error = QStringLiteral("%1: cannot write: %2")
                         .arg(m_file.fileName(), m_file.errorString());
            return false;
        }
        return true;
    }

    QFile m_file;
    std::mutex m_mutex;
};

/** Digits after the point for numbers of this size: 3 significant ones at most. */
int digitsFor(double value)
{
    const double size = std::abs(value);
    return size >= 100 ? 0 : (size >= 10 ? 1 : (size >= 1 ? 2 : 3));
}

QString fixed(double value, int digits)
{
    return std::isnan(value) ? QStringLiteral("–") : QString::number(value, 'f', digits);
}

/** A difference with its sign: +0.25, -1.5, and 0.00 for what rounds to nothing. */
QString signedFixed(double value, int digits)
{
    QString text = fixed(std::abs(value), digits);
    if (text.count(QLatin1Char('0')) + text.count(QLatin1Char('.')) == text.size())
        return text;
    return (value > 0 ? QLatin1Char('+') : QLatin1Char('-')) + text;
}

/** Mean ± sd of the non-null values, as the table prints it. */
QString meanAndSd(const std::vector<double> &values)
{
    const Summary s = summarise(values);
    if (s.n == 0)
        return QStringLiteral("–");
    const int digits = digitsFor(s.mean);
    return QStringLiteral("%1 ± %2").arg(fixed(s.mean, digits), fixed(s.sd, digits));
}

/** Lines of cells, the first column left-aligned and the others right-aligned. */
QString aligned(const std::vector<QStringList> &lines)
{
    std::vector<int> widths;
    for (const QStringList &line : lines) {
        widths.resize(std::max(widths.size(), size_t(line.size())), 0);
        for (int c = 0; c < line.size(); ++c)
            widths[size_t(c)] = std::max(widths[size_t(c)], int(line[c].size()));
    }
    QString text;
    for (const QStringList &line : lines) {
        for (int c = 0; c < line.size(); ++c)
            text += (c == 0 ? line[c].leftJustified(widths[0])
                            : line[c].rightJustified(widths[size_t(c)] + 2));
        text += QLatin1Char('\n');
    }
    return text;
}

/** The routers of the rows, in the order they were given. */
QStringList routersOf(const std::vector<Row> &rows)
{
    QStringList routers;
    for (const Row &row : rows) {
        if (!routers.contains(row.inputs[1]))
            routers.append(row.inputs[1]);
    }
    return routers;
}

/** Metric `m` of `router`'s runs, indexed by the pairing key (every input but the router). */
std::map<QString, double> valuesOf(const std::vector<Row> &rows, const QString &router, int m)
{
    std::map<QString, double> values;
    for (const Row &row : rows) {
        if (row.inputs[1] != router)
            continue;
        QStringList key = row.inputs;
        key.removeAt(1);
        values[key.join(QLatin1Char(','))] = row.metrics[size_t(m)];
    }
    return values;
}

/** The table: a row per metric, a column per router, in the order routers were given. */
QString table(const std::vector<Row> &rows)
{
    const QStringList routers = routersOf(rows);
    std::vector<QStringList> lines;
    lines.push_back(QStringList{QStringLiteral("metric")} + routers);
    for (int m = 0; m < metricKeys().size(); ++m) {
        QStringList line{metricKeys()[m]};
        bool any = false;
        for (const QString &router : routers) {
            std::vector<double> values;
            for (const auto &[key, value] : valuesOf(rows, router, m))
                values.push_back(value);
            line.append(meanAndSd(values));
            any = any || line.last() != QStringLiteral("–");
        }
        if (any)
            lines.push_back(line);
    }
    return aligned(lines);
}

/**
 * Each router against the baseline, run by run on the same inputs (scene, operator, seed,
 * duration): per metric the mean paired difference, its bootstrap interval and the
 * signed-rank test's p, and a legend that names them.
 */
QString pairedTable(const std::vector<Row> &rows, const QString &baseline)
{
    QStringList others = routersOf(rows);
    others.removeAll(baseline);
    if (baseline.isEmpty() || others.isEmpty())
        return QString();
    std::vector<QStringList> lines;
    QStringList header{QStringLiteral("metric")};
    for (const QString &router : others)
        header << QStringLiteral("Δ %1").arg(router) << QStringLiteral("95% CI")
               << QStringLiteral("p");
    lines.push_back(header);
    int pairs = 0;
    for (int m = 0; m < metricKeys().size(); ++m) {
        if (metricSpecs()[size_t(m)]->role != MetricRole::Outcome)
            continue; // the machine's speed and the run's length, not the router's effect
        const std::map<QString, double> base = valuesOf(rows, baseline, m);
        QStringList line{metricKeys()[m]};
        bool any = false;
        for (const QString &router : others) {
            std::vector<double> a;
            std::vector<double> b;
            for (const auto &[key, value] : valuesOf(rows, router, m)) {
                const auto match = base.find(key);
                a.push_back(match == base.end() ? std::nan("") : match->second);
                b.push_back(value);
            }
            const PairedComparison c = comparePaired(a, b);
            pairs = std::max(pairs, c.pairs);
            if (c.pairs == 0) {
                line << QStringLiteral("–") << QString() << QString();
                continue;
            }
            any = true;
            const int digits =
                digitsFor(std::max(std::abs(c.interval.low), std::abs(c.interval.high)));
            line << signedFixed(c.meanDifference, digits)
                 << QStringLiteral("[%1, %2]")
                        .arg(fixed(c.interval.low, digits), fixed(c.interval.high, digits))
                 << (c.test.n == 0      ? QStringLiteral("–")
                     : c.test.p < 0.001 ? QStringLiteral("<0.001")
                                        : QString::number(c.test.p, 'f', 3));
        }
        if (any)
            lines.push_back(line);
    }
    return QStringLiteral("\nPaired with %1 (%2 runs each):\n").arg(baseline).arg(pairs) +
           aligned(lines) +
           QStringLiteral(
               "Δ: mean paired difference, router − %1, over the runs both made with the same "
               "inputs (scene, operator, seed,\nduration). 95% CI: percentile bootstrap of "
               "that mean, 10000 resamples. p: two-sided Wilcoxon signed-rank test\n(exact "
               "up to %2 non-zero differences without ties, else the normal approximation; "
               "zero differences dropped).\n")
               .arg(baseline)
               .arg(ExactLimit);
}

} // namespace

QString CompareCommand::summary() const
{
    return tr("Runs a grid of routers × seeds on a scene in parallel and prints each metric's "
              "mean ± sd per router and, against a baseline, the paired difference with its "
              "95% interval and p; writes one CSV row per run.");
}

void CompareCommand::configure(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("scene"), tr("Scene name or MJCF file."), tr("NAME|FILE")});
    parser.addOption({QStringLiteral("routers"), tr("Comma-separated routers (presets or files)."),
                      tr("LIST")});
    parser.addOption(
        {QStringLiteral("operator"),
         tr("Who drives the grippers: %1.").arg(operatorNames().join(QStringLiteral(", "))),
         tr("NAME")});
    parser.addOption({QStringLiteral("seeds"), tr("Seeds 1..N per router."), tr("N")});
    parser.addOption({QStringLiteral("duration"), tr("Simulated seconds per run."), tr("S")});
    addSceneOptions(parser);
    parser.addOption({QStringLiteral("jobs"), tr("Runs at once (default: the cores)."), tr("N")});
    parser.addOption({QStringLiteral("shard"),
                      tr("Run only slice I of N of the grid (1-based); auto: this task's slice "
                         "of a Slurm job array."),
                      tr("I/N|auto")});
    parser.addOption({QStringLiteral("csv"), tr("Where to write one row per run."), tr("FILE|-")});
    parser.addOption({QStringLiteral("resume"),
                      tr("Keep the runs a killed compare of the same grid finished (its "
                         "FILE.partial, or FILE) and do only the rest.")});
    parser.addOption({QStringLiteral("baseline"),
                      tr("The router the others are compared with, run by run (default: none, "
                         "when compared)."),
                      tr("ROUTER")});
    parser.addOption({QStringLiteral("merge"),
                      tr("Combine the CSV files given as arguments and print the table.")});
    parser.addPositionalArgument(QStringLiteral("files"), tr("CSV files, with --merge."),
                                 tr("[FILE...]"));
}

int CompareCommand::execute(const QCommandLineParser &parser)
{
    const Provenance provenance;
    if (parser.isSet(QStringLiteral("merge")))
        return merge(parser, parser.positionalArguments(), parser.value(QStringLiteral("csv")));
    if (!parser.positionalArguments().isEmpty())
        return usageError(tr("files are only taken with --merge"));
    for (const QString &required :
         {QStringLiteral("scene"), QStringLiteral("routers"), QStringLiteral("operator"),
          QStringLiteral("seeds"), QStringLiteral("duration")}) {
        if (!parser.isSet(required))
            return usageError(tr("--%1 is required").arg(required));
    }
    double seeds = 0;
    RunOptions common;
    double jobs = std::max(1u, std::thread::hardware_concurrency());
    if (!numberOption(parser, QStringLiteral("seeds"), &seeds) ||
        !simulationOptions(parser, &common) ||
        !numberOption(parser, QStringLiteral("jobs"), &jobs))
        return ExitUsage;
    if (seeds < 1 || seeds != std::floor(seeds) || seeds > 100000)
        return usageError(tr("--seeds must be a whole number from 1"));
    if (jobs < 1 || jobs != std::floor(jobs))
        return usageError(tr("--jobs must be a whole number from 1"));
    Shard shard;
    if (!shardOption(parser, &shard))
        return ExitUsage;
    const QStringList routers =
        parser.value(QStringLiteral("routers")).split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (routers.isEmpty())
        return usageError(tr("--routers lists no router"));
    QString baseline;
    if (!chooseBaseline(parser, routers, &baseline))
        return ExitUsage;

    // The grid, in a fixed order so that shard I of N is the same slice on every machine.
    std::vector<RunOptions> grid;
    int index = 0;
    for (const QString &router : routers) {
        for (int seed = 1; seed <= int(seeds); ++seed) {
            if (!shard.takes(index++))
                continue;
            RunOptions options = common;
            options.scene = parser.value(QStringLiteral("scene"));
            options.router = router;
            options.operatorName = parser.value(QStringLiteral("operator"));
            options.seed = std::uint64_t(seed);
            grid.push_back(options);
        }
    }
    // Check each router once, up front, so a typo is one message and not one per run.
    QStringList checked;
    for (const RunOptions &options : grid) {
        if (checked.contains(options.router))
            continue;
        checked.append(options.router);
        QString error;
        RunOptions probe = options;
        probe.duration = 0;
        const std::unique_ptr<SimRun> run = SimRun::create(probe, &error);
        if (!run)
            return inputError(error);
        reportWarnings(run->pipeline().router().graph());
    }

    for (const RunOptions &options : grid) {
        keepFromOutputs(options.scene, Kept::Input);
        keepFromOutputs(options.router, Kept::Input);
    }
    const QString csvPath = parser.value(QStringLiteral("csv"));
    // A journal and a sidecar only beside a regular file: not beside a pipe or a device
    // (/dev/full), whose folder is not the user's.
    const bool csvFile = parser.isSet(QStringLiteral("csv")) && csvPath != QLatin1String("-") &&
                         (!QFileInfo::exists(csvPath) || QFileInfo(csvPath).isFile());
    const bool resume = parser.isSet(QStringLiteral("resume"));
    if (resume && !csvFile)
        return usageError(tr("--resume needs --csv FILE, a regular file: the runs it keeps are "
                             "that file's"));
    QIODevice *csv = nullptr;
    QIODevice *sidecar = nullptr;
    if (parser.isSet(QStringLiteral("csv"))) {
        csv = openOutput(csvPath);
        if (!csv)
            return ExitInvalidInput;
    }
    if (csvFile) {
        sidecar = openOutput(csvPath + QStringLiteral(".provenance.json"));
        if (!sidecar)
            return ExitInvalidInput;
    }

    // A file grid's runs go to the journal as they end; resumed, the runs a killed compare
    // of this grid finished are kept, and only the rest run.
    const auto inputsOf = [](const RunOptions &options) {
        return QStringList{options.scene, options.router, options.operatorName,
                           QString::number(options.seed), QString::number(options.duration)};
    };
    std::vector<Row> rows(grid.size());
    std::vector<bool> done(grid.size(), false);
    int resumed = 0;
    Journal journal;
    if (csvFile) {
        m_journal = Journal::pathOf(csvPath);
        QString error;
        if (QFileInfo::exists(m_journal) && !resume)
            return inputError(tr("%1: is left from a compare that did not finish: --resume keeps "
                                 "its runs, or remove it")
                                  .arg(m_journal));
        for (const QString &path : {csvPath, m_journal}) {
            std::vector<Row> kept;
            if (!resume || !QFileInfo::exists(path))
                continue;
            if (!Journal::read(path, &kept, &error))
                return inputError(error);
            for (const Row &row : kept) {
                size_t i = 0;
                while (i < grid.size() && inputsOf(grid[i]) != row.inputs)
                    ++i;
                if (i == grid.size())
                    return inputError(tr("%1: has a run of another grid (%2); resume with the "
                                         "grid it was made by")
                                          .arg(path, row.inputs.join(QLatin1Char(','))));
                if (!done[i]) {
                    rows[i] = row;
                    done[i] = true;
                    ++resumed;
                }
            }
        }
        std::vector<Row> start;
        for (size_t i = 0; i < grid.size(); ++i) {
            if (done[i])
                start.push_back(rows[i]);
        }
        if (!journal.start(m_journal, start, &error))
            return inputError(error);
    }
    std::atomic<size_t> next{0};
    std::mutex failure;
    QString journalError;
    const auto worker = [&] {
        for (size_t i = next++; i < grid.size(); i = next++) {
            if (done[i])
                continue;
            const RunOptions &options = grid[i];
            QString error;
            std::unique_ptr<SimRun> run = SimRun::create(options, &error);
            RunSink sink;
            const auto start = std::chrono::steady_clock::now();
            while (run->step(sink)) {
            }
            const double wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const QJsonObject metrics = run->report(wall);
            Row row;
            row.inputs = inputsOf(options);
            for (const QString &key : metricKeys()) {
                const QJsonValue v = metrics.value(key);
                row.metrics.push_back(v.isDouble() ? v.toDouble() : std::nan(""));
            }
            rows[i] = row;
            QString written;
            if (csvFile && !journal.append(row, &written)) {
                // The rest would be lost too: stop, keeping what the journal holds.
                const std::lock_guard<std::mutex> lock(failure);
                journalError = written;
                next = grid.size();
            }
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < int(jobs); ++j)
        threads.emplace_back(worker);
    for (std::thread &thread : threads)
        thread.join();
    if (!journalError.isEmpty())
        return inputError(journalError);

    if (csv) {
        csv->write(csvHeader());
        for (const Row &row : rows)
            csv->write(csvLine(row));
    }
    if (sidecar) {
        // Where the CSV came from; the CSV itself stays a header and rows.
        QJsonObject json = provenance.toJson(true);
        json.insert(QStringLiteral("shard"), shard.text());
        json.insert(QStringLiteral("runs"), int(grid.size()));
        json.insert(QStringLiteral("resumed"), resumed);
        json.insert(
            QStringLiteral("grid"),
            QJsonObject{{QStringLiteral("scene"), parser.value(QStringLiteral("scene"))},
                        {QStringLiteral("routers"), QJsonArray::fromStringList(routers)},
                        {QStringLiteral("operator"), parser.value(QStringLiteral("operator"))},
                        {QStringLiteral("seeds"), QStringLiteral("1-%1").arg(int(seeds))},
                        {QStringLiteral("duration"), common.duration}});
        sidecar->write(QJsonDocument(json).toJson());
    }
    if (!csv || parser.value(QStringLiteral("csv")) != QLatin1String("-"))
        m_out << table(rows) << pairedTable(rows, baseline);
    return ExitOk;
}

void CompareCommand::committed()
{
    if (!m_journal.isEmpty())
        QFile::remove(m_journal);
}

bool CompareCommand::chooseBaseline(const QCommandLineParser &parser, const QStringList &routers,
                                    QString *baseline)
{
    // The default pairs with no feedback when the grid has it, and prints no pairs otherwise.
    const bool given = parser.isSet(QStringLiteral("baseline"));
    *baseline = given ? parser.value(QStringLiteral("baseline")) : QStringLiteral("none");
    if (!routers.contains(*baseline)) {
        if (given) {
            usageError(tr("--baseline %1 is not one of the routers compared (%2)")
                           .arg(*baseline, routers.join(QStringLiteral(", "))));
            return false;
        }
        baseline->clear();
    }
    return true;
}

int CompareCommand::merge(const QCommandLineParser &parser, const QStringList &files,
                          const QString &csvPath)
{
    if (files.isEmpty())
        return usageError(tr("--merge needs the CSV files to combine"));
    std::vector<Row> rows;
    for (const QString &path : files) {
        QIODevice *file = openInput(path);
        if (!file)
            return ExitInvalidInput;
        const QByteArray header = file->readLine();
        if (header != csvHeader())
            return inputError(tr("%1:1: not a semhap compare CSV (header differs)").arg(path));
        for (int line = 2; !file->atEnd(); ++line) {
            const QStringList cells =
                QString::fromUtf8(file->readLine()).trimmed().split(QLatin1Char(','));
            if (cells.size() == 1 && cells.first().isEmpty())
                continue;
            if (cells.size() != inputKeys().size() + metricKeys().size())
                return inputError(tr("%1:%2: expected %3 cells, found %4")
                                      .arg(path)
                                      .arg(line)
                                      .arg(inputKeys().size() + metricKeys().size())
                                      .arg(cells.size()));
            Row row;
            row.inputs = cells.mid(0, inputKeys().size());
            for (int c = int(inputKeys().size()); c < cells.size(); ++c) {
                bool ok = cells[c].isEmpty();
                const double value = ok ? std::nan("") : cells[c].toDouble(&ok);
                if (!ok)
                    return inputError(
                        tr("%1:%2: '%3' is not a number").arg(path).arg(line).arg(cells[c]));
                row.metrics.push_back(value);
            }
            rows.push_back(row);
        }
    }
    if (!csvPath.isEmpty()) {
        QIODevice *csv = openOutput(csvPath);
        if (!csv)
            return ExitInvalidInput;
        csv->write(csvHeader());
        for (const Row &row : rows)
            csv->write(csvLine(row));
        if (csvPath == QLatin1String("-"))
            return ExitOk;
    }
    QString baseline;
    if (!chooseBaseline(parser, routersOf(rows), &baseline))
        return ExitUsage;
    m_out << table(rows) << pairedTable(rows, baseline);
    return ExitOk;
}

} // namespace semhap
