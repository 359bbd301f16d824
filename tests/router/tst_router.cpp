// SPDX-License-Identifier: MIT
#include "forcedetector.h"
#include "gatedrouter.h"
#include "impactdetector.h"
#include "jsonreader.h"
#include "pipeline.h"
#include "router.h"
#include "routergraph.h"
#include "routernodetype.h"
#include "slipdetector.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

const QStringList PresetDevices{"left.air",  "left.fingertips",  "left.vibro", "overlay",
                                "right.air", "right.fingertips", "right.vibro"};

/** A router document with a force detector, a filter, a pattern and a device, to vary. */
QJsonObject baseRouter()
{
    return QJsonDocument::fromJson(R"({
      "format": "semhap.router/1", "name": "test",
      "nodes": [
        {"id": "right.force", "type": "force",
         "params": {"gripper": "right", "grasp": 20, "break": 80, "max": 120}},
        {"id": "warn", "type": "filter", "params": {"category": "exception"}},
        {"id": "geiger", "type": "pattern", "params": {"pattern": "vib.geiger"}},
        {"id": "right.vibro", "type": "device", "params": {"model": "lra4"}}
      ],
      "links": [
        {"from": "right.force", "to": "warn"},
        {"from": "warn", "to": "geiger"},
        {"from": "geiger", "to": "right.vibro"}
      ]})")
        .object();
}

/** Applies a JSON merge of `path` = `value` into the base router (path like "nodes/1"). */
QJsonObject edited(const QString &path, const QJsonValue &value)
{
    QJsonObject root = baseRouter();
    const QStringList parts = path.split('/');
    if (parts.size() == 1) {
        root.insert(parts[0], value);
        return root;
    }
    QJsonArray array = root.value(parts[0]).toArray();
    const int index = parts[1].toInt();
    if (index >= array.size())
        array.append(value);
    else if (parts.size() == 2)
        array[index] = value;
    else {
        QJsonObject item = array[index].toObject();
        QJsonObject params = item.value("params").toObject();
        params.insert(parts[3], value);
        item.insert("params", params);
        array[index] = item;
    }
    root.insert(parts[0], array);
    return root;
}

QJsonObject object(const char *json)
{
    return QJsonDocument::fromJson(json).object();
}

QString compileError(const QJsonObject &json)
{
    RouterGraph graph;
    LoadError error;
    if (!RouterGraph::fromJson(json, "r.json", &graph, &error))
        return error.toString();
    if (Router::compile(graph, &error))
        return QString();
    return error.toString();
}

} // namespace

class TestRouter : public QObject
{
    Q_OBJECT

private slots:
    void presets_data();
    void presets();
    void unknownPreset();
    void graphRoundTrip();
    void followsARenamedPatternFile_data();
    void followsARenamedPatternFile();
    void oldNodeTypeIsReadWithAWarning();
    void invalid_data();
    void invalid();
    void sessionRouterNamesNoFile();
    void overrides_data();
    void overrides();
    void embeddedPatternAndModel();
    void patternFileRelativeToRouter();
    void nodeTypesTable();
    void checkLinkAgreesWithTheCompiler_data();
    void checkLinkAgreesWithTheCompiler();
    void checkLinkCountsDetectorsHeard();
    void deviceHands();
    void activityShowsWhatRouted();
    void invalidPredictive_data();
    void invalidPredictive();
    void defaultHorizon();
    void namedSignalsDriveDetectors();
    void signalsTheSourceLacksAreRefused();
    void thresholdsTellTheirSignalAndLevels();
    void aMessageHasOneCategory();
    void oldThresholdsReadAsNew();
    void predictiveWarningComesEarlier();
};

