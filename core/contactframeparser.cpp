// SPDX-License-Identifier: MIT
#include "contactframeparser.h"

#include "detectorparams.h"
#include "jsonreader.h"
#include "nametable.h"
#include "routernodes.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <climits>
#include <cmath>
#include <tuple>

namespace semhap {

namespace {

/** The offending value as the reason quotes it: numbers short, strings quoted and cut. */
QString describe(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return formatNumber(value.toDouble());
    case QJsonValue::String: {
        const QString text = value.toString();
        constexpr int MaxQuoted = 40;
        if (text.size() > MaxQuoted)
            return QLatin1Char('"') + text.left(MaxQuoted) + QStringLiteral("...\"");
        return QLatin1Char('"') + text + QLatin1Char('"');
    }
    default:
        return jsonTypeName(value);
    }
}

QString quotedField(const QString &field)
{
    return QLatin1Char('"') + field + QLatin1Char('"');
}

bool fail(QString *reason, const QString &why)
{
    *reason = why;
    return false;
}

} // namespace

bool ContactFrameParser::parse(const QByteArray &json, ContactFrame *frame, QString *reason)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError) {
        return fail(reason, QStringLiteral("invalid JSON at column %1: %2")
                                .arg(error.offset + 1)
                                .arg(error.errorString()));
    }
    if (!document.isObject()) {
        return fail(reason, QStringLiteral("a contact frame must be a JSON object, got %1")
                                .arg(document.isArray() ? QStringLiteral("an array")
                                                        : QStringLiteral("a scalar")));
    }
    return parse(document.object(), frame, reason);
}

bool ContactFrameParser::parse(const QJsonObject &json, ContactFrame *frame, QString *reason)
{
    const QJsonValue t = json.value(QLatin1String("t"));
    if (t.isUndefined())
        return fail(reason, QStringLiteral("\"t\" is missing"));
    if (!t.isDouble() || !std::isfinite(t.toDouble()))
        return fail(reason,
                    QStringLiteral("\"t\" must be a finite number, got %1").arg(describe(t)));

    const QJsonValue gripperValue = json.value(QLatin1String("gripper"));
    if (gripperValue.isUndefined())
        return fail(reason, QStringLiteral("\"gripper\" is missing"));
    Gripper gripper = Gripper::Right;
    if (!gripperValue.isString() || !gripperFromName(gripperValue.toString(), &gripper)) {
        return fail(reason, QStringLiteral("\"gripper\" must be \"left\" or \"right\", got %1")
                                .arg(describe(gripperValue)));
    }

    ContactFrame parsed;
    parsed.t = t.toDouble();
    parsed.gripper = gripper;
    QString leftActor;
    QString rightActor;
    if (!parseFingertip(json, QLatin1String("left"), &parsed.left, &leftActor, reason) ||
        !parseFingertip(json, QLatin1String("right"), &parsed.right, &rightActor, reason) ||
        !checkFingertip(parsed.left, QLatin1String("left"), reason) ||
        !checkFingertip(parsed.right, QLatin1String("right"), reason) ||
        !checkClock(parsed, reason) || !parseSignals(json, &parsed.signalValues, reason))
        return false;
    take(&parsed, leftActor, rightActor);
    *frame = parsed;
    return true;
}

bool ContactFrameParser::accept(ContactFrame *frame, const QString &leftActor,
                                const QString &rightActor, QString *reason)
{
    if (!std::isfinite(frame->t))
        return fail(
            reason,
            QStringLiteral("\"t\" must be a finite number, got %1").arg(formatNumber(frame->t)));
    for (const auto &[tip, name, actor] :
         {std::tuple(&frame->left, QLatin1String("left"), &leftActor),
          std::tuple(&frame->right, QLatin1String("right"), &rightActor)}) {
        if (!checkFingertip(*tip, name, reason))
            return false;
        if (actor->isNull() != (tip->actor < 0)) // a named actor's name must be known
            return fail(reason, QStringLiteral("%1 names no actor of the session")
                                    .arg(quotedField(name + QLatin1String(".actor"))));
    }
    for (const SignalValue &signal : frame->signalValues) {
        if (!std::isfinite(signal.value))
            return fail(reason, QStringLiteral("%1 must be a finite number, got %2")
                                    .arg(quotedField(QStringLiteral("signals.") +
                                                     signalNames().name(signal.id)),
                                         formatNumber(signal.value)));
    }
    if (!checkClock(*frame, reason))
        return false;
    take(frame, leftActor, rightActor);
    return true;
}

