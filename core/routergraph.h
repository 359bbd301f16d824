// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "loaderror.h"
#include "pattern.h"
#include "player.h"
#include "routernodetype.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace semhap {

class JsonReader;

/** A node of a router graph as saved: its id, its type and its parameters. */
struct RouterNode
{
    QString id;         ///< unique in the graph; the name events and devices carry
    QString type;       ///< one of the types in RouterNodeTypes
    QJsonObject params; ///< type-specific parameters, checked when the graph is compiled
    QJsonObject ui;     ///< editor data (position…), kept as is
};

/** A directed link from an output port to an input port. */
struct RouterLink
{
    QString from;
    QString fromPort; ///< empty: the node's default output
    QString to;
    QString toPort; ///< empty: the node's default input
};

/**
 * A router as data (`"format": "semhap.router/1"`): nodes, links, and optionally the user
 * patterns and device models it uses, embedded so the file runs the same elsewhere. This
 * is the document; Router compiles it into something that runs.
 */
class RouterGraph
{
public:
    static constexpr const char *Format = "semhap.router/1";
    /** The most nodes a router may have: far more than any design, bounded for safety. */
    static constexpr int MaxNodes = 1000000;
    /** The most links a router may have. */
    static constexpr int MaxLinks = 2000000;
    /** The most devices (bands, overlays) a router may drive: each is rendered every tick. */
    static constexpr int MaxDevices = 256;
    /**
     * The most detectors whose messages may meet at one node: each brings two messages and
     * a node tracks at most ActiveMessages::Capacity of them without allocating.
     */
    static constexpr int MaxUpstreamDetectors = 8;

    /** Parses the document's structure; node types and parameters are checked by compile. */
    static bool fromJson(const QJsonObject &json, const QString &file, RouterGraph *graph,
                         LoadError *error);
    static bool fromFile(const QString &path, RouterGraph *graph, LoadError *error);
    QJsonObject toJson() const;

    /** The index of node `id` in nodes, or -1. */
    int nodeIndex(const QString &id) const;

    /**
     * The pattern a node's `pattern` parameter names: an embedded one of that name first,
     * then a built-in, then a file relative to baseDir (when filesAllowed). Null with a
     * one-sentence `reason`. The compiler, the editor and the plots all ask this.
     */
    PatternPtr pattern(const QString &nameOrPath, QString *reason) const;
    /** The same for a device node's `model`. */
    DeviceModelPtr model(const QString &nameOrPath, QString *reason) const;
    /** The pattern a pattern node plays, or null (another type, or not found). */
    PatternPtr playedPattern(const RouterNode &node) const;
    /**
     * The ids of the pattern nodes that play the file `path`: those whose `pattern` names a
     * file (not an embedded pattern or a built-in) that resolves to `path` as pattern() would
     * resolve it. Paths are compared, not files: `path` may be gone (a renamed pattern).
     */
    QStringList nodesPlayingFile(const QString &path) const;
    /** Points every node nodesPlayingFile(`from`) finds at `to`; the ids it changed. */
    QStringList followRenamedFile(const QString &from, const QString &to);
    /**
     * A node's input ports as the compiler makes them: its type's, and for a pattern node
     * one signal input per parameter of its pattern but intensity (which events set).
     * Empty for an unknown type; a pattern that cannot be found adds none.
     */
    std::vector<PortSpec> inputsOf(const RouterNode &node) const;
    /** A node's output ports: its type's. */
    static std::vector<PortSpec> outputsOf(const RouterNode &node);
    /** The port a link end names: `port`, or the node's default (first) one when empty. */
    QString portOf(const QString &node, const QString &port, bool output) const;
    /** Whether links lead from node `from` to node `to` (a node reaches itself). */
    bool reaches(const QString &from, const QString &to) const;
    /**
     * Whether `link` may be added to the graph as it stands, by the rules the compiler
     * enforces: both ports exist, carry the same type, a single input is free, the link is
     * new, makes no cycle and lets no node hear more than MaxUpstreamDetectors detectors.
     * False with the compiler's one-sentence reason. What the node editor asks on a drop.
     */
    bool checkLink(const RouterLink &link, QString *reason) const;
    /** Which part of a link a problem is about. */
    enum class LinkEnd
    {
        From,
        To,
        Both
    };
    /**
     * The port rules of one link, shared by checkLink and the compiler: empty when the
     * named ports exist and match, else the reason, with the end it is about in `end`.
     * `linksIntoPort` is how many links the target port has already.
     */
    static QString portProblem(const RouterNode &from, const QString &fromPort,
                               const RouterNode &to, const std::vector<PortSpec> &inputs,
                               const QString &toPort, int linksIntoPort, LinkEnd *end);
    /**
     * Whether a voice of node `from` (a pattern node playing `pattern`, or a proportional
     * node when `pattern` is null) on `channels` (empty: its own) can drive `model`: empty,
     * with the channel routes filled in, or the reason. Shared by checkLink and the compiler.
     */
    static QString voiceProblem(const RouterNode &from, const Pattern *pattern,
                                const QStringList &channels, const RouterNode &device,
                                const DeviceModel &model, std::vector<PlayerInput::Route> *routes);
    /** Why a node hears too many detectors (the fan-in limit). */
    static QString fanInProblem();
    /** Whether a node of `type` raises messages of its own (force, slip, threshold). */
    static bool isDetectorType(const QString &type);

