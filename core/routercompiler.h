// SPDX-License-Identifier: MIT
#pragma once

#include "router.h"
#include "routernodetype.h"

#include <QHash>

#include <memory>
#include <vector>

namespace semhap {

/**
 * Turns a RouterGraph into a Router, reporting the first problem with node and reason. Each
 * node is built by its type's row (RouterNodeType::build), through a NodeBuilder; the
 * compiler resolves links, checks the graph and wires what the rows built.
 */
class RouterCompiler
{
public:
    RouterCompiler(const RouterGraph &graph, const RouterContext &context, LoadError *error)
        : m_graph(graph), m_context(context), m_error(error)
    {}

    std::unique_ptr<Router> compile();

private:
    struct NodeInfo
    {
        const RouterNodeType *type = nullptr;
        std::vector<PortSpec> inputs;
        std::vector<int> inputLinks; ///< links into each input port
        PatternPtr pattern;
        QStringList channels; ///< pattern and proportional nodes: explicit channel list
        DeviceModelPtr model;
        Player::MixPolicy policy = Player::MixPolicy::Priority;
        int hand = -1; ///< devices: the Gripper that feels it, -1 for none
    };
    struct ResolvedLink
    {
        int from = -1;
        int fromPort = 0;
        int to = -1;
        int toPort = 0;
        PortType type = PortType::Event;
    };

    bool fail(const QString &pointer, const QString &reason);
    bool failNode(int node, const QString &key, const QString &reason);
    QString nodeLabel(int node) const;

    /** Checks the node's parameters against `specs`: known, well-formed, required ones given. */
    bool checkParams(int node, const std::vector<ParamSpec> &specs);
    /** A checked parameter's value, or its spec's default when absent. */
    QJsonValue param(int node, const QString &key) const;
    /** A filter parameter as a bit set over its choices; absent: 0, which a filter takes as any.
     */
    unsigned choiceBits(int node, const QString &key) const;

    class Builder;
    bool buildNode(int node);
    bool buildPattern(int node);
    bool buildDevice(int node);
    /** Takes a node a row built: the router runs it, and lists it by what it does. */
    bool adopt(int node, std::unique_ptr<RuntimeNode> runtime);
    /** The message and category of a threshold or compose node; false after failNode. */
    bool messageOf(int node, Message *message, Category *category);
    /** A [low, high] or single-number level parameter; false after failNode. */
    bool level(int node, const QString &key, bool range, double *low, double *high);
    /** The default horizons of predict nodes: downstream devices' delay + reaction time. */
    void setDefaultHorizons();

    /**
     * The pattern or model `name` that node `node`'s parameter `key` names, by `lookup`
     * (RouterGraph::pattern, model), each looked up once into `found`; null after failNode.
     */
    template<typename Ptr, typename Lookup>
    Ptr findFile(int node, const QString &key, const QString &name, QHash<QString, Ptr> *found,
                 Lookup lookup);

    /** The graph's size against the caps (RouterGraph::MaxNodes, MaxLinks, MaxDevices). */
    bool checkSize();
    bool resolveLinks();
    bool checkCycles();
    bool checkFanIn();
    bool wire();
    bool connectVoice(int linkIndex, const ResolvedLink &link);

    const RouterGraph &m_graph;
    RouterContext m_context;
    LoadError *m_error;
    std::vector<NodeInfo> m_info;
    std::vector<ResolvedLink> m_links;
    QHash<QString, int> m_nodeIndex;       ///< node id → index
    std::vector<std::vector<int>> m_out;   ///< per node, the links leaving it
    std::vector<int> m_order;              ///< nodes in topological order (checkCycles)
    QHash<QString, PatternPtr> m_patterns; ///< embedded and loaded patterns by name or path
    QHash<QString, DeviceModelPtr> m_models;
    QHash<int, std::pair<Category, int>> m_categories; ///< message -> category, first node
    std::unique_ptr<Router> m_router;
};

} // namespace semhap
