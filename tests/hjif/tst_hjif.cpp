// SPDX-License-Identifier: MIT
// MPEG haptics (HJIF): patterns and routers written out and read back render the same output
// within 1 %, the files pass the JSON Schema of hjif/hjif.schema.json in Ajv, and whatever a
// file holds is read with a located error or within bounded work.
#include "clirun.h"
#include "hjifconverter.h"
#include "hjifdocument.h"
#include "jsonreader.h"
#include "patternlibrary.h"
#include "patternrender.h"
#include "router.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numeric>

using namespace semhap;

namespace {

/** The largest difference between two renders, channel by channel, as a share of 1. */
double largestDifference(const RenderedPattern &a, const RenderedPattern &b)
{
    double worst = 0.0;
    for (size_t c = 0; c < a.values.size(); ++c) {
        for (size_t k = 0; k < a.values[c].size(); ++k)
            worst = std::max(worst, std::abs(a.values[c][k] - b.values[c][k]));
    }
    return worst;
}

/** Writes a document through its JSON and reads it back, as a file would go. */
HjifDocument throughJson(const HjifDocument &document)
{
    QJsonObject json;
    LoadError error;
    HjifDocument back;
    if (!parseJsonObject(HjifConverter::serialize(document), QStringLiteral("t.hjif"), &json,
                         &error) ||
        !HjifDocument::fromJson(json, QStringLiteral("t.hjif"), &back, nullptr, &error))
        qFatal("%s", qPrintable(error.toString()));
    return back;
}

/** A one-perception file of `channel` (a channel object) on lra4 or pneumatic6, as JSON. */
QByteArray fileWith(const QString &modality, const QString &channels,
                    const QString &library = QStringLiteral("[]"), qint64 timescale = 1000)
{
    return QStringLiteral(R"({"version": "2023", "profile": "Main", "level": 1,
        "date": "2026-11-30", "description": "t", "timescale": %1, "avatars": [], "syncs": [],
        "perceptions": [{"id": 0, "avatar_id": 0, "description": "p",
        "perception_modality": "%2", "effect_library": %3, "channels": %4}]})")
        .arg(timescale)
        .arg(modality, library, channels)
        .toUtf8();
}

QString channelWith(const QString &band, const QString &effects, int id = 0)
{
    return QStringLiteral(R"({"id": %1, "description": "", "gain": 1, "mixing_coefficient": 1,
        "body_part_mask": 0, "bands": [{"band_type": "%2", "lower_frequency_limit": 0,
        "upper_frequency_limit": 1000, "effects": %3}]})")
        .arg(id)
        .arg(band, effects);
}

bool importBytes(const QByteArray &bytes, const ConvertOptions &options, QJsonObject *pattern,
                 QStringList *warnings, LoadError *error)
{
    return HjifConverter::parsePattern(bytes, QStringLiteral("t.hjif"), options, pattern, warnings,
                                       error);
}

RenderedPattern renderOf(const QJsonObject &json, double duration)
{
    LoadError error;
    const PatternPtr pattern = Pattern::fromJson(json, QStringLiteral("p"), &error);
    if (!pattern)
        qFatal("%s", qPrintable(error.toString()));
    RenderOptions options;
    options.duration = duration;
    RenderedPattern out;
    QString reason;
    if (!renderPattern(pattern, *DeviceModelLibrary::builtin(pattern->model()), options, &out,
                       &reason))
        qFatal("%s", qPrintable(reason));
    return out;
}

const QStringList Messaging{"C1", "C2", "C3", "C3p", "C4", "C4p", "usb", "wipe"};

} // namespace

class TestHjif : public QObject
{
    Q_OBJECT

private slots:
    void patternRoundTrip_data();
    void patternRoundTrip();
    void routerRoundTrip_data();
    void routerRoundTrip();
    void routersWithoutHaptics_data();
    void routersWithoutHaptics();
    void schema();
    void malformed_data();
    void malformed();
    void boundedWork_data();
    void boundedWork();
    void foreignContent();
    void denseKeyframesAreSampled();
    void asTheReferenceSoftwarePlays();
    void commandLine();
};

void TestHjif::patternRoundTrip_data()
{
    QTest::addColumn<QString>("name");
    for (const QString &name : PatternLibrary::builtinNames()) {
        if (!name.startsWith(QLatin1String("visual.")))
            QTest::newRow(qPrintable(name)) << name;
    }
}

