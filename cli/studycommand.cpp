// SPDX-License-Identifier: MIT
#include "studycommand.h"

#include "provenance.h"
#include "quitsignal.h"
#include "studyanalysis.h"
#include "studydatabase.h"
#include "studyexport.h"
#include "studymerge.h"
#include "studyprotocol.h"
#include "studysimulation.h"
#include "studytable.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace semhap {

namespace {

/** The most simulated participants one call adds. */
constexpr int MaxParticipants = 1000;

} // namespace

QString StudyCommand::summary() const
{
    return tr("A user study headless: simulate a protocol's participants, export a study's "
              "tidy CSV, analyze a study or a CSV.");
}

void StudyCommand::configure(QCommandLineParser &parser)
{
    parser.setApplicationDescription(tr(
        "semhap study simulate PROTOCOL --participants N --out STUDY.db [--trial-seconds S]\n"
        "                      [--operator reactive|perceiving] [--person NAME=VALUE]...\n"
        "                      [--shard I/N|auto] [--resume]\n"
        "semhap study merge OUT.db SHARD.db...\n"
        "semhap study export STUDY.db --csv DIR\n"
        "semhap study analyze STUDY.db|MEASURES.csv [--report DIR] [--json] [--measure M]...\n\n"
        "simulate: runs the protocol with simulated participants (the reactive or the\n"
        "perceiving operator, a seed each) into a new study, the questionnaires left\n"
        "unanswered. With --shard, only slice I of N of the participants (each keeps\n"
        "its name, seed and order of conditions), for a cluster's job array.\n"
        "merge: joins the shards of one simulated study into a new study OUT.db.\n"
        "export: writes DIR/measures.csv (participant,condition,trial,measure,value),\n"
        "DIR/trials.csv and DIR/answers.csv.\n"
        "analyze: the analysis of each measure (docs/studies.md) as Markdown on standard\n"
        "output, as JSON with --json, or as DIR/report.md with a box plot per measure."));
    parser.addPositionalArgument(QStringLiteral("action"),
                                 tr("simulate, merge, export or analyze"));
    parser.addPositionalArgument(
        QStringLiteral("file"),
        tr("The protocol, the study, (analyze) a tidy CSV, or (merge) the new study and its "
           "shards."));
    parser.addOption({QStringLiteral("participants"),
                      tr("simulate: how many participants (1 to %1).").arg(MaxParticipants),
                      tr("N")});
    parser.addOption(
        {QStringLiteral("out"), tr("simulate: the new study's file."), tr("STUDY.db")});
    parser.addOption({QStringLiteral("trial-seconds"),
                      tr("simulate: cap every practice round and trial at S simulated seconds."),
                      tr("S")});
    parser.addOption({QStringLiteral("operator"),
                      tr("simulate: the participants' operator, reactive (the default) or "
                         "perceiving (docs/operator.md)."),
                      tr("NAME")});
    parser.addOption({QStringLiteral("shard"),
                      tr("simulate: only slice I of N of the participants (1-based); auto: this "
                         "task's slice of a Slurm job array."),
                      tr("I/N|auto")});
    parser.addOption({QStringLiteral("resume"),
                      tr("simulate: go on with the study a killed simulation began (the runs "
                         "done stay; the rest run).")});
    parser.addOption({QStringLiteral("person"),
                      tr("simulate: set a parameter of the perceiving operator's person "
                         "(repeatable; docs/operator.md)."),
                      tr("NAME=VALUE")});
    parser.addOption(
        {QStringLiteral("csv"), tr("export: the folder of the CSV files."), tr("DIR")});
    parser.addOption({QStringLiteral("r"),
                      tr("export: write measures.csv and analysis.R, which computes the "
                         "analysis' tests in R, into DIR (docs/science.md)."),
                      tr("DIR")});
    parser.addOption({QStringLiteral("report"),
                      tr("analyze: write report.md and a box plot per measure into DIR."),
                      tr("DIR")});
    parser.addOption({QStringLiteral("json"), tr("analyze: print the statistics as JSON.")});
    parser.addOption({QStringLiteral("measure"),
                      tr("analyze: only this measure (repeatable); default: every one."),
                      tr("NAME")});
}

int StudyCommand::execute(const QCommandLineParser &parser)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty())
        return usageError(tr("an action is required: simulate, merge, export or analyze"));
    const QString action = positional.first();
    if (positional.size() < 2)
        return usageError(tr("%1 needs a file").arg(action));
    if (action == QLatin1String("merge"))
        return merge(positional.at(1), positional.mid(2));
    if (positional.size() > 2)
        return usageError(tr("unexpected argument '%1'").arg(positional.at(2)));
    if (action == QLatin1String("simulate"))
        return simulate(parser, positional.at(1));
    if (action == QLatin1String("export")) {
        const bool csv = parser.isSet(QStringLiteral("csv"));
        const bool r = parser.isSet(QStringLiteral("r"));
        if (!csv && !r)
            return usageError(tr("export needs --csv DIR or --r DIR"));
        return exportFiles(positional.at(1), csv ? parser.value(QStringLiteral("csv")) : QString(),
                           r ? parser.value(QStringLiteral("r")) : QString());
    }
    if (action == QLatin1String("analyze"))
        return analyze(parser, positional.at(1));
    return usageError(tr("unknown action '%1': simulate, merge, export or analyze").arg(action));
}

