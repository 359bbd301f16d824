// SPDX-License-Identifier: MIT
#include "workspace.h"

#include "devicemanager.h"
#include "deviceuri.h"
#include "jsonreader.h"
#include "outputfile.h"
#include "patterndocument.h"
#include "routerdocument.h"
#include "studiooptions.h"
#include "studydocument.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSettings>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** Where the device addresses the user added are kept between sessions. */
const QString AddressesKey = QStringLiteral("devices/addresses");

/**
 * A router graph as the workspace keeps it: the document, and where it came from (its file
 * and the folder its relative pattern and model paths are resolved against).
 */
QJsonObject graphEntry(const RouterGraph &graph)
{
    return QJsonObject{{QStringLiteral("graph"), graph.toJson()},
                       {QStringLiteral("file"), graph.file},
                       {QStringLiteral("base_dir"), graph.baseDir}};
}

/**
 * Reads a graphEntry() at `pointer` of the workspace file `path`, its errors located there
 * (`/router/graph/nodes/2/…`); `extraKeys` are the entry's other keys, read by the caller.
 */
bool readGraphEntry(const QJsonObject &entry, const QString &path, const QString &pointer,
                    std::initializer_list<QLatin1String> keys, RouterGraph *graph,
                    LoadError *error)
{
    JsonReader reader(path);
    QJsonObject json;
    QString file;
    QString baseDir;
    if (!reader.checkKeys(entry, pointer, keys) ||
        !reader.object(entry, pointer, QLatin1String("graph"), &json) ||
        !reader.string(entry, pointer, QLatin1String("file"), &file, false) ||
        !reader.string(entry, pointer, QLatin1String("base_dir"), &baseDir, false)) {
        *error = reader.error();
        return false;
    }
    if (!RouterGraph::fromJson(json, path, graph, error)) {
        error->pointer = pointer + QStringLiteral("/graph") + error->pointer;
        return false;
    }
    graph->file = file;
    graph->baseDir = baseDir;
    return true;
}

} // namespace

Workspace::Workspace(QObject *parent)
    : QObject(parent), m_study(std::make_unique<StudyDocument>(m_engine)),
      m_routerDocument(new RouterDocument(this)), m_patternDocument(new PatternDocument(this))
{
    const QSettings settings;
    for (const QString &text : settings.value(AddressesKey).toStringList()) {
        DeviceUri uri;
        QString error;
        if (DeviceUri::parse(text, &uri, &error))
            m_engine.devices().addConfigured(uri.toString());
        else
            qWarning("%s: %s: %s", qPrintable(settings.fileName()), qPrintable(AddressesKey),
                     qPrintable(error));
    }
    m_autosaveTimer.setInterval(AutosaveInterval);
    connect(&m_autosaveTimer, &QTimer::timeout, this, [this] { autosave(); });
}

Workspace::~Workspace()
{
    if (!m_autosavePath.isEmpty())
        autosave();
}

void Workspace::saveDeviceAddresses()
{
    QSettings().setValue(AddressesKey, m_engine.devices().configured());
}

QString Workspace::defaultFile()
{
    // Beside the settings and named after them: another program of the organisation (a
    // test) keeps its own.
    const QFileInfo settings(QSettings().fileName());
    return settings.absolutePath() + QLatin1Char('/') + settings.completeBaseName() +
           QStringLiteral(".workspace.json");
}