void TestHjif::patternRoundTrip()
{
    QFETCH(QString, name);
    const PatternPtr original = PatternLibrary::builtin(name);
    const QJsonObject json = original->toJson();
    const DeviceModelPtr model = DeviceModelLibrary::builtin(original->model());
    HjifDocument document;
    LoadError error;
    QVERIFY2(HjifConverter::patternToDocument(json, name, {}, &document, nullptr, &error),
             qPrintable(error.toString()));

    // The perception carries the band: its sense, device, and a channel per actuator.
    QCOMPARE(document.perceptions.size(), size_t(1));
    const HjifPerception &p = document.perceptions.front();
    const bool lra = model->name() == QLatin1String("lra4");
    QCOMPARE(p.modality, lra ? QStringLiteral("Vibrotactile") : QStringLiteral("Pressure"));
    QCOMPARE(p.devices.size(), size_t(1));
    QCOMPARE(p.devices.front().name, model->name());
    QCOMPARE(p.devices.front().resonanceFrequency.has_value(), lra);
    QCOMPARE(int(p.channels.size()), model->channelCount());
    const quint32 both = model->actuator().body == QLatin1String("fingers")
                             ? HjifDocument::LeftFingers | HjifDocument::RightFingers
                             : HjifDocument::LeftWrist | HjifDocument::RightWrist;
    for (size_t c = 0; c < p.channels.size(); ++c) {
        QCOMPARE(p.channels[c].description, model->channels()[c].name);
        QCOMPARE(p.channels[c].bodyPartMask, both);
        QCOMPARE(p.channels[c].bands.front().type,
                 lra ? HjifBand::Type::VectorialWave : HjifBand::Type::Curve);
    }

    // Back as a pattern, it plays what the original played from a begin to the same end.
    QJsonObject imported;
    QVERIFY2(HjifConverter::documentToPattern(throughJson(document), name, {}, &imported, nullptr,
                                              &error),
             qPrintable(error.toString()));
    QCOMPARE(imported.value(QLatin1String("model")).toString(), model->name());
    RenderOptions options;
    std::vector<int> all(original->tracks().size());
    std::iota(all.begin(), all.end(), 0);
    QVERIFY(HapticConverter::span(json, name, {}, all, &options.releaseAt, &options.duration,
                                  nullptr, &error));
    options.duration += 0.5; // and silence after
    RenderedPattern before;
    RenderedPattern after;
    QString reason;
    QVERIFY(renderPattern(original, *model, options, &before, &reason));
    options.releaseAt = std::numeric_limits<double>::infinity();
    QVERIFY(renderPattern(Pattern::fromJson(imported, name, &error), *model, options, &after,
                          &reason));
    const double difference = largestDifference(before, after);
    qInfo("%s: largest difference %.4f over %zu channels", qPrintable(name), difference,
          before.values.size());
    QVERIFY2(difference <= 0.01, qPrintable(QString::number(difference)));
}

void TestHjif::routerRoundTrip_data()
{
    QTest::addColumn<QString>("name");
    for (const QString &name : Messaging)
        QTest::newRow(qPrintable(name)) << name;
}

void TestHjif::routerRoundTrip()
{
    QFETCH(QString, name);
    LoadError error;
    const std::unique_ptr<Router> router = loadRouter(name, {}, &error);
    QVERIFY2(router, qPrintable(error.toString()));
    HjifDocument document;
    QVERIFY2(HjifConverter::routerToDocument(*router, name, {}, &document, nullptr, &error),
             qPrintable(error.toString()));
    document = throughJson(document);

    // The perceptions follow the felt devices that play messages, each message in its slot.
    const Player &player = router->player();
    const std::vector<MessageRoute> routes = router->messageRoutes(1.0);
    size_t perception = 0;
    int checked = 0;
    double worst = 0.0;
    for (int device = 0; device < player.deviceCount(); ++device) {
        const DeviceModel &model = player.deviceModel(device);
        if (model.modality() == QLatin1String("sight"))
            continue;
        double slot = 0.0;
        for (const MessageRoute &route : routes) {
            if (route.device != device)
                continue;
            QVERIFY(perception < document.perceptions.size());
            const HjifPerception &p = document.perceptions[perception];
            QCOMPARE(p.devices.front().name, model.name());
            Gripper hand;
            QVERIFY(router->deviceHand(device, &hand));
            const quint32 wrist =
                hand == Gripper::Left ? HjifDocument::LeftWrist : HjifDocument::RightWrist;
            QCOMPARE(p.channels.front().bodyPartMask, wrist);
            QVERIFY(p.description.contains(player.deviceName(device)));

            RenderOptions options;
            options.intensity = route.intensity;
            std::vector<int> all(route.played->tracks().size());
            std::iota(all.begin(), all.end(), 0);
            QVERIFY(HapticConverter::span(route.played->toJson(), name, {}, all,
                                          &options.releaseAt, &options.duration, nullptr, &error));
            const double length = options.duration;
            options.duration += 0.5;
            RenderedPattern expected;
            renderRoutedPattern(route.played, route.routes, model, options, &expected);
            const auto position = std::llround(slot * 1000.0);
            for (size_t c = 0; c < p.channels.size(); ++c) {
                const auto &effects = p.channels[c].bands.front().effects;
                const auto use = std::find_if(effects.begin(), effects.end(), [&](const auto &e) {
                    return e.position == position;
                });
                if (use == effects.end()) {
                    // Nothing in this slot: the message leaves the channel at rest.
                    QCOMPARE(
                        *std::max_element(expected.values[c].begin(), expected.values[c].end()),
                        0.0);
                    continue;
                }
                QCOMPARE(use->type, HjifEffect::Type::Reference);
                const auto library = std::find_if(p.library.begin(), p.library.end(),
                                                  [&](const auto &e) { return e.id == use->id; });
                QVERIFY(library != p.library.end());
                QCOMPARE(library->semantic, HjifConverter::semanticKeyword(
                                                route.message.message, route.message.category));
                ConvertOptions read;
                read.perception = p.id;
                read.effect = use->id;
                QJsonObject imported;
                QVERIFY2(HjifConverter::documentToPattern(document, name, read, &imported, nullptr,
                                                          &error),
                         qPrintable(error.toString()));
                const RenderedPattern back = renderOf(imported, options.duration);
                double difference = 0.0;
                for (size_t k = 0; k < back.values[c].size(); ++k)
                    difference =
                        std::max(difference, std::abs(back.values[c][k] - expected.values[c][k]));
                worst = std::max(worst, difference);
                QVERIFY2(difference <= 0.01, qPrintable(QStringLiteral("%1, channel %2: %3")
                                                            .arg(p.description)
                                                            .arg(c)
                                                            .arg(difference)));
                ++checked;
            }
            slot += length + HjifConverter::Gap;
        }
        if (slot > 0.0)
            ++perception;
    }
    QCOMPARE(perception, document.perceptions.size());
    QVERIFY(checked > 0);
    qInfo("%s: %d channel effects back within %.4f", qPrintable(name), checked, worst);
}

