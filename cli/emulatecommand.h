// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/** `semhap emulate`: a wristband in software on a pty or a UDP port, until SIGINT/SIGTERM. */
class EmulateCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::EmulateCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("emulate"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