void TestRouter::presets_data()
{
    QTest::addColumn<QString>("name");
    for (const char *name : {"none", "visual", "sensory", "C1", "C2", "C3", "C4", "C3p", "C4p"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

void TestRouter::presets()
{
    QFETCH(QString, name);
    QVERIFY(RouterPresets::names().contains(name));
    LoadError error;
    const std::unique_ptr<Router> router = loadRouter(name, {}, &error);
    QVERIFY2(router, qPrintable(error.toString()));
    QStringList devices;
    for (int d = 0; d < router->player().deviceCount(); ++d)
        devices.append(router->player().deviceName(d));
    QCOMPARE(devices, PresetDevices);
    QVERIFY(router->nodeIds().contains("right.force"));
    QVERIFY(router->nodeIds().contains("left.slip"));
    QCOMPARE(router->graph().name, name);
}

void TestRouter::unknownPreset()
{
    LoadError error;
    QVERIFY(!loadRouter("C5", {}, &error));
    QCOMPARE(
        error.toString(),
        QString("C5: no such router preset (presets: C1, C2, C3, C3p, C4, C4p, none, sensory, "
                "usb, visual, wipe)"));
}

void TestRouter::graphRoundTrip()
{
    for (const QString &name : RouterPresets::names()) {
        RouterGraph graph;
        LoadError error;
        QVERIFY(RouterPresets::preset(name, &graph, &error));
        RouterGraph again;
        QVERIFY(RouterGraph::fromJson(graph.toJson(), name, &again, &error));
        QCOMPARE(again.toJson(), graph.toJson());
    }
}

void TestRouter::followsARenamedPatternFile_data()
{
    QTest::addColumn<QString>("named"); // what the node's `pattern` says
    QTest::addColumn<bool>("follows");
    QTest::newRow("relative to the router") << "mine/buzz.json" << true;
    QTest::newRow("absolute") << "/home/lab/patterns/mine/buzz.json" << true;
    QTest::newRow("with dots") << "/home/lab/patterns/./mine/../mine/buzz.json" << true;
    QTest::newRow("another file") << "mine/tick.json" << false;
    QTest::newRow("a built-in") << "vib.geiger" << false;
}

void TestRouter::followsARenamedPatternFile()
{
    // A pattern file that moved (the designer renamed it): the nodes that play it, and only
    // they, name it where it is now; the file itself is gone, so paths are compared.
    QFETCH(QString, named);
    QFETCH(bool, follows);
    RouterGraph graph;
    LoadError error;
    QVERIFY(RouterPresets::preset("C3", &graph, &error));
    graph.baseDir = "/home/lab/patterns";
    const int geiger = graph.nodeIndex("right.geiger");
    QVERIFY(geiger >= 0);
    graph.nodes[size_t(geiger)].params.insert("pattern", named);
    const QString from = "/home/lab/patterns/mine/buzz.json";
    const QString to = "/home/lab/patterns/mine/my.buzz.json";
    QCOMPARE(graph.nodesPlayingFile(from), follows ? QStringList{"right.geiger"} : QStringList());
    QCOMPARE(graph.followRenamedFile(from, to),
             follows ? QStringList{"right.geiger"} : QStringList());
    QCOMPARE(graph.nodes[size_t(geiger)].params.value("pattern").toString(), follows ? to : named);
    QCOMPARE(graph.nodesPlayingFile(from), QStringList());
}

void TestRouter::invalid_data()
{
    QTest::addColumn<QJsonObject>("json");
    QTest::addColumn<QString>("error");

    QTest::newRow("wrong format")
        << edited("format", "semhap.pattern/1")
        << "r.json: /format: unsupported format 'semhap.pattern/1', expected 'semhap.router/1'";
    QTest::newRow("nodes missing")
        << object(R"({"format": "semhap.router/1"})") << "r.json: missing key 'nodes'";
    QTest::newRow("node not object")
        << edited("nodes/1", 5) << "r.json: /nodes/1: expected a node object, got a number";
    QTest::newRow("duplicate id") << edited("nodes/1",
                                            object(R"({"id": "right.force", "type": "filter"})"))
                                  << "r.json: /nodes/1/id: duplicate node id 'right.force'";
    QTest::newRow("colon in id") << edited("nodes/1", object(R"({"id": "a:b", "type": "filter"})"))
                                 << "r.json: /nodes/1/id: 'a:b' is not a valid id (non-empty, no "
                                    "':' or spaces)";
    QTest::newRow("stray node key")
        << edited("nodes/1", object(R"({"id": "warn", "type": "filter", "grasp": 3})"))
        << "r.json: /nodes/1: unknown key 'grasp'";
    QTest::newRow("unknown type")
        << edited("nodes/1", object(R"({"id": "warn", "type": "fliter"})"))
        << "r.json: /nodes/1/type: node 'warn': unknown node type 'fliter' (known: force, slip, "
           "impact, signal, derivative, predict, threshold, compose, filter, gate, debounce, "
           "curve, "
           "pattern, proportional, device)";
    QTest::newRow("impact full below rate")
        << edited("nodes/1", object(R"({"id": "right.impact", "type": "impact",
                                        "params": {"gripper": "right", "full": 500}})"))
        << "r.json: /nodes/1/params/full: node 'right.impact' (impact): must be greater than "
           "rate (1000), got 500";
    QTest::newRow("detector without gripper")
        << edited("nodes/0", object(R"({"id": "right.force", "type": "force"})"))
        << "r.json: /nodes/0: node 'right.force' (force): needs \"gripper\": \"left\" or "
           "\"right\"";
    QTest::newRow("bad gripper") << edited("nodes/0/params/gripper", "middle")
                                 << "r.json: /nodes/0/params/gripper: node 'right.force' (force): "
                                    "must be \"left\" or \"right\"";
    QTest::newRow("break below grasp") << edited("nodes/0/params/break", 10)
                                       << "r.json: /nodes/0/params/break: node 'right.force' "
                                          "(force): must be greater than grasp (20), got 10";
    QTest::newRow("detector param type") << edited("nodes/0/params/max", "lots")
                                         << "r.json: /nodes/0/params/max: node 'right.force' "
                                            "(force): must be a finite number, found a string";
    QTest::newRow("unknown detector param")
        << edited("nodes/0/params/loss", 3)
        << "r.json: /nodes/0/params/loss: node 'right.force' "
           "(force): unknown parameter 'loss' (known: gripper, "
           "grasp, break, max, hysteresis, minDuration)";
    QTest::newRow("filter value") << edited("nodes/1/params/category", "warning")
                                  << "r.json: /nodes/1/params/category: node 'warn' (filter): "
                                     "must be \"confirmation\" or \"exception\", or a list of "
                                     "them";
    QTest::newRow("unknown filter param") << edited("nodes/1/params/phase", "begin")
                                          << "r.json: /nodes/1/params/phase: node 'warn' "
                                             "(filter): unknown parameter 'phase' (known: "
                                             "message, category, gripper)";
    QTest::newRow("unknown pattern")
        << edited("nodes/2/params/pattern", "vib.gieger")
        << "r.json: /nodes/2/params/pattern: node 'geiger' (pattern): unknown pattern "
           "'vib.gieger' (built-in: air.proportional, air.pulse5hz, air.squeeze, vib.geiger, "
           "vib.rampup, visual.blink, visual.confirm)";
    QTest::newRow("unknown pattern param")
        << edited("nodes/2/params/speed", 3)
        << "r.json: /nodes/2/params/speed: node 'geiger' (pattern): unknown parameter 'speed' "
           "(known: pattern, channels, intensity)";
    QTest::newRow("unknown device model")
        << edited("nodes/3/params/model", "lra5")
        << "r.json: /nodes/3/params/model: node 'right.vibro' (device): unknown device model "
           "'lra5' (built-in: fingertips2, lra4, overlay, pneumatic6)";
    QTest::newRow("bad policy") << edited("nodes/3/params/policy", "loudest")
                                << "r.json: /nodes/3/params/policy: node 'right.vibro' (device): "
                                   "must be \"priority\", \"max\" or \"sum\"";
    QTest::newRow("dangling link")
        << edited("links/3", object(R"({"from": "warn", "to": "nowhere"})"))
        << "r.json: /links/3/to: dangling link: no node 'nowhere'";
    QTest::newRow("link not object")
        << edited("links/0", "a->b")
        << "r.json: /links/0: expected a link object {\"from\", \"to\"}, "
           "got a string";
    QTest::newRow("unknown output port")
        << edited("links/0", object(R"({"from": "right.force:out", "to": "warn"})"))
        << "r.json: /links/0/from: node 'right.force' (force) has no output 'out'";
    QTest::newRow("unknown input port")
        << edited("links/1", object(R"({"from": "warn", "to": "geiger:rate"})"))
        << "r.json: /links/1/to: node 'geiger' (pattern) has no input 'rate' (inputs: events)";
    QTest::newRow("type mismatch")
        << edited("links/3", object(R"({"from": "right.force", "to": "right.vibro"})"))
        << "r.json: /links/3: port type mismatch: 'right.force:events' sends event, "
           "'right.vibro:in' takes voice";
    QTest::newRow("device has no outputs")
        << edited("links/3", object(R"({"from": "right.vibro", "to": "warn"})"))
        << "r.json: /links/3/from: node 'right.vibro' (device) has no outputs";
    QTest::newRow("detector has no inputs")
        << edited("links/3", object(R"({"from": "warn", "to": "right.force"})"))
        << "r.json: /links/3/to: node 'right.force' (force) has no inputs";
    QTest::newRow("cycle") << edited("links/3", object(R"({"from": "warn", "to": "warn"})"))
                           << "r.json: /nodes/1: node 'warn' (filter): is part of a cycle";
    QTest::newRow("model mismatch")
        << edited("nodes/3/params/model", "pneumatic6")
        << "r.json: /links/2: node 'geiger' (pattern) -> device 'right.vibro': pattern "
           "'vib.geiger' is for model lra4, not pneumatic6";
    QTest::newRow("bad channel remap")
        << edited("nodes/2/params/channels", QJsonArray{"m1", "m9"})
        << "r.json: /links/2: node 'geiger' (pattern) -> device 'right.vibro': pattern "
           "'vib.geiger' drives channel 'm9', which model lra4 does not have (channels: m1, "
           "m2, m3, m4)";
    QTest::newRow("empty channel list")
        << edited("nodes/2/params/channels", QJsonArray{})
        << "r.json: /nodes/2/params/channels: node 'geiger' (pattern): must be a non-empty "
           "array of channel names";
    QTest::newRow("single input twice")
        << object(R"({"format": "semhap.router/1", "nodes": [
             {"id": "F", "type": "signal", "params": {"gripper": "right", "quantity": "F"}},
             {"id": "N", "type": "signal", "params": {"gripper": "right", "quantity": "N"}},
             {"id": "p", "type": "proportional", "params": {"ref": 100}}],
             "links": [{"from": "F", "to": "p"}, {"from": "N", "to": "p"}]})")
        << "r.json: /links/1/to: 'p:in' takes a single link and already has one";
    QTest::newRow("bad quantity")
        << object(R"({"format": "semhap.router/1", "nodes": [
             {"id": "F", "type": "signal", "params": {"gripper": "right", "quantity": "G"}}]})")
        << "r.json: /nodes/0/params/quantity: node 'F' (signal): must be \"F\", \"N\", "
           "\"left.f\", \"right.f\", \"left.n\", \"right.n\", \"friction\", "
           "\"left.friction\" or \"right.friction\" or a signal's name of [a-z0-9_.]";
    QTest::newRow("curve points")
        << object(R"({"format": "semhap.router/1", "nodes": [
             {"id": "c", "type": "curve", "params": {"points": [[0, 0], [0, 1]]}}]})")
        << "r.json: /nodes/0/params/points: node 'c' (curve): must be a list of [x, y] points "
           "with x increasing";
    QTest::newRow("debounce band")
        << object(R"({"format": "semhap.router/1", "nodes": [
             {"id": "h", "type": "debounce", "params": {"band": 2}}]})")
        << "r.json: /nodes/0/params/band: node 'h' (debounce): must be within [0, 1], got "
           "2";
    QTest::newRow("gate mode")
        << object(R"({"format": "semhap.router/1", "nodes": [
             {"id": "g", "type": "gate", "params": {"mode": "ajar"}}]})")
        << "r.json: /nodes/0/params/mode: node 'g' (gate): must be \"block\" or \"open\"";
    QTest::newRow("proportional ref")
        << object(R"({"format": "semhap.router/1", "nodes": [
             {"id": "p", "type": "proportional", "params": {"ref": 0}}]})")
        << "r.json: /nodes/0/params/ref: node 'p' (proportional): must be positive, "
           "got 0";
    QJsonArray nine;
    QJsonArray links;
    for (int i = 0; i < 9; ++i) {
        nine.append(QJsonObject{{"id", QString("d%1").arg(i)},
                                {"type", "force"},
                                {"params", QJsonObject{{"gripper", "right"}}}});
        links.append(QJsonObject{{"from", QString("d%1").arg(i)}, {"to", "all"}});
    }
    nine.append(QJsonObject{{"id", "all"}, {"type", "filter"}});
    QTest::newRow("fan-in")
        << QJsonObject{{"format", "semhap.router/1"}, {"nodes", nine}, {"links", links}}
        << "r.json: /nodes/9: node 'all' (filter): listens to more than 8 detectors; at most 8 "
           "may feed one node";
    QJsonArray bands;
    for (int i = 0; i <= RouterGraph::MaxDevices; ++i)
        bands.append(QJsonObject{{"id", QString("band%1").arg(i)},
                                 {"type", "device"},
                                 {"params", QJsonObject{{"model", "lra4"}}}});
    QTest::newRow("too many devices")
        << QJsonObject{{"format", "semhap.router/1"}, {"nodes", bands}}
        << "r.json: /nodes/256: node 'band256' (device): one device more than the 256 a router "
           "may drive";
}