void TestHjif::routersWithoutHaptics_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("error");
    QTest::newRow("none") << "none"
                          << "none: no message plays on a device that is felt";
    QTest::newRow("sensory") << "sensory"
                             << "sensory: no message plays on a device that is felt";
    QTest::newRow("visual") << "visual"
                            << "visual: no message plays on a device that is felt";
}

void TestHjif::routersWithoutHaptics()
{
    QFETCH(QString, name);
    QFETCH(QString, error);
    LoadError e;
    const std::unique_ptr<Router> router = loadRouter(name, {}, &e);
    QVERIFY(router);
    HjifDocument document;
    QStringList warnings;
    QVERIFY(!HjifConverter::routerToDocument(*router, name, {}, &document, &warnings, &e));
    QCOMPARE(e.toString(), error);
    if (name == QLatin1String("visual"))
        QCOMPARE(warnings, QStringList{"visual: device 'overlay' (overlay) is sight, not felt: "
                                       "its 4 message(s) are left out"});
}

void TestHjif::schema()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QStringList files;
    const auto write = [&](const QString &name, const QByteArray &bytes) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(bytes);
        files.append(file.fileName());
    };
    LoadError error;
    for (const QString &name : PatternLibrary::builtinNames()) {
        if (name.startsWith(QLatin1String("visual.")))
            continue;
        HjifDocument document;
        ConvertOptions options;
        options.hand = QStringLiteral("left");
        QVERIFY(HjifConverter::patternToDocument(PatternLibrary::builtin(name)->toJson(), name,
                                                 options, &document, nullptr, &error));
        write(name + QStringLiteral(".hjif"), HjifConverter::serialize(document));
    }
    for (const QString &name : Messaging) {
        const std::unique_ptr<Router> router = loadRouter(name, {}, &error);
        HjifDocument document;
        QVERIFY(HjifConverter::routerToDocument(*router, name, {}, &document, nullptr, &error));
        write(name + QStringLiteral(".hjif"), HjifConverter::serialize(document));
    }
    const QString schema = QStringLiteral(SEMHAP_SOURCE_DIR "/hjif/hjif.schema.json");
    const QString tool = QStringLiteral(SEMHAP_INTEROP_TOOLS "/hjif-schema.mjs");
    QProcess node;
    node.setProcessChannelMode(QProcess::MergedChannels);
    node.start(QStringLiteral(SEMHAP_NODE), QStringList{tool, schema} + files);
    QVERIFY(node.waitForFinished(60000));
    const QByteArray said = node.readAll();
    QVERIFY2(node.exitCode() == 0, said.constData());
    QCOMPARE(said.count("valid\n"), files.size());

    // The schema is no rubber stamp: each of these breaks one rule of the layout.
    QJsonObject good;
    QVERIFY(readJsonObjectFile(files.last(), &good, &error));
    const auto broken = [&](const char *name, const std::function<void(QJsonObject &)> &edit) {
        QJsonObject json = good;
        edit(json);
        QFile file(dir.filePath(QLatin1String(name) + QStringLiteral(".bad.hjif")));
        if (file.open(QIODevice::WriteOnly))
            file.write(QJsonDocument(json).toJson());
        return file.fileName();
    };
    const auto onPerception = [](QJsonObject &json, const std::function<void(QJsonObject &)> &f) {
        QJsonArray perceptions = json.value(QLatin1String("perceptions")).toArray();
        QJsonObject p = perceptions.first().toObject();
        f(p);
        perceptions[0] = p;
        json.insert(QStringLiteral("perceptions"), perceptions);
    };
    const auto onBand = [&](QJsonObject &json, const std::function<void(QJsonObject &)> &f) {
        onPerception(json, [&](QJsonObject &p) {
            QJsonArray channels = p.value(QLatin1String("channels")).toArray();
            QJsonObject channel = channels.first().toObject();
            QJsonArray bands = channel.value(QLatin1String("bands")).toArray();
            QJsonObject band = bands.first().toObject();
            f(band);
            bands[0] = band;
            channel.insert(QStringLiteral("bands"), bands);
            channels[0] = channel;
            p.insert(QStringLiteral("channels"), channels);
        });
    };
    const QStringList bad{
        broken("nosyncs", [](QJsonObject &j) { j.remove(QStringLiteral("syncs")); }),
        broken("version", [](QJsonObject &j) { j.insert(QStringLiteral("version"), 2023); }),
        broken("timescale", [](QJsonObject &j) { j.insert(QStringLiteral("timescale"), 0); }),
        broken("modality",
               [&](QJsonObject &j) {
                   onPerception(j, [](QJsonObject &p) {
                       p.insert(QStringLiteral("perception_modality"), QStringLiteral("Smell"));
                   });
               }),
        broken("bandtype",
               [&](QJsonObject &j) {
                   onBand(j, [](QJsonObject &b) {
                       b.insert(QStringLiteral("band_type"), QStringLiteral("Sinus"));
                   });
               }),
        broken("referencewithoutid",
               [&](QJsonObject &j) {
                   onBand(j, [](QJsonObject &b) {
                       b.insert(
                           QStringLiteral("effects"),
                           QJsonArray{QJsonObject{{"effect_type", "Reference"}, {"position", 0}}});
                   });
               }),
        broken("amplitude",
               [&](QJsonObject &j) {
                   onBand(j, [](QJsonObject &b) {
                       b.insert(QStringLiteral("effects"),
                                QJsonArray{QJsonObject{
                                    {"effect_type", "Basis"},
                                    {"position", 0},
                                    {"keyframes",
                                     QJsonArray{QJsonObject{{"relative_position", 0},
                                                            {"amplitude_modulation", 1.5}}}}}});
                   });
               }),
        broken("typo", [&](QJsonObject &j) {
            onBand(j, [](QJsonObject &b) { b.insert(QStringLiteral("efects"), QJsonArray()); });
        })};
    node.start(QStringLiteral(SEMHAP_NODE),
               QStringList{tool, schema, QStringLiteral("--invalid")} + bad);
    QVERIFY(node.waitForFinished(60000));
    const QByteArray refused = node.readAll();
    QVERIFY2(node.exitCode() == 0, refused.constData());
    QCOMPARE(refused.count(": invalid: "), bad.size());
}

