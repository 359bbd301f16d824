// SPDX-License-Identifier: MIT
#include "comparecommand.h"

#include "simrun.h"

#include <QFile>
#include <QJsonObject>
#include <QRegularExpression>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <thread>

namespace semhap {

namespace {

// The metrics a comparison reports, in table order; inputs come first in the CSV.
const QStringList &metricKeys()
{
    static const QStringList keys{QStringLiteral("cubes_transferred"),
                                  QStringLiteral("cubes_dropped"),
                                  QStringLiteral("cubes_broken"),
                                  QStringLiteral("grasps"),
                                  QStringLiteral("average_grasp_force"),
                                  QStringLiteral("grasps_per_transfer"),
                                  QStringLiteral("average_peak_grasp_force"),
                                  QStringLiteral("containers_dropped"),
                                  QStringLiteral("transfers_per_container_cycle"),
                                  QStringLiteral("warning_lead_time"),
                                  QStringLiteral("breaks_warned_share"),
                                  QStringLiteral("breaks_warned_in_time_share"),
                                  QStringLiteral("drop_warning_lead_time"),
                                  QStringLiteral("drops_warned_share"),
                                  QStringLiteral("drops_warned_in_time_share"),
                                  QStringLiteral("confirmations_per_grasp"),
                                  QStringLiteral("slip_episodes"),
                                  QStringLiteral("warnings_per_slip_episode"),
                                  QStringLiteral("box_refills"),
                                  QStringLiteral("realtime_factor")};
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

/** Mean ± sd of the non-null values, as the table prints it. */
QString summarise(const std::vector<double> &values)
{
    double sum = 0;
    int n = 0;
    for (double v : values) {
        if (!std::isnan(v)) {
            sum += v;
            ++n;
        }
    }
    if (n == 0)
        return QStringLiteral("–");
    const double mean = sum / n;
    double squares = 0;
    for (double v : values) {
        if (!std::isnan(v))
            squares += (v - mean) * (v - mean);
    }
    const double sd = n > 1 ? std::sqrt(squares / (n - 1)) : 0.0;
    const int digits = std::abs(mean) >= 100 ? 0 : (std::abs(mean) >= 10 ? 1 : 2);
    return QStringLiteral("%1 ± %2").arg(mean, 0, 'f', digits).arg(sd, 0, 'f', digits);
}

/** The table: a row per metric, a column per router, in the order routers were given. */
QString table(const std::vector<Row> &rows)
{
    QStringList routers;
    for (const Row &row : rows) {
        if (!routers.contains(row.inputs[1]))
            routers.append(row.inputs[1]);
    }
    std::vector<QStringList> lines;
    lines.push_back(QStringList{QStringLiteral("metric")} + routers);
    for (int m = 0; m < metricKeys().size(); ++m) {
        QStringList line{metricKeys()[m]};
        bool any = false;
        for (const QString &router : routers) {
            std::vector<double> values;
            for (const Row &row : rows) {
                if (row.inputs[1] == router)
                    values.push_back(row.metrics[size_t(m)]);
            }
            line.append(summarise(values));
            any = any || line.last() != QStringLiteral("–");
        }
        if (any)
            lines.push_back(line);
    }
    std::vector<int> widths(size_t(routers.size() + 1), 0);
    for (const QStringList &line : lines) {
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

} // namespace

QString CompareCommand::summary() const
{
    return tr("Runs a grid of routers × seeds on a scene in parallel and prints each metric's "
              "mean ± sd per router; writes one CSV row per run.");
}

void CompareCommand::configure(QCommandLineParser &parser)
{
    parser.addOption({QStringLiteral("scene"), tr("Scene name or MJCF file."), tr("NAME|FILE")});
    parser.addOption({QStringLiteral("routers"), tr("Comma-separated routers (presets or files)."),
                      tr("LIST")});
    parser.addOption({QStringLiteral("operator"), tr("scripted or reactive."), tr("NAME")});
    parser.addOption({QStringLiteral("seeds"), tr("Seeds 1..N per router."), tr("N")});
    parser.addOption({QStringLiteral("duration"), tr("Simulated seconds per run."), tr("S")});
    parser.addOption(
        {QStringLiteral("cubes"), tr("Cubes in play (default: the scene's)."), tr("N")});
    parser.addOption({QStringLiteral("jobs"), tr("Runs at once (default: the cores)."), tr("N")});
    parser.addOption({QStringLiteral("shard"),
                      tr("Run only slice I of N of the grid (1-based), for job arrays."),
                      tr("I/N")});
    parser.addOption({QStringLiteral("csv"), tr("Where to write one row per run."), tr("FILE|-")});
    parser.addOption({QStringLiteral("merge"),
                      tr("Combine the CSV files given as arguments and print the table.")});
    parser.addPositionalArgument(QStringLiteral("files"), tr("CSV files, with --merge."),
                                 tr("[FILE...]"));
}

int CompareCommand::execute(const QCommandLineParser &parser)
{
    if (parser.isSet(QStringLiteral("merge")))
        return merge(parser.positionalArguments(), parser.value(QStringLiteral("csv")));
    if (!parser.positionalArguments().isEmpty())
        return usageError(tr("files are only taken with --merge"));
    for (const QString &required :
         {QStringLiteral("scene"), QStringLiteral("routers"), QStringLiteral("operator"),
          QStringLiteral("seeds"), QStringLiteral("duration")}) {
        if (!parser.isSet(required))
            return usageError(tr("--%1 is required").arg(required));
    }
    double seeds = 0;
    double duration = 0;
    double cubes = -1;
    double jobs = std::max(1u, std::thread::hardware_concurrency());
    if (!numberOption(parser, QStringLiteral("seeds"), &seeds) ||
        !numberOption(parser, QStringLiteral("duration"), &duration) ||
        !numberOption(parser, QStringLiteral("cubes"), &cubes) ||
        !numberOption(parser, QStringLiteral("jobs"), &jobs))
        return ExitUsage;
    if (seeds < 1 || seeds != std::floor(seeds) || seeds > 100000)
        return usageError(tr("--seeds must be a whole number from 1"));
    if (duration <= 0)
        return usageError(tr("--duration must be positive"));
    if (jobs < 1 || jobs != std::floor(jobs))
        return usageError(tr("--jobs must be a whole number from 1"));
    int shard = 1;
    int shards = 1;
    if (parser.isSet(QStringLiteral("shard"))) {
        const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("^(\\d+)/(\\d+)$"))
                                              .match(parser.value(QStringLiteral("shard")));
        shard = m.captured(1).toInt();
        shards = m.captured(2).toInt();
        if (!m.hasMatch() || shards < 1 || shard < 1 || shard > shards)
            return usageError(tr("--shard expects I/N with 1 <= I <= N, e.g. 3/10"));
    }
    const QStringList routers =
        parser.value(QStringLiteral("routers")).split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (routers.isEmpty())
        return usageError(tr("--routers lists no router"));

    // The grid, in a fixed order so that shard I of N is the same slice on every machine.
    std::vector<RunOptions> grid;
    int index = 0;
    for (const QString &router : routers) {
        for (int seed = 1; seed <= int(seeds); ++seed) {
            if (index++ % shards != shard - 1)
                continue;
            RunOptions options;
            options.scene = parser.value(QStringLiteral("scene"));
            options.router = router;
            options.operatorName = parser.value(QStringLiteral("operator"));
            options.seed = std::uint64_t(seed);
            options.duration = duration;
            options.sceneOptions.cubes = int(cubes);
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
        if (!SimRun::create(probe, &error))
            return inputError(error);
    }

    QIODevice *csv = nullptr;
    if (parser.isSet(QStringLiteral("csv"))) {
        csv = openOutput(parser.value(QStringLiteral("csv")));
        if (!csv)
            return ExitInvalidInput;
    }
    std::vector<Row> rows(grid.size());
    std::atomic<size_t> next{0};
    const auto worker = [&] {
        for (size_t i = next++; i < grid.size(); i = next++) {
            const RunOptions &options = grid[i];
            QString error;
            std::unique_ptr<SimRun> run = SimRun::create(options, &error);
            RunSink sink;
            const auto start = std::chrono::steady_clock::now();
            while (run->step(sink)) {
            }
            const double wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            QJsonObject metrics = run->metrics();
            metrics.insert(QStringLiteral("realtime_factor"), run->time() / std::max(wall, 1e-9));
            Row row;
            row.inputs = {options.scene, options.router, options.operatorName,
                          QString::number(options.seed), QString::number(options.duration)};
            for (const QString &key : metricKeys()) {
                const QJsonValue v = metrics.value(key);
                row.metrics.push_back(v.isDouble() ? v.toDouble() : std::nan(""));
            }
            rows[i] = row;
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < int(jobs); ++j)
        threads.emplace_back(worker);
    for (std::thread &thread : threads)
        thread.join();

    if (csv) {
        csv->write(csvHeader());
        for (const Row &row : rows)
            csv->write(csvLine(row));
    }
    if (!csv || parser.value(QStringLiteral("csv")) != QLatin1String("-"))
        m_out << table(rows);
    return ExitOk;
}

int CompareCommand::merge(const QStringList &files, const QString &csvPath)
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
    m_out << table(rows);
    return ExitOk;
}

} // namespace semhap
