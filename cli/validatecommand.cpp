// SPDX-License-Identifier: MIT
#include "validatecommand.h"

#include "devicemodel.h"
#include "distinctiveness.h"
#include "gripperadapter.h"
#include "grippercheck.h"
#include "gripperlibrary.h"
#include "jsonreader.h"
#include "pattern.h"
#include "patternrender.h"
#include "router.h"
#include "studyprotocol.h"
#include "world.h"

#include <QFile>
#include <QFileInfo>

#include <cmath>

namespace semhap {

namespace {

// A scene is valid when MuJoCo compiles it and semhap finds its grippers (sim/README.md).
bool validateScene(const QString &path, const QString &gripper, QString *error, QString *what,
                   QStringList *warnings)
{
    SceneOptions options;
    options.gripper = gripper;
    std::unique_ptr<World> world = World::load(path, options, error);
    if (!world)
        return false;
    GripperAdapter adapter;
    LoadError adapterError;
    const bool adapted = !gripper.isEmpty() && GripperAdapter::read(GripperLibrary::find(gripper),
                                                                    &adapter, &adapterError);
    *warnings = GripperCheck::warnings(*world, path, adapted ? &adapter : nullptr);
    QStringList grippers;
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        if (world->hasGripper(g))
            grippers.append(gripperName(g));
    }
    *what = QStringLiteral("scene (grippers: %1; %2 objects)")
                .arg(grippers.join(QStringLiteral(", ")))
                .arg(world->objects().size());
    return true;
}

/** `value` to `decimals` places, without a negative zero. */
QString fixed(double value, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    return QString::number(std::round(value * scale) / scale + 0.0, 'f', decimals);
}

/** `(x, y, z)` to the millimetre or thousandth. */
QString vector(const std::array<double, 3> &v)
{
    return QStringLiteral("(%1, %2, %3)").arg(fixed(v[0], 3), fixed(v[1], 3), fixed(v[2], 3));
}

/**
 * An adapter is valid when its model goes into a bundled scene's wrist and its fingers close:
 * what the loader measured is the description (docs/grippers.md).
 */
bool validateGripper(const QString &path, QString *error, QString *what, QStringList *warnings)
{
    SceneOptions options;
    options.gripper = path;
    const QString scene = QStringLiteral("box_and_block");
    std::unique_ptr<World> world = World::load(scene, options, error);
    GripperAdapter adapter;
    LoadError adapterError;
    if (!world || !GripperAdapter::read(path, &adapter, &adapterError))
        return false;
    *warnings = GripperCheck::warnings(*world, scene, &adapter);
    const GripperGeometry &g = world->gripperGeometry(Gripper::Right);
    const GripperComposer::Mount &mount = *world->gripperMount();
    const auto arms = g.armRange(0);
    *what = ValidateCommand::tr(
                "gripper adapter, measured in %1: mount pos %2 quat (%3, %4, %5, %6); closing "
                "axis %7, approach axis %8 (in the wrist's frame); pads %9 mm apart open, %10 mm "
                "closed; pads' centre %11 mm below the wrist open, %12 mm closed; moment arm "
                "%13 to %14 mm per unit of the finger joint; a full grasp touches %15 pad geoms")
                .arg(scene, vector(mount.pos), fixed(mount.quat[0], 4), fixed(mount.quat[1], 4),
                     fixed(mount.quat[2], 4), fixed(mount.quat[3], 4), vector(g.closingAxis()),
                     vector(g.approachAxis()), fixed(g.openGap() * 1000, 1))
                .arg(fixed(g.closedGap() * 1000, 1), fixed(g.drop(g.openGap()) * 1000, 1),
                     fixed(g.drop(g.closedGap()) * 1000, 1), fixed(arms[0] * 1000, 1),
                     fixed(arms[1] * 1000, 1))
                .arg(world->fullContacts(Gripper::Right));
    return true;
}

} // namespace

QString ValidateCommand::summary() const
{
    return tr("Checks pattern, router, device model, scene and gripper adapter files. Device "
              "model files "
              "given on the same command line are known to the patterns and routers checked.");
}

void ValidateCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("files"), tr("Files to check."), tr("FILE..."));
    parser.addOption({QStringLiteral("gripper"),
                      tr("Check the scenes with this gripper adapter's model in their wrists."),
                      tr("NAME|FILE")});
}

