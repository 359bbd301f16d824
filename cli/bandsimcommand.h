// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap bandsim`: a reference band's real firmware image on a simulated chip, on a pty,
 * until SIGINT/SIGTERM.
 */
class BandSimCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::BandSimCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("bandsim"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
