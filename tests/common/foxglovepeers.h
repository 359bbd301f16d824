// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>

/**
 * The reference robot (tests/interop/foxglove-robot.mjs, @foxglove/ws-protocol's
 * FoxgloveServer playing the grasp), started with `args`; its port, or 0. Needs SEMHAP_NODE
 * and SEMHAP_INTEROP_TOOLS.
 */
inline int startRobot(QProcess &robot, const QStringList &args)
{
    robot.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    robot.start(QStringLiteral(SEMHAP_NODE),
                QStringList{QStringLiteral(SEMHAP_INTEROP_TOOLS "/foxglove-robot.mjs")} + args);
    if (!robot.waitForReadyRead(30000))
        return 0;
    return QJsonDocument::fromJson(robot.readLine()).object().value("port").toInt();
}

/**
 * The reference Foxglove viewer (tests/interop/foxglove-viewer.mjs, @foxglove/ws-protocol's
 * FoxgloveClient), started on `url`: it waits for the server to come, subscribes to every
 * channel ("subscribed TOPIC" lines) and decodes every message.
 */
inline void startViewer(QProcess &viewer, const QString &url, const QStringList &more = {})
{
    viewer.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    viewer.start(QStringLiteral(SEMHAP_NODE),
                 QStringList{QStringLiteral(SEMHAP_INTEROP_TOOLS "/foxglove-viewer.mjs"), url} +
                     more);
}

/** Reads the viewer's output until it has said `line` (or 30 s passed); all it said. */
inline QByteArray waitForViewer(QProcess &viewer, const QByteArray &line)
{
    QByteArray said;
    while (!said.contains(QByteArray(line + '\n')) && viewer.waitForReadyRead(30000))
        said += viewer.readAllStandardOutput();
    return said;
}

/** What the viewer printed when its server closed: topics with counts, first and last. */
inline QJsonObject viewed(QProcess &viewer)
{
    // waitForFinished() is false for a process that has finished already.
    if (viewer.state() != QProcess::NotRunning && !viewer.waitForFinished(30000))
        return {};
    const QList<QByteArray> lines = viewer.readAllStandardOutput().trimmed().split('\n');
    return QJsonDocument::fromJson(lines.last()).object();
}