    /** The signal inputs a pattern node gets for `pattern`'s parameters. */
    static void appendPatternInputs(const Pattern &pattern, std::vector<PortSpec> *inputs);
    /**
     * A node's parameters as the compiler checks them: its type's, and for a pattern node
     * one number per parameter of its pattern (the node's value overrides the default).
     */
    std::vector<ParamSpec> paramsOf(const RouterNode &node) const;
    /** The parameters a pattern node gets for `pattern`'s parameters. */
    static void appendPatternParams(const Pattern &pattern, std::vector<ParamSpec> *params);
    /**
     * Adds `pattern` to the embedded ones and returns the name the nodes must use: its own,
     * or, when another pattern of that name is embedded already (two files may name their
     * patterns alike), a suffixed one (`mine~2`). A pattern embedded already keeps its name.
     */
    QString embedPattern(const PatternPtr &pattern);
    QString embedModel(const DeviceModelPtr &model);
    /**
     * Embeds every pattern and model file the nodes name, so the document runs the same on
     * another machine, and points the nodes at them; built-ins stay by name. False with
     * `NODE: cannot embed FILE: reason`.
     */
    bool embedFiles(LoadError *error);

    /**
     * Applies `NODE.PARAM=VALUE` (the node id may itself contain dots: the last dot splits).
     * VALUE is read as JSON when it parses as such, otherwise as a string.
     */
    bool applyOverride(const QString &assignment, LoadError *error);

    QString name;
    QString description;
    QString file;    ///< where it was loaded from (errors, relative pattern paths)
    QString baseDir; ///< folder relative pattern and model paths are resolved against
    /** What loading found old but readable (a deprecated spelling), each located. */
    std::vector<LoadError> warnings;
    std::vector<RouterNode> nodes;
    std::vector<RouterLink> links;
    std::vector<PatternPtr> patterns;   ///< embedded patterns, found by name first
    std::vector<DeviceModelPtr> models; ///< embedded device models, found by name first
    /**
     * Whether patterns and models may be loaded from files it names. A router read back
     * from a session carries everything it uses; one that names a file is refused, so a
     * session can make replay read nothing else.
     */
    bool filesAllowed = true;

private:
    static bool readDocument(JsonReader &reader, const QJsonObject &json, RouterGraph *graph);
};

/** The router presets shipped as resources (`:/semhap/routers/NAME.json`). */
class RouterPresets
{
public:
    static QStringList names();
    /** A preset by name; false (with error) when there is none. */
    static bool preset(const QString &name, RouterGraph *graph, LoadError *error);
    /** A preset name or a file path (a `/` or a `.json` ending make it a path). */
    static bool load(const QString &nameOrPath, RouterGraph *graph, LoadError *error);
};

} // namespace semhap