bool ContactFrameParser::checkSignalName(const QString &name, QString *reason)
{
    static const QStringList builtins = SignalNode::quantityNames();
    const QString field = quotedField(QStringLiteral("signals.") + name);
    if (!isPlainName(name))
        return fail(reason, QStringLiteral("%1: a signal's name must be 1 to %2 characters "
                                           "of a-z, 0-9, _ and .")
                                .arg(field)
                                .arg(MaxPlainNameLength));
    if (builtins.contains(name))
        return fail(reason, QStringLiteral("%1: \"%2\" is a built-in quantity, not a signal name")
                                .arg(field, name));
    return true;
}

bool ContactFrameParser::checkClock(const ContactFrame &frame, QString *reason) const
{
    if (std::abs(frame.t) > MaxTime)
        return fail(reason, QStringLiteral("\"t\" must be within ±%1 s, got %2")
                                .arg(formatNumber(MaxTime), formatNumber(frame.t)));
    const size_t g = size_t(frame.gripper);
    // A jump far past the stream's clock is a sender gone wrong, not a pause: every device
    // instant in between would have to be rendered.
    bool started = false;
    double latest = 0.0;
    for (size_t i = 0; i < m_seen.size(); ++i) {
        if (m_seen[i]) {
            latest = started ? std::max(latest, m_lastT[i]) : m_lastT[i];
            started = true;
        }
    }
    if (started && frame.t - latest > m_maxGap) {
        return fail(reason, QStringLiteral("\"t\" jumps by %1 s, more than the %2 s allowed "
                                           "(--max-gap)")
                                .arg(formatNumber(frame.t - latest), formatNumber(m_maxGap)));
    }
    if (m_seen[g] && !(frame.t > m_lastT[g])) {
        return fail(reason, QStringLiteral("\"t\" must increase per gripper, got %1 after %2 "
                                           "for \"%3\"")
                                .arg(formatNumber(frame.t), formatNumber(m_lastT[g]),
                                     gripperName(frame.gripper)));
    }
    return true;
}

void ContactFrameParser::take(ContactFrame *frame, const QString &leftActor,
                              const QString &rightActor)
{
    // Only a valid frame may change state: the clock and the actor table.
    m_seen[size_t(frame->gripper)] = true;
    m_lastT[size_t(frame->gripper)] = frame->t;
    frame->left.actor = m_actors.intern(leftActor);
    frame->right.actor = m_actors.intern(rightActor);
}

bool ContactFrameParser::checkFingertip(const Fingertip &tip, QLatin1String name, QString *reason)
{
    const QString prefix = name + QLatin1Char('.');
    if (!std::isfinite(tip.f) || tip.f < 0.0)
        return fail(reason, QStringLiteral("%1 must be a finite non-negative number, got %2")
                                .arg(quotedField(prefix + u'f'), formatNumber(tip.f)));
    if (tip.n < 0)
        return fail(reason, QStringLiteral("%1 must be a non-negative integer, got %2")
                                .arg(quotedField(prefix + u'n'))
                                .arg(tip.n));
    for (size_t i = 0; tip.hasFxyz && i < 3; ++i) {
        if (!std::isfinite(tip.fxyz[i]))
            return fail(reason, QStringLiteral("%1 must be an array of 3 finite numbers, got "
                                               "an array")
                                    .arg(quotedField(prefix + QLatin1String("fxyz"))));
    }
    if (!std::isfinite(tip.mu) || tip.mu < 0.0)
        return fail(reason,
                    QStringLiteral("%1 must be a finite positive number or null, got %2")
                        .arg(quotedField(prefix + QLatin1String("mu")), formatNumber(tip.mu)));
    return true;
}

