// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"
#include "studyexport.h"

namespace semhap {

/**
 * `semhap study`: a user study headless (docs/studies.md) — `simulate` runs a protocol with
 * simulated participants into a new study, `export` writes a study's tidy CSV, `analyze`
 * runs the analysis on a study or a tidy CSV.
 */
class StudyCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::StudyCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("study"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;

private:
    int simulate(const QCommandLineParser &parser, const QString &protocol);
    /** Joins the shards of a simulated study into `out`. */
    int merge(const QString &out, const QStringList &shards);
    /** `study export`: the CSV files into `csvDir`, the R analysis into `rDir` (each if given). */
    int exportFiles(const QString &study, const QString &csvDir, const QString &rDir);
    int analyze(const QCommandLineParser &parser, const QString &input);
    /** Writes `files` into the folder `dir`; false after an error line. */
    bool writeFiles(const QString &dir, const std::vector<StudyExport::File> &files);
};

} // namespace semhap