void TestRouter::oldNodeTypeIsReadWithAWarning()
{
    // The debounce node was called "hysteresis", like the detectors' parameter: files that
    // say so still load, with a located warning, and are written back with the new name.
    RouterGraph graph;
    LoadError error;
    QVERIFY(RouterGraph::fromJson(object(R"({"format": "semhap.router/1", "nodes": [
        {"id": "f", "type": "filter"},
        {"id": "h", "type": "hysteresis", "params": {"hold": 0.1}}]})"),
                                  "old.json", &graph, &error));
    QCOMPARE(graph.nodes[1].type, QString("debounce"));
    QCOMPARE(graph.warnings.size(), size_t(1));
    QCOMPARE(graph.warnings[0].toString(),
             QString("old.json: /nodes/1/type: deprecated: node type \"hysteresis\" is now "
                     "\"debounce\" (read as \"debounce\")"));
    QCOMPARE(graph.toJson()["nodes"][1]["type"].toString(), QString("debounce"));
    const std::unique_ptr<Router> router = Router::compile(graph, &error);
    QVERIFY2(router, qPrintable(error.toString()));
    QCOMPARE(router->graph().warnings.size(), size_t(1));
    QVERIFY(graph.nodes[0].type == "filter");

    // A fingertip's quantity was "f.left"; it is "left.f", as the contact frame spells it.
    QVERIFY(RouterGraph::fromJson(object(R"({"format": "semhap.router/1", "nodes": [
        {"id": "s", "type": "signal", "params": {"gripper": "right", "quantity": "n.left"}}]})"),
                                  "old.json", &graph, &error));
    QCOMPARE(graph.nodes[0].params.value("quantity").toString(), QString("left.n"));
    QCOMPARE(graph.warnings.size(), size_t(1));
    QCOMPARE(graph.warnings[0].toString(),
             QString("old.json: /nodes/0/params/quantity: deprecated: quantity \"n.left\" is "
                     "now \"left.n\" (read as \"left.n\")"));
    QVERIFY2(Router::compile(graph, &error), qPrintable(error.toString()));
}

void TestRouter::invalid()
{
    QFETCH(QJsonObject, json);
    QFETCH(QString, error);
    QCOMPARE(compileError(json), error);
}

