// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

class SessionReader;

/**
 * `semhap export`: a session as files other tools read — CSV, one file per stream (pandas,
 * PlotJuggler), or JSON Lines in the spec's stream formats.
 */
class ExportCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::ExportCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("export"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;

private:
    bool exportCsv(SessionReader &session, const QString &dir);
    bool exportJsonLines(SessionReader &session, const QString &dir);
};

} // namespace semhap
