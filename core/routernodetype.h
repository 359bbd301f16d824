// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace semhap {

/** What flows along a link: semantic events, a continuous value, or a voice's channels. */
enum class PortType
{
    Event,
    Signal,
    Voice
};

QString portTypeName(PortType type);

/** One port of a node type. */
struct PortSpec
{
    QString name;
    PortType type;
    bool multiple; ///< inputs: accepts several links; outputs always do
};

/**
 * A router node type: its ports and its parameters' specs. The table is the one place node
 * types are described: the compiler checks graphs against it, the node editor builds its
 * palette and inspector from it, the reference is written from it. Adding a parameter is a
 * line here and the code that uses its value in the compiler.
 */
struct RouterNodeType
{
    QString type;
    QString description;
    std::vector<PortSpec> inputs;  ///< the first is the default input
    std::vector<PortSpec> outputs; ///< the first is the default output
    std::vector<ParamSpec> params; ///< its parameters (pattern nodes add the pattern's)

    /** What a node of the type does in a router, read from its ports. */
    enum class Role
    {
        Source, ///< no inputs: reads contact frames (detectors, signals)
        Logic,  ///< events or signals in and out
        Voices, ///< makes voices (pattern, proportional)
        Device  ///< no outputs: plays
    };
    Role role() const;

    const PortSpec *input(const QString &name) const;
    const PortSpec *output(const QString &name) const;
    const ParamSpec *param(const QString &name) const;
};

/**
 * How far back a derivative or prediction takes its slope by default (s): longer than the
 * ring-down of a finger landing on an object (20-35 ms of +-2 N at 2 ms steps, measured in
 * the simulation), so that an impact does not read as a steep ramp.
 */
constexpr double DefaultSlopeTau = 0.05;

/** Every node type, in palette order. */
const std::vector<RouterNodeType> &routerNodeTypes();
/** The type named `type`, or null. */
const RouterNodeType *routerNodeType(const QString &type);

} // namespace semhap
