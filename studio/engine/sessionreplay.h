// SPDX-License-Identifier: MIT
#pragma once

#include "runhistory.h"
#include "runsource.h"
#include "sessioninfo.h"

#include <QObject>
#include <QString>

#include <memory>
#include <vector>

namespace semhap {

class RouterGraph;
class SceneFeed;
class SessionReader;
class World;

/**
 * A recorded session opened read-only in the studio: its streams are read once, and the
 * time a scrubber picks fills the RunHistory with the window the plots and the event log
 * show, so every live view replays without knowing it. Re-routing runs the recorded
 * contact frames through another router (the editor's), like `semhap replay --router`.
 *
 * A simulated session's scene states (schema 2) put the bodies of a world of its own scene
 * where they were at the time shown, for the viewport: world() and sceneFeed().
 */
class SessionReplay : public QObject, public RunSource
{
    Q_OBJECT

public:
    explicit SessionReplay(RunHistory &history, QObject *parent = nullptr);
    ~SessionReplay() override;

    Pipeline *pipeline() override { return nullptr; }
    Hands hands() const override { return m_hands; }
    bool isStreaming() const override { return false; }
    QString caption() const override { return tr("Replay"); }

    /**
     * Reads the session at `path`, leaving the history alone until begin(). False with a
     * one-line `error`, keeping the session open before, if any.
     */
    bool open(const QString &path, QString *error);
    /** Loads the session's scene and shows its start: the history is the replay's from here. */
    void begin();
    void close();
    bool isOpen() const { return !m_path.isEmpty(); }
    const QString &path() const { return m_path; }
    /** Rows the session holds that break their stream's rules: skipped, not shown. */
    qint64 skippedRows() const;

    double startTime() const { return m_start; }
    double endTime() const { return m_end; }
    /** The time shown: the history holds what happened up to it. */
    double time() const override { return m_time; }
    /** Shows the session up to `t`; forward moves only add what is new. */
    void seek(double t);

    /**
     * Runs the recorded contact frames through `graph` and shows its events and device
     * frames instead of the recorded ones. False with the compiler's `error`.
     */
    bool reroute(const RouterGraph &graph, QString *error);
    /** Back to the events and device frames the session recorded. */
    void showRecorded();
    /** Whether the events shown are a re-routing's rather than the recording's. */
    bool isRerouted() const { return m_rerouted; }
    /**
     * The preset or file the router shown is named after: the re-routing graph's (its
     * name when it has no file), else the recording's `router_source`.
     */
    QString routerSource() const;
    /**
     * Whether the router shown routes differently from the one routerSource() names
     * (routesAs()): an edit applied in the studio, `--set` overrides. Only a preset is
     * compared for the recording — a session makes the studio read no file it names.
     */
    bool isRouterEdited() const { return m_rerouted ? m_reroutedEdited : m_recordedEdited; }
    /** Whether the recording's router differs from its preset, as isRouterEdited(). */
    bool isRecordedRouterEdited() const { return m_recordedEdited; }
    /** The router shown as the toolbar names it: `C3`, or `C3*` when edited. */
    QString routerName() const;
    /** What the session says of itself: scene, router, operator, dates, notes. */
    const SessionInfo &info() const;

    qsizetype frameCount() const { return qsizetype(m_frames.size()); }

    /** The scene at the time shown; null when the session has none (see sceneNote()). */
    const World *world() const override { return m_world.get(); }
    SceneFeed *sceneFeed() const override { return m_sceneFeed.get(); }
    /** Why there is no scene to show: no states recorded, or the scene does not load. */
    QString sceneNote() const override { return m_sceneNote; }
    /** The events shown: the recording's or the re-routing's. */
    const std::vector<SemanticEvent> &events() const { return m_shown.events; }

signals:
    void opened();
    void closed();
    void timeChanged(double t);
    /** The events and device frames shown changed (re-routed or back to the recording). */
    void streamsChanged();

private:
    struct Streams
    {
        std::vector<SemanticEvent> events;
        std::vector<DeviceFrame> deviceFrames;
        std::vector<NodeActivity> activity;
        std::vector<RunDevice> devices;
        std::array<GripperThresholds, 2> thresholds{};
        QStringList nodeIds;
    };
    void refill(double t);
    void appendUpTo(double from, double to);
    /** Loads the session's scene when it recorded scene states; else says why not. */
    void loadScene();
    /** Puts the scene's bodies where they were at `t` and hands a picture to the viewport. */
    void showScene(double t);

    RunHistory &m_history;
    QString m_path;
    std::vector<ContactFrame> m_frames;
    Hands m_hands{true, true}; ///< the hands that recorded frames
    Streams m_recorded;
    Streams m_shown;
    bool m_rerouted = false;
    QString m_reroutedWith; ///< the re-routing graph's file, or its name without one
    bool m_reroutedEdited = false;
    bool m_recordedEdited = false;
    double m_start = 0.0;
    double m_end = 0.0;
    double m_time = 0.0;

    std::unique_ptr<SessionReader> m_reader; ///< kept open: scene states are read as needed
    std::unique_ptr<World> m_world;
    std::unique_ptr<SceneFeed> m_sceneFeed;
    QString m_sceneNote;
    double m_sceneTime = 0.0; ///< the time of the state shown
};

} // namespace semhap
