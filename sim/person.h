// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "operator.h"
#include "perception.h"
#include "personparameters.h"
#include "random.h"

#include <array>
#include <deque>
#include <optional>
#include <vector>

namespace semhap {

class Router;
class Task;

/**
 * What a person makes of the bands and the overlay (docs/operator.md): a cue is felt once
 * the band's delivered output crosses the modality's detection level, recognised as the
 * band's nearest pattern through perceptual noise (so patterns a few JND apart are
 * mistaken), and acted on after a reaction time drawn for its modality; an overlay is seen
 * only on the hand looked at; a continuous squeeze is read to a JND; a warning is answered
 * as often as that hand's warnings have been borne out. Its output is a Feeling per hand
 * that holds what the person has taken in and will act on now: an operator acts on it at
 * once.
 */
class Person
{
public:
    /** What the person has made of its cues so far, per hand. */
    struct Record
    {
        int cues = 0;     ///< haptic and visual cues taken in
        int misread = 0;  ///< taken for a message of the other meaning
        int warnings = 0; ///< cues taken for warnings
        int ignored = 0;  ///< warnings not answered, for their track record
    };

    Person(const PersonParameters &parameters, std::uint64_t seed);

    /**
     * Learns the patterns `router` plays on each band, at mid intensity, and how far apart
     * they feel; again whenever the router is replaced. Cues under way are forgotten.
     */
    void learn(const Router &router);
    /** The router last learnt (null before). */
    const Router *learnt() const { return m_router; }
    /** Looks at `hand` from `t` on; a switch takes a saccade before the hand is seen. */
    void look(Gripper hand, double t);
    Gripper lookedAt() const { return m_gaze; }
    /**
     * Takes in this tick's output: each band of `perception` (learnt first), the overlay,
     * and, for the warnings' track record, what `task` says came of them.
     */
    void sense(const Perception &perception, const Task &task, double t);
    /**
     * As sense(), from the router learnt: `bands` as Perception::bands() gives them, the
     * overlay as each hand's Feeling shows it.
     */
    void take(const std::vector<Perception::Band> &bands, const std::array<Feeling, 2> &overlay,
              const Task &task, double t);
    /** What the person acts on now about `hand`: each cue at 1 while it is taken in. */
    Feeling feeling(Gripper hand) const { return m_out[size_t(hand)]; }
    /** Drops the cues under way (another operator drove the hands meanwhile). */
    void forget();

    const Record &record(Gripper hand) const { return m_records[size_t(hand)]; }
    /** The share of `hand`'s warnings the person answers now. */
    double reliance(Gripper hand) const { return m_reliance[size_t(hand)]; }

    /**
     * The pattern a person recognises when `truth` plays, of patterns `distance` (JND, from
     * the truth to each) apart: the truth, or the one its noise carried it nearest to. The
     * noise is Gaussian, 1 / 0.954 JND along each direction, so that two patterns 1 JND apart
     * are told apart 75 % of the time side by side (docs/operator.md).
     */
    static int identify(const std::vector<double> &distance, int truth, Random &random);
    /** A reaction time (s) of `mean`, drawn from an ex-Gaussian of the parameters' spread. */
    double reactionTime(double mean);

private:
    struct Template
    {
        int pattern = -1;  ///< the pattern node (graph order)
        int meaning = -1;  ///< PlayerInput::Confirmation or Exception
        double rise = 0.0; ///< s, as the band delivers it
    };
    /** A cue on one band (or one highlight of the overlay) while its pulses keep coming. */
    struct Cue
    {
        double onset = 0.0;
        double last = 0.0;  ///< when it was last present
        double delay = 0.0; ///< its reaction time: it is acted on from onset + delay
        int meaning = -1;   ///< as recognised
        bool answered = true;
        int truth = -1;       ///< the template (pattern) that played; -1 for the overlay
        bool live = false;    ///< still present (its pulses have not stopped)
        bool actedOn = false; ///< given to the hands at least once
    };
    struct Band
    {
        int hand = -1;
        QString modality;
        double detection = 0.0;
        std::vector<Template> templates;
        std::vector<std::vector<double>> distance; ///< between templates, JND
        std::deque<Cue> cues;
    };
    struct Hand
    {
        std::array<std::deque<Cue>, 2> shown;           ///< the overlay's confirmation, warning
        double pressure = 0.0;                          ///< the squeeze as last read
        double adapted = 0.0;                           ///< what a steady squeeze has faded to
        double reading = 0.0;                           ///< what the person acts on now
        std::deque<std::pair<double, double>> readings; ///< due, value
        std::deque<double> alarms; ///< onsets of warnings whose outcome is not known yet
    };

    /** A cue's present state on `cues`; opens a new one on an onset, with `start(t)`. */
    template<typename Start>
    void track(std::deque<Cue> &cues, bool present, int truth, double t, const Start &start);
    /** A warning taken in on `hand`: answered or not, by the hand's track record. */
    bool answer(Gripper hand, double t);
    void readPressure(Gripper hand, double pressure, bool watched, double t, double dt);
    void judgeAlarms(const Task &task, double t);
    void updateOut(double t);
    bool sees(Gripper hand, double t) const;

    PersonParameters m_parameters;
    Random m_random;
    const Router *m_router = nullptr;
    std::vector<Band> m_bands;
    std::array<Hand, 2> m_hands{};
    std::array<Record, 2> m_records{};
    std::array<double, 2> m_reliance{};
    std::array<Feeling, 2> m_out{};
    bool m_bothWrists = false;
    Gripper m_gaze = Gripper::Right;
    double m_gazeSince = -1e9;
    double m_lastTick = 0.0;
};

} // namespace semhap
