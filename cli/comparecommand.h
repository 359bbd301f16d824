// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap compare`: a grid of headless runs (routers × seeds), in parallel, summarised as
 * each metric's mean ± sd per router — the paper's studies, headless. `--shard I/N` runs one
 * slice for a job array; `--merge` combines the slices' CSVs.
 */
class CompareCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::CompareCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("compare"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
    /** The CSV is whole: the journal of its runs goes. */
    void committed() override;

private:
    QString m_journal; ///< the journal of this run's rows, removed once the CSV is whole
    int merge(const QCommandLineParser &parser, const QStringList &files, const QString &csvPath);
    /** The --baseline among `routers` (empty: none to pair with); false after a usage error. */
    bool chooseBaseline(const QCommandLineParser &parser, const QStringList &routers,
                        QString *baseline);
};

} // namespace semhap