QJsonObject Workspace::toJson() const
{
    const Engine &engine = m_engine;
    QJsonObject json{{QStringLiteral("format"), QLatin1String(Format)}};
    // A replay keeps the run it replaced behind it: that is the run to come back to.
    const RunSource *run = engine.streamingSource();
    if (engine.isListening()) {
        const LiveRigOptions rig = engine.liveOptions();
        QJsonObject live{{QStringLiteral("address"), rig.address},
                         {QStringLiteral("port"), rig.port},
                         {QStringLiteral("router"), rig.router},
                         {QStringLiteral("overrides"), QJsonArray::fromStringList(rig.overrides)}};
        if (!rig.foxglove.isEmpty()) {
            live.insert(QStringLiteral("foxglove"), rig.foxglove.toString());
            live.insert(QStringLiteral("topics"), rig.topics);
        }
        json.insert(QStringLiteral("live_rig"), live);
    } else if (run) {
        json.insert(QStringLiteral("simulation"), engine.options().toJson());
    }
    if (run && engine.isRunRouterEdited())
        json.insert(QStringLiteral("router"), graphEntry(engine.routerGraph()));

    QJsonArray bindings;
    for (const BoundDevice &device : engine.devices().status()) {
        if (device.uri == DeviceUri::virtualFor(device.name))
            continue; // what every device of a router gets anyway
        bindings.append(QJsonObject{{QStringLiteral("device"), device.name},
                                    {QStringLiteral("uri"), device.uri},
                                    {QStringLiteral("model"), device.model}});
    }
    json.insert(QStringLiteral("bindings"), bindings);

    QJsonObject routerDocument = graphEntry(m_routerDocument->graph());
    routerDocument.insert(QStringLiteral("path"), m_routerDocument->path());
    routerDocument.insert(QStringLiteral("modified"), m_routerDocument->isModified());
    json.insert(QStringLiteral("router_document"), routerDocument);
    if (!m_patternDocument->json().isEmpty())
        json.insert(QStringLiteral("pattern_document"),
                    QJsonObject{{QStringLiteral("pattern"), m_patternDocument->json()},
                                {QStringLiteral("file"), m_patternDocument->path()},
                                {QStringLiteral("read_only"), m_patternDocument->isReadOnly()},
                                {QStringLiteral("modified"), m_patternDocument->isModified()}});
    json.insert(QStringLiteral("session"), QJsonObject{{QStringLiteral("name"), m_sessionName},
                                                       {QStringLiteral("notes"), m_sessionNotes}});
    if (m_study->isOpen())
        json.insert(QStringLiteral("study"),
                    QJsonObject{{QStringLiteral("file"),
                                 QFileInfo(m_study->database()->path()).absoluteFilePath()},
                                {QStringLiteral("participant"), m_study->participant()}});
    return json;
}

bool Workspace::restore(const QString &path, const StudioOptions &options, QStringList *problems)
{
    m_restored = QJsonObject();
    m_restoredPath = path;
    m_copyKept = false;
    if (!QFileInfo::exists(path))
        return false;
    QJsonObject json;
    LoadError error;
    JsonReader reader(path);
    if (!readJsonObjectFile(path, &json, &error) ||
        !checkFormat(json, path, QLatin1String(Format), &error)) {
        problems->append(error.toString());
    } else if (!reader.checkKeys(json, QString(),
                                 {QLatin1String("format"), QLatin1String("simulation"),
                                  QLatin1String("live_rig"), QLatin1String("router"),
                                  QLatin1String("bindings"), QLatin1String("router_document"),
                                  QLatin1String("pattern_document"), QLatin1String("session"),
                                  QLatin1String("study")})) {
        problems->append(reader.error().toString());
    } else {
        m_restored = json;
        if (!options.runGiven) // the command line's run wins
            restoreRun(json, path, options, problems);
        restoreDocuments(json, path, problems);
        restoreStudy(json, path, problems);
    }
    if (!problems->isEmpty())
        keepCopy(path, problems);
    return m_engine.isLoaded();
}

void Workspace::keepCopy(const QString &path, QStringList *problems)
{
    // The next autosave writes only what came back: what did not is kept beside it.
    if (m_copyKept)
        return;
    m_copyKept = true;
    QFile file(path);
    LoadError error;
    const QString copy = path + QStringLiteral(".bak");
    if (!file.open(QIODevice::ReadOnly) || !OutputFile::write(copy, file.readAll(), &error))
        problems->append(error.isSet()
                             ? error.toString()
                             : path + QStringLiteral(": cannot read: ") + file.errorString());
    else
        problems->append(tr("%1: the file as it was is kept as %2").arg(path, copy));
}

