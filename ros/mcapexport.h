// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "topicmap.h"

#include <QString>

class QIODevice;

namespace semhap {

class SessionReader;

/**
 * A session as MCAP for the lab's viewers (Foxglove, PlotJuggler, Rerun, `ros2 bag info`):
 * every frame, none decimated, on SemhapMessages' topics, as ROS 2 messages in CDR with
 * their `ros2msg` schemas. The same mapping read the other way, topicMap(), imports an
 * export again.
 *
 * Times are the session's start (its UTC clock) plus each row's t; the Metadata record
 * `semhap` keeps that start as `time_origin` (ns), so an import counts t from it again.
 * Metadata `router` holds the router's JSON, `scene` the scene.
 */
class McapExport
{
public:
    /** Writes `session` to `out`; false with `error` (the session's or the device's). */
    static bool write(SessionReader &session, QIODevice *out, QString *error);

    /** The map of an export's topics back to contact frames, for `import --topics semhap`. */
    static TopicMap topicMap();
};

} // namespace semhap
