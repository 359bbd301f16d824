// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * `semhap convert IN OUT`: between semhap patterns and the haptic files users already have
 * (AHAP, Meta `.haptic`, MPEG haptics `.hjif`), the formats told by the file extensions;
 * `semhap convert --router R OUT.hjif`: a router's messages as an HJIF effect library.
 */
class ConvertCommand : public Command
{
    Q_DECLARE_TR_FUNCTIONS(semhap::ConvertCommand)

public:
    using Command::Command;
    QString name() const override { return QStringLiteral("convert"); }
    QString summary() const override;

protected:
    void configure(QCommandLineParser &parser) override;
    int execute(const QCommandLineParser &parser) override;
};

} // namespace semhap
