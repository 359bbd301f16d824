// SPDX-License-Identifier: MIT
#pragma once

#include "handplan.h"
#include "operator.h"
#include "random.h"

#include <deque>

namespace semhap {

/**
 * Inserts usb_insertion's plug the way a person would (sim/README.md, "usb_insertion"): takes
 * it from the table, carries it above the port, turns and centres it by eye — an error that
 * shrinks exponentially to a seeded residual (the eye's accuracy) — then lowers it and pushes
 * it in with a limited force. Seeing the plug stuck on the port's face, it backs off, looks
 * again and retries; seeing it seated, it lets go and waits for the next one.
 *
 * `scripted` aligns for a seeded time and goes in, whatever it feels. `reactive` does the
 * same, and also goes in as soon as it feels the alignment confirmed (a squeeze after the
 * grasp's has faded), and stops and backs off to look again on a warning while going in —
 * each `reactionTime` after it felt it. Without feedback, the two are the same person.
 */
class InsertionOperator : public Operator
{
public:
    InsertionOperator(std::uint64_t seed, bool reactive, double reactionTime);

    QString name() const override;
    void act(World &world) override;
    /**
     * Starts over from where the hand is: it rises clear; a plug in hand is then looked at and
     * carried to the port, else the hand opens and takes the plug again from the table.
     */
    void engage(const World &world) override;
    void feel(Gripper hand, const Feeling &feeling, double t) override;

private:
    enum class Phase
    {
        Idle,     ///< waiting for a plug on the table
        Picking,  ///< reaching, grasping, lifting
        Carrying, ///< above the port
        Aligning, ///< turning and centring by eye
        Inserting,
        Backing, ///< backing off to look again
        Leaving  ///< letting go of a seated plug
    };
    struct Percept
    {
        double due;
        bool warning; ///< else a confirmation
        double felt;  ///< when it was felt
    };

    void planPick(World &world);
    /** Sees where the plug sits in the hand (m_tipInHand, m_plugYawInHand). */
    void lookAtHand(const World &world);
    void startAligning(World &world, double t, bool lookAgain);
    void startInserting(const World &world);
    /** Backs off from the tip's `depth` (m) to look again. */
    void startBacking(double depth);
    /** Where the wrist must be for the plug's tip to be `above` the mouth, turned to the port. */
    void aim(World &world, double above);
    void react(World &world, const Percept &percept);

    Random m_random;
    bool m_reactive;
    double m_reactionTime;
    HandPlan m_hand{Gripper::Right};
    std::deque<Percept> m_percepts;
    Phase m_phase = Phase::Idle;
    int m_plug = -1;
    double m_pace = 1.0;
    double m_since = 0.0;      ///< when the phase began
    double m_alignTime = 0.0;  ///< scripted: how long it aligns before going in (s)
    double m_lostSince = -1.0; ///< when the plug left the fingertips; -1: held
    // The eye's error: start values, residuals, and when the look began.
    double m_yawError0 = 0.0;
    double m_yawResidual = 0.0;
    std::array<double, 2> m_offset0{};
    std::array<double, 2> m_offsetResidual{};
    double m_lookedAt = 0.0;
    // Where the plug is in the hand (the tip from the wrist, gripper frame) and its yaw there.
    std::array<double, 3> m_tipInHand{};
    double m_plugYawInHand = 0.0;
    // Going in: how far down the tip is commanded (m below the face), its progress.
    double m_command = 0.0;
    double m_bestDepth = -1.0;
    double m_progressAt = 0.0;
    std::array<bool, 2> m_pending{}; ///< a confirmation, a warning on its way to a reaction
};

} // namespace semhap