void Workspace::restoreRun(const QJsonObject &json, const QString &path,
                           const StudioOptions &options, QStringList *problems)
{
    JsonReader reader(path);
    QJsonObject simulation;
    QJsonObject rig;
    if (!reader.object(json, QString(), QLatin1String("simulation"), &simulation, false) ||
        !reader.object(json, QString(), QLatin1String("live_rig"), &rig, false)) {
        problems->append(reader.error().toString());
        return;
    }
    QString error;
    if (!rig.isEmpty()) {
        const QString at = QStringLiteral("/live_rig");
        LiveRigOptions live = options.liveRig;
        double port = live.port;
        QString robot;
        if (!reader.checkKeys(rig, at,
                              {QLatin1String("address"), QLatin1String("port"),
                               QLatin1String("router"), QLatin1String("overrides"),
                               QLatin1String("foxglove"), QLatin1String("topics")}) ||
            !reader.string(rig, at, QLatin1String("address"), &live.address) ||
            !reader.number(rig, at, QLatin1String("port"), &port) ||
            !reader.string(rig, at, QLatin1String("router"), &live.router) ||
            !reader.strings(rig, at, QLatin1String("overrides"), &live.overrides, false) ||
            !reader.string(rig, at, QLatin1String("foxglove"), &robot, false) ||
            !reader.string(rig, at, QLatin1String("topics"), &live.topics, !robot.isEmpty())) {
            problems->append(reader.error().toString());
            return;
        }
        live.foxglove = QUrl(robot);
        if (port < 0 || port > 65535 || port != std::floor(port)) {
            problems->append(LoadError::at(path, at + QStringLiteral("/port"),
                                           QStringLiteral("expected a port from 0 to 65535"))
                                 .toString());
            return;
        }
        live.port = int(port);
        if (!m_engine.listen(live, &error)) {
            problems->append(LoadError::at(path, at, error).toString());
            return;
        }
    } else if (!simulation.isEmpty()) {
        const QString at = QStringLiteral("/simulation");
        RunOptions run = options.run;
        if (!RunOptions::fromJson(reader, simulation, at, &run)) {
            problems->append(reader.error().toString());
            return;
        }
        if (!m_engine.load(run, &error)) {
            problems->append(LoadError::at(path, at, error).toString());
            return;
        }
    } else {
        return;
    }

    QJsonObject edited;
    if (!reader.object(json, QString(), QLatin1String("router"), &edited, false)) {
        problems->append(reader.error().toString());
    } else if (!edited.isEmpty()) {
        RouterGraph graph;
        LoadError graphError;
        if (!readGraphEntry(
                edited, path, QStringLiteral("/router"),
                {QLatin1String("graph"), QLatin1String("file"), QLatin1String("base_dir")}, &graph,
                &graphError))
            problems->append(graphError.toString());
        else if (!m_engine.setRouter(graph, &error))
            problems->append(LoadError::at(path, QStringLiteral("/router"), error).toString());
    }
}

void Workspace::restoreBindings(QStringList *problems)
{
    const QString &path = m_restoredPath;
    const qsizetype before = problems->size();
    JsonReader reader(path);
    QJsonArray bindings;
    if (!reader.array(m_restored, QString(), QLatin1String("bindings"), &bindings, false))
        problems->append(reader.error().toString());
    m_restored = QJsonObject(); // once
    const std::vector<BoundDevice> devices = m_engine.devices().status();
    for (int i = 0; i < bindings.size(); ++i) {
        const QString at = jsonPointerChild(QStringLiteral("/bindings"), i);
        const QJsonObject binding = bindings[i].toObject();
        JsonReader bindingReader(path);
        QString device;
        QString uri;
        QString model;
        if (!bindings[i].isObject() ||
            !bindingReader.checkKeys(
                binding, at,
                {QLatin1String("device"), QLatin1String("uri"), QLatin1String("model")}) ||
            !bindingReader.string(binding, at, QLatin1String("device"), &device) ||
            !bindingReader.string(binding, at, QLatin1String("uri"), &uri) ||
            !bindingReader.string(binding, at, QLatin1String("model"), &model)) {
            problems->append(
                bindingReader.error().isSet()
                    ? bindingReader.error().toString()
                    : LoadError::at(path, at, QStringLiteral("expected an object")).toString());
            continue;
        }
        // Only to the same device of the same model: a band is never driven as another.
        const bool fits = std::any_of(devices.begin(), devices.end(), [&](const BoundDevice &d) {
            return d.name == device && d.model == model;
        });
        QString error;
        if (!fits)
            problems->append(
                LoadError::at(path, at,
                              tr("%1 stays unbound: the router that runs has no %2 device '%3'")
                                  .arg(uri, model, device))
                    .toString());
        else if (!m_engine.bindDevice(device, uri, &error))
            problems->append(LoadError::at(path, at, error).toString());
    }
    if (problems->size() > before)
        keepCopy(path, problems);
}