void TestRouter::sessionRouterNamesNoFile()
{
    // A router read back from a session must carry what it uses: a crafted session must not
    // make replay read another file.
    RouterGraph graph;
    LoadError error;
    QVERIFY(RouterGraph::fromJson(object(R"({"format": "semhap.router/1", "nodes": [
            {"id": "p", "type": "pattern", "params": {"pattern": "/etc/passwd.json"}}]})"),
                                  "s.db", &graph, &error));
    graph.filesAllowed = false;
    QVERIFY(!Router::compile(graph, &error));
    QCOMPARE(error.toString(), QString("s.db: /nodes/0/params/pattern: node 'p' (pattern): names "
                                       "the file '/etc/passwd.json'; this router must carry its "
                                       "patterns"));
}

void TestRouter::overrides_data()
{
    QTest::addColumn<QStringList>("overrides");
    QTest::addColumn<QString>("error");
    QTest::newRow("valid") << QStringList{"right.force.break=90", "left.slip.loss=30"}
                           << QString();
    QTest::newRow("no equals") << QStringList{"right.force.break"}
                               << "--set right.force.break: expected NODE.PARAM=VALUE";
    QTest::newRow("no dot") << QStringList{"break=90"}
                            << "--set break=90: expected NODE.PARAM=VALUE";
    QTest::newRow("unknown node") << QStringList{"right.slip.loss=3"}
                                  << "--set right.slip.loss=3: no node 'right.slip' in router "
                                     "'C3'";
    QTest::newRow("not a number") << QStringList{"right.force.break=abc"}
                                  << "--set right.force.break=abc: node 'right.force' (force): "
                                     "must be a finite number, found a string";
    QTest::newRow("invalid value") << QStringList{"right.force.break=200"}
                                   << "--set right.force.break=200: node 'right.force' (force): "
                                      "must be greater than break (200), got 120";
    QTest::newRow("unknown param") << QStringList{"right.force.brake=90"}
                                   << "--set right.force.brake=90: node 'right.force' (force): "
                                      "unknown parameter 'brake' (known: gripper, grasp, break, "
                                      "max, hysteresis, minDuration)";
    QTest::newRow("pattern swap") << QStringList{"right.geiger.pattern=vib.rampup"} << QString();
    QTest::newRow("pattern model clash")
        << QStringList{"right.geiger.pattern=air.squeeze"}
        << "C3: /links/7: node 'right.geiger' (pattern) -> device 'right.vibro': pattern "
           "'air.squeeze' is for model pneumatic6, not lra4";
}

void TestRouter::overrides()
{
    QFETCH(QStringList, overrides);
    QFETCH(QString, error);
    LoadError e;
    const std::unique_ptr<Router> router = loadRouter("C3", overrides, &e);
    QCOMPARE(router ? QString() : e.toString(), error);
    if (router && overrides.first().startsWith("right.force.break")) {
        const QJsonObject params = router->graph().nodes[0].params;
        QCOMPARE(params.value("break").toDouble(), 90.0);
    }
}

void TestRouter::embeddedPatternAndModel()
{
    QJsonObject json = object(R"({
      "format": "semhap.router/1",
      "patterns": [{"format": "semhap.pattern/1", "name": "buzz", "model": "band2",
                    "tracks": [{"channels": ["*"], "sustain": {"type": "const", "value": 0.5}}]}],
      "models": [{"format": "semhap.device/1", "name": "band2", "rate": 50,
                  "channels": [{"name": "a"}, {"name": "b"}]}],
      "nodes": [
        {"id": "f", "type": "force", "params": {"gripper": "left"}},
        {"id": "buzz", "type": "pattern", "params": {"pattern": "buzz"}},
        {"id": "band", "type": "device", "params": {"model": "band2"}}],
      "links": [{"from": "f", "to": "buzz"}, {"from": "buzz", "to": "band"}]})");
    QCOMPARE(compileError(json), QString());

    RouterGraph graph;
    LoadError error;
    QVERIFY(RouterGraph::fromJson(json, "r.json", &graph, &error));
    RouterGraph again;
    QVERIFY(RouterGraph::fromJson(graph.toJson(), "r.json", &again, &error));
    QCOMPARE(again.patterns.size(), size_t(1));
    QCOMPARE(again.models.size(), size_t(1));

    json.insert("patterns", QJsonArray{object(R"({"format": "semhap.pattern/1"})")});
    QCOMPARE(compileError(json), QString("r.json: /patterns/0: missing key 'name'"));
}

void TestRouter::patternFileRelativeToRouter()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QFile pattern(dir.filePath("soft.json"));
    QVERIFY(pattern.open(QIODevice::WriteOnly));
    pattern.write(R"({"format": "semhap.pattern/1", "name": "soft", "model": "lra4",
                      "tracks": [{"channels": ["m1"], "sustain": {"type": "const", "value": 0.3}}]})");
    pattern.close();
    QJsonObject json = edited("nodes/2/params/pattern", "soft.json");
    QFile router(dir.filePath("r.json"));
    QVERIFY(router.open(QIODevice::WriteOnly));
    router.write(QJsonDocument(json).toJson());
    router.close();

    LoadError error;
    QVERIFY2(loadRouter(dir.filePath("r.json"), {}, &error), qPrintable(error.toString()));
    QVERIFY(!loadRouter(dir.filePath("missing.json"), {}, &error));
    QVERIFY(error.toString().contains("missing.json: cannot read"));
}

void TestRouter::nodeTypesTable()
{
    for (const RouterNodeType &type : routerNodeTypes()) {
        QVERIFY(!type.description.isEmpty());
        QCOMPARE(routerNodeType(type.type), &type);
        // Every parameter is described, and a default passes its own check: the editor shows
        // these defaults and the reference is written from these specs.
        for (const ParamSpec &spec : type.params) {
            const QString what = type.type + '.' + spec.name;
            QVERIFY2(!spec.help.isEmpty(), qPrintable(what));
            QCOMPARE(type.param(spec.name), &spec);
            QString reason;
            const QJsonValue value = spec.defaultValue();
            QVERIFY2(value.isUndefined() || spec.check(value, &reason), qPrintable(what));
        }
    }
    QVERIFY(!routerNodeType("nonsense"));
    // The detectors' defaults are the ones their parameters start with.
    QCOMPARE(routerNodeType("force")->param("break")->defaultNumber, ForceDetector::Params().brk);
    QCOMPARE(routerNodeType("slip")->param("loss")->defaultNumber, SlipDetector::Params().loss);
    QCOMPARE(routerNodeType("impact")->param("rate")->defaultNumber,
             ImpactDetector::Params().rate);
    // The detector rows are the detector kinds: the built-in four keep their ids.
    QCOMPARE(detectorKindNames().mid(0, 4),
             QStringList({"force", "slip", "threshold", "compose"}));
    QVERIFY(detectorKindNames().contains("impact"));
}

void TestRouter::checkLinkAgreesWithTheCompiler_data()
{
    QTest::addColumn<QString>("preset");
    QTest::newRow("C3") << "C3";
    QTest::newRow("C3p") << "C3p";
}

