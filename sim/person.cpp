// SPDX-License-Identifier: MIT
#include "person.h"

#include "distinctiveness.h"
#include "perception.h"
#include "router.h"
#include "task.h"

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/**
 * The perceptual noise along each direction, in JND: two patterns 1 JND apart are told
 * apart 75 % of the time in two-alternative forced choice, so d' = 0.954 per JND, and one
 * observation's noise is 1 / 0.954 JND (Macmillan & Creelman 2005).
 */
constexpr double Noise = 1.0 / 0.954;
/** The patterns a person learns are those of a message at mid intensity. */
constexpr double LearntIntensity = 0.5;
/** The fastest a person reacts (s): faster answers are anticipations, not reactions. */
constexpr double FastestReaction = 0.1;
/** A warning whose outcome the task never tells is forgotten after this long (s). */
constexpr double LongestWait = 60.0;

} // namespace

Person::Person(const PersonParameters &parameters, std::uint64_t seed)
    : m_parameters(parameters), m_random(seed)
{
    m_reliance.fill(parameters.firstReliance);
}

void Person::learn(const Router &router)
{
    m_router = &router;
    m_bands.clear();
    const Distinctiveness distinctiveness(m_parameters.senses);
    const Player &player = router.player();
    const std::vector<MessageRoute> routes = router.messageRoutes(LearntIntensity);
    std::array<bool, 2> worn{};
    for (int d = 0; d < player.deviceCount(); ++d) {
        Band band;
        Gripper hand = Gripper::Right;
        if (router.deviceHand(d, &hand)) {
            band.hand = int(hand);
            worn[size_t(hand)] = true;
        }
        const DeviceModel &model = player.deviceModel(d);
        band.modality = model.modality();
        band.detection = m_parameters.senses.detection(band.modality);
        std::vector<Percept> percepts;
        for (const MessageRoute &route : routes) {
            const bool known =
                std::any_of(band.templates.begin(), band.templates.end(),
                            [&](const Template &t) { return t.pattern == route.pattern; });
            if (route.device != d || known)
                continue;
            Template t;
            t.pattern = route.pattern;
            t.meaning = route.message.category == Category::Exception ? PlayerInput::Exception
                                                                      : PlayerInput::Confirmation;
            Percept percept;
            QString reason;
            // A band of no modality has nothing to compare: its patterns are told apart.
            if (!distinctiveness.perceive(route.played, route.routes, model, route.intensity,
                                          &percept, &reason))
                percept = Percept();
            t.rise = percept.rise;
            band.templates.push_back(t);
            percepts.push_back(percept);
        }
        const size_t n = percepts.size();
        band.distance.assign(n, std::vector<double>(n, 0.0));
        for (size_t a = 0; a < n; ++a) {
            for (size_t b = 0; b < n; ++b) {
                if (a != b)
                    band.distance[a][b] =
                        band.modality.isEmpty()
                            ? m_parameters.senses.otherModality
                            : distinctiveness.distance(percepts[a], percepts[b]).total;
            }
        }
        m_bands.push_back(std::move(band));
    }
    m_bothWrists = worn[0] && worn[1];
    for (Hand &hand : m_hands) {
        for (auto &cues : hand.shown)
            cues.clear();
    }
}

void Person::look(Gripper hand, double t)
{
    if (hand == m_gaze)
        return;
    m_gaze = hand;
    m_gazeSince = t;
}

bool Person::sees(Gripper hand, double t) const
{
    return hand == m_gaze && t - m_gazeSince >= m_parameters.saccade;
}

double Person::reactionTime(double mean)
{
    // Ex-Gaussian: a normal part and an exponential tail, whose sum has the given mean.
    const double tail = std::min(m_parameters.reactionTail, mean / 2);
    const double normal = m_random.normal(mean - tail, m_parameters.reactionSd);
    const double exponential = -tail * std::log1p(-m_random.uniform());
    return std::max(FastestReaction, normal + exponential);
}

int Person::identify(const std::vector<double> &distance, int truth, Random &random)
{
    // Each rival pattern wins when the noise along the way to it carries the percept past
    // the half-way point, and the one carried farthest past wins. Exact for two patterns;
    // for more it takes the rivals' directions as independent.
    int chosen = truth;
    double farthest = 0.0;
    for (size_t j = 0; j < distance.size(); ++j) {
        if (int(j) == truth)
            continue;
        const double past = random.normal(0.0, 1.0) - distance[j] / (2 * Noise);
        if (past > farthest) {
            farthest = past;
            chosen = int(j);
        }
    }
    return chosen;
}