int ValidateCommand::execute(const QCommandLineParser &parser)
{
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty())
        return usageError(tr("no files given"));

    // Read everything first, so that a pattern can use a device model listed after it.
    struct Document
    {
        QString path;
        QJsonObject json;
        LoadError error;
    };
    std::vector<Document> documents;
    std::vector<DeviceModelPtr> models;
    for (const QString &path : files) {
        Document doc{path, {}, {}};
        if (!path.endsWith(QLatin1String(".xml"), Qt::CaseInsensitive) &&
            readJsonObjectFile(path, &doc.json, &doc.error) &&
            doc.json.value(QStringLiteral("format")).toString() ==
                QLatin1String(DeviceModel::Format)) {
            if (DeviceModelPtr model = DeviceModel::fromJson(doc.json, path, &doc.error))
                models.push_back(model);
        }
        documents.push_back(doc);
    }

    int invalid = 0;
    for (const Document &doc : documents) {
        LoadError error = doc.error;
        QString what;
        QStringList warnings;
        const QString format = doc.json.value(QStringLiteral("format")).toString();
        bool ok = false;
        if (doc.path.endsWith(QLatin1String(".xml"), Qt::CaseInsensitive)) {
            QString sceneError;
            ok = validateScene(doc.path, parser.value(QStringLiteral("gripper")), &sceneError,
                               &what, &warnings);
            if (!ok) {
                report(sceneError);
                ++invalid;
                continue;
            }
        } else if (error.isSet()) {
            ok = false;
        } else if (format == QLatin1String(Pattern::Format)) {
            PatternPtr pattern = Pattern::fromJson(doc.json, doc.path, &error);
            if (pattern) {
                DeviceModelPtr model = DeviceModelLibrary::builtin(pattern->model());
                for (const DeviceModelPtr &m : models) {
                    if (m->name() == pattern->model())
                        model = m;
                }
                std::vector<PlayerInput::Route> routes;
                QString reason;
                if (!model)
                    error = LoadError::at(
                        doc.path, QStringLiteral("/model"),
                        tr("unknown device model '%1' (give its file too)").arg(pattern->model()));
                else if (!resolvePatternRoutes(*pattern, *model, {}, &routes, &reason))
                    error = LoadError::at(doc.path, QStringLiteral("/tracks"), reason);
                ok = !error.isSet();
                what = tr("pattern '%1'").arg(pattern->name());
            }
        } else if (format == QLatin1String(RouterGraph::Format)) {
            RouterGraph graph;
            if (RouterGraph::fromJson(doc.json, doc.path, &graph, &error)) {
                graph.baseDir = QFileInfo(doc.path).absolutePath();
                graph.models.insert(graph.models.end(), models.begin(), models.end());
                reportWarnings(graph);
                const std::unique_ptr<Router> router = Router::compile(graph, &error);
                ok = router != nullptr;
                if (ok)
                    reportConfusable(doc.path, *router);
                what = tr("router '%1'").arg(graph.name);
            }
        } else if (format == QLatin1String(GripperAdapter::Format)) {
            QString reason;
            ok = validateGripper(doc.path, &reason, &what, &warnings);
            if (!ok) {
                report(reason);
                ++invalid;
                continue;
            }
        } else if (format == QLatin1String(StudyProtocol::Format)) {
            StudyProtocol protocol;
            ok = StudyProtocol::read(doc.path, &protocol, &error);
            if (ok) {
                const size_t orders = protocol.order().rows().size();
                QStringList design;
                for (const StudyProtocol::Factor &factor : protocol.factors)
                    design.append(
                        QStringLiteral("%1 %2").arg(factor.levels.size()).arg(factor.id));
                what =
                    tr("study protocol '%1' (%2 conditions%3; %4)")
                        .arg(protocol.name)
                        .arg(protocol.conditions.size())
                        .arg(design.isEmpty() ? QString()
                                              : tr(": %1").arg(design.join(QStringLiteral(" × "))))
                        .arg(orders > 0
                                 ? tr("%1 orders, participants take them in turn").arg(orders)
                                 : tr("a seeded random order per participant"));
            }
        } else if (format == QLatin1String(DeviceModel::Format)) {
            DeviceModelPtr model = DeviceModel::fromJson(doc.json, doc.path, &error);
            ok = model != nullptr;
            if (model)
                what = tr("device model '%1'").arg(model->name());
        } else {
            error = LoadError::at(doc.path, QStringLiteral("/format"),
                                  tr("unknown format '%1' (expected %2, %3, %4, %5 or %6)")
                                      .arg(format, QLatin1String(Pattern::Format),
                                           QLatin1String(RouterGraph::Format),
                                           QLatin1String(DeviceModel::Format),
                                           QLatin1String(GripperAdapter::Format),
                                           QLatin1String(StudyProtocol::Format)));
        }
        for (const QString &warning : warnings)
            report(tr("%1: warning: %2").arg(doc.path, warning));
        if (ok) {
            m_out << tr("%1: valid %2").arg(doc.path, what) << '\n';
        } else {
            report(error.toString());
            ++invalid;
        }
    }
    return invalid == 0 ? ExitOk : ExitInvalidInput;
}

void ValidateCommand::reportConfusable(const QString &path, const Router &router)
{
    std::vector<BandDistinctiveness> bands;
    QString reason;
    if (!Distinctiveness().bands(router, 0.5, &bands, &reason)) {
        report(tr("%1: warning: its patterns cannot be compared: %2").arg(path, reason));
        return;
    }
    for (const BandDistinctiveness &band : bands) {
        for (const BandDistinctiveness::Pair &pair : band.confusable)
            report(tr("%1: warning: on %2, %3 and %4 feel %5 JND apart: a person will confuse "
                      "them (semhap distinct)")
                       .arg(path, band.device, band.messages[pair.a], band.messages[pair.b])
                       .arg(pair.distance, 0, 'f', 2));
    }
}

} // namespace semhap
