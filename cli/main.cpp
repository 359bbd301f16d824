// SPDX-License-Identifier: MIT
// semhap: the headless command line (route, render, validate, ...).
#include "clitool.h"
#include "outputfile.h"

#include <QCoreApplication>
#include <QFile>

#include <csignal>
#include <cstdio>
#include <unistd.h>

int main(int argc, char *argv[])
{
    // A file over the size limit is a write error to report, like a full disk, not a kill.
    std::signal(SIGXFSZ, SIG_IGN);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("semhap"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SEMHAP_VERSION));

    QFile in;
    QFile err;
    if (!in.open(stdin, QIODevice::ReadOnly) ||
        !err.open(stderr, QIODevice::WriteOnly | QIODevice::Unbuffered))
        return 2;
    // Standard output keeps every write error, so a full disk or a closed pipe is reported.
    const std::unique_ptr<semhap::OutputFile> out =
        semhap::OutputFile::forDescriptor(STDOUT_FILENO, QStringLiteral("standard output"));
    int code = 0;
    {
        semhap::CliTool tool({&in, out->device(), &err, out.get()});
        code = tool.run(QCoreApplication::arguments().mid(1));
    }
    semhap::LoadError error;
    if (!out->commit(&error)) {
        err.write(error.toString().toUtf8() + '\n');
        code = 1;
    }
    return code;
}
