// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <array>
#include <vector>

struct mjModel_;

namespace semhap {

/**
 * What a gripper's fingers do as they close, measured from its model at load by a sweep of
 * the finger joints from open to closed (the linkages left to settle at each step, without
 * contacts or gravity): the closing and approach axes, the gap between the pads, how far
 * below the wrist the pads are, and how far each pad travels per unit of its joint. All in
 * the wrist's frame (the body `<hand>.gripper`), metres. Unmeasured (a gripper without
 * fingertips), the pads are at the wrist, no gap, and a finger travels as its joint moves.
 */
class GripperGeometry
{
public:
    /** Sweeps `model`'s gripper; false with `error` when a finger does not move its pads. */
    bool measure(const mjModel_ *model, int wristBody, const std::array<int, 2> &joints,
                 const std::array<std::vector<int>, 2> &padGeoms, QString *error);

    /** Unit vector from the right pad to the left pad, fully open. */
    const std::array<double, 3> &closingAxis() const { return m_closing; }
    /** The pads' centre, fully open. */
    const std::array<double, 3> &openCentre() const { return m_openCentre; }
    /**
     * The pad geoms whose faces meet a flat object held between the fingers (both fingers
     * together): the contact count of a full, steady grasp.
     */
    int fullContacts() const { return m_fullContacts; }
    /** Unit vector from the wrist towards the pads, across the closing axis. */
    const std::array<double, 3> &approachAxis() const { return m_approach; }
    /** The gap between the pads' inner faces (m), fully open and fully closed. */
    double openGap() const { return m_samples.empty() ? 0.0 : m_samples.front().gap; }
    double closedGap() const { return m_samples.empty() ? 0.0 : m_samples.back().gap; }
    /** How far the pads' centre is from the wrist along the approach axis at `gap` (m). */
    double drop(double gap) const;
    /** How far the pads reach along the approach axis at `gap`: their farthest point (m). */
    double reach(double gap) const;
    /** How far finger `finger` (0 left, 1 right) has closed at joint position `q` (m). */
    double travel(int finger, double q) const;
    /** d travel / d q at `q`: the moment arm a force motor on the joint acts through (m). */
    double arm(int finger, double q) const;
    /**
     * The generalized force the gripper's own springs put on `finger`'s joint at `q`, through
     * the linkage (N·m or N; positive along the joint): what a motor must take away for the
     * pads to press with exactly the commanded force.
     */
    double spring(int finger, double q) const;
    /** Whether the fingers close as their joints' positions grow (else as they shrink). */
    bool closesAsJointRises() const
    {
        return m_samples.size() < 2 || m_samples.back().q[0] > m_samples.front().q[0];
    }
    /** The least and the greatest moment arm of `finger` over its travel (m). */
    std::array<double, 2> armRange(int finger) const;

private:
    struct Sample
    {
        std::array<double, 2> q{};
        std::array<double, 2> travel{};
        std::array<double, 2> spring{};
        double gap = 0.0;
        double drop = 0.0;
        double reach = 0.0;
    };
    /** The samples around `q` of finger `finger` and where `q` lies between them (0..1). */
    size_t segment(int finger, double q, double *fraction) const;
    /** The samples around `gap` and where it lies between them. */
    size_t gapSegment(double gap, double *fraction) const;
    /** `field` interpolated at `gap`, and of `finger` at its joint position `q`. */
    double atGap(double gap, double Sample::*field) const;
    double atQ(int finger, double q, std::array<double, 2> Sample::*field) const;

    std::vector<Sample> m_samples; ///< from open to closed
    std::array<double, 3> m_closing{0, 1, 0};
    std::array<double, 3> m_approach{0, 0, -1};
    std::array<double, 3> m_openCentre{};
    int m_fullContacts = 0;
};

} // namespace semhap