bool Person::answer(Gripper hand, double t)
{
    Record &record = m_records[size_t(hand)];
    ++record.warnings;
    m_hands[size_t(hand)].alarms.push_back(t);
    // Probability matching: a warning is answered as often as this hand's have been right.
    const bool answered = m_random.uniform() < m_reliance[size_t(hand)];
    record.ignored += answered ? 0 : 1;
    return answered;
}

template<typename Start>
void Person::track(std::deque<Cue> &cues, bool present, int truth, double t, const Start &start)
{
    if (!cues.empty() && cues.back().live) {
        Cue &cue = cues.back();
        if (present && truth == cue.truth) {
            cue.last = t;
            return;
        }
        // Another pattern begins (a new cue), or the pulses have stopped.
        if (present || t - cue.last > Perception::PulseGap)
            cue.live = false;
    }
    if (present && (cues.empty() || !cues.back().live)) {
        Cue cue = start(t);
        cue.onset = cue.last = t;
        cue.truth = truth;
        cue.live = true;
        cues.push_back(cue);
    }
    // Gone once it has ended and reached the hands (or was let pass).
    while (!cues.empty() && !cues.front().live &&
           (cues.front().actedOn || !cues.front().answered) &&
           cues.front().last + cues.front().delay < t)
        cues.pop_front();
}

void Person::readPressure(Gripper hand, double pressure, bool watched, double t, double dt)
{
    Hand &h = m_hands[size_t(hand)];
    const double detection = m_parameters.senses.pressureDetection;
    if (pressure < detection)
        pressure = 0.0;
    if (pressure == 0.0 && h.pressure == 0.0 && h.readings.empty()) {
        h.adapted = 0.0; // nothing felt, nothing on its way: the common case, kept cheap
        return;
    }
    h.adapted += (pressure - h.adapted) * std::min(1.0, dt / m_parameters.pressureAdaptation);
    const double jnd = std::log1p(m_parameters.senses.pressureLevelWeber);
    const auto steps = [&](double a, double b) {
        if (a <= 0.0 || b <= 0.0)
            return (a <= 0.0) == (b <= 0.0) ? 0.0 : HUGE_VAL;
        return std::abs(std::log(a / b)) / jnd;
    };
    // Watched, the squeeze is read to a JND; unwatched, only a change that outruns its
    // fading from notice is.
    const bool noticed =
        steps(pressure, h.pressure) >= 1.0 && (watched || steps(pressure, h.adapted) >= 1.0);
    if (noticed) {
        h.pressure = pressure;
        h.readings.emplace_back(
            t + reactionTime(m_parameters.touchReaction) + m_parameters.dualTaskCost, pressure);
    }
    // The latest reading due is what the person acts on; earlier ones are overtaken.
    for (size_t k = h.readings.size(); k-- > 0;) {
        if (h.readings[k].first <= t) {
            h.reading = h.readings[k].second;
            h.readings.erase(h.readings.begin(), h.readings.begin() + long(k) + 1);
            break;
        }
    }
}

void Person::judgeAlarms(const Task &task, double t)
{
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        std::deque<double> &alarms = m_hands[size_t(hand)].alarms;
        while (!alarms.empty()) {
            const std::optional<bool> right = task.warranted(hand, alarms.front(), t);
            if (right) {
                // The track record moves towards each outcome by the adaptation rate.
                double &reliance = m_reliance[size_t(hand)];
                reliance += m_parameters.adaptationRate * ((*right ? 1.0 : 0.0) - reliance);
            } else if (t - alarms.front() < LongestWait) {
                break;
            }
            alarms.pop_front();
        }
    }
}

void Person::sense(const Perception &perception, const Task &task, double t)
{
    if (&perception.router() != m_router)
        learn(perception.router());
    take(perception.bands(),
         {perception.feeling(Gripper::Left), perception.feeling(Gripper::Right)}, task, t);
}

