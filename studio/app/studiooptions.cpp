// SPDX-License-Identifier: MIT
#include "studiooptions.h"

#include "sessioninfo.h"

#include <QCommandLineParser>
#include <QSize>

namespace semhap {

namespace {

/** The studio runs until the user stops it; a day is longer than any session. */
constexpr double StudioDuration = 24 * 3600.0;

} // namespace

bool StudioOptions::parse(const QStringList &args, StudioOptions *options, QString *message,
                          bool *help)
{
    *help = false;
    StudioOptions o;
    o.run.duration = StudioDuration;
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("semhap studio: watch and tune semantic haptic feedback on a simulated task."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption versionOption = parser.addVersionOption();
    const QCommandLineOption scene({QStringLiteral("scene")},
                                   tr("Scene: a bundled name or an MJCF file."), tr("scene"),
                                   o.run.scene);
    const QCommandLineOption router({QStringLiteral("router")},
                                    tr("Router: a preset name or a semhap.router/1 file."),
                                    tr("router"), o.run.router);
    const QCommandLineOption op({QStringLiteral("operator")},
                                tr("Who drives until you do: scripted, reactive or perceiving."),
                                tr("name"), o.run.operatorName);
    const QCommandLineOption person(
        {QStringLiteral("person")},
        tr("Set a parameter of the perceiving operator's person (repeatable)."),
        tr("NAME=VALUE"));
    const QCommandLineOption seed({QStringLiteral("seed")}, tr("The operator's seed."), tr("n"),
                                  QString::number(o.run.seed));
    const QCommandLineOption reactionTime(
        {QStringLiteral("reaction-time")},
        tr("Reaction time in seconds of the operator and of the person the router's predict "
           "nodes warn."),
        tr("seconds"), QString::number(o.run.reactionTime));
    const QCommandLineOption cubes({QStringLiteral("cubes")},
                                   tr("Cubes in play (default: the scene's)."), tr("n"));
    const QCommandLineOption gripper(
        {QStringLiteral("gripper")},
        tr("A gripper adapter, by name or as a semhap.gripper/1 file, whose model takes the "
           "place of the scene's grippers (default: the scene's own)."),
        tr("gripper"));
    const QCommandLineOption speed({QStringLiteral("speed")},
                                   tr("Simulated seconds per real second."), tr("factor"),
                                   QStringLiteral("1"));
    const QCommandLineOption paused({QStringLiteral("paused")}, tr("Open paused."));
    const QCommandLineOption screenshot({QStringLiteral("screenshot")},
                                        tr("Grab the whole window to this PNG, then quit."),
                                        tr("file.png"));
    const QCommandLineOption quitAfter({QStringLiteral("quit-after")},
                                       tr("Grab (with --screenshot) and quit after this "
                                          "many seconds."),
                                       tr("seconds"));
    const QCommandLineOption size({QStringLiteral("size")}, tr("Window size, e.g. 1280x800."),
                                  tr("WxH"));
    const QCommandLineOption language({QStringLiteral("language")},
                                      tr("User interface language: en or de."), tr("code"));
    const QCommandLineOption posePort({QStringLiteral("pose-port")},
                                      tr("UDP port of the network pose input (0: off)."),
                                      tr("port"), QString::number(o.posePort));
    const QCommandLineOption listen({QStringLiteral("listen")},
                                    tr("Start on a live rig: contact frames over UDP on this "
                                       "port (ADDRESS:PORT to listen beyond this machine)."),
                                    tr("[address:]port"));
    const QCommandLineOption defaultLayout({QStringLiteral("default-layout")},
                                           tr("Ignore the saved window layout."));
    const QCommandLineOption study({QStringLiteral("study")},
                                   tr("Open this study (a study database) in study mode."),
                                   tr("STUDY.db"));
    const QCommandLineOption participant({QStringLiteral("participant")},
                                         tr("With --study: the participant to work with."),
                                         tr("id"));
    const QCommandLineOption startStep({QStringLiteral("start-step")},
                                       tr("With --participant: start their next step at once "
                                          "(for scripts and tests)."));
    parser.addOptions({scene, router, op, person, seed, reactionTime, cubes, gripper, speed, paused,
                       screenshot, quitAfter, size, language, posePort, listen, defaultLayout,
                       study, participant, startStep});
    if (!parser.parse(QStringList(QCoreApplication::applicationFilePath()) + args)) {
        *message = parser.errorText();
        return false;
    }
    if (parser.isSet(helpOption) || parser.isSet(versionOption)) {
        *help = true;
        *message = parser.isSet(helpOption)
                       ? parser.helpText()
                       : QCoreApplication::applicationName() + QLatin1Char(' ') +
                             QCoreApplication::applicationVersion() + QLatin1Char('\n');
        return false;
    }
    if (!parser.positionalArguments().isEmpty()) {
        *message = tr("unexpected argument '%1'").arg(parser.positionalArguments().first());
        return false;
    }

    // One reader for every number, so each bad value is reported the same way.
    const auto number = [&](const QCommandLineOption &option, double low, double high,
                            double *value) {
        bool ok = false;
        const QString text = parser.value(option);
        const double v = text.toDouble(&ok);
        if (!ok || !(v >= low && v <= high)) {
            *message = tr("--%1: expected a number from %2 to %3, got '%4'")
                           .arg(option.names().first())
                           .arg(low)
                           .arg(high)
                           .arg(text);
            return false;
        }
        *value = v;
        return true;
    };
    o.run.scene = parser.value(scene);
    o.run.router = parser.value(router);
    o.run.operatorName = parser.value(op);
    for (const QString &assignment : parser.values(person)) {
        QString reason;
        if (!o.run.person.set(assignment, &reason)) {
            *message = QStringLiteral("--person ") + reason;
            return false;
        }
    }
    double value = 0.0;
    if (!number(seed, 0, RunOptions::MaxSeed, &value))
        return false;
    o.run.seed = std::uint64_t(value);
    if (!number(reactionTime, 0, SessionInfo::MaxReactionTime, &o.run.reactionTime))
        return false;
    if (parser.isSet(cubes)) {
        if (!number(cubes, 0, RunOptions::MaxCubes, &value))
            return false;
        o.run.sceneOptions.cubes = int(value);
    }
    o.run.sceneOptions.gripper = parser.value(gripper);
    if (!number(speed, 0.01, 100, &o.speed))
        return false;
    o.autoRun = !parser.isSet(paused);
    o.screenshot = parser.value(screenshot);
    if (parser.isSet(quitAfter) && !number(quitAfter, 0, 1e6, &o.quitAfter))
        return false;
    if (!o.screenshot.isEmpty() && o.quitAfter < 0)
        o.quitAfter = 3.0; // a screenshot alone means "grab once it has run a moment"
    if (parser.isSet(size)) {
        const QStringList parts = parser.value(size).split(QLatin1Char('x'));
        const int w = parts.size() == 2 ? parts[0].toInt() : 0;
        const int h = parts.size() == 2 ? parts[1].toInt() : 0;
        if (w < 320 || h < 240 || w > 10000 || h > 10000) {
            *message = tr("--size: expected WIDTHxHEIGHT such as 1280x800, got '%1'")
                           .arg(parser.value(size));
            return false;
        }
        o.size = QSize(w, h);
    }
    o.language = parser.value(language);
    if (!o.language.isEmpty() && o.language != QLatin1String("en") &&
        o.language != QLatin1String("de")) {
        *message = tr("--language: expected en or de, got '%1'").arg(o.language);
        return false;
    }
    if (!number(posePort, 0, 65535, &value))
        return false;
    o.posePort = int(value);
    if (parser.isSet(listen)) {
        const QString text = parser.value(listen);
        const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
        bool ok = false;
        const int port = text.mid(colon + 1).toInt(&ok);
        if (!ok || port < 0 || port > 65535 || colon == 0) {
            *message = tr("--listen: expected a port or ADDRESS:PORT such as 9871 or "
                          "0.0.0.0:9871, got '%1'")
                           .arg(text);
            return false;
        }
        o.live = true;
        o.liveRig.port = port;
        if (colon > 0)
            o.liveRig.address = text.left(colon);
        o.liveRig.router = o.run.router;
    }
    o.restoreLayout = !parser.isSet(defaultLayout);
    o.study = parser.value(study);
    o.participant = parser.value(participant);
    o.startStep = parser.isSet(startStep);
    if ((!o.participant.isEmpty() && o.study.isEmpty()) ||
        (o.startStep && o.participant.isEmpty())) {
        *message = o.startStep && o.participant.isEmpty()
                       ? tr("--start-step: name the participant with --participant")
                       : tr("--participant: name the study with --study");
        return false;
    }
    for (const QCommandLineOption *option :
         {&scene, &router, &op, &person, &seed, &reactionTime, &cubes, &gripper, &listen})
        o.runGiven = o.runGiven || parser.isSet(*option);
    *options = o;
    return true;
}

} // namespace semhap
