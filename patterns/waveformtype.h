// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h"

#include <QJsonObject>
#include <QString>

#include <vector>

namespace semhap {

/**
 * A waveform type of the pattern format: its JSON name, what it makes, and its fields'
 * specs. The table is the one place waveform types are described: the parser reads its
 * keys, defaults and ranges from it, the designer builds its menu and inspector from it.
 * A Number field may be bound to a pattern parameter (`{"param": "x"}`) unless the type is
 * `param` itself.
 */
struct WaveformType
{
    QString type;
    QString description;
    std::vector<ParamSpec> fields; ///< in the order the parser hands them to the waveform

    const ParamSpec *field(const QString &name) const;
    /** Whether it takes other waveforms as inputs (`in` or `of`). */
    bool isModifier() const;
    /**
     * Whether its Number fields may be bound to a pattern parameter: all but `param`, whose
     * numbers shape the parameter it reads.
     */
    bool bindsParams() const;
};

/** Every waveform type, in menu order. */
const std::vector<WaveformType> &waveformTypes();
/** The type named `type`, or null. */
const WaveformType *waveformType(const QString &type);

/**
 * A new waveform of `type` (a `const` for an unknown one), its required fields at the
 * table's starting values. A modifier takes `previous`, when it is a waveform, as its
 * (first) input: changing a node's type to a combinator wraps it.
 */
QJsonObject newWaveform(const QString &type, const QJsonValue &previous = QJsonValue());

} // namespace semhap