void TestHjif::malformed_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("error");
    const QString effect = QStringLiteral(
        R"([{"effect_type": "Basis", "position": 0, "keyframes": [{"relative_position": 0,
        "amplitude_modulation": 0.5}, {"relative_position": 100, "amplitude_modulation": 1}]}])");
    const QString curve = channelWith(QStringLiteral("Curve"), effect);
    const auto replaced = [&](const QString &from, const QString &to) {
        return fileWith(QStringLiteral("Pressure"), QLatin1Char('[') + curve + QLatin1Char(']'))
            .replace(from.toUtf8(), to.toUtf8());
    };
    QTest::newRow("bad JSON") << QByteArray("{\n  \"version\": }")
                              << "t.hjif:2:15: invalid JSON: "
                                 "object is missing after "
                                 "a comma";
    QTest::newRow("no version") << replaced(R"("version": "2023", )", QString())
                                << "t.hjif: missing key 'version'";
    QTest::newRow("version a number")
        << replaced(R"("2023")", "2023") << "t.hjif: /version: expected a string, got a number";
    QTest::newRow("version too early")
        << replaced(R"("2023")", R"("2019")")
        << "t.hjif: /version: expected the year of the standard's edition (2023 or later), with "
           "-N for an amendment, got '2019'";
    QTest::newRow("profile") << replaced(R"("Main")", R"("Max")")
                             << "t.hjif: /profile: unknown profile 'Max' (one of Main, Simple "
                                "Parametric)";
    QTest::newRow("level") << replaced(R"("level": 1)", R"("level": 3)")
                           << "t.hjif: /level: must be between 1 and 2, got 3";
    QTest::newRow("timescale zero")
        << replaced(R"("timescale": 1000)", R"("timescale": 0)")
        << "t.hjif: /timescale: must be between 1 and 4294967295, got 0";
    QTest::newRow("timescale fraction") << replaced(R"("timescale": 1000)", R"("timescale": 0.5)")
                                        << "t.hjif: /timescale: expected an integer, got 0.5";
    QTest::newRow("no avatars") << replaced(R"("avatars": [], )", QString())
                                << "t.hjif: missing key 'avatars'";
    QTest::newRow("modality") << replaced(R"("Pressure")", R"("Smell")")
                              << "t.hjif: /perceptions/0/perception_modality: unknown "
                                 "perception_modality 'Smell' (one of Other, Pressure, "
                                 "Acceleration, Velocity, Position, Temperature, Vibrotactile, "
                                 "Water, Wind, Force, Vibrotactile Texture, Stiffness, Friction, "
                                 "Electrotactile, Vibration, Kinesthetic, Texture)";
    QTest::newRow("no channel") << fileWith(QStringLiteral("Pressure"), QStringLiteral("[]"))
                                << "t.hjif: /perceptions/0/channels: expected at least one "
                                   "channel";
    QTest::newRow("duplicate channel")
        << fileWith(QStringLiteral("Pressure"), QLatin1Char('[') + curve + ", " + curve + ']')
        << "t.hjif: /perceptions/0/channels/1/id: channel 0 is not unique";
    QTest::newRow("unknown reference device")
        << replaced(R"("body_part_mask": 0,)", R"("body_part_mask": 0, "reference_device_id": 4,)")
        << "t.hjif: /perceptions/0/channels/0/reference_device_id: no reference device 4 in the "
           "perception";
    QTest::newRow("band type") << replaced(R"("Curve")", R"("Wave")")
                               << "t.hjif: /perceptions/0/channels/0/bands/0/band_type: unknown "
                                  "band_type 'Wave' (one of Transient, Curve, VectorialWave, "
                                  "WaveletWave)";
    QTest::newRow("limits the wrong way round")
        << replaced(R"("lower_frequency_limit": 0)", R"("lower_frequency_limit": 2000)")
        << "t.hjif: /perceptions/0/channels/0/bands/0/upper_frequency_limit: 1000 Hz is below the "
           "lower limit, 2000 Hz";
    QTest::newRow("curve type on a wave")
        << replaced(R"("band_type": "Curve")",
                    R"("band_type": "VectorialWave", "curve_type": "Linear")")
        << "t.hjif: /perceptions/0/channels/0/bands/0/curve_type: only Curve bands have a curve "
           "type";
    QTest::newRow("keyframes back in time")
        << replaced(R"("relative_position": 100)", R"("relative_position": -1)")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0/keyframes/1/relative_position: "
           "must be between 0 and 2147483647, got -1";
    QTest::newRow("keyframes out of order")
        << replaced(R"("relative_position": 0,)", R"("relative_position": 200,)")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0/keyframes/1/relative_position: "
           "keyframe positions must not decrease";
    QTest::newRow("amplitude above 1")
        << replaced(R"("amplitude_modulation": 1})", R"("amplitude_modulation": 1.5})")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0/keyframes/1/"
           "amplitude_modulation: must be between -1 and 1, got 1.5";
    QTest::newRow("reference without id")
        << replaced(R"("effect_type": "Basis")", R"("effect_type": "Reference")")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0: missing key 'id'";
    QTest::newRow("reference to nothing")
        << replaced(R"("effect_type": "Basis")", R"("effect_type": "Reference", "id": 7)")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0/id: no effect 7 in the "
           "perception's effect_library";
    const QString toSelf =
        QStringLiteral(R"([{"effect_type": "Reference", "id": 0, "position": 0}])");
    const QString useZero = QLatin1Char('[') +
                            channelWith(QStringLiteral("Curve"),
                                        QStringLiteral(R"([{"effect_type": "Reference", "id": 0,
                                        "position": 0}])")) +
                            QLatin1Char(']');
    QTest::newRow("library reference")
        << fileWith(QStringLiteral("Pressure"), useZero, toSelf)
        << "t.hjif: /perceptions/0/effect_library/0/id: library effect 0 refers to itself";
    QTest::newRow("duplicate library effect")
        << fileWith(QStringLiteral("Pressure"), useZero,
                    QStringLiteral(R"([{"effect_type": "Basis", "id": 0, "position": 0},
                    {"effect_type": "Basis", "id": 0, "position": 0}])"))
        << "t.hjif: /perceptions/0/effect_library/1/id: library effect 0 is not unique";
    QTest::newRow("beyond ten minutes")
        << replaced(R"("relative_position": 100)", R"("relative_position": 2147483647)")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0: plays until 2.14748e+06 s, more "
           "than 600 s";
    QTest::newRow("a wave beyond ten minutes")
        << replaced(R"("band_type": "Curve")", R"("band_type": "VectorialWave")")
               .replace(R"("relative_position": 100)", R"("relative_position": 700000)")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0: plays until 700 s, more than "
           "600 s";
    QTest::newRow("beyond ten minutes at one tick a second")
        << replaced(R"("timescale": 1000)", R"("timescale": 1)")
               .replace(R"("relative_position": 100)", R"("relative_position": 601)")
        << "t.hjif: /perceptions/0/channels/0/bands/0/effects/0: plays until 601 s, more than "
           "600 s";
}

