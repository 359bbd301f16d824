// SPDX-License-Identifier: MIT
#pragma once

namespace semhap {

/**
 * Stop-all on SIGINT and SIGTERM, even when the process is stuck: transports register the
 * descriptors of their open links, and the handler (async-signal-safe: it only calls
 * write()) sends a pre-encoded stop-all frame on each, then lets the signal end the
 * process as it would have. The CLI installs it; the studio may too.
 */
class EmergencyStop
{
public:
    /** Installs the SIGINT and SIGTERM handlers (once; later calls do nothing). */
    static void install();
    /**
     * Installs handlers for a loop that owns devices and files (`listen`, `route` on bands):
     * a signal sends stop-all at once and asks the loop to quit (QuitSignal::requested()),
     * so it closes its session and outputs; a second signal ends the process as it would
     * have.
     */
    static void installGraceful();
    /** Adds a descriptor to stop on a signal; false when the table (32) is full. */
    static bool add(int fd);
    static void remove(int fd);
    /** Sends stop-all on every registered descriptor now (what the handler does). */
    static void stopAllNow();
};

} // namespace semhap
