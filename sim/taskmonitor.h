// SPDX-License-Identifier: MIT
#pragma once

#include "world.h"

#include <QJsonObject>

#include <vector>

namespace semhap {

/**
 * The task a scene poses: its rules (a dropped container respawns on its home site after a
 * 2 s penalty) and its metrics, as the paper reports them, plus the warning lead time. The
 * definitions are in docs/metrics.md. Call observe() after every physics step.
 */
class TaskMonitor
{
public:
    explicit TaskMonitor(const World &world);

    /** Applies the rules and counts, after a physics step. */
    void observe(World &world);
    /** Whether the operator perceives a warning about `hand` now (from Perception). */
    void setWarningFelt(Gripper hand, bool felt, double t);

    /** The metrics so far, snake_case keys; averages over nothing are null. */
    QJsonObject metrics() const;

    static constexpr double RespawnPenalty = 2.0;

private:
    void observeGrasp(World &world);
    void observeTransfers(const World &world);
    void observeContainer(World &world);

    Region m_place;
    bool m_hasPlace = false;
    int m_container = -1;
    Region m_home;

    // The right hand's grasps.
    int m_grasped = -1;  ///< object held now
    int m_lostSteps = 0; ///< steps the held object has been out of the fingertips
    int m_grasps = 0;
    double m_graspForceSum = 0.0;
    long m_graspSteps = 0;
    double m_peak = 0.0;
    double m_peakSum = 0.0;
    int m_dropped = 0;
    int m_broken = 0;
    std::vector<bool> m_transferred;
    int m_transfers = 0;

    // Warnings felt before fractures.
    double m_lastFelt = -1.0;    ///< last time a warning was perceptible, -1: never
    double m_warningSince = 0.0; ///< when the warning felt last began
    int m_warnedBreaks = 0;
    double m_leadTimeSum = 0.0;

    // The container (bimanual).
    bool m_containerHeld = false;
    double m_containerLostAt = -1.0;
    double m_heldHeight = 0.0;
    bool m_containerDown = false;
    double m_containerDroppedAt = 0.0;
    int m_containersDropped = 0;
};

} // namespace semhap