void Person::take(const std::vector<Perception::Band> &now, const std::array<Feeling, 2> &overlay,
                  const Task &task, double t)
{
    const double dt = std::max(0.0, t - m_lastTick);
    m_lastTick = t;
    const PersonParameters &p = m_parameters;
    std::array<double, 2> pressure{};
    for (size_t d = 0; d < m_bands.size(); ++d) {
        Band &band = m_bands[d];
        const Perception::Band &felt = now[d];
        if (band.hand < 0)
            continue;
        const Gripper hand = Gripper(band.hand);
        if (felt.priority == PlayerInput::Continuous) {
            pressure[size_t(hand)] = std::max(pressure[size_t(hand)], felt.level);
            continue;
        }
        const bool present =
            felt.priority >= PlayerInput::Confirmation && felt.level >= band.detection;
        const auto at = std::find_if(band.templates.begin(), band.templates.end(),
                                     [&](const Template &x) { return x.pattern == felt.pattern; });
        const int truth = at == band.templates.end() ? -1 : int(at - band.templates.begin());
        track(band.cues, present, truth, t, [&](double onset) {
            Cue cue;
            cue.meaning = felt.priority;
            double delay = reactionTime(p.touchReaction) + p.dualTaskCost +
                           (m_bothWrists ? p.locationCost : 0.0);
            if (truth >= 0) {
                const int seen = identify(band.distance[size_t(truth)], truth, m_random);
                cue.meaning = band.templates[size_t(seen)].meaning;
                // A squeeze is known for what it is once it has risen.
                if (band.modality == QLatin1String("pressure"))
                    delay += band.templates[size_t(truth)].rise;
            }
            cue.delay = delay;
            Record &record = m_records[size_t(hand)];
            ++record.cues;
            record.misread += cue.meaning != felt.priority ? 1 : 0;
            if (cue.meaning == PlayerInput::Exception)
                cue.answered = answer(hand, onset);
            return cue;
        });
    }
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        Hand &h = m_hands[size_t(hand)];
        const Feeling &shown = overlay[size_t(hand)];
        const bool seen = sees(hand, t);
        const std::array<double, 2> levels{shown.shownConfirmation, shown.shownWarning};
        for (size_t k = 0; k < 2; ++k) {
            // The overlay's two highlights differ in colour and place: never mistaken.
            const int meaning = k == 0 ? PlayerInput::Confirmation : PlayerInput::Exception;
            track(h.shown[k], seen && levels[k] >= p.senses.sightDetection, -1, t,
                  [&](double onset) {
                      Cue cue;
                      cue.meaning = meaning;
                      cue.delay = reactionTime(p.sightReaction) + p.dualTaskCost;
                      ++m_records[size_t(hand)].cues;
                      if (meaning == PlayerInput::Exception)
                          cue.answered = answer(hand, onset);
                      return cue;
                  });
        }
        readPressure(hand, pressure[size_t(hand)], sees(hand, t), t, dt);
    }
    judgeAlarms(task, t);
    updateOut(t);
}

void Person::updateOut(double t)
{
    for (size_t hand = 0; hand < 2; ++hand) {
        Feeling out;
        const auto takeIn = [&](std::deque<Cue> &cues) {
            for (Cue &cue : cues) {
                // Acted on from its reaction time while it lasts, and once at least: a cue
                // felt for one tick would otherwise fall between two.
                if (cue.answered && t >= cue.onset + cue.delay &&
                    (t <= cue.last + cue.delay || !cue.actedOn)) {
                    (cue.meaning == PlayerInput::Exception ? out.warning : out.confirmation) = 1.0;
                    cue.actedOn = true;
                }
            }
        };
        for (Band &band : m_bands) {
            if (band.hand == int(hand))
                takeIn(band.cues);
        }
        for (auto &cues : m_hands[hand].shown)
            takeIn(cues);
        out.pressure = m_hands[hand].reading;
        m_out[hand] = out;
    }
}

void Person::forget()
{
    for (Band &band : m_bands)
        band.cues.clear();
    for (Hand &hand : m_hands) {
        for (auto &cues : hand.shown)
            cues.clear();
        // The squeeze is read afresh: a reading kept would be acted on for as long as the
        // squeeze holds still.
        hand.readings.clear();
        hand.pressure = hand.adapted = hand.reading = 0.0;
    }
}

} // namespace semhap
