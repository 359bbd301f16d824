// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/** `semhap run`: the whole pipeline on a simulated scene, headless, with task metrics. */
class RunCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::RunCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("run"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
