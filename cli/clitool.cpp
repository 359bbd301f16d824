// SPDX-License-Identifier: MIT
#include "clitool.h"

#include "bandsimcommand.h"
#include "comparecommand.h"
#include "convertcommand.h"
#include "devicescommand.h"
#include "distinctcommand.h"
#include "emulatecommand.h"
#include "exportcommand.h"
#include "importcommand.h"
#include "listencommand.h"
#include "playcommand.h"
#include "rendercommand.h"
#include "replaycommand.h"
#include "routecommand.h"
#include "runcommand.h"
#include "semhaprevision.h"
#include "studycommand.h"
#include "validatecommand.h"

namespace semhap {

namespace {

const QStringList &commandNames()
{
    static const QStringList names{
        QStringLiteral("route"),   QStringLiteral("render"),  QStringLiteral("validate"),
        QStringLiteral("run"),     QStringLiteral("compare"), QStringLiteral("play"),
        QStringLiteral("devices"), QStringLiteral("emulate"), QStringLiteral("bandsim"),
        QStringLiteral("convert"), QStringLiteral("replay"),  QStringLiteral("export"),
        QStringLiteral("listen"),  QStringLiteral("import"),  QStringLiteral("study"),
        QStringLiteral("distinct")};
    return names;
}

} // namespace

std::unique_ptr<Command> CliTool::makeCommand(const QString &name) const
{
    if (name == QLatin1String("route"))
        return std::make_unique<RouteCommand>(m_io);
    if (name == QLatin1String("render"))
        return std::make_unique<RenderCommand>(m_io);
    if (name == QLatin1String("validate"))
        return std::make_unique<ValidateCommand>(m_io);
    if (name == QLatin1String("run"))
        return std::make_unique<RunCommand>(m_io);
    if (name == QLatin1String("compare"))
        return std::make_unique<CompareCommand>(m_io);
    if (name == QLatin1String("play"))
        return std::make_unique<PlayCommand>(m_io);
    if (name == QLatin1String("devices"))
        return std::make_unique<DevicesCommand>(m_io);
    if (name == QLatin1String("emulate"))
        return std::make_unique<EmulateCommand>(m_io);
    if (name == QLatin1String("bandsim"))
        return std::make_unique<BandSimCommand>(m_io);
    if (name == QLatin1String("convert"))
        return std::make_unique<ConvertCommand>(m_io);
    if (name == QLatin1String("replay"))
        return std::make_unique<ReplayCommand>(m_io);
    if (name == QLatin1String("export"))
        return std::make_unique<ExportCommand>(m_io);
    if (name == QLatin1String("listen"))
        return std::make_unique<ListenCommand>(m_io);
    if (name == QLatin1String("import"))
        return std::make_unique<ImportCommand>(m_io);
    if (name == QLatin1String("study"))
        return std::make_unique<StudyCommand>(m_io);
    if (name == QLatin1String("distinct"))
        return std::make_unique<DistinctCommand>(m_io);
    return nullptr;
}

QString CliTool::usage() const
{
    QString text = tr("Usage: semhap COMMAND [OPTIONS]\n"
                      "Semantic haptic feedback, headless: detectors, router and patterns.\n\n"
                      "Commands:\n");
    for (const QString &name : commandNames())
        text += QStringLiteral("  %1  %2\n").arg(name, -9).arg(makeCommand(name)->summary());
    text += tr("\nRun 'semhap COMMAND --help' for a command's options.\n"
               "Exit codes: 0 success, 1 invalid input, 2 usage error.\n");
    return text;
}

int CliTool::run(const QStringList &arguments)
{
    if (arguments.isEmpty()) {
        m_io.err->write(usage().toUtf8());
        return ExitUsage;
    }
    const QString &first = arguments.first();
    if (first == QLatin1String("--help") || first == QLatin1String("-h") ||
        first == QLatin1String("help")) {
        m_io.out->write(usage().toUtf8());
        return ExitOk;
    }
    if (first == QLatin1String("--version")) {
        m_io.out->write(QByteArrayLiteral("semhap " SEMHAP_VERSION " (" SEMHAP_REVISION ")\n"));
        return ExitOk;
    }
    std::unique_ptr<Command> command = makeCommand(first);
    if (!command) {
        m_io.err->write(tr("semhap: unknown command '%1'\n").arg(first).toUtf8() +
                        tr("Try 'semhap --help'.\n").toUtf8());
        return ExitUsage;
    }
    return command->run(arguments.mid(1));
}

} // namespace semhap