void TestRouter::checkLinkAgreesWithTheCompiler()
{
    // Every link one could draw between two ports of a preset: the editor's check says yes
    // exactly when the graph with that link compiles.
    QFETCH(QString, preset);
    RouterGraph graph;
    LoadError error;
    QVERIFY(RouterPresets::preset(preset, &graph, &error));
    int accepted = 0;
    int refused = 0;
    for (const RouterNode &from : graph.nodes) {
        for (const PortSpec &out : RouterGraph::outputsOf(from)) {
            for (const RouterNode &to : graph.nodes) {
                for (const PortSpec &in : graph.inputsOf(to)) {
                    const RouterLink link{from.id, out.name, to.id, in.name};
                    QString reason;
                    const bool allowed = graph.checkLink(link, &reason);
                    RouterGraph linked = graph;
                    linked.links.push_back(link);
                    LoadError compileError;
                    const bool compiles = bool(Router::compile(linked, &compileError));
                    QVERIFY2(allowed == compiles,
                             qPrintable(QString("%1:%2 -> %3:%4: editor '%5', compiler '%6'")
                                            .arg(from.id, out.name, to.id, in.name, reason,
                                                 compileError.toString())));
                    QCOMPARE(reason.isEmpty(), allowed);
                    ++(allowed ? accepted : refused);
                }
            }
        }
    }
    QVERIFY(accepted > 0);
    QVERIFY(refused > 0);
}

void TestRouter::deviceHands()
{
    // A device's hand is its `hand`; without one, the id's first part when that names a
    // gripper. `lefty.vibro` is nobody's, where a name-prefix test took it for the left.
    RouterGraph graph;
    const auto device = [&](const QString &id, const QJsonObject &params) {
        QJsonObject p = params;
        p.insert("model", "lra4");
        graph.nodes.push_back({id, "device", p, {}});
    };
    device("lefty.vibro", {});
    device("band", QJsonObject{{"hand", "left"}});
    device("left.vibro", {});
    device("right.vibro", QJsonObject{{"hand", "left"}});
    device("overlay", {});
    LoadError error;
    const std::unique_ptr<Router> router = Router::compile(graph, &error);
    QVERIFY2(router, qPrintable(error.toString()));
    const auto handOf = [&](const QString &id) {
        Gripper hand = Gripper::Right;
        const bool has = router->deviceHand(router->player().deviceIndex(id), &hand);
        return has ? gripperName(hand) : QString("none");
    };
    QCOMPARE(handOf("lefty.vibro"), QString("none"));
    QCOMPARE(handOf("band"), QString("left"));
    QCOMPARE(handOf("left.vibro"), QString("left"));
    QCOMPARE(handOf("right.vibro"), QString("left"));
    QCOMPARE(handOf("overlay"), QString("none"));

    graph.nodes[0].params.insert("hand", "middle");
    QVERIFY(!Router::compile(graph, &error));
    QCOMPARE(error.toString(),
             QString("<input>: /nodes/0/params/hand: node 'lefty.vibro' (device): must "
                     "be \"left\" or \"right\""));
}

void TestRouter::activityShowsWhatRouted()
{
    // The right hand's force detector feeds a grasp filter and a break filter; the break
    // filter goes through a gate that the left hand's force detector's grasp opens. What each
    // node passes on is what really routed: the filters split the messages, the gate holds
    // the break warning back until the control is active.
    LoadError error;
    std::unique_ptr<Router> compiled = Router::compile(gatedRouter(), &error);
    QVERIFY2(compiled, qPrintable(error.toString()));
    Pipeline pipeline(std::move(compiled));
    struct Sink : PipelineSink
    {
        std::vector<NodeActivity> changes;
        void onNodeActivity(const NodeActivity &activity) override { changes.push_back(activity); }
    } sink;
    const Router &router = pipeline.router();
    const auto level = [&](const QString &id) {
        return router.activity()[size_t(router.nodeIds().indexOf(id))].level;
    };
    const auto feed = [&](double t, Gripper gripper, double force) {
        pipeline.process(forceFrame(t, gripper, force), sink);
    };
    feed(0.0, Gripper::Right, 30); // grasp only
    QCOMPARE(level("force"), 1.0);
    QCOMPARE(level("grasps"), 1.0);
    QVERIFY(!router.activity()[size_t(router.nodeIds().indexOf("breaks"))].isActive());
    feed(0.01, Gripper::Right, 100); // grasp + break at (100 - 80) / (120 - 80)
    QCOMPARE(level("breaks"), 0.5);
    QVERIFY(router.activity()[size_t(router.nodeIds().indexOf("force"))].exception);
    QCOMPARE(level("gate"), -1.0); // the gate opens on its control only
    QCOMPARE(level("buzz"), -1.0);
    feed(0.02, Gripper::Left, 30); // the control's grasp opens the gate
    QCOMPARE(level("gate"), 0.5);
    QCOMPARE(level("buzz"), 0.5);
    const NodeActivity &buzz = router.activity()[size_t(router.nodeIds().indexOf("buzz"))];
    QCOMPARE(buzz.messageCount, 1);
    QCOMPARE(buzz.messages[0], int(Message::Break));
    QCOMPARE(buzz.t, 0.02);
    // Every change was handed to the sink, each node once per change.
    QVERIFY(!sink.changes.empty());
    QCOMPARE(sink.changes.back().level, router.activity()[size_t(sink.changes.back().node)].level);
    const size_t before = sink.changes.size();
    feed(0.03, Gripper::Left, 30); // nothing changes
    QCOMPARE(sink.changes.size(), before);
}

void TestRouter::checkLinkCountsDetectorsHeard()
{
    // Nine detectors into one filter chain: the ninth link is refused by both, with the
    // compiler's words.
    RouterGraph graph;
    graph.nodes.push_back({"join", "filter", {}, {}});
    graph.nodes.push_back({"out", "filter", {}, {}});
    graph.links.push_back({"join", "", "out", ""});
    for (int d = 0; d < RouterGraph::MaxUpstreamDetectors; ++d) {
        const QString id = QString("d%1").arg(d);
        graph.nodes.push_back({id, "force", QJsonObject{{"gripper", "right"}}, {}});
        QString reason;
        QVERIFY2(graph.checkLink({id, "", "join", ""}, &reason), qPrintable(reason));
        graph.links.push_back({id, "", "join", ""});
    }
    LoadError error;
    QVERIFY2(Router::compile(graph, &error), qPrintable(error.toString()));
    graph.nodes.push_back({"extra", "force", QJsonObject{{"gripper", "left"}}, {}});
    QString reason;
    QVERIFY(!graph.checkLink({"extra", "", "out", ""}, &reason));
    QCOMPARE(reason, QString("node 'out' (filter): listens to more than 8 detectors; at most 8 "
                             "may feed one node"));
    graph.links.push_back({"extra", "", "out", ""});
    QVERIFY(!Router::compile(graph, &error));
    QVERIFY2(error.toString().endsWith(reason), qPrintable(error.toString()));
}

