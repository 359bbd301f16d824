// SPDX-License-Identifier: MIT
#include "topicmap.h"

#include "jsonreader.h"
#include "mcapexport.h"

namespace semhap {

namespace {

const QLatin1String Format("semhap.topics/1");

struct AxisName
{
    const char *name;
    TopicMap::Axis axis;
};

const AxisName Axes[] = {
    {"x", TopicMap::Axis::PlusX},   {"-x", TopicMap::Axis::MinusX}, {"y", TopicMap::Axis::PlusY},
    {"-y", TopicMap::Axis::MinusY}, {"z", TopicMap::Axis::PlusZ},   {"-z", TopicMap::Axis::MinusZ},
};

bool readSource(JsonReader &reader, const QJsonObject &json, const QString &pointer,
                TopicMap::Source *source)
{
    return reader.checkKeys(json, pointer, {QLatin1String("topic"), QLatin1String("field")}) &&
           reader.nonEmptyString(json, pointer, QLatin1String("topic"), &source->topic) &&
           reader.nonEmptyString(json, pointer, QLatin1String("field"), &source->field);
}

bool readTip(JsonReader &reader, const QJsonObject &json, const QString &pointer,
             TopicMap::Tip *tip)
{
    if (!reader.checkKeys(json, pointer,
                          {QLatin1String("topic"), QLatin1String("force"),
                           QLatin1String("normal_axis"), QLatin1String("contact_threshold"),
                           QLatin1String("actor"), QLatin1String("mu"), QLatin1String("count")}) ||
        !reader.nonEmptyString(json, pointer, QLatin1String("topic"), &tip->topic) ||
        !reader.string(json, pointer, QLatin1String("force"), &tip->force, false) ||
        !reader.number(json, pointer, QLatin1String("contact_threshold"), &tip->contactThreshold,
                       false) ||
        !reader.string(json, pointer, QLatin1String("actor"), &tip->actor, false) ||
        !reader.number(json, pointer, QLatin1String("mu"), &tip->mu, false))
        return false;
    if (tip->force.isEmpty())
        return reader.fail(pointer + QStringLiteral("/force"),
                           QStringLiteral("expected the path "
                                          "of a force vector"));
    if (tip->contactThreshold < 0)
        return reader.fail(pointer + QStringLiteral("/contact_threshold"),
                           QStringLiteral("expected a force of 0 N or more"));
    if (tip->mu < 0)
        return reader.fail(pointer + QStringLiteral("/mu"),
                           QStringLiteral("expected a coefficient of 0 or more"));
    if (tip->actor.isEmpty())
        return reader.fail(pointer + QStringLiteral("/actor"),
                           QStringLiteral("expected the name of what the tip touches"));
    QString axis = QStringLiteral("y");
    if (!reader.string(json, pointer, QLatin1String("normal_axis"), &axis, false))
        return false;
    bool known = false;
    QStringList names;
    for (const AxisName &a : Axes) {
        names << QLatin1String(a.name);
        if (axis == QLatin1String(a.name)) {
            tip->normalAxis = a.axis;
            known = true;
        }
    }
    if (!known)
        return reader.fail(pointer + QStringLiteral("/normal_axis"),
                           QStringLiteral("expected one of %1, got %2")
                               .arg(names.join(QStringLiteral(", ")), quoted(axis)));
    QJsonObject count;
    if (!reader.object(json, pointer, QLatin1String("count"), &count, false))
        return false;
    tip->hasCount = json.contains(QLatin1String("count"));
    if (tip->hasCount &&
        !readSource(reader, count, pointer + QStringLiteral("/count"), &tip->count))
        return false;
    tip->present = true;
    return true;
}

} // namespace

bool TopicMap::load(const QString &path, TopicMap *map, LoadError *error)
{
    if (path == QLatin1String("semhap")) {
        *map = McapExport::topicMap();
        return true;
    }
    QJsonObject json;
    if (!readJsonObjectFile(path, &json, error) || !checkFormat(json, path, Format, error))
        return false;
    JsonReader reader(path);
    if (!fromJson(reader, json, map)) {
        *error = reader.error();
        return false;
    }
    return true;
}

bool TopicMap::fromJson(JsonReader &reader, const QJsonObject &json, TopicMap *map)
{
    TopicMap m;
    if (!reader.checkKeys(
            json, QString(),
            {QLatin1String("format"), QLatin1String("time"), QLatin1String("grippers")}))
        return false;
    QString time = QStringLiteral("header");
    if (!reader.string(json, QString(), QLatin1String("time"), &time, false))
        return false;
    if (time != QLatin1String("header") && time != QLatin1String("log"))
        return reader.fail(QStringLiteral("/time"),
                           QStringLiteral("expected 'header' or 'log', got %1").arg(quoted(time)));
    m.time = time == QLatin1String("log") ? Time::Log : Time::Header;
    QJsonObject grippers;
    if (!reader.object(json, QString(), QLatin1String("grippers"), &grippers))
        return false;
    if (!reader.checkKeys(grippers, QStringLiteral("/grippers"),
                          {QLatin1String("left"), QLatin1String("right")}))
        return false;
    if (grippers.isEmpty())
        return reader.fail(QStringLiteral("/grippers"),
                           QStringLiteral("expected a gripper: left or right"));
    for (const Gripper g : {Gripper::Left, Gripper::Right}) {
        const QLatin1String name(g == Gripper::Left ? "left" : "right");
        if (!grippers.contains(name))
            continue;
        const QString at = QStringLiteral("/grippers/") + name;
        QJsonObject gj;
        if (!reader.object(grippers, QStringLiteral("/grippers"), name, &gj))
            return false;
        if (!reader.checkKeys(gj, at,
                              {QLatin1String("clock"), QLatin1String("left"),
                               QLatin1String("right"), QLatin1String("signals")}))
            return false;
        GripperTopics &topics = m.grippers[size_t(g)];
        topics.present = true;
        for (const auto &[key, tip] : {std::pair{QLatin1String("left"), &topics.left},
                                       std::pair{QLatin1String("right"), &topics.right}}) {
            QJsonObject tj;
            if (!reader.object(gj, at, key, &tj, false))
                return false;
            if (gj.contains(key) && !readTip(reader, tj, at + QLatin1Char('/') + key, tip))
                return false;
        }
        if (!topics.left.present && !topics.right.present)
            return reader.fail(at, QStringLiteral("expected a fingertip: left or right"));
        if (!reader.string(gj, at, QLatin1String("clock"), &topics.clock, false))
            return false;
        if (topics.clock.isEmpty())
            topics.clock = topics.left.present ? topics.left.topic : topics.right.topic;
        QJsonObject signalsJson;
        if (!reader.object(gj, at, QLatin1String("signals"), &signalsJson, false))
            return false;
        for (auto it = signalsJson.begin(); it != signalsJson.end(); ++it) {
            const QString where = jsonPointerChild(at + QStringLiteral("/signals"), it.key());
            if (!it->isObject())
                return reader.fail(where, QStringLiteral("expected an object with topic and "
                                                         "field, got %1")
                                              .arg(jsonTypeName(*it)));
            Signal signal;
            signal.name = it.key();
            if (!readSource(reader, it->toObject(), where, &signal.source))
                return false;
            topics.signalList.push_back(signal);
        }
        QStringList own;
        for (const Tip *tip : {&topics.left, &topics.right}) {
            if (tip->present)
                own << tip->topic << (tip->hasCount ? tip->count.topic : QString());
        }
        for (const Signal &signal : topics.signalList)
            own << signal.source.topic;
        if (!own.contains(topics.clock))
            return reader.fail(
                at + QStringLiteral("/clock"),
                QStringLiteral("%1 is none of this gripper's topics").arg(quoted(topics.clock)));
    }
    *map = m;
    return true;
}

QStringList TopicMap::topics() const
{
    QStringList out;
    const auto add = [&](const QString &topic) {
        if (!topic.isEmpty() && !out.contains(topic))
            out << topic;
    };
    for (const GripperTopics &g : grippers) {
        for (const Tip *tip : {&g.left, &g.right}) {
            if (!tip->present)
                continue;
            add(tip->topic);
            if (tip->hasCount)
                add(tip->count.topic);
        }
        for (const Signal &s : g.signalList)
            add(s.source.topic);
    }
    return out;
}

std::array<double, 3> TopicMap::rotate(Axis axis, const std::array<double, 3> &f)
{
    const auto [x, y, z] = f;
    switch (axis) {
    case Axis::PlusY:
        return {x, y, z};
    case Axis::MinusY:
        return {-x, -y, z};
    case Axis::PlusX:
        return {-y, x, z};
    case Axis::MinusX:
        return {y, -x, z};
    case Axis::PlusZ:
        return {x, z, -y};
    case Axis::MinusZ:
        return {x, -z, y};
    }
    return f;
}

} // namespace semhap
