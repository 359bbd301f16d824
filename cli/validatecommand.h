// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/** `semhap validate`: checks pattern, router, device model and scene files. */
class ValidateCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::ValidateCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("validate"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
