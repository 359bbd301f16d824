// SPDX-License-Identifier: MIT
#pragma once

#include "routercontext.h"
#include "semanticevent.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <memory>

namespace semhap {

class Detector;
class RuntimeNode;

/**
 * What a node type's build function is given (RouterNodeType::build): the node's checked
 * parameters, the router's context, and the calls that make the node. The router compiler
 * implements it; a build function reads values, makes its node and hands it over with
 * adopt(), or says what is wrong with fail().
 */
class NodeBuilder
{
public:
    virtual ~NodeBuilder() = default;

    /** The node's index in the graph: what its events carry. */
    virtual int node() const = 0;
    /** The node's parameters as written, checked against its type's specs. */
    virtual const QJsonObject &params() const = 0;
    /** A checked parameter's value, or its spec's default when absent. */
    virtual QJsonValue param(const QString &key) const = 0;
    double number(const QString &key) const { return param(key).toDouble(); }
    /** The `gripper` parameter (right when absent). */
    Gripper gripper() const;
    /** The `channels` parameter as a list (empty when absent). */
    QStringList channels() const;
    /** A choice-list parameter as a bit set over its choices; absent: 0 (any). */
    virtual unsigned choiceBits(const QString &key) const = 0;
    /** The person, signals and grippers the router is compiled for. */
    virtual const RouterContext &context() const = 0;
    /** The detector kind of the node's type (its row's): what its events carry. */
    virtual DetectorKind kind() const = 0;

    /** Reports `reason` at parameter `key` (or the node, when empty); always false. */
    virtual bool fail(const QString &key, const QString &reason) = 0;
    /**
     * The message and category of a node that raises a message of its own (`message` and
     * `category` parameters): one category per message in a router; false after fail().
     */
    virtual bool messageOf(Message *message, Category *category) = 0;
    /** A [low, high] or single-number level parameter; false after fail(). */
    virtual bool level(const QString &key, bool range, double *low, double *high) = 0;

    /** Takes the node made; the router runs it. Returns true. */
    virtual bool adopt(std::unique_ptr<RuntimeNode> node) = 0;
    /** Takes a detector: the router hands it every contact frame. Returns true. */
    virtual bool adoptDetector(std::unique_ptr<Detector> detector) = 0;
    /** Makes the node play its `pattern` parameter into its voice links; false after fail(). */
    virtual bool playPattern() = 0;
    /** Makes the node a device of its `model`, `policy` and `hand`; false after fail(). */
    virtual bool drive() = 0;
};

/**
 * The build function of a detector whose Params read, validate and fit themselves to the
 * gripper (ForceDetector, SlipDetector): a row's build is `&buildDetector<ForceDetector>`.
 */
template<typename T> bool buildDetector(NodeBuilder &b)
{
    QJsonObject params = b.params();
    params.remove(QStringLiteral("gripper"));
    typename T::Params p;
    QString key;
    QString reason;
    if (!p.read(params, &key, &reason) || !p.validate(&key, &reason))
        return b.fail(key, reason);
    // The node's own values are checked and kept in the graph; they run fitted to the
    // gripper, like a predict node's horizon to the reaction time.
    const Gripper gripper = b.gripper();
    return b.adoptDetector(std::make_unique<T>(
        b.node(), gripper, p.fittedTo(b.context().grippers[size_t(gripper)]), b.kind()));
}

} // namespace semhap
