// SPDX-License-Identifier: MIT
#include "validatecommand.h"

#include "devicemodel.h"
#include "jsonreader.h"
#include "pattern.h"
#include "patternrender.h"
#include "router.h"
#include "world.h"

#include <QFile>
#include <QFileInfo>

namespace semhap {

namespace {

// A scene is valid when MuJoCo compiles it and semhap finds its grippers (sim/README.md).
bool validateScene(const QString &path, QString *error, QString *what)
{
    std::unique_ptr<World> world = World::load(path, SceneOptions(), error);
    if (!world)
        return false;
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

} // namespace

QString ValidateCommand::summary() const
{
    return tr("Checks pattern, router, device model and scene files. Device model files "
              "given on the same command line are known to the patterns and routers checked.");
}

void ValidateCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("files"), tr("Files to check."), tr("FILE..."));
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
        const QString format = doc.json.value(QStringLiteral("format")).toString();
        bool ok = false;
        if (doc.path.endsWith(QLatin1String(".xml"), Qt::CaseInsensitive)) {
            QString sceneError;
            ok = validateScene(doc.path, &sceneError, &what);
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
                ok = Router::compile(graph, &error) != nullptr;
                what = tr("router '%1'").arg(graph.name);
            }
        } else if (format == QLatin1String(DeviceModel::Format)) {
            DeviceModelPtr model = DeviceModel::fromJson(doc.json, doc.path, &error);
            ok = model != nullptr;
            if (model)
                what = tr("device model '%1'").arg(model->name());
        } else {
            error = LoadError::at(doc.path, QStringLiteral("/format"),
                                  tr("unknown format '%1' (expected %2, %3 or %4)")
                                      .arg(format, QLatin1String(Pattern::Format),
                                           QLatin1String(RouterGraph::Format),
                                           QLatin1String(DeviceModel::Format)));
        }
        if (ok) {
            m_out << tr("%1: valid %2").arg(doc.path, what) << '\n';
        } else {
            report(error.toString());
            ++invalid;
        }
    }
    return invalid == 0 ? ExitOk : ExitInvalidInput;
}

} // namespace semhap
