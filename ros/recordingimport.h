// SPDX-License-Identifier: MIT
#pragma once

#include "sessioninfo.h"

#include <QString>

#include <functional>
#include <memory>

namespace semhap {

class Router;

/**
 * A robot's recording made into a session (`semhap import`, the studio's File → Open): its
 * frames through the topic map, routed by the router, recorded with their events and
 * device frames. The recording is checked whole before the session is made, and nothing is
 * dropped: the import waits for the disk.
 */
class RecordingImport
{
public:
    struct Result
    {
        long long frames = 0;
        double startTime = 0.0; ///< the recording's time of the session's t = 0 (s)
        bool cancelled = false;
        QString error; ///< located, as the readers and the session writer give it
    };

    /**
     * Imports `recording` through the map at `topics` into a new session at `session`.
     * `info` says the router's source and overrides and any notes; `source`, `recording`
     * and `topics` are set here. `keepGoing` is asked now and then with the share done
     * (0 to 1); false cancels, and the session then holds what was imported. False with
     * `result->error` when the recording, the map or the session fails.
     */
    static bool run(const QString &recording, const QString &topics,
                    std::unique_ptr<Router> router, SessionInfo info, const QString &session,
                    const std::function<bool(double done)> &keepGoing, Result *result);
};

} // namespace semhap
