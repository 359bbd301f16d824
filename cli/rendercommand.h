// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/** `semhap render`: a pattern's lifecycle sampled to CSV, from begin to an optional end. */
class RenderCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::RenderCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("render"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