namespace {

/** The right hand's force signal through a predict node to a threshold, then the band. */
QJsonObject predictiveRouter()
{
    return QJsonDocument::fromJson(R"({
      "format": "semhap.router/1", "name": "predictive",
      "nodes": [
        {"id": "F", "type": "signal", "params": {"gripper": "right", "quantity": "F"}},
        {"id": "F.predicted", "type": "predict", "params": {}},
        {"id": "break", "type": "threshold",
         "params": {"gripper": "right", "message": "break", "begin": 80,
                    "intensity": [80, 120]}},
        {"id": "geiger", "type": "pattern", "params": {"pattern": "vib.geiger"}},
        {"id": "right.vibro", "type": "device", "params": {"model": "lra4"}}
      ],
      "links": [
        {"from": "F", "to": "F.predicted"}, {"from": "F.predicted", "to": "break"},
        {"from": "break", "to": "geiger"}, {"from": "geiger", "to": "right.vibro"}
      ]})")
        .object();
}

QJsonObject withParam(QJsonObject router, int node, const QString &key, const QJsonValue &value)
{
    QJsonArray nodes = router.value("nodes").toArray();
    QJsonObject n = nodes.at(node).toObject();
    QJsonObject params = n.value("params").toObject();
    if (value.isUndefined())
        params.remove(key);
    else
        params.insert(key, value);
    n.insert("params", params);
    nodes.replace(node, n);
    router.insert("nodes", nodes);
    return router;
}

/** The time the first break warning begins, feeding a right-hand force ramp to `router`. */
double firstBreakWarning(std::unique_ptr<Router> router)
{
    EventBuffer events;
    ContactFrame frame;
    frame.gripper = Gripper::Right;
    router->start(0.0);
    for (int k = 0; k <= 1000; ++k) {
        frame.t = k * 0.002;
        const double force = std::min(100.0 * frame.t, 110.0); // 100 N/s, then held
        frame.left.f = frame.right.f = force / 2;
        frame.left.n = frame.right.n = 16;
        frame.left.actor = frame.right.actor = 0;
        events.clear();
        router->process(frame, events);
        for (const SemanticEvent &e : events) {
            if (e.message == Message::Break && e.phase == EventPhase::Begin)
                return e.t;
        }
    }
    return -1.0;
}

} // namespace

namespace {

/**
 * A task's router built only from generic nodes: "aligned" while the plug's angle error is
 * inside ±0.05 rad, and "aligned.grasp" while aligned and the right hand grasps.
 */
QJsonObject alignmentRouter()
{
    return object(R"({"format": "semhap.router/1", "nodes": [
        {"id": "right.force", "type": "force", "params": {"gripper": "right"}},
        {"id": "angle", "type": "signal",
         "params": {"gripper": "right", "quantity": "plug.angle_error"}},
        {"id": "aligned", "type": "threshold",
         "params": {"gripper": "right", "message": "aligned", "category": "confirmation",
                    "condition": "inside", "begin": [-0.05, 0.05], "end": [-0.06, 0.06]}},
        {"id": "ready", "type": "compose",
         "params": {"message": "aligned.grasp", "category": "confirmation", "mode": "while"}},
        {"id": "squeeze", "type": "pattern", "params": {"pattern": "air.squeeze"}},
        {"id": "right.air", "type": "device", "params": {"model": "pneumatic6"}}
      ],
      "links": [
        {"from": "angle", "to": "aligned"}, {"from": "aligned", "to": "ready:a"},
        {"from": "right.force", "to": "ready:b"}, {"from": "ready", "to": "squeeze"},
        {"from": "squeeze", "to": "right.air"}
      ]})");
}

} // namespace

void TestRouter::namedSignalsDriveDetectors()
{
    LoadError error;
    RouterGraph graph;
    QVERIFY(RouterGraph::fromJson(alignmentRouter(), "r.json", &graph, &error));
    std::unique_ptr<Router> router = Router::compile(graph, &error);
    QVERIFY2(router, qPrintable(error.toString()));
    const int angle = signalNames().intern("plug.angle_error");
    router->start(0.0);
    QStringList seen;
    EventBuffer events;
    // The angle closes in while a grasp (20 N) holds from 0.1 s on; a frame without the
    // signal (0.3 s) leaves the threshold as it was.
    const QList<double> angles{0.2, 0.1, 0.04, std::nan(""), 0.055, 0.07, 0.0};
    for (int k = 0; k < angles.size(); ++k) {
        ContactFrame frame;
        frame.t = k * 0.1;
        frame.left.f = frame.right.f = k >= 1 ? 15.0 : 0.0;
        frame.left.n = frame.right.n = 16;
        if (!std::isnan(angles[k]))
            frame.signalValues.set(angle, angles[k]);
        events.clear();
        router->process(frame, events);
        for (const SemanticEvent &e : events) {
            seen.append(QStringLiteral("%1 %2 %3 %4")
                            .arg(e.t)
                            .arg(router->nodeIds().at(e.node), messageName(e.message),
                                 eventPhaseName(e.phase)));
        }
    }
    QCOMPARE(seen, (QStringList{"0.1 right.force grasp begin", "0.2 aligned aligned begin",
                                "0.2 ready aligned.grasp begin", "0.5 aligned aligned end",
                                "0.5 ready aligned.grasp end", "0.6 aligned aligned begin",
                                "0.6 ready aligned.grasp begin"}));
    // The composed message is a confirmation: it plays the squeeze that confirms grasps.
    QCOMPARE(router->activity()[4].isActive(), true);
}

void TestRouter::signalsTheSourceLacksAreRefused()
{
    LoadError error;
    RouterGraph graph;
    QVERIFY(RouterGraph::fromJson(alignmentRouter(), "r.json", &graph, &error));
    RouterContext context;
    context.knowsSignals = true;
    context.signalNames[size_t(Gripper::Right)] = QStringList{"plug.depth", "plug.lateral"};
    QVERIFY(!Router::compile(graph, &error, context));
    QCOMPARE(error.toString(),
             QStringLiteral("r.json: /nodes/1/params/quantity: node 'angle' (signal): the right "
                            "gripper's frames carry no signal 'plug.angle_error' (they carry: "
                            "plug.depth, plug.lateral)"));
    context.signalNames[size_t(Gripper::Right)].append("plug.angle_error");
    QVERIFY2(Router::compile(graph, &error, context), qPrintable(error.toString()));
}