void Workspace::restoreDocuments(const QJsonObject &json, const QString &path,
                                 QStringList *problems)
{
    JsonReader reader(path);
    QJsonObject router;
    QJsonObject pattern;
    QJsonObject session;
    if (!reader.object(json, QString(), QLatin1String("router_document"), &router, false) ||
        !reader.object(json, QString(), QLatin1String("pattern_document"), &pattern, false) ||
        !reader.object(json, QString(), QLatin1String("session"), &session, false)) {
        problems->append(reader.error().toString());
        return;
    }

    // Unsaved edits come back as unsaved: the stack is marked as never clean.
    if (!router.isEmpty()) {
        const QString at = QStringLiteral("/router_document");
        JsonReader documentReader(path);
        QString file;
        RouterGraph graph;
        LoadError error;
        if (!readGraphEntry(router, path, at,
                            {QLatin1String("graph"), QLatin1String("file"),
                             QLatin1String("base_dir"), QLatin1String("path"),
                             QLatin1String("modified")},
                            &graph, &error)) {
            problems->append(error.toString());
        } else if (!documentReader.string(router, at, QLatin1String("path"), &file, false)) {
            problems->append(documentReader.error().toString());
        } else {
            m_routerDocument->reset(graph, file);
            if (router.value(QLatin1String("modified")).toBool())
                m_routerDocument->undoStack()->resetClean();
        }
    }
    if (!pattern.isEmpty()) {
        const QString at = QStringLiteral("/pattern_document");
        JsonReader documentReader(path);
        QJsonObject content;
        QString file;
        if (!documentReader.checkKeys(pattern, at,
                                      {QLatin1String("pattern"), QLatin1String("file"),
                                       QLatin1String("read_only"), QLatin1String("modified")}) ||
            !documentReader.object(pattern, at, QLatin1String("pattern"), &content) ||
            !documentReader.string(pattern, at, QLatin1String("file"), &file, false)) {
            problems->append(documentReader.error().toString());
        } else {
            // The designer shows why a pattern does not load; it is kept as it was.
            m_patternDocument->reset(content, file,
                                     pattern.value(QLatin1String("read_only")).toBool());
            if (pattern.value(QLatin1String("modified")).toBool())
                m_patternDocument->undoStack()->resetClean();
        }
    }
    const QString at = QStringLiteral("/session");
    if (!reader.string(session, at, QLatin1String("name"), &m_sessionName, false) ||
        !reader.string(session, at, QLatin1String("notes"), &m_sessionNotes, false))
        problems->append(reader.error().toString());
}

void Workspace::restoreStudy(const QJsonObject &json, const QString &path, QStringList *problems)
{
    const QString at = QStringLiteral("/study");
    JsonReader reader(path);
    QJsonObject study;
    QString file;
    QString participant;
    if (!reader.object(json, QString(), QLatin1String("study"), &study, false) ||
        !reader.checkKeys(study, at, {QLatin1String("file"), QLatin1String("participant")}) ||
        !reader.string(study, at, QLatin1String("file"), &file, !study.isEmpty()) ||
        !reader.string(study, at, QLatin1String("participant"), &participant, false)) {
        problems->append(reader.error().toString());
        return;
    }
    if (file.isEmpty())
        return;
    // Another studio holding it says so here, in the study's words.
    QString error;
    if (!m_study->open(file, &error)) {
        problems->append(LoadError::at(path, at, error).toString());
        return;
    }
    if (!participant.isEmpty())
        m_study->setParticipant(participant);
}

void Workspace::autosaveTo(const QString &path)
{
    m_autosavePath = path;
    m_autosaveTimer.start();
}

bool Workspace::autosave(QString *error)
{
    if (m_autosavePath.isEmpty())
        return true;
    const QByteArray bytes = QJsonDocument(toJson()).toJson(QJsonDocument::Indented);
    if (bytes == m_saved)
        return true;
    LoadError failure;
    QDir().mkpath(QFileInfo(m_autosavePath).absolutePath());
    if (!OutputFile::write(m_autosavePath, bytes, &failure)) {
        if (error)
            *error = failure.toString();
        if (!m_autosaveFailing)
            emit autosaveFailed(failure.toString());
        m_autosaveFailing = true;
        return false;
    }
    m_saved = bytes;
    m_autosaveFailing = false;
    return true;
}

} // namespace semhap