void TestHjif::malformed()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, error);
    QJsonObject pattern;
    LoadError e;
    QVERIFY(!importBytes(json, {}, &pattern, nullptr, &e));
    QCOMPARE(e.toString(), error);
}

void TestHjif::boundedWork_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("error");
    // Millions of keyframes: refused once the file holds more elements than the bound.
    QByteArray many = "[";
    const QByteArray keyframe = R"({"relative_position":0},)";
    many.reserve(keyframe.size() * (HjifDocument::MaxElements + 2));
    for (qint64 i = 0; i <= HjifDocument::MaxElements; ++i)
        many += keyframe;
    many.chop(1);
    many += ']';
    QTest::newRow("millions of keyframes")
        << fileWith(QStringLiteral("Pressure"),
                    QLatin1Char('[') +
                        channelWith(QStringLiteral("Curve"),
                                    QStringLiteral(R"([{"effect_type": "Basis", "position": 0,
                                    "keyframes": %1}])")
                                        .arg(QString::fromLatin1(many))) +
                        QLatin1Char(']'))
        << QStringLiteral("t.hjif: /perceptions/0/channels/0/bands/0/effects/0/keyframes: more "
                          "than 2000000 keyframes, effects, bands and channels in all: the file "
                          "is refused");
    // A library effect of 100 000 keyframes used 50 times renders to 5 000 000 points.
    QString library =
        QStringLiteral(R"([{"effect_type": "Basis", "id": 0, "position": 0, "keyframes": [)");
    for (int i = 0; i < 100000; ++i)
        library +=
            QStringLiteral(R"({"relative_position":%1,"amplitude_modulation":0.5},)").arg(i / 200);
    library.chop(1);
    library += QStringLiteral("]}]");
    QString uses = QStringLiteral("[");
    for (int i = 0; i < 50; ++i)
        uses += QStringLiteral(R"({"effect_type": "Reference", "id": 0, "position": %1},)")
                    .arg(i * 1000);
    uses.chop(1);
    uses += QLatin1Char(']');
    QTest::newRow("references multiply the work")
        << fileWith(QStringLiteral("Pressure"),
                    QLatin1Char('[') + channelWith(QStringLiteral("Curve"), uses) +
                        QLatin1Char(']'),
                    library)
        << QStringLiteral("t.hjif: /perceptions/0/effect_library/0: renders to more than 4000000 "
                          "points: the file is refused");
    // Keyframes without an amplitude cost work too, each time a reference plays them.
    QString empty =
        QStringLiteral(R"([{"effect_type": "Basis", "id": 0, "position": 0, "keyframes": [)");
    for (int i = 0; i < 100000; ++i)
        empty += QStringLiteral("{},");
    empty.chop(1);
    empty += QStringLiteral("]}]");
    QTest::newRow("references to keyframes without amplitudes")
        << fileWith(QStringLiteral("Pressure"),
                    QLatin1Char('[') + channelWith(QStringLiteral("Curve"), uses) +
                        QLatin1Char(']'),
                    empty)
        << QStringLiteral("t.hjif: /perceptions/0/effect_library/0: renders to more than 4000000 "
                          "points: the file is refused");
    // A cubic curve between keyframes ten minutes apart, in many effects, is sampled finely.
    QString cubic = QStringLiteral("[");
    for (int i = 0; i < 10; ++i)
        cubic += QStringLiteral(R"({"effect_type": "Basis", "position": 0, "keyframes": [
            {"relative_position": 0, "amplitude_modulation": 0},
            {"relative_position": 599000, "amplitude_modulation": 1}]},)");
    cubic.chop(1);
    cubic += QLatin1Char(']');
    QTest::newRow("cubic curves for ten minutes")
        << fileWith(QStringLiteral("Pressure"),
                    QLatin1Char('[') +
                        channelWith(QStringLiteral("Curve"), cubic)
                            .replace(QStringLiteral(R"("band_type": "Curve")"),
                                     QStringLiteral(R"("band_type": "Curve",
                                     "curve_type": "Cubic")")) +
                        QLatin1Char(']'))
        << QStringLiteral("t.hjif: /perceptions/0/channels/0/bands/0/effects/6: renders to more "
                          "than 4000000 points: the file is refused");
    // A huge timescale is only a fine clock: four billion ticks a second read as they are.
    QTest::newRow("huge timescale")
        << fileWith(
               QStringLiteral("Pressure"),
               QLatin1Char('[') +
                   channelWith(QStringLiteral("Curve"), QStringLiteral(R"([{"effect_type": "Basis",
                                    "position": 2147483647, "keyframes": [
                                    {"relative_position": 0, "amplitude_modulation": 1},
                                    {"relative_position": 2147483647,
                                    "amplitude_modulation": 0}]}])")) +
                   QLatin1Char(']'),
               QStringLiteral("[]"), 4294967295LL)
        << QString();
}

