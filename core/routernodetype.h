// SPDX-License-Identifier: MIT
#pragma once

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
 * A router node type: its ports and parameters. The table is what the compiler checks
 * graphs against and what the node editor's palette shows.
 */
struct RouterNodeType
{
    QString type;
    QString description;
    std::vector<PortSpec> inputs;  ///< the first is the default input
    std::vector<PortSpec> outputs; ///< the first is the default output
    QStringList params;            ///< known parameters (pattern nodes add the pattern's)

    const PortSpec *input(const QString &name) const;
    const PortSpec *output(const QString &name) const;
};

/** Every node type, in palette order. */
const std::vector<RouterNodeType> &routerNodeTypes();
/** The type named `type`, or null. */
const RouterNodeType *routerNodeType(const QString &type);

} // namespace semhap
