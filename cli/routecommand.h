// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/** `semhap route`: contact frames through detectors, router and player on a virtual clock. */
class RouteCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::RouteCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("route"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
