// SPDX-License-Identifier: MIT
#include "sessioninfo.h"

#include "contactframe.h"
#include "sessionclock.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>

#include <climits>
#include <cmath>
#include <functional>

namespace semhap {

namespace {

const QString FormatKey = QStringLiteral("format");
const QString SchemaKey = QStringLiteral("schema_version");
const QString SourceKey = QStringLiteral("source");
const QString SceneKey = QStringLiteral("scene");
const QString RouterKey = QStringLiteral("router");
const QString RouterSourceKey = QStringLiteral("router_source");
const QString OverridesKey = QStringLiteral("overrides");
const QString BindingsKey = QStringLiteral("bindings");
const QString OperatorKey = QStringLiteral("operator");
const QString SeedKey = QStringLiteral("seed");
const QString VersionKey = QStringLiteral("semhap_version");
const QString StartedKey = QStringLiteral("started_utc");
const QString EndedKey = QStringLiteral("ended_utc");
const QString NotesKey = QStringLiteral("notes");
const QString ReactionTimeKey = QStringLiteral("reaction_time");

/** A gripper's trait's key: `left_full_contacts`, `right_force_ripple`. */
QString traitKey(Gripper gripper, const char *trait)
{
    return gripperName(gripper) + QLatin1Char('_') + QLatin1String(trait);
}

const char *const FullContactsTrait = "full_contacts";
const char *const ForceRippleTrait = "force_ripple";

/**
 * Moves `key`'s number from `rows` to `value` when the key is there; false with `error`
 * (`KEY: expected WHAT, got 'TEXT'`) when it is not a number `valid` takes.
 */
bool takeNumber(QMap<QString, QString> &rows, const QString &key, const QString &expected,
                const std::function<bool(double)> &valid, double *value, QString *error)
{
    if (!rows.contains(key))
        return true;
    const QString text = rows.take(key);
    bool ok = false;
    const double number = text.toDouble(&ok);
    if (!ok || !valid(number)) {
        *error = QStringLiteral("%1: expected %2, got '%3'").arg(key, expected, text);
        return false;
    }
    *value = number;
    return true;
}

/** A number as text that reads back as the same double. */
QString exactNumber(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

QString compact(const QJsonDocument &document)
{
    return QString::fromUtf8(document.toJson(QJsonDocument::Compact));
}

QString utc(const QDateTime &time)
{
    return time.isValid() ? time.toUTC().toString(Qt::ISODateWithMs) : QString();
}

} // namespace

void SessionInfo::addBindings(const QStringList &list)
{
    for (const QString &binding : list)
        bindings.insert(binding.section(QLatin1Char('='), 0, 0),
                        binding.section(QLatin1Char('='), 1));
}

QMap<QString, QString> SessionInfo::toMetadata() const
{
    QMap<QString, QString> rows = extra;
    rows.insert(FormatKey, QLatin1String(Format));
    rows.insert(SchemaKey, QString::number(SchemaVersion));
    rows.insert(SourceKey, source);
    rows.insert(SceneKey, scene);
    rows.insert(RouterKey, compact(QJsonDocument(router)));
    rows.insert(RouterSourceKey, routerSource);
    rows.insert(OverridesKey, compact(QJsonDocument(QJsonArray::fromStringList(overrides))));
    rows.insert(BindingsKey, compact(QJsonDocument(bindings)));
    rows.insert(OperatorKey, operatorName);
    rows.insert(SeedKey, seed);
    rows.insert(VersionKey, semhapVersion);
    rows.insert(StartedKey, utc(started));
    if (ended.isValid())
        rows.insert(EndedKey, utc(ended));
    rows.insert(NotesKey, notes);
    rows.insert(ReactionTimeKey, exactNumber(routerContext.reactionTime));
    for (Gripper gripper : {Gripper::Left, Gripper::Right}) {
        const GripperTraits &traits = routerContext.grippers[size_t(gripper)];
        rows.insert(traitKey(gripper, FullContactsTrait), QString::number(traits.fullContacts));
        rows.insert(traitKey(gripper, ForceRippleTrait), exactNumber(traits.forceRipple));
    }
    return rows;
}

QJsonObject SessionInfo::toJson() const
{
    QJsonObject json;
    const QMap<QString, QString> rows = toMetadata();
    for (auto it = rows.begin(); it != rows.end(); ++it) {
        // A JSON key's value is written as JSON, not as a string holding JSON.
        const QJsonDocument document =
            isJsonKey(it.key()) ? QJsonDocument::fromJson(it.value().toUtf8()) : QJsonDocument();
        if (document.isObject())
            json.insert(it.key(), document.object());
        else if (document.isArray())
            json.insert(it.key(), document.array());
        else
            json.insert(it.key(), it.value());
    }
    return json;
}

bool SessionInfo::isJsonKey(const QString &key)
{
    return key == RouterKey || key == OverridesKey || key == BindingsKey ||
           key == QLatin1String(OpenAtStartKey) || key == QLatin1String(SessionClock::MetadataKey);
}

bool SessionInfo::fromMetadata(const QMap<QString, QString> &rows, SessionInfo *result,
                               QString *error)
{
    SessionInfo info;
    QMap<QString, QString> rest = rows;
    const auto take = [&rest](const QString &key) { return rest.take(key); };
    take(FormatKey);
    take(SchemaKey);
    info.source = take(SourceKey);
    info.scene = take(SceneKey);
    info.router = QJsonDocument::fromJson(take(RouterKey).toUtf8()).object();
    info.routerSource = take(RouterSourceKey);
    for (const QJsonValue &item : QJsonDocument::fromJson(take(OverridesKey).toUtf8()).array())
        info.overrides.append(item.toString());
    info.bindings = QJsonDocument::fromJson(take(BindingsKey).toUtf8()).object();
    info.operatorName = take(OperatorKey);
    info.seed = take(SeedKey);
    info.semhapVersion = take(VersionKey);
    info.started = QDateTime::fromString(take(StartedKey), Qt::ISODateWithMs);
    info.ended = QDateTime::fromString(take(EndedKey), Qt::ISODateWithMs);
    info.notes = take(NotesKey);
    // Sessions recorded before the router had a context ran it with the defaults: a key
    // missing leaves its default.
    RouterContext &context = info.routerContext;
    const auto seconds = [](double s) { return s >= 0.0 && s <= MaxReactionTime; };
    const auto count = [](double n) { return n >= 0 && n <= INT_MAX && n == std::floor(n); };
    const auto newtons = [](double f) { return f >= 0.0 && std::isfinite(f); };
    if (!takeNumber(rest, ReactionTimeKey,
                    QStringLiteral("seconds from 0 to %1").arg(MaxReactionTime), seconds,
                    &context.reactionTime, error))
        return false;
    for (Gripper gripper : {Gripper::Left, Gripper::Right}) {
        GripperTraits &traits = context.grippers[size_t(gripper)];
        double contacts = traits.fullContacts;
        if (!takeNumber(rest, traitKey(gripper, FullContactsTrait),
                        QStringLiteral("a whole number of contacts"), count, &contacts, error) ||
            !takeNumber(rest, traitKey(gripper, ForceRippleTrait),
                        QStringLiteral("newtons, 0 or more"), newtons, &traits.forceRipple, error))
            return false;
        traits.fullContacts = int(contacts);
    }
    info.extra = rest;
    *result = info;
    return true;
}

} // namespace semhap
