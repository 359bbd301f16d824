// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "handcommand.h"
#include "pipeline.h"
#include "scenestate.h"
#include "sessionclock.h"
#include "sessioninfo.h"

#include <QString>

#include <atomic>
#include <limits>
#include <memory>
#include <vector>

namespace semhap {

class ActorTable;
class Router;

/**
 * Records a session into a new SQLite database (docs/sessions.md) while it runs. The
 * producer — the pipeline thread — only copies each value into a preallocated batch
 * under a mutex held for that copy; a writer thread of its own swaps the batch out and
 * commits it every ~50 ms in one transaction (WAL, synchronous=NORMAL), so the pipeline
 * never waits for the disk and a crash or kill loses at most the last batch. When the
 * batch is full (the disk stalled for seconds) values are dropped and counted, never
 * waited for; unless Options::waitWhenFull, for a producer that keeps no clock.
 *
 * Use it as the pipeline's sink (events, device frames) and call recordContactFrame() for
 * each frame before the pipeline processes it; recordHandCommand() may come from any
 * thread. One router per session: its names are read once, at create(), and so are its
 * active messages — a recording started mid-grasp writes a begin for each at its first
 * frame and lists them in the metadata (`open_at_start`).
 */
class SessionWriter : public PipelineSink
{
public:
    struct Options
    {
        int capacity = 1 << 15; ///< values one batch holds (≈ 8 s of a busy bimanual run)
        int commitMs = 50;      ///< how often the writer thread commits
        /// Wait for the writer when the batch is full instead of dropping: for producers
        /// with no clock to keep, such as an import from a file.
        bool waitWhenFull = false;
        /// Keep the steady clock beside the session's time (SessionClock): not for a
        /// producer whose frames were not made now, such as an import from a file.
        bool steadyClock = true;
    };

    /**
     * Creates the database at `path` (which must not exist: sessions are never
     * overwritten), writes `info` with the router's self-contained JSON and its devices,
     * and starts the writer thread. Null with a one-line `error` (`FILE: reason`).
     */
    static std::unique_ptr<SessionWriter> create(const QString &path, SessionInfo info,
                                                 const Router &router, QString *error);
    static std::unique_ptr<SessionWriter> create(const QString &path, SessionInfo info,
                                                 const Router &router, Options options,
                                                 QString *error);
    /** Finishes (see finish()) if that was not done. */
    ~SessionWriter() override;

    /** Where contact frames' actor ids are named; read on the producer thread only. */
    void setActorTable(const ActorTable *actors) { m_actors = actors; }

    /** Records a contact frame; `arrival` is its receive time (s), NaN when simulated. */
    void recordContactFrame(const ContactFrame &frame, double arrival);
    /** Records what the user commanded a hand. Any thread. */
    void recordHandCommand(const HandCommand &input);
    /** Records where the scene's bodies are (at display rate, for the replay's viewport). */
    void recordSceneState(const SceneState &state);
    void onEvent(const SemanticEvent &event) override;
    void onDeviceFrame(const DeviceFrame &frame) override;

    /**
     * Commits what is queued, stamps the end time and closes the database. False with a
     * one-line `error` when any write failed during the session.
     */
    bool finish(QString *error = nullptr);

    /** Values refused because the batch was full (the disk fell behind). */
    quint64 dropped() const { return m_dropped.load(std::memory_order_relaxed); }
    /** Values committed so far. */
    quint64 committed() const { return m_committed.load(std::memory_order_relaxed); }
    /** CPU seconds the writer thread has used (for the benchmark). */
    double writerCpuSeconds() const;
    const QString &path() const { return m_path; }

private:
    class Thread;
    SessionWriter(const QString &path, Options options);
    void pushActors(const ContactFrame &frame);

    QString m_path;
    std::unique_ptr<Thread> m_thread;
    const ActorTable *m_actors = nullptr;
    /** Producer thread: begins of messages active at create(), due at the first frame. */
    std::vector<SemanticEvent> m_open;
    int m_actorsSent = 0; ///< producer thread: actor ids already handed to the writer
    /** Producer thread: the last frame's clock pair, and when the next is due (steady s). */
    bool m_steadyClock;
    SessionClock::Sample m_lastClock;
    double m_nextClockSample = -std::numeric_limits<double>::infinity();
    bool m_clockSampled = false;
    std::atomic<quint64> m_dropped{0};
    std::atomic<quint64> m_committed{0};
    bool m_finished = false;
};

} // namespace semhap
