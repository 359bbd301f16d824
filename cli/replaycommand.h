// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap replay`: a recorded session's contact frames through its own router or another —
 * the offline A/B of two feedback designs on the same recorded motion.
 */
class ReplayCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::ReplayCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("replay"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
