// SPDX-License-Identifier: MIT
#include "command.h"

#include <QFile>

#include <cmath>

namespace semhap {

Command::Command(const CommandIo &io) : m_io(io), m_out(io.out) {}

Command::~Command()
{
    m_out.flush();
}

int Command::run(const QStringList &arguments)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(summary());
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  tr("Show this help."));
    parser.addOption(help);
    configure(parser);

    if (!parser.parse(QStringList{QStringLiteral("semhap")} + arguments))
        return usageError(parser.errorText());
    if (parser.isSet(help)) {
        // Qt names the program after argv[0]; users call it `semhap COMMAND`.
        QString text = parser.helpText();
        const int programEnd = int(text.indexOf(QLatin1Char(' '), 7));
        if (text.startsWith(QLatin1String("Usage: ")) && programEnd > 0)
            text.replace(7, programEnd - 7, QStringLiteral("semhap ") + name());
        m_out << text;
        m_out.flush();
        return ExitOk;
    }
    const int code = execute(parser);
    m_out.flush();
    return code;
}

int Command::usageError(const QString &message)
{
    report(QStringLiteral("semhap %1: %2").arg(name(), message));
    report(tr("Try 'semhap %1 --help'.").arg(name()));
    return ExitUsage;
}

int Command::inputError(const QString &line)
{
    report(line);
    return ExitInvalidInput;
}

void Command::report(const QString &line)
{
    m_io.err->write(line.toUtf8() + '\n');
}

bool Command::numberOption(const QCommandLineParser &parser, const QString &option, double *value)
{
    if (!parser.isSet(option))
        return true;
    bool ok = false;
    const double parsed = parser.value(option).toDouble(&ok);
    if (!ok || !std::isfinite(parsed)) {
        usageError(tr("--%1 expects a number, got '%2'").arg(option, parser.value(option)));
        return false;
    }
    *value = parsed;
    return true;
}

QIODevice *Command::openOutput(const QString &path)
{
    if (path == QLatin1String("-"))
        return m_io.out;
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        inputError(tr("%1: cannot write: %2").arg(path, file->errorString()));
        return nullptr;
    }
    m_files.push_back(std::move(file));
    return m_files.back().get();
}

QIODevice *Command::openInput(const QString &path)
{
    if (path == QLatin1String("-"))
        return m_io.in;
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::ReadOnly)) {
        inputError(tr("%1: cannot read: %2").arg(path, file->errorString()));
        return nullptr;
    }
    m_files.push_back(std::move(file));
    return m_files.back().get();
}

bool Command::checkSingleStdout(const QStringList &outputs)
{
    if (outputs.count(QStringLiteral("-")) <= 1)
        return true;
    usageError(tr("at most one output may be '-' (standard output)"));
    return false;
}

} // namespace semhap
