// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap import`: a robot's recording (rosbag2 in MCAP) made into a session through a
 * topic map, routed as `route` routes it, so that the studio opens, replays, scrubs and
 * re-routes it as any recorded session.
 */
class ImportCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::ImportCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("import"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
