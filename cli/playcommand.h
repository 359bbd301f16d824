// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap play`: a pattern's whole lifecycle in real time on a device — begin at 0, end at
 * --release-at, stop-all at the end — the designer's audition from the command line.
 */
class PlayCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::PlayCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("play"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