void TestHjif::boundedWork()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, error);
    QJsonObject pattern;
    LoadError e;
    const bool read = importBytes(json, {}, &pattern, nullptr, &e);
    QVERIFY2(read == error.isEmpty(), qPrintable(e.toString()));
    if (!read)
        QCOMPARE(e.toString(), error);
    else {
        // Half a second of rest, then a fall from 1 to 0 over the next half second.
        const RenderedPattern out = renderOf(pattern, 1.1);
        QVERIFY(std::abs(out.values[0][400]) < 1e-9);
        QVERIFY(std::abs(out.values[0][750] - 0.5) < 0.01);
        QVERIFY(std::abs(out.values[0][1050]) < 1e-9);
    }
}

void TestHjif::foreignContent()
{
    // What other tools write: a transient, a cubic curve, a square wave for a bellows, a
    // wavelet band and a composite effect, unknown keys, a carrier not the LRA's.
    const QString transient =
        channelWith(QStringLiteral("Transient"),
                    QStringLiteral(R"([{"effect_type": "Basis", "position": 100, "keyframes": [
        {"relative_position": 0, "amplitude_modulation": -0.8}]}])"));
    const QString cubic =
        channelWith(QStringLiteral("Curve"),
                    QStringLiteral(R"([{"effect_type": "Basis", "position": 0, "keyframes": [
        {"relative_position": 0, "amplitude_modulation": 0},
        {"relative_position": 1000, "amplitude_modulation": 1}]}])"),
                    1)
            .replace(QStringLiteral(R"("band_type": "Curve")"),
                     QStringLiteral(R"("band_type": "Curve", "curve_type": "Cubic")"));
    const QString square = channelWith(QStringLiteral("VectorialWave"),
                                       QStringLiteral(R"([{"effect_type": "Basis", "position": 0,
        "base_signal": "Square", "keyframes": [
        {"relative_position": 0, "amplitude_modulation": 1, "frequency_modulation": 5},
        {"relative_position": 1000, "amplitude_modulation": 1}]}])"),
                                       2);
    const QString wavelet =
        channelWith(QStringLiteral("WaveletWave"),
                    QStringLiteral(R"([{"effect_type": "Basis", "position": 0}])"), 3);
    const QString composite =
        channelWith(QStringLiteral("Curve"),
                    QStringLiteral(R"([{"effect_type": "Composite", "position": 0, "hue": 1},
        {"effect_type": "Basis", "position": 0, "hue": 2}])"),
                    4);
    const QByteArray file =
        fileWith(QStringLiteral("Pressure"), QLatin1Char('[') + transient + ", " + cubic + ", " +
                                                 square + ", " + wavelet + ", " + composite + ']');
    QJsonObject pattern;
    QStringList warnings;
    LoadError error;
    QVERIFY2(importBytes(file, {}, &pattern, &warnings, &error), qPrintable(error.toString()));
    QCOMPARE(pattern.value(QLatin1String("model")).toString(), QStringLiteral("pneumatic6"));
    QCOMPARE(warnings,
             (QStringList{"t.hjif: /perceptions/0/channels/4/bands/0/effects/0/hue: ignored: "
                          "unknown key (and in 1 more places)",
                          "t.hjif: /perceptions/0/channels/3/bands/0: ignored: WaveletWave bands "
                          "are coded signals semhap does not decode",
                          "t.hjif: /perceptions/0/channels/4/bands/0/effects/0: ignored: "
                          "composite effects are not converted"}));
    const RenderedPattern out = renderOf(pattern, 1.0);
    // b1: a 22 ms pulse of 0.8 at 100 ms.
    QCOMPARE(out.values[0][99], 0.0);
    QVERIFY(std::abs(out.values[0][110] - 0.8) < 1e-9);
    QCOMPARE(out.values[0][130], 0.0);
    // b2: the smooth step, half way at half time, a quarter in under 0.5 (3u² − 2u³ at 0.25).
    QVERIFY(std::abs(out.values[1][500] - 0.5) < 0.005);
    QVERIFY(std::abs(out.values[1][250] - 0.15625) < 0.005);
    // b3: a 5 Hz square wave raised for the bellows: 100 ms full, 100 ms empty.
    QVERIFY(out.values[2][50] > 0.99);
    QVERIFY(out.values[2][150] < 0.01);
    QVERIFY(out.values[2][250] > 0.99);

    // An LRA takes a wave's amplitude; a carrier not its own is named.
    const QByteArray vibro =
        fileWith(QStringLiteral("Vibrotactile"),
                 QLatin1Char('[') +
                     channelWith(QStringLiteral("VectorialWave"),
                                 QStringLiteral(R"([{"effect_type": "Basis", "position": 0,
            "keyframes": [{"relative_position": 0, "amplitude_modulation": 0.6,
            "frequency_modulation": 80}, {"relative_position": 500,
            "amplitude_modulation": -0.6}]}])")) +
                     QLatin1Char(']'));
    ConvertOptions onLra;
    onLra.model = QStringLiteral("lra4");
    warnings.clear();
    QJsonObject lra;
    QVERIFY2(importBytes(QByteArray(vibro).replace(R"("effect_library": [])",
                                                   R"("effect_library": [],
        "reference_devices": [{"id": 1, "name": "lra4", "minimum_frequency": 170,
        "maximum_frequency": 175}])"),
                         onLra, &lra, &warnings, &error),
             qPrintable(error.toString()));
    QCOMPARE(warnings, QStringList{"t.hjif: /perceptions/0/channels/0/bands/0/effects/0: a 80 Hz "
                                   "wave plays at the band's own carrier"});
    const RenderedPattern felt = renderOf(lra, 1.0);
    QCOMPARE(felt.values.size(), size_t(4));
    QVERIFY(std::abs(felt.values[0][250] - 0.6) < 1e-9);
    QCOMPARE(felt.values[0][600], 0.0);
}

