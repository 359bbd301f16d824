// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "pattern.h"
#include "player.h"

#include <QString>

#include <vector>

namespace semhap {

/**
 * How a pattern feels on its band: the features of the band's delivered output (after its
 * response) that the perceptual distance compares (docs/perception.md).
 */
struct Percept
{
    QString modality;        ///< the model's: vibration, pressure or sight
    double level = 0.0;      ///< peak of the strongest channel, as a share of its range
    double pulseRate = 0.0;  ///< pulses per second; 0 for a steady output
    double duty = 0.0;       ///< share of the time from onset spent above half the level
    double rise = 0.0;       ///< seconds from onset (10 % of the level) to 90 % of it
    std::vector<double> place; ///< each channel's share of the output's energy
    std::vector<double> angle; ///< each channel's angle around the band (NaN: unknown)

    bool felt() const { return level > 0.0; }
};

/**
 * The constants of the perceptual distance, each a just-noticeable difference (JND) from the
 * psychophysics literature; docs/perception.md gives each one's source and range.
 */
struct PerceptionConstants
{
    double vibrationLevelJnd = 2.5;   ///< dB of vibration amplitude
    double pressureLevelWeber = 0.15; ///< Weber fraction of pressure (an assumption)
    double sightLevelWeber = 0.02;    ///< Weber fraction of a highlight's luminance
    double rateWeber = 0.2;           ///< Weber fraction of a pulse rate (its interval)
    double durationWeber = 0.16;      ///< Weber fraction of a duration (on-time, rise)
    double shortestRise = 0.03;       ///< s: rises shorter than this feel alike, as a tap
    double wristPlaces = 4.0;         ///< places told apart around the wrist
    double otherModality = 10.0;      ///< the least distance between two senses, JND
    /** Levels (share of the range) below which an output is not felt, per modality. */
    double vibrationDetection = 0.04;
    double pressureDetection = 0.05;
    double sightDetection = 0.02;

    /** The level below which `modality`'s output is not felt. */
    double detection(const QString &modality) const;
};

/** A distance between two percepts, in JND, feature by feature and combined. */
struct PerceptDistance
{
    double level = 0.0;
    double rate = 0.0;
    double duty = 0.0;
    double rise = 0.0;
    double place = 0.0;
    double total = 0.0; ///< the features' Euclidean sum; at least otherModality across senses
};

class Router;

/** The distances between the messages a router plays on one band. */
struct BandDistinctiveness
{
    QString device;       ///< the router's device node
    QString model;        ///< its device model
    QStringList messages; ///< `NODE:message`, in the router's order
    std::vector<std::vector<double>> distance; ///< JND, by message
    /** Pairs under 1 JND (a < b), nearest first: a person will confuse them. */
    struct Pair
    {
        int a = 0;
        int b = 0;
        double distance = 0.0;
    };
    std::vector<Pair> confusable;
};

/**
 * How far apart patterns feel, in JND: each is rendered on its device model, passed through
 * the model's response, reduced to a Percept, and two percepts are compared feature by
 * feature, each difference divided by its JND, the features summed as a Euclidean norm.
 */
class Distinctiveness
{
public:
    /** The seconds of output a percept is taken from, from the pattern's begin. */
    static constexpr double Window = 2.0;
    /** Samples per second of the analysis. */
    static constexpr double Rate = 1000.0;

    explicit Distinctiveness(const PerceptionConstants &constants = {})
        : m_constants(constants)
    {}

    /**
     * The percept of `pattern` played on `model` at `intensity`, begun at 0 and not ended
     * within the window; false with `reason` when the model names no modality or the pattern
     * does not play on it.
     */
    bool perceive(const PatternPtr &pattern, const DeviceModel &model, double intensity,
                  Percept *percept, QString *reason) const;
    /** As perceive(), through `routes` resolved already (a router's: Router::messageRoutes). */
    bool perceive(const PatternPtr &pattern, const std::vector<PlayerInput::Route> &routes,
                  const DeviceModel &model, double intensity, Percept *percept,
                  QString *reason) const;
    /** The distance between two percepts; 0 for identical ones. */
    PerceptDistance distance(const Percept &a, const Percept &b) const;
    /**
     * For each of `router`'s bands that plays a message, the matrix over those messages,
     * each message's pattern played at `intensity` through the curves on its way
     * (Router::messageRoutes); false with `reason` when a band's model names no modality.
     */
    bool bands(const Router &router, double intensity, std::vector<BandDistinctiveness> *bands,
               QString *reason) const;

    const PerceptionConstants &constants() const { return m_constants; }

private:
    /** How far the stimulation moves round the band between two felt percepts, in JND. */
    double placeDistance(const Percept &a, const Percept &b) const;

    PerceptionConstants m_constants;
};

} // namespace semhap
