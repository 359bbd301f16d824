// SPDX-License-Identifier: MIT
#pragma once

#include "clitool.h"

#include <QBuffer>
#include <QStringList>

/** What `semhap ARGS` gave, run in this process: its exit code and both outputs. */
struct CliResult
{
    int code;
    QByteArray out;
    QByteArray err;
};

/** Runs `semhap ARGS` in this process (no standard input). */
inline CliResult semhapRun(const QStringList &args)
{
    CliResult r{0, {}, {}};
    QBuffer out(&r.out);
    QBuffer err(&r.err);
    out.open(QIODevice::WriteOnly);
    err.open(QIODevice::WriteOnly);
    semhap::CliTool tool({nullptr, &out, &err});
    r.code = tool.run(args);
    return r;
}