void TestHjif::denseKeyframesAreSampled()
{
    // 20 000 keyframes a second, alternating 1 and 0.5: finer than semhap plays.
    QString keyframes;
    for (int i = 0; i < 20000; ++i)
        keyframes += QStringLiteral(R"({"relative_position":%1,"amplitude_modulation":%2},)")
                         .arg(i)
                         .arg(i % 2 ? 0.5 : 1.0);
    keyframes.chop(1);
    const QByteArray file =
        fileWith(QStringLiteral("Pressure"),
                 QLatin1Char('[') +
                     channelWith(QStringLiteral("Curve"),
                                 QStringLiteral(R"([{"effect_type": "Basis", "position": 0,
                        "keyframes": [%1]}])")
                                     .arg(keyframes)) +
                     QLatin1Char(']'),
                 QStringLiteral("[]"), 20000);
    QJsonObject pattern;
    LoadError error;
    QVERIFY2(importBytes(file, {}, &pattern, nullptr, &error), qPrintable(error.toString()));
    const QJsonArray points = pattern.value(QLatin1String("tracks"))
                                  .toArray()
                                  .first()
                                  .toObject()
                                  .value(QLatin1String("attack"))
                                  .toObject()
                                  .value(QLatin1String("points"))
                                  .toArray();
    // A sample a millisecond at most, each on a keyframe of the file.
    QVERIFY2(points.size() <= 1002, qPrintable(QString::number(points.size())));
    for (const QJsonValue &p : points) {
        const double v = p.toArray().at(1).toDouble();
        QVERIFY(v == 0.0 || v == 0.5 || v == 1.0);
    }
}

