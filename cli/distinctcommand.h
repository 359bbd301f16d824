// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap distinct`: how far apart patterns feel, in just-noticeable differences, as their
 * bands render them (docs/perception.md): the matrix of a router's messages on each band, or
 * of any patterns.
 */
class DistinctCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::DistinctCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("distinct"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;

private:
    int comparePatterns(const QString &list, double intensity, bool json);
    int compareRouter(const QString &name, double intensity, bool json);
};

} // namespace semhap
