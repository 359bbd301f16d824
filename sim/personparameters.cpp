// SPDX-License-Identifier: MIT
#include "personparameters.h"

#include "jsonreader.h"

#include <cmath>

namespace semhap {

namespace {

// Rows name the fields through small accessors, so that a parameter of the shared senses and
// one of the person read the same way.
#define SEMHAP_FIELD(expr) [](PersonParameters &p) -> double & { return p.expr; }

} // namespace

const std::vector<PersonParameters::Row> &PersonParameters::rows()
{
    // Ranges as docs/operator.md and docs/perception.md give them, with their sources.
    static const std::vector<Row> rows{
        {"vibration_level_jnd", SEMHAP_FIELD(senses.vibrationLevelJnd), 1.6, 4.0, "dB"},
        {"pressure_level_weber", SEMHAP_FIELD(senses.pressureLevelWeber), 0.07, 0.30, ""},
        {"sight_level_weber", SEMHAP_FIELD(senses.sightLevelWeber), 0.01, 0.1, ""},
        {"rate_weber", SEMHAP_FIELD(senses.rateWeber), 0.1, 0.25, ""},
        {"duration_weber", SEMHAP_FIELD(senses.durationWeber), 0.10, 0.25, ""},
        {"shortest_rise", SEMHAP_FIELD(senses.shortestRise), 0.02, 0.05, "s"},
        {"wrist_places", SEMHAP_FIELD(senses.wristPlaces), 2.0, 4.0, ""},
        {"vibration_detection", SEMHAP_FIELD(senses.vibrationDetection), 0.02, 0.06, ""},
        {"pressure_detection", SEMHAP_FIELD(senses.pressureDetection), 0.01, 0.1, ""},
        {"sight_detection", SEMHAP_FIELD(senses.sightDetection), 0.01, 0.05, ""},
        {"touch_reaction", SEMHAP_FIELD(touchReaction), 0.20, 0.30, "s"},
        {"sight_reaction", SEMHAP_FIELD(sightReaction), 0.20, 0.30, "s"},
        {"reaction_sd", SEMHAP_FIELD(reactionSd), 0.02, 0.05, "s"},
        {"reaction_tail", SEMHAP_FIELD(reactionTail), 0.03, 0.10, "s"},
        {"dual_task_cost", SEMHAP_FIELD(dualTaskCost), 0.13, 0.30, "s"},
        {"location_cost", SEMHAP_FIELD(locationCost), 0.02, 0.12, "s"},
        {"saccade", SEMHAP_FIELD(saccade), 0.15, 0.25, "s"},
        {"pressure_adaptation", SEMHAP_FIELD(pressureAdaptation), 0.5, 5.0, "s"},
        {"first_reliance", SEMHAP_FIELD(firstReliance), 0.5, 1.0, ""},
        {"adaptation_rate", SEMHAP_FIELD(adaptationRate), 0.02, 0.3, ""},
    };
    return rows;
}

#undef SEMHAP_FIELD

bool PersonParameters::set(const QString &assignment, QString *reason)
{
    const qsizetype equals = assignment.indexOf(QLatin1Char('='));
    const QString name = assignment.left(equals);
    for (const Row &row : rows()) {
        if (equals < 0 || name != QLatin1String(row.name))
            continue;
        bool ok = false;
        const double value = assignment.mid(equals + 1).toDouble(&ok);
        if (!ok || !(value >= row.low && value <= row.high)) {
            // The default is stated so that a sweep over the range knows which end it already has.
            *reason = QStringLiteral("%1: expected a number from %2 to %3%4 (default %5)")
                          .arg(assignment)
                          .arg(row.low)
                          .arg(row.high)
                          .arg(*row.unit ? QStringLiteral(" ") + QLatin1String(row.unit)
                                         : QString())
                          .arg(PersonParameters().value(row));
            return false;
        }
        row.field(*this) = value;
        return true;
    }
    QStringList names;
    for (const Row &row : rows())
        names.append(QLatin1String(row.name));
    *reason = QStringLiteral("%1: expected NAME=VALUE, NAME one of %2")
                  .arg(assignment, names.join(QStringLiteral(", ")));
    return false;
}

QJsonObject PersonParameters::toJson() const
{
    const PersonParameters defaults;
    QJsonObject json;
    for (const Row &row : rows()) {
        if (value(row) != defaults.value(row))
            json.insert(QLatin1String(row.name), value(row));
    }
    return json;
}

bool PersonParameters::fromJson(JsonReader &reader, const QJsonObject &json,
                                const QString &pointer, PersonParameters *parameters)
{
    PersonParameters p;
    for (auto it = json.begin(); it != json.end(); ++it) {
        const QString where = jsonPointerChild(pointer, it.key());
        double number = 0.0;
        if (!reader.finiteNumber(it.value(), where, &number))
            return false;
        QString reason;
        if (!p.set(it.key() + QLatin1Char('=') + QString::number(number, 'g', 17), &reason))
            return reader.fail(where, reason.mid(reason.indexOf(QLatin1String(": ")) + 2));
    }
    *parameters = p;
    return true;
}

bool PersonParameters::operator==(const PersonParameters &other) const
{
    for (const Row &row : rows()) {
        if (value(row) != other.value(row))
            return false;
    }
    return true;
}

} // namespace semhap