void TestRouter::thresholdsTellTheirSignalAndLevels()
{
    // A range on a named signal read directly; a level on F through predict (same units)
    // and on its derivative (other units); the compose node is no threshold.
    QJsonObject json = alignmentRouter();
    QJsonArray nodes = json.value("nodes").toArray();
    QJsonArray links = json.value("links").toArray();
    nodes.append(object(R"({"id": "F", "type": "signal",
                            "params": {"gripper": "left", "quantity": "F"}})"));
    nodes.append(object(R"({"id": "Fp", "type": "predict", "params": {}})"));
    nodes.append(object(R"({"id": "dF", "type": "derivative", "params": {}})"));
    nodes.append(object(R"({"id": "soon", "type": "threshold",
                            "params": {"gripper": "right", "message": "break", "begin": 80,
                                       "end": 70}})"));
    nodes.append(object(R"({"id": "steep", "type": "threshold",
                            "params": {"gripper": "left", "message": "steep",
                                       "category": "exception", "condition": "below",
                                       "begin": -5}})"));
    for (const char *link :
         {R"({"from": "F", "to": "Fp"})", R"({"from": "Fp", "to": "dF"})",
          R"({"from": "Fp", "to": "soon"})", R"({"from": "dF", "to": "steep"})"})
        links.append(object(link));
    json.insert("nodes", nodes);
    json.insert("links", links);
    LoadError error;
    RouterGraph graph;
    QVERIFY(RouterGraph::fromJson(json, "r.json", &graph, &error));
    std::unique_ptr<Router> router = Router::compile(graph, &error);
    QVERIFY2(router, qPrintable(error.toString()));

    const std::vector<ThresholdLevels> levels = router->thresholds();
    QCOMPARE(levels.size(), size_t(3));
    const ThresholdLevels &aligned = levels[0];
    QCOMPARE(aligned.node, QStringLiteral("aligned"));
    QCOMPARE(aligned.quantity, QStringLiteral("plug.angle_error"));
    QCOMPARE(aligned.signalGripper, Gripper::Right);
    QCOMPARE(messageName(aligned.message), QStringLiteral("aligned"));
    QCOMPARE(aligned.category, Category::Confirmation);
    QCOMPARE(aligned.condition, QStringLiteral("inside"));
    QVERIFY(aligned.range);
    QCOMPARE(aligned.begin, -0.05);
    QCOMPARE(aligned.beginHigh, 0.05);
    QCOMPARE(aligned.end, -0.06);
    QCOMPARE(aligned.endHigh, 0.06);
    QVERIFY(aligned.via.isEmpty());
    QVERIFY(aligned.levelsInSignalUnits);

    const ThresholdLevels &soon = levels[1];
    QCOMPARE(soon.node, QStringLiteral("soon"));
    QCOMPARE(soon.quantity, QStringLiteral("F"));
    QCOMPARE(soon.signalGripper, Gripper::Left);
    QCOMPARE(soon.gripper, Gripper::Right);
    QVERIFY(!soon.range);
    QCOMPARE(soon.begin, 80.0);
    QCOMPARE(soon.end, 70.0);
    QCOMPARE(soon.via, QStringList{"predict"});
    QVERIFY(soon.levelsInSignalUnits);

    const ThresholdLevels &steep = levels[2];
    QCOMPARE(steep.quantity, QStringLiteral("F"));
    QCOMPARE(steep.via, (QStringList{"predict", "derivative"}));
    QVERIFY(!steep.levelsInSignalUnits);
    QCOMPARE(steep.condition, QStringLiteral("below"));
}

void TestRouter::aMessageHasOneCategory()
{
    QJsonObject json = alignmentRouter();
    json = withParam(json, 3, "message", "aligned");
    LoadError error;
    RouterGraph graph;
    QVERIFY(RouterGraph::fromJson(json, "r.json", &graph, &error));
    QVERIFY(Router::compile(graph, &error)); // both confirmations: one meaning
    json = withParam(json, 3, "category", "exception");
    QVERIFY(RouterGraph::fromJson(json, "r.json", &graph, &error));
    QVERIFY(!Router::compile(graph, &error));
    QCOMPARE(error.toString(),
             QStringLiteral("r.json: /nodes/3/params/category: node 'ready' (compose): 'aligned' "
                            "has the category confirmation in node 'aligned': a message has "
                            "one"));
}

void TestRouter::oldThresholdsReadAsNew()
{
    // semhap 1.0's level/full/hysteresis: the same warning, read as condition, begin, end
    // and intensity, with a located warning.
    const QJsonObject old =
        withParam(withParam(withParam(withParam(withParam(predictiveRouter(), 2, "begin",
                                                          QJsonValue(QJsonValue::Undefined)),
                                                2, "intensity", QJsonValue(QJsonValue::Undefined)),
                                      2, "level", 80),
                            2, "full", 120),
                  2, "hysteresis", 3);
    LoadError error;
    RouterGraph graph;
    QVERIFY(RouterGraph::fromJson(old, "r.json", &graph, &error));
    QCOMPARE(graph.warnings.size(), size_t(1));
    QCOMPARE(graph.warnings.front().toString(),
             QStringLiteral("r.json: /nodes/2/params: deprecated: threshold parameters "
                            "\"level\", \"full\" and \"hysteresis\" are now \"condition\", "
                            "\"begin\", \"end\" and \"intensity\" (read as those)"));
    const QJsonObject params = graph.nodes[2].params;
    QCOMPARE(params.value("condition").toString(), QStringLiteral("above"));
    QCOMPARE(params.value("begin").toDouble(), 80.0);
    QCOMPARE(params.value("end").toDouble(), 77.0);
    QCOMPARE(params.value("intensity").toArray(), (QJsonArray{80, 120}));
    QVERIFY(!params.contains("level") && !params.contains("hysteresis"));
    QVERIFY2(Router::compile(graph, &error), qPrintable(error.toString()));
    // C3p and C4p as shipped use the new form.
    for (const char *preset : {"C3p", "C4p"}) {
        QVERIFY(RouterPresets::preset(preset, &graph, &error));
        QVERIFY2(graph.warnings.empty(), preset);
    }
}

