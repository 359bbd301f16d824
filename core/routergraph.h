// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "loaderror.h"
#include "pattern.h"
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
    /**
     * A node's input ports as the compiler makes them: its type's, and for a pattern node
     * one signal input per parameter of its pattern but intensity (which events set).
     * Empty for an unknown type; a pattern that cannot be found adds none.
     */
    std::vector<PortSpec> inputsOf(const RouterNode &node) const;
    /** The signal inputs a pattern node gets for `pattern`'s parameters. */
    static void appendPatternInputs(const Pattern &pattern, std::vector<PortSpec> *inputs);
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
