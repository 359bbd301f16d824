// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <limits>
#include <vector>

namespace semhap {

/** What kind of value a parameter takes. */
enum class ParamKind
{
    Number,    ///< a finite number within the spec's range
    Choice,    ///< one of the spec's choices
    Choices,   ///< one of the choices or a list of them: a filter, where absent means any
    Points,    ///< a list of [x, y] pairs
    Channels,  ///< a non-empty list of channel names
    Pattern,   ///< a pattern's name or file
    Model,     ///< a device model's name or file
    ParamName, ///< the name of one of the pattern's parameters
    Start,     ///< where a ramp starts: "current", "peak" or a number
    Waveform,  ///< one waveform, the input of a modifier
    Waveforms, ///< a non-empty list of waveforms, the inputs of a combinator
    Signal,    ///< a built-in quantity (the choices) or the name of a frame's signal
    Level      ///< a number, or a [low, high] range of two numbers
};

/** What leaving a parameter out means. */
enum class ParamAbsent
{
    Required, ///< it must be given
    Default,  ///< its default applies (defaultNumber or defaultChoice)
    Any,      ///< a filter that matches everything
    Computed  ///< a value worked out from the rest of the document (say so in help)
};

/**
 * One parameter of a router node type or field of a waveform type: its name, kind, range,
 * default, unit and one-line help. The tables of these specs are the one place such rules
 * are written: loaders check values against them, editors build their fields from them.
 */
struct ParamSpec
{
    QString name;
    ParamKind kind = ParamKind::Number;
    ParamAbsent absent = ParamAbsent::Default;
    double defaultNumber = 0.0; ///< a number's value when absent (ParamAbsent::Default)
    QString defaultChoice;      ///< a choice's value when absent (ParamAbsent::Default)
    double minimum = -std::numeric_limits<double>::infinity();
    double maximum = std::numeric_limits<double>::infinity();
    bool minimumExclusive = false; ///< the minimum itself is refused ("must be positive")
    QStringList choices;           ///< Choice, Choices and Signal
    /** Choice and Choices: a plain name (isPlainName) beyond the choices is taken too. */
    bool openChoices = false;
    QString unit;       ///< a number's unit ("N", "s", "Hz"), empty when none
    QString help;       ///< one sentence, for tooltips and the reference
    QJsonValue example; ///< what an editor fills a new required parameter with; else undefined

    /** A number that defaults to `value`. */
    static ParamSpec number(const QString &name, double value, const QString &unit,
                            const QString &help);
    /** One of `choices`, defaulting to `value` (empty: required). */
    static ParamSpec choice(const QString &name, const QStringList &choices, const QString &value,
                            const QString &help);
    /** A filter over `choices`: one of them or a list; absent matches any. */
    static ParamSpec anyOf(const QString &name, const QStringList &choices, const QString &help);
    /** A value of `kind` with no default of its own. */
    static ParamSpec of(const QString &name, ParamKind kind, ParamAbsent absent,
                        const QString &help);

    ParamSpec atLeast(double value) const;                 ///< a number's inclusive minimum
    ParamSpec above(double value) const;                   ///< a number's exclusive minimum
    ParamSpec atMost(double value) const;                  ///< a number's inclusive maximum
    ParamSpec required() const;                            ///< must be given
    ParamSpec computed() const;                            ///< absent: worked out elsewhere
    ParamSpec startingWith(const QJsonValue &value) const; ///< sets example
    ParamSpec orNewName() const;                           ///< sets openChoices
    ParamSpec withChoices(const QStringList &list) const;  ///< sets choices

    /**
     * Checks a value given in a document, with the loaders' wording (`must not be negative,
     * got -1`). Names of patterns, models and parameters are checked for form only: whether
     * they exist is for the loader to say. Waveforms are not checked here.
     */
    bool check(const QJsonValue &value, QString *reason) const;
    /** Checks a number against the range. */
    bool checkNumber(double value, QString *reason) const;
    /** Why an absent required parameter is wrong: `needs "gripper" ("left" or "right")`. */
    QString missingReason() const;
    /** The value used when absent: a number, a choice, or undefined. */
    QJsonValue defaultValue() const;
    /** Whether `value` is one of the choices, or a plain name where those are taken. */
    bool isChoice(const QString &value) const;
    /** The choices as a sentence fragment: `"a", "b" or "c"`. */
    QString choiceList() const;
};

/** The spec named `name` in `specs`, or null. */
const ParamSpec *findParamSpec(const std::vector<ParamSpec> &specs, const QString &name);
/** The names of `specs`, in order. */
QStringList paramSpecNames(const std::vector<ParamSpec> &specs);

/**
 * Whether `name` has the form of a new message's or a frame signal's name: `[a-z0-9_.]+`,
 * at most MaxPlainNameLength characters.
 */
bool isPlainName(const QString &name);
/** The longest message or signal name. */
constexpr int MaxPlainNameLength = 64;

/** `value` in its shortest round-trip form, for messages that quote a number. */
QString formatNumber(double value);

} // namespace semhap
