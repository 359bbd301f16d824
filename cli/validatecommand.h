// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

class Router;

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

private:
    /** Warns of the messages a router plays on one band that a person will confuse. */
    void reportConfusable(const QString &path, const Router &router);
};

} // namespace semhap
