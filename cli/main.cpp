// SPDX-License-Identifier: MIT
// semhap: the headless command line (route, render, validate, ...).
#include "clitool.h"

#include <QCoreApplication>
#include <QFile>

#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("semhap"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SEMHAP_VERSION));

    QFile in;
    QFile out;
    QFile err;
    if (!in.open(stdin, QIODevice::ReadOnly) || !out.open(stdout, QIODevice::WriteOnly) ||
        !err.open(stderr, QIODevice::WriteOnly | QIODevice::Unbuffered))
        return 2;
    semhap::CliTool tool({&in, &out, &err});
    const int code = tool.run(QCoreApplication::arguments().mid(1));
    out.flush();
    return code;
}
