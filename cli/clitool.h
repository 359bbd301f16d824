// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace semhap {

/**
 * The `semhap` tool: picks the subcommand named by the first argument and runs it. Kept out
 * of main() so tests can run whole command lines in-process.
 */
class CliTool
{
    Q_DECLARE_TR_FUNCTIONS(semhap::CliTool)

public:
    explicit CliTool(const CommandIo &io) : m_io(io) {}
    /** Runs `semhap ARGS...` (arguments without the program name); returns the exit code. */
    int run(const QStringList &arguments);

private:
    std::unique_ptr<Command> makeCommand(const QString &name) const;
    QString usage() const;

    CommandIo m_io;
};

} // namespace semhap
