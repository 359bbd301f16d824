// SPDX-License-Identifier: MIT
#pragma once

#include "metricspec.h"
#include "task.h"
#include "world.h"

#include <QJsonObject>

#include <array>
#include <vector>

namespace semhap {

/**
 * The task a scene poses: its rules (a dropped container respawns on its home site after a
 * 2 s penalty; an emptied cube box is refilled) and its metrics, as the paper reports them,
 * plus how early each failure was warned of and how often a message was felt per grasp and
 * per slip. The definitions are in docs/metrics.md. Call observe() after every physics step
 * and feel() with what each hand perceives.
 */
class TaskMonitor : public Task
{
public:
    /**
     * `reactionTime`: how long before a failure a warning must be felt to count in time;
     * `horizon`: how long before it a warning's onset may lie and still count.
     */
    /** The metrics others read: a practice round's goal counts transfers (StudyProtocol). */
    static constexpr const char *CubesTransferred = "cubes_transferred";
    /** The studio says when the pile is finished. */
    static constexpr const char *CompletionTime = "completion_time";

    explicit TaskMonitor(const World &world, double reactionTime = DefaultReactionTime,
                         double horizon = DefaultHorizon);

    void observe(World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;
    QJsonObject metrics() const override;
    /** Its metrics, a row each (docs/metrics.md), in the order a reader looks for them. */
    static const std::vector<MetricSpec> &metricSpecs();
    std::optional<bool> warranted(Gripper hand, double onset, double t) const override;

    static constexpr double RespawnPenalty = 2.0;
    /** How far from its home site (m) a container still stands on its base. */
    static constexpr double OffHome = 0.01;
    /**
     * Whether `container` stands on its base: upright and within OffHome of the `home` site.
     * Operators wait for this before they take it again; the task respawns it otherwise.
     */
    static bool isOnBase(const World &world, int container, const Region &home);

private:
    /** A message as the operator perceives it: one while its pulses keep coming. */
    struct Cue
    {
        double lastFelt = -1.0; ///< last time it was perceptible, -1: never
        double since = 0.0;     ///< when the cue felt last began
        int onsets = 0;

        void feel(bool felt, double t);
        /** Whether it was felt at `t` (its pulses had not stopped). */
        bool feltAt(double t) const;
    };
    /**
     * One hand's warnings judged as a detector's alarms are (docs/metrics.md): when each felt
     * warning began, the failures and the episodes that warrant one, and how much of the
     * holding time a warning was felt.
     */
    struct Alarms
    {
        std::vector<double> onsets;   ///< when each felt warning began
        std::vector<double> failures; ///< drops (left) or breaks (right)
        std::vector<double> episodes; ///< slip episodes (left), break-line crossings (right)
        double held = 0.0;            ///< holding time, s
        double warnedHeld = 0.0;      ///< of it, with a warning felt, s

        /** Counts `dt` of holding, with a warning felt or not. */
        void hold(double dt, bool warned)
        {
            held += dt;
            warnedHeld += warned ? dt : 0.0;
        }

        /** The share of failures with an onset from `horizon` to `reactionTime` before. */
        QJsonValue warnedByOnsetShare(double reactionTime, double horizon) const;
        /** Whether a failure or an episode followed `onset` within `horizon`. */
        bool borneOut(double onset, double horizon) const;
        /** The share of onsets up to `end - horizon` a failure or an episode followed. */
        QJsonValue precision(double horizon, double end) const;
        QJsonValue duty() const;
    };
    /** Warnings before one kind of failure. */
    struct Failures
    {
        int count = 0;
        int warned = 0;
        int inTime = 0;
        double leadTimeSum = 0.0;

        void add(double t, const Cue &warning, double reactionTime);
    };

    void observeGrasp(World &world);
    void observeTransfers(const World &world);
    /** Notes the first time no cube of the pile is left to carry (box_and_block). */
    void observeCompletion(const World &world);
    void observeContainer(World &world);
    void observeContainerSlip(const World &world, bool held);
    void refill(World &world);
    /** Whether `object` is one of the cubes (not the container). */
    bool isCube(const World &world, size_t object) const;
    /** Whether `object` is inside the container: within its walls, above its floor. */
    bool isInContainer(const World &world, int object) const;
    /** Puts the container back on its home site, empty: its cubes go back to the box. */
    void respawnContainer(World &world);
    /** Puts a cube (whole again) where the scene started it, or above if that is taken. */
    void returnToBox(World &world, int object);

    double m_reactionTime;
    double m_horizon;
    double m_time = 0.0; ///< the last step observed
    std::array<Alarms, 2> m_alarms;
    bool m_overBreakLine = false; ///< the held object's force is above the force that breaks it
    Region m_place;
    bool m_hasPlace = false;
    Region m_pick;
    bool m_hasPick = false;
    int m_container = -1;
    Region m_home;

    // The right hand's grasps.
    int m_grasped = -1;  ///< object held now
    int m_lostSteps = 0; ///< steps the held object has been out of the fingertips
    /** Per object: both fingertips touched it during the grasp going on. */
    std::vector<bool> m_inGrasp;
    int m_grasps = 0;
    double m_graspForceSum = 0.0;
    long m_graspSteps = 0;
    double m_peak = 0.0;
    double m_peakSum = 0.0;
    double m_graspGrip = 0.0;   ///< the highest grip during the grasp (N)
    double m_graspHeight = 0.0; ///< the wrist's height as the grasp began (m)
    double m_liftedBy = 0.0;    ///< how high above that the wrist has been since (m)
    int m_dropped = 0;
    std::vector<bool> m_transferred;
    int m_transfers = 0;
    int m_refills = 0;
    double m_completedAt = -1.0; ///< when the pile was first finished; -1: not yet

    // What each hand felt, and the failures it was warned of.
    std::array<Cue, 2> m_warnings{};
    std::array<Cue, 2> m_confirmations{};
    Failures m_breaks;
    Failures m_drops;

    // The container (bimanual).
    bool m_containerHeld = false;
    int m_holds = 0;
    int m_setDowns = 0;
    double m_emptyAt = -1.0; ///< when a container put down is emptied; -1: none pending
    double m_containerLostAt = -1.0;
    Cue m_warningAtLoss; ///< the left hand's warning as it was when the container left it
    double m_heldHeight = 0.0;
    bool m_containerDown = false;
    double m_containerDroppedAt = 0.0;
    // Slip episodes: the container sliding in the left fingertips.
    bool m_hasRelative = false;
    std::array<double, 3> m_relative{}; ///< the container in the gripper frame, last step
    double m_slipSpeed = 0.0;           ///< smoothed, m/s
    bool m_slipping = false;
    double m_slipQuietSince = 0.0;
    int m_slipEpisodes = 0;
};

} // namespace semhap