void TestRouter::invalidPredictive_data()
{
    QTest::addColumn<QJsonObject>("json");
    QTest::addColumn<QString>("error");
    QTest::newRow("threshold without begin")
        << withParam(predictiveRouter(), 2, "begin", QJsonValue(QJsonValue::Undefined))
        << "r.json: /nodes/2: node 'break' (threshold): needs \"begin\": a finite number or a "
           "[low, high] range";
    QTest::newRow("a range where a level goes")
        << withParam(predictiveRouter(), 2, "begin", QJsonArray{70, 90})
        << "r.json: /nodes/2/params/begin: node 'break' (threshold): must be a number for the "
           "condition 'above'";
    QTest::newRow("a level where a range goes")
        << withParam(withParam(predictiveRouter(), 2, "condition", "inside"), 2, "begin", 80)
        << "r.json: /nodes/2/params/begin: node 'break' (threshold): must be a [low, high] "
           "range for the condition 'inside'";
    QTest::newRow("empty range")
        << withParam(withParam(predictiveRouter(), 2, "condition", "outside"), 2, "begin",
                     QJsonArray{90, 90})
        << "r.json: /nodes/2/params/begin: node 'break' (threshold): empty range: low 90 is not "
           "below high 90";
    QTest::newRow("end above begin: crossed")
        << withParam(predictiveRouter(), 2, "end", 81)
        << "r.json: /nodes/2/params/end: node 'break' (threshold): begin/end levels crossed "
           "(above: end must not be above begin)";
    QTest::newRow("below: end below begin")
        << withParam(withParam(predictiveRouter(), 2, "condition", "below"), 2, "end", 79)
        << "r.json: /nodes/2/params/end: node 'break' (threshold): begin/end levels crossed "
           "(below: end must not be below begin)";
    QTest::newRow("inside: an end range narrower than begin's")
        << withParam(withParam(withParam(predictiveRouter(), 2, "condition", "inside"), 2, "begin",
                               QJsonArray{0, 1}),
                     2, "end", QJsonArray{0.2, 2})
        << "r.json: /nodes/2/params/end: node 'break' (threshold): begin/end levels crossed "
           "(inside: the end range must contain the begin range)";
    QTest::newRow("outside: an end range wider than begin's")
        << withParam(withParam(withParam(predictiveRouter(), 2, "condition", "outside"), 2,
                               "begin", QJsonArray{0, 1}),
                     2, "end", QJsonArray{-0.5, 1})
        << "r.json: /nodes/2/params/end: node 'break' (threshold): begin/end levels crossed "
           "(outside: the end range must lie within the begin range)";
    QTest::newRow("unknown condition")
        << withParam(predictiveRouter(), 2, "condition", "over")
        << "r.json: /nodes/2/params/condition: node 'break' (threshold): must be \"above\", "
           "\"below\", \"inside\" or \"outside\"";
    QTest::newRow("a new message needs a category")
        << withParam(predictiveRouter(), 2, "message", "crack")
        << "r.json: /nodes/2: node 'break' (threshold): needs \"category\" for the new message "
           "'crack': \"confirmation\" or \"exception\"";
    QTest::newRow("not a message name")
        << withParam(predictiveRouter(), 2, "message", "Crack!")
        << "r.json: /nodes/2/params/message: node 'break' (threshold): must be \"grasp\", "
           "\"break\" or \"slip\" or a new name of [a-z0-9_.]";
    QTest::newRow("a built-in message keeps its category")
        << withParam(predictiveRouter(), 2, "category", "confirmation")
        << "r.json: /nodes/2/params/category: node 'break' (threshold): 'break' has the category "
           "exception";
    QTest::newRow("intensity from a point")
        << withParam(predictiveRouter(), 2, "intensity", QJsonArray{80, 80})
        << "r.json: /nodes/2/params/intensity: node 'break' (threshold): must be [x0, x1] with "
           "x0 and x1 apart: the input at intensity 0 and at 1";
    QTest::newRow("negative minDuration")
        << withParam(predictiveRouter(), 2, "minDuration", -1)
        << "r.json: /nodes/2/params/minDuration: node 'break' (threshold): must not be "
           "negative, got -1";
    QTest::newRow("negative horizon")
        << withParam(predictiveRouter(), 1, "horizon", -0.1)
        << "r.json: /nodes/1/params/horizon: node 'F.predicted' (predict): must not be negative, "
           "got -0.1";
    QTest::newRow("negative tau") << withParam(predictiveRouter(), 1, "tau", -0.1)
                                  << "r.json: /nodes/1/params/tau: node 'F.predicted' "
                                     "(predict): must not be negative, got -0.1";
    QTest::newRow("zero mu")
        << withParam(predictiveRouter(), 0, "mu", 0)
        << "r.json: /nodes/0/params/mu: node 'F' (signal): must be positive, got 0";
}

void TestRouter::invalidPredictive()
{
    QFETCH(QJsonObject, json);
    QFETCH(QString, error);
    RouterGraph graph;
    LoadError loadError;
    QVERIFY2(RouterGraph::fromJson(json, "r.json", &graph, &loadError),
             qPrintable(loadError.toString()));
    QVERIFY(!Router::compile(graph, &loadError));
    QCOMPARE(loadError.toString(), error);
}

void TestRouter::defaultHorizon()
{
    // The lra4 band's response delay (no dead time, 12 ms rise: tau = 0.012 / ln 9) plus the
    // reaction time of the run; a horizon given is kept; with no device downstream, the
    // reaction time alone.
    RouterGraph graph;
    LoadError error;
    QVERIFY(RouterGraph::fromJson(predictiveRouter(), "r.json", &graph, &error));
    const double lra4 = 0.012 / std::log(9.0);
    QVERIFY(std::abs(DeviceModelLibrary::load("lra4", &error)->responseDelay() - lra4) < 1e-12);
    for (double reaction : {0.25, 0.4}) {
        RouterContext context;
        context.reactionTime = reaction;
        std::unique_ptr<Router> router = Router::compile(graph, &error, context);
        QVERIFY(router);
        const double begin = firstBreakWarning(std::move(router));
        // The ramp is predicted to cross 80 N a horizon ahead of the 0.8 s it does (the slope
        // has settled by then: 10 tau).
        const double horizon = reaction + lra4;
        QVERIFY2(std::abs(begin - (0.8 - horizon)) < 0.005,
                 qPrintable(QString("began at %1, horizon %2").arg(begin).arg(horizon)));
    }
    RouterGraph fixed;
    QVERIFY(RouterGraph::fromJson(withParam(predictiveRouter(), 1, "horizon", 0.1), "r.json",
                                  &fixed, &error));
    const double begin = firstBreakWarning(Router::compile(fixed, &error));
    QVERIFY2(std::abs(begin - 0.7) < 0.005, qPrintable(QString::number(begin)));
}

void TestRouter::predictiveWarningComesEarlier()
{
    // The same squeeze through C3 and C3p: C3p's predictive warning begins about its horizon
    // (the band's delay plus the reaction time) before C3's, which waits for F > 80.
    LoadError error;
    const double c3 = firstBreakWarning(loadRouter("C3", {}, &error));
    const double c3p = firstBreakWarning(loadRouter("C3p", {}, &error));
    QVERIFY(std::abs(c3 - 0.802) < 1e-9);
    const double horizon = 0.25 + 0.012 / std::log(9.0);
    QVERIFY2(std::abs((c3 - c3p) - horizon) < 0.005,
             qPrintable(QString("%1 %2").arg(c3).arg(c3p)));
}

QTEST_GUILESS_MAIN(TestRouter)
#include "tst_router.moc"