int StudyCommand::merge(const QString &out, const QStringList &shards)
{
    if (shards.isEmpty())
        return usageError(tr("merge needs the new study and its shards: OUT.db SHARD.db..."));
    for (const QString &shard : shards)
        keepFromOutputs(shard, Kept::Input);
    if (!checkOutputPath(out))
        return ExitInvalidInput;
    QString error;
    if (!StudyMerge::merge(out, shards, &error))
        return inputError(error);
    m_out << tr("%1: merged %2 shards\n").arg(out).arg(shards.size());
    return ExitOk;
}

int StudyCommand::simulate(const QCommandLineParser &parser, const QString &protocolPath)
{
    if (!parser.isSet(QStringLiteral("out")))
        return usageError(tr("simulate needs --out STUDY.db"));
    double participants = 0;
    if (!parser.isSet(QStringLiteral("participants")))
        return usageError(tr("simulate needs --participants N"));
    if (!numberOption(parser, QStringLiteral("participants"), &participants))
        return ExitUsage;
    if (participants < 1 || participants > MaxParticipants ||
        participants != std::floor(participants))
        return usageError(
            tr("--participants must be a whole number from 1 to %1").arg(MaxParticipants));
    StudySimulation::Options options;
    options.participants = int(participants);
    Shard shard;
    if (!shardOption(parser, &shard))
        return ExitUsage;
    options.shard = shard.index;
    options.shards = shard.count;
    if (parser.isSet(QStringLiteral("trial-seconds"))) {
        if (!numberOption(parser, QStringLiteral("trial-seconds"), &options.maxSeconds))
            return ExitUsage;
        if (!(options.maxSeconds > 0) || options.maxSeconds > StudyProtocol::MaxSeconds)
            return usageError(tr("--trial-seconds must be more than 0 and at most %1")
                                  .arg(StudyProtocol::MaxSeconds));
    }
    options.operatorName = parser.value(QStringLiteral("operator"));
    if (options.operatorName.isEmpty())
        options.operatorName = QStringLiteral("reactive");
    if (!StudySimulation::operatorNames().contains(options.operatorName))
        return usageError(tr("--operator must be one of %1")
                              .arg(StudySimulation::operatorNames().join(QStringLiteral(", "))));
    if (!personOptions(parser, &options.person))
        return ExitUsage;
    const QString out = parser.value(QStringLiteral("out"));
    keepFromOutputs(protocolPath, Kept::Input);
    if (!checkOutputPath(out))
        return ExitInvalidInput;
    StudyProtocol protocol;
    LoadError loadError;
    if (!StudyProtocol::read(protocolPath, &protocol, &loadError))
        return inputError(loadError.toString());
    QString error;
    options.resume = parser.isSet(QStringLiteral("resume")) && QFileInfo::exists(out);
    std::unique_ptr<StudyDatabase> study =
        options.resume ? StudyDatabase::open(out, StudyDatabase::Access::Write, &error)
                       : StudyDatabase::create(out, protocol, &error);
    if (!study)
        return inputError(error);
    // What a merge checks the shards by, and where this one came from (docs/cluster.md).
    const Provenance provenance;
    QJsonArray numbers;
    for (int number = 1; number <= options.participants; ++number) {
        if (shard.takes(number - 1))
            numbers.append(number);
    }
    QJsonObject simulation{
        {QStringLiteral("participants"), options.participants},
        {QStringLiteral("shard"), shard.text()},
        {QStringLiteral("operator"), options.operatorName},
        {QStringLiteral("trial_seconds"), options.maxSeconds},
        {QStringLiteral("person"), options.person.toJson()},
        {QStringLiteral("simulated"), numbers},
        {QStringLiteral("seeds"), QStringLiteral("participant * 100 + trial (0: practice)")},
        {QStringLiteral("attempt"), 1}};
    if (options.resume) {
        // Resumed only as it was begun: the same protocol, slice and simulation.
        const QJsonObject before =
            QJsonDocument::fromJson(study->value(QStringLiteral("simulation")).toUtf8()).object();
        if (study->value(QStringLiteral("protocol")).toUtf8() != protocol.source)
            return inputError(
                tr("%1: was simulated from another protocol than %2").arg(out, protocolPath));
        for (const QString &key :
             {QStringLiteral("participants"), QStringLiteral("shard"), QStringLiteral("operator"),
              QStringLiteral("trial_seconds"), QStringLiteral("person")}) {
            if (before.value(key) != simulation.value(key))
                return inputError(tr("%1: was simulated with another %2; resume it with the "
                                     "options it was begun with")
                                      .arg(out, key));
        }
        simulation.insert(QStringLiteral("attempt"),
                          before.value(QStringLiteral("attempt")).toInt(1) + 1);
    }
    const auto record = [&](bool ended) {
        QJsonObject json = simulation;
        json.insert(QStringLiteral("provenance"), provenance.toJson(ended));
        return study->setValue(
            QStringLiteral("simulation"),
            QString::fromUtf8(QJsonDocument(json).toJson(QJsonDocument::Compact)), &error);
    };
    if (!record(false))
        return inputError(error);
    QuitSignal::install();
    options.cancelled = [] { return QuitSignal::requested(); };
    options.progress = [&](const StudyDatabase::Trial &trial) {
        const StudyProtocol::Condition &condition = protocol.conditions[size_t(trial.condition)];
        m_out << tr("%1 %2 %3: %4 s, %5 transferred\n")
                     .arg(trial.participant, condition.id,
                          trial.practice ? QStringLiteral("practice")
                                         : QStringLiteral("trial %1").arg(trial.number))
                     .arg(trial.seconds, 0, 'f', 1)
                     .arg(StudyProtocol::transfers(trial.metrics));
        flushOutputs(); // a pipe sees each run as it ends
    };
    if (!StudySimulation::run(*study, options, &error) || !record(true))
        return inputError(error);
    m_out << tr("%1: %2 simulated %3, %4 runs (sessions in %5)\n")
                 .arg(out)
                 .arg(numbers.size())
                 .arg(numbers.size() == 1 ? tr("participant") : tr("participants"))
                 .arg(study->trials().size())
                 .arg(StudyDatabase::sessionsFolder(out).section(QLatin1Char('/'), -1));
    return ExitOk;
}