void TestHjif::asTheReferenceSoftwarePlays()
{
    const auto basis = [](const QString &keyframes, const QString &extra = QString()) {
        return QStringLiteral(R"({"effect_type": "Basis", "position": 0%1, "keyframes": [%2]})")
            .arg(extra, keyframes);
    };
    // b1: a library effect placed by its reference: its own position (0.5 s) is not added.
    const QString placed = channelWith(
        QStringLiteral("Curve"),
        QStringLiteral(R"([{"effect_type": "Reference", "id": 4, "position": 100}])"), 0);
    const QString library = QStringLiteral(
        R"([{"effect_type": "Basis", "id": 4, "position": 500, "keyframes": [
        {"relative_position": 0, "amplitude_modulation": 1},
        {"relative_position": 100, "amplitude_modulation": 1}]}])");
    // b2: a Curve band without a curve type is the reference's default, its cubic.
    const QString cubic = channelWith(
        QStringLiteral("Curve"),
        QLatin1Char('[') +
            basis(QStringLiteral(R"({"relative_position": 0, "amplitude_modulation": 0},
            {"relative_position": 400, "amplitude_modulation": 1})")) +
            QLatin1Char(']'),
        1);
    // b3: until its first amplitude keyframe a wave holds that amplitude.
    const QString held = channelWith(
        QStringLiteral("VectorialWave"),
        QLatin1Char('[') +
            basis(QStringLiteral(R"({"relative_position": 0, "frequency_modulation": 2},
            {"relative_position": 100, "amplitude_modulation": 0.8},
            {"relative_position": 300, "amplitude_modulation": 0.8})"),
                  QStringLiteral(R"(, "base_signal": "Square", "phase": 6.2831854820251465)")) +
            QLatin1Char(']'),
        2);
    // b4: a wave faster than a bellows follows is its mean level.
    const QString fast = channelWith(
        QStringLiteral("VectorialWave"),
        QLatin1Char('[') +
            basis(QStringLiteral(R"({"relative_position": 0, "amplitude_modulation": 0.6,
            "frequency_modulation": 999}, {"relative_position": 200,
            "amplitude_modulation": 0.6})")) +
            QLatin1Char(']'),
        3);
    QJsonObject pattern;
    QStringList warnings;
    LoadError error;
    QVERIFY2(importBytes(fileWith(QStringLiteral("Pressure"),
                                  QLatin1Char('[') + placed + ", " + cubic + ", " + held + ", " +
                                      fast + ']',
                                  library),
                         {}, &pattern, &warnings, &error),
             qPrintable(error.toString()));
    QCOMPARE(warnings, QStringList{"t.hjif: /perceptions/0/channels/3/bands/0/effects/0: a 999 Hz "
                                   "wave is faster than the device follows (7 Hz): played as its "
                                   "mean level"});
    const RenderedPattern out = renderOf(pattern, 1.0);
    QCOMPARE(out.values[0][50], 0.0);
    QCOMPARE(out.values[0][150], 1.0);
    QCOMPARE(out.values[0][250], 0.0);
    QVERIFY(std::abs(out.values[1][100] - 0.15625) < 0.005);
    QVERIFY(std::abs(out.values[2][50] - 0.8) < 1e-9); // the square is high for 250 ms
    QVERIFY(std::abs(out.values[3][100] - 0.3) < 1e-9);

    // On a device with a carrier a curve below zero is felt by its size; channels whose
    // names are not the model's go to the first channels free.
    const QString below = channelWith(
        QStringLiteral("Curve"),
        QLatin1Char('[') +
            basis(QStringLiteral(R"({"relative_position": 0, "amplitude_modulation": -0.5},
            {"relative_position": 200, "amplitude_modulation": -0.5})")) +
            QLatin1Char(']'),
        0);
    QString named = below;
    named.replace(QStringLiteral(R"("description": "")"),
                  QStringLiteral(R"("description": "m2")"));
    QString other = below;
    other.replace(QStringLiteral(R"("id": 0)"), QStringLiteral(R"("id": 1)"))
        .replace(QStringLiteral(R"("description": "")"),
                 QStringLiteral(R"("description": "Channel 2")"));
    warnings.clear();
    QVERIFY2(importBytes(fileWith(QStringLiteral("Vibrotactile"),
                                  QLatin1Char('[') + named + ", " + other + ']'),
                         {}, &pattern, &warnings, &error),
             qPrintable(error.toString()));
    QCOMPARE(warnings, QStringList());
    const RenderedPattern felt = renderOf(pattern, 0.5);
    QVERIFY(std::abs(felt.values[0][100] - 0.5) < 1e-9); // "Channel 2" on m1
    QVERIFY(std::abs(felt.values[1][100] - 0.5) < 1e-9); // "m2" on m2
    QCOMPARE(felt.values[2][100], 0.0);
}

void TestHjif::commandLine()
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("c3.hjif"));
    CliResult r = semhapRun({"convert", "--router", "C3", out});
    QVERIFY2(r.code == 0, r.err.constData());
    QCOMPARE(r.err.count('\n'), 4); // each pattern's sustain cut to a second
    const QString pattern = dir.filePath(QStringLiteral("alarm.json"));
    r = semhapRun({"convert", out, pattern, "--perception", "3", "--effect", "0"});
    QVERIFY2(r.code == 0, r.err.constData());
    QCOMPARE(r.err, QByteArray()); // the perception asked for: no word of the others
    LoadError error;
    const PatternPtr alarm = PatternLibrary::load(pattern, &error);
    QVERIFY2(alarm, qPrintable(error.toString()));
    QCOMPARE(alarm->model(), QStringLiteral("lra4"));
    QVERIFY(alarm->description().contains(QLatin1String("effect 0 (UX/Alarm)")));
    const auto builtin = [&](const QString &name) {
        const QString path = dir.filePath(name + QStringLiteral(".json"));
        QFile file(path);
        if (file.open(QIODevice::WriteOnly))
            file.write(QJsonDocument(PatternLibrary::builtin(name)->toJson()).toJson());
        return path;
    };
    r = semhapRun({"convert", builtin("air.squeeze"), dir.filePath(QStringLiteral("s.hjif")),
                   "--hand", "right"});
    QVERIFY2(r.code == 0, r.err.constData());

    struct Refusal
    {
        QStringList args;
        QByteArray said;
    };
    const QList<Refusal> refusals{
        {{"convert", "--router", "C3", "c3.json"},
         "--router writes an HJIF file: OUT must end in .hjif"},
        {{"convert", "--router", "C3", "a.hjif", "b.hjif"}, "expected OUT after --router"},
        {{"convert", pattern, "x.ahap", "--effect", "1"}, "--effect is for reading HJIF files"},
        {{"convert", out, "x.json", "--effect", "one"}, "--effect expects an id"},
        {{"convert", pattern, "x.hjif", "--hand", "both"}, "--hand expects left or right"},
        {{"convert", pattern, "x.json", "--hand", "left"}, "--hand is for writing HJIF files"},
        {{"convert", "--router", "C3", "--hand", "left", "x.hjif"},
         "--hand is for patterns: a router's devices name their hands"},
        {{"convert", out, "x.json", "--channel", "m1"}, "--channel and --modulate are for AHAP"},
        {{"convert", "--router", "C3", "--device", "lra4", "x.hjif"}, "--device is for imports"},
        {{"convert", "--router", "visual", dir.filePath("v.hjif")},
         "visual: no message plays on a device that is felt"},
        {{"convert", builtin("visual.blink"), dir.filePath("v.hjif")},
         "model 'overlay' is sight, not felt: HJIF carries haptics"}};
    for (const Refusal &refusal : refusals) {
        r = semhapRun(refusal.args);
        QVERIFY2(r.code != 0 && r.err.contains(refusal.said),
                 qPrintable(refusal.args.join(' ') + ": " + r.err));
    }
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("v.hjif"))));
}

QTEST_GUILESS_MAIN(TestHjif)
#include "tst_hjif.moc"
