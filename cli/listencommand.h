// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap listen`: contact frames from another program over UDP (a game engine, a robot)
 * through detectors, router and devices exactly as `route` runs them, live, optionally
 * recorded into a session with each frame's arrival time.
 */
class ListenCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::ListenCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("listen"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