bool ContactFrameParser::parseSignals(const QJsonObject &json, FrameSignals *signalValues,
                                      QString *reason)
{
    const QJsonValue value = json.value(QLatin1String("signals"));
    if (value.isUndefined() || value.isNull())
        return true;
    if (!value.isObject())
        return fail(
            reason,
            QStringLiteral("\"signals\" must be an object or null, got %1").arg(describe(value)));
    const QJsonObject object = value.toObject();
    if (object.size() > FrameSignals::Capacity)
        return fail(reason, QStringLiteral("\"signals\" has %1 signals, more than the %2 a "
                                           "frame may carry")
                                .arg(object.size())
                                .arg(FrameSignals::Capacity));
    // Every name and value first: a rejected line must not grow the name table.
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!checkSignalName(it.key(), reason))
            return false;
        if (!it.value().isDouble() || !std::isfinite(it.value().toDouble()))
            return fail(reason, QStringLiteral("%1 must be a finite number, got %2")
                                    .arg(quotedField(QStringLiteral("signals.") + it.key()),
                                         describe(it.value())));
    }
    for (auto it = object.begin(); it != object.end(); ++it) {
        const int id = signalNames().intern(it.key());
        if (id < 0)
            return fail(reason, QStringLiteral("\"signals.%1\": more distinct signal names "
                                               "than the %2 semhap holds")
                                    .arg(it.key())
                                    .arg(NameTable::Capacity));
        signalValues->set(id, it.value().toDouble());
    }
    return true;
}

bool ContactFrameParser::parseFingertip(const QJsonObject &json, QLatin1String name,
                                        Fingertip *tip, QString *actor, QString *reason) const
{
    const QJsonValue value = json.value(name);
    if (value.isUndefined() || value.isNull())
        return true;
    if (!value.isObject()) {
        return fail(reason, QStringLiteral("%1 must be an object or null, got %2")
                                .arg(quotedField(name), describe(value)));
    }
    const QJsonObject object = value.toObject();
    const QString prefix = name + QLatin1Char('.');

    const QJsonValue f = object.value(QLatin1String("f"));
    if (f.isUndefined())
        return fail(reason, QStringLiteral("%1 is missing").arg(quotedField(prefix + u'f')));
    if (!f.isDouble()) { // its range is checkFingertip()'s
        return fail(reason, QStringLiteral("%1 must be a finite non-negative number, got %2")
                                .arg(quotedField(prefix + u'f'), describe(f)));
    }

    const QJsonValue n = object.value(QLatin1String("n"));
    if (n.isUndefined())
        return fail(reason, QStringLiteral("%1 is missing").arg(quotedField(prefix + u'n')));
    const double count = n.toDouble(-1.0);
    if (!n.isDouble() || !(count >= 0.0) || count > double(INT_MAX) ||
        count != std::floor(count)) {
        return fail(reason, QStringLiteral("%1 must be a non-negative integer, got %2")
                                .arg(quotedField(prefix + u'n'), describe(n)));
    }

    const QJsonValue actorValue = object.value(QLatin1String("actor"));
    const QString actorField = quotedField(prefix + QLatin1String("actor"));
    if (actorValue.isUndefined())
        return fail(reason, QStringLiteral("%1 is missing").arg(actorField));
    if (!actorValue.isNull() && (!actorValue.isString() || actorValue.toString().isEmpty())) {
        return fail(reason, QStringLiteral("%1 must be a non-empty string or null, got %2")
                                .arg(actorField, describe(actorValue)));
    }

    const QJsonValue fxyz = object.value(QLatin1String("fxyz"));
    std::array<double, 3> components{};
    const bool hasFxyz = !fxyz.isUndefined() && !fxyz.isNull();
    if (hasFxyz) {
        const QJsonArray array = fxyz.toArray();
        bool valid = fxyz.isArray() && array.size() == 3;
        for (qsizetype i = 0; valid && i < 3; ++i) {
            components[size_t(i)] = array.at(i).toDouble(qQNaN());
            valid = array.at(i).isDouble();
        }
        if (!valid) {
            return fail(reason,
                        QStringLiteral("%1 must be an array of 3 finite numbers, got %2")
                            .arg(quotedField(prefix + QLatin1String("fxyz")), describe(fxyz)));
        }
    }

    const QJsonValue mu = object.value(QLatin1String("mu"));
    const bool hasMu = !mu.isUndefined() && !mu.isNull();
    if (hasMu && (!mu.isDouble() || !std::isfinite(mu.toDouble()) || mu.toDouble() <= 0.0)) {
        return fail(reason, QStringLiteral("%1 must be a finite positive number or null, got %2")
                                .arg(quotedField(prefix + QLatin1String("mu")), describe(mu)));
    }

    tip->f = f.toDouble();
    tip->n = int(count);
    tip->hasFxyz = hasFxyz;
    tip->fxyz = components;
    tip->mu = hasMu ? mu.toDouble() : 0.0;
    *actor = actorValue.toString();
    return true;
}

} // namespace semhap
