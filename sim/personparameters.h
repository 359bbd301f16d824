// SPDX-License-Identifier: MIT
#pragma once

#include "distinctiveness.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace semhap {

class JsonReader;

/**
 * Everything the perceiving operator's person is made of (docs/operator.md): the perceptual
 * constants its senses share with `semhap distinct`, and its reaction times, gaze and
 * reliance on warnings. Each is a row of rows(), with the range its source gives; none is
 * fitted to a study's results.
 */
struct PersonParameters
{
    PerceptionConstants senses;
    double touchReaction = 0.25;     ///< s, mean simple reaction to a vibrotactile cue
    double sightReaction = 0.25;     ///< s, mean simple reaction to a highlight in view
    double reactionSd = 0.03;        ///< s, the Gaussian part of a reaction's spread
    double reactionTail = 0.05;      ///< s, the exponential tail of a reaction (ex-Gaussian tau)
    double dualTaskCost = 0.13;      ///< s, added while the hands do a task
    double locationCost = 0.07;      ///< s, added to tell which wrist a cue is on
    double saccade = 0.2;            ///< s, from a gaze switch to seeing the new hand
    double pressureAdaptation = 1.0; ///< s, how fast a steady squeeze fades from notice
    double firstReliance = 1.0;      ///< the share of a new warning's alarms answered
    double adaptationRate = 0.1;     ///< how far each judged alarm moves the reliance

    /** One parameter: its name on the command line and in JSON, its range, its unit. */
    struct Row
    {
        const char *name;
        double &(*field)(PersonParameters &);
        double low;
        double high;
        const char *unit; ///< "s", "dB", or "" for a ratio
    };
    static const std::vector<Row> &rows();
    /** The value of row `row`. */
    double value(const Row &row) const { return row.field(const_cast<PersonParameters &>(*this)); }

    /**
     * Applies `NAME=VALUE` (one of rows(), within its range); false with `reason` naming
     * the parameter or the range.
     */
    bool set(const QString &assignment, QString *reason);
    /** The parameters that differ from the defaults, by name. */
    QJsonObject toJson() const;
    /** Reads toJson()'s object at `pointer` over the defaults; false with the located reason. */
    static bool fromJson(JsonReader &reader, const QJsonObject &json, const QString &pointer,
                         PersonParameters *parameters);
    bool operator==(const PersonParameters &other) const;
};

} // namespace semhap
