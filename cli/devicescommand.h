// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap devices`: the transports semhap knows and the ports and HID devices present; with
 * --probe, what one band says about itself.
 */
class DevicesCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::DevicesCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("devices"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;

private:
    /** Prints what the band at `uri` answers (--probe); an exit code. */
    int probe(const QString &uri);
};

} // namespace semhap
