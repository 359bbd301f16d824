// SPDX-License-Identifier: MIT
#pragma once

#include "paramspec.h"
#include "semanticevent.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <functional>

#include <vector>

namespace semhap {

class NodeBuilder;

/** Says one rewrite of an older file's spelling: where under the node (`/type`), and what. */
using UpgradeWarning = std::function<void(const QString &pointer, const QString &message)>;
/** `deprecated: WHAT "OLD" is now "NOW" (read as "NOW")`: one wording for every rewrite. */
QString deprecatedSpelling(const QString &what, const QString &old, const QString &now);

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
 * A router node type: its ports, its parameters' specs and how a node of it is built. The
 * table is the one place node types are described: the compiler builds and checks graphs by
 * it, the node editor builds its palette and inspector from it, the reference is written
 * from it. A new node type is a row; a new parameter is a line in its row and the code that
 * uses its value in the row's build function.
 */
struct RouterNodeType
{
    /** Builds a node from its checked parameters (NodeBuilder::adopt); false after fail(). */
    using Build = bool (*)(NodeBuilder &builder);

    QString type;
    QString description;
    std::vector<PortSpec> inputs;  ///< the first is the default input
    std::vector<PortSpec> outputs; ///< the first is the default output
    std::vector<ParamSpec> params; ///< its parameters (pattern nodes add the pattern's)
    Build build = nullptr;
    /**
     * Whether it raises messages of its own (a detector): its events carry its detectorKind,
     * named as the type, and a node hears at most RouterGraph::MaxUpstreamDetectors of them.
     */
    bool isDetector = false;
    /** Names the type had in older files: such a node is read as this type, with a warning. */
    QStringList formerNames = {};
    /** Rewrites the parameters older files spelled otherwise, saying each (null: none). */
    void (*upgrade)(QJsonObject &params, const UpgradeWarning &warn) = nullptr;
    DetectorKind detectorKind = DetectorKind::Force; ///< detectors: the kind of its events

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
    /** Its first parameter of `kind` (the pattern a node plays, a device's model), or null. */
    const ParamSpec *paramOfKind(ParamKind kind) const;
};

/**
 * How far back a derivative or prediction takes its slope by default (s): longer than the
 * ring-down of a finger landing on an object (20-35 ms of +-2 N at 2 ms steps, measured in
 * the simulation), so that an impact does not read as a steep ramp.
 */
constexpr double DefaultSlopeTau = 0.05;

/** Every node type, in palette order. */
const std::vector<RouterNodeType> &routerNodeTypes();
/** The names of the detector kinds: the detector rows' types, the built-in four first. */
QStringList detectorKindNames();
/** The type named `type`, or null. */
const RouterNodeType *routerNodeType(const QString &type);

} // namespace semhap
