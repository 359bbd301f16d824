// SPDX-License-Identifier: MIT
#include "paramspec.h"

#include "jsonreader.h"

#include <QJsonArray>
#include <QLocale>

#include <cmath>

namespace semhap {

namespace {

// What a value of `spec` looks like, for "needs" and "must be" messages.
QString expected(const ParamSpec &spec)
{
    switch (spec.kind) {
    case ParamKind::Number:
        return QStringLiteral("a finite number");
    case ParamKind::Choice:
        return spec.openChoices ? spec.choiceList() + QStringLiteral(" or a new name of "
                                                                     "[a-z0-9_.]")
                                : spec.choiceList();
    case ParamKind::Choices:
        return spec.choiceList() + (spec.openChoices
                                        ? QStringLiteral(" or a new name of [a-z0-9_.], or a list")
                                        : QStringLiteral(", or a list of them"));
    case ParamKind::Signal:
        return spec.choiceList() + QStringLiteral(" or a signal's name of [a-z0-9_.]");
    case ParamKind::Level:
        return QStringLiteral("a finite number or a [low, high] range");
    case ParamKind::Points:
        return QStringLiteral("a list of [x, y] points with x increasing");
    case ParamKind::Channels:
        return QStringLiteral("a non-empty array of channel names");
    case ParamKind::Pattern:
        return QStringLiteral("a pattern name or file");
    case ParamKind::Model:
        return QStringLiteral("a device model name or file");
    case ParamKind::ParamName:
        return QStringLiteral("a parameter name");
    case ParamKind::Start:
        return QStringLiteral("\"current\", \"peak\" or a number");
    case ParamKind::Waveform:
        return QStringLiteral("a waveform");
    case ParamKind::Waveforms:
        return QStringLiteral("a non-empty list of waveforms");
    }
    return QString();
}

bool isName(const QJsonValue &value)
{
    return value.isString() && !value.toString().isEmpty();
}

bool checkPoints(const QJsonValue &value)
{
    const QJsonArray points = value.toArray();
    if (!value.isArray() || points.isEmpty())
        return false;
    double last = -std::numeric_limits<double>::infinity();
    for (const QJsonValue &point : points) {
        const QJsonArray xy = point.toArray();
        if (xy.size() != 2 || !xy.at(0).isDouble() || !xy.at(1).isDouble() ||
            !std::isfinite(xy.at(0).toDouble()) || !std::isfinite(xy.at(1).toDouble()) ||
            xy.at(0).toDouble() <= last)
            return false;
        last = xy.at(0).toDouble();
    }
    return true;
}

bool checkChannels(const QJsonValue &value)
{
    const QJsonArray channels = value.toArray();
    if (!value.isArray() || channels.isEmpty())
        return false;
    for (const QJsonValue &channel : channels) {
        if (!isName(channel))
            return false;
    }
    return true;
}

} // namespace

ParamSpec ParamSpec::number(const QString &name, double value, const QString &unit,
                            const QString &help)
{
    ParamSpec spec;
    spec.name = name;
    spec.defaultNumber = value;
    spec.unit = unit;
    spec.help = help;
    return spec;
}

ParamSpec ParamSpec::choice(const QString &name, const QStringList &choices, const QString &value,
                            const QString &help)
{
    ParamSpec spec;
    spec.name = name;
    spec.kind = ParamKind::Choice;
    spec.absent = value.isEmpty() ? ParamAbsent::Required : ParamAbsent::Default;
    spec.defaultChoice = value;
    spec.choices = choices;
    spec.help = help;
    return spec;
}

ParamSpec ParamSpec::anyOf(const QString &name, const QStringList &choices, const QString &help)
{
    ParamSpec spec;
    spec.name = name;
    spec.kind = ParamKind::Choices;
    spec.absent = ParamAbsent::Any;
    spec.choices = choices;
    spec.help = help;
    return spec;
}

ParamSpec ParamSpec::of(const QString &name, ParamKind kind, ParamAbsent absent,
                        const QString &help)
{
    ParamSpec spec;
    spec.name = name;
    spec.kind = kind;
    spec.absent = absent;
    spec.help = help;
    return spec;
}

ParamSpec ParamSpec::atLeast(double value) const
{
    ParamSpec spec = *this;
    spec.minimum = value;
    spec.minimumExclusive = false;
    return spec;
}

ParamSpec ParamSpec::above(double value) const
{
    ParamSpec spec = *this;
    spec.minimum = value;
    spec.minimumExclusive = true;
    return spec;
}

ParamSpec ParamSpec::atMost(double value) const
{
    ParamSpec spec = *this;
    spec.maximum = value;
    return spec;
}

ParamSpec ParamSpec::required() const
{
    ParamSpec spec = *this;
    spec.absent = ParamAbsent::Required;
    return spec;
}

ParamSpec ParamSpec::computed() const
{
    ParamSpec spec = *this;
    spec.absent = ParamAbsent::Computed;
    return spec;
}

ParamSpec ParamSpec::startingWith(const QJsonValue &value) const
{
    ParamSpec spec = *this;
    spec.example = value;
    return spec;
}

ParamSpec ParamSpec::withChoices(const QStringList &list) const
{
    ParamSpec spec = *this;
    spec.choices = list;
    return spec;
}

ParamSpec ParamSpec::orNewName() const
{
    ParamSpec spec = *this;
    spec.openChoices = true;
    return spec;
}

bool ParamSpec::checkNumber(double value, QString *reason) const
{
    const QString got = QStringLiteral(", got ") + formatNumber(value);
    const bool low = minimumExclusive ? !(value > minimum) : !(value >= minimum);
    const bool high = !(value <= maximum);
    if (!low && !high)
        return true;
    if (std::isfinite(minimum) && std::isfinite(maximum))
        *reason = QStringLiteral("must be within [%1, %2]")
                      .arg(formatNumber(minimum), formatNumber(maximum)) +
                  got;
    else if (high)
        *reason = QStringLiteral("must be at most ") + formatNumber(maximum) + got;
    else if (minimum == 0.0)
        *reason = (minimumExclusive ? QStringLiteral("must be positive")
                                    : QStringLiteral("must not be negative")) +
                  got;
    else
        *reason = (minimumExclusive ? QStringLiteral("must be greater than ")
                                    : QStringLiteral("must be at least ")) +
                  formatNumber(minimum) + got;
    return false;
}

bool ParamSpec::check(const QJsonValue &value, QString *reason) const
{
    bool ok = true;
    switch (kind) {
    case ParamKind::Number:
        if (!value.isDouble() || !std::isfinite(value.toDouble())) {
            *reason = QStringLiteral("must be a finite number, found ") + jsonTypeName(value);
            return false;
        }
        return checkNumber(value.toDouble(), reason);
    case ParamKind::Choice:
    case ParamKind::Signal:
        ok = value.isString() && isChoice(value.toString());
        break;
    case ParamKind::Choices: {
        const QJsonArray list = value.isArray() ? value.toArray() : QJsonArray{value};
        ok = !list.isEmpty();
        for (const QJsonValue &item : list)
            ok = ok && item.isString() && isChoice(item.toString());
        break;
    }
    case ParamKind::Level: {
        const QJsonArray range = value.toArray();
        const auto finite = [](const QJsonValue &v) {
            return v.isDouble() && std::isfinite(v.toDouble());
        };
        ok = finite(value) ||
             (value.isArray() && range.size() == 2 && finite(range[0]) && finite(range[1]));
        break;
    }
    case ParamKind::Points:
        ok = checkPoints(value);
        break;
    case ParamKind::Channels:
        ok = checkChannels(value);
        break;
    case ParamKind::Pattern:
    case ParamKind::Model:
    case ParamKind::ParamName:
        ok = isName(value);
        break;
    case ParamKind::Start:
        ok = value.isDouble() || value.toString() == QLatin1String("current") ||
             value.toString() == QLatin1String("peak");
        break;
    case ParamKind::Waveform:
    case ParamKind::Waveforms:
        return true;
    }
    if (!ok)
        *reason = QStringLiteral("must be ") + expected(*this);
    return ok;
}

bool ParamSpec::isChoice(const QString &value) const
{
    return choices.contains(value) ||
           ((openChoices || kind == ParamKind::Signal) && isPlainName(value));
}

QString ParamSpec::missingReason() const
{
    return QStringLiteral("needs \"%1\": %2").arg(name, expected(*this));
}

QJsonValue ParamSpec::defaultValue() const
{
    if (absent != ParamAbsent::Default)
        return QJsonValue(QJsonValue::Undefined);
    if (kind == ParamKind::Number)
        return defaultNumber;
    if (kind == ParamKind::Choice)
        return defaultChoice;
    return QJsonValue(QJsonValue::Undefined);
}

QString ParamSpec::choiceList() const
{
    QStringList quotedChoices;
    for (const QString &choice : choices)
        quotedChoices.append(QLatin1Char('"') + choice + QLatin1Char('"'));
    if (quotedChoices.size() < 2)
        return quotedChoices.join(QString());
    const QString last = quotedChoices.takeLast();
    return quotedChoices.join(QStringLiteral(", ")) + QStringLiteral(" or ") + last;
}

bool isPlainName(const QString &name)
{
    if (name.isEmpty() || name.size() > MaxPlainNameLength)
        return false;
    for (const QChar c : name) {
        const char16_t u = c.unicode();
        if (!((u >= 'a' && u <= 'z') || (u >= '0' && u <= '9') || u == '_' || u == '.'))
            return false;
    }
    return true;
}

const ParamSpec *findParamSpec(const std::vector<ParamSpec> &specs, const QString &name)
{
    for (const ParamSpec &spec : specs) {
        if (spec.name == name)
            return &spec;
    }
    return nullptr;
}

QStringList paramSpecNames(const std::vector<ParamSpec> &specs)
{
    QStringList names;
    for (const ParamSpec &spec : specs)
        names.append(spec.name);
    return names;
}

QString formatNumber(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

} // namespace semhap