int StudyCommand::exportFiles(const QString &path, const QString &csvDir, const QString &rDir)
{
    QString error;
    std::unique_ptr<StudyDatabase> study =
        StudyDatabase::open(path, StudyDatabase::Access::Read, &error);
    if (!study)
        return inputError(error);
    keepFromOutputs(path, Kept::Input);
    // Every file made before any is written: a study that reads short writes nothing.
    std::vector<StudyExport::File> csv, r;
    if (!csvDir.isEmpty() && (csv = StudyExport::results(*study, &error)).empty())
        return inputError(error);
    if (!rDir.isEmpty() && (r = StudyExport::rAnalysis(*study, &error)).empty())
        return inputError(error);
    return (csv.empty() || writeFiles(csvDir, csv)) && (r.empty() || writeFiles(rDir, r))
               ? ExitOk
               : ExitInvalidInput;
}

bool StudyCommand::writeFiles(const QString &dir, const std::vector<StudyExport::File> &files)
{
    for (const StudyExport::File &file : files) {
        QIODevice *out = openOutputIn(dir, file.name);
        if (!out)
            return false;
        out->write(file.bytes);
    }
    return true;
}

int StudyCommand::analyze(const QCommandLineParser &parser, const QString &input)
{
    StudyTable table;
    QString name;
    if (input.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) {
        LoadError loadError;
        if (!StudyTable::readCsv(input, &table, &loadError))
            return inputError(loadError.toString());
        name = QFileInfo(input).fileName();
    } else {
        QString error;
        std::unique_ptr<StudyDatabase> study =
            StudyDatabase::open(input, StudyDatabase::Access::Read, &error);
        if (!study)
            return inputError(error);
        table = StudyTable::fromStudy(*study);
        if (!study->readError().isEmpty())
            return inputError(study->readError());
        name = study->protocol().name;
    }
    keepFromOutputs(input, Kept::Input);
    QStringList measures = parser.values(QStringLiteral("measure"));
    measures.removeDuplicates();
    const QStringList known = table.measures();
    for (const QString &measure : measures) {
        if (!known.contains(measure))
            return inputError(tr("%1: no measure '%2' (measures: %3)")
                                  .arg(input, measure, known.join(QStringLiteral(", "))));
    }
    StudyAnalysis analysis = StudyAnalysis::run(table, measures);
    analysis.source = QFileInfo(input).fileName();
    analysis.name = name;
    if (parser.isSet(QStringLiteral("report")) &&
        !writeFiles(parser.value(QStringLiteral("report")), StudyExport::report(analysis)))
        return ExitInvalidInput;
    if (parser.isSet(QStringLiteral("json")))
        m_out << QJsonDocument(analysis.toJson()).toJson(QJsonDocument::Indented);
    else if (!parser.isSet(QStringLiteral("report")))
        m_out << QString::fromUtf8(analysis.markdown());
    return ExitOk;
}

} // namespace semhap
