// SPDX-License-Identifier: MIT
#include "scenelibrary.h"

#include "inputfile.h"
#include "mjcfelement.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <cstring>
#include <mutex>

namespace semhap {

namespace {

/**
 * MuJoCo's message as one `FILE:LINE: reason` line: its messages span lines and name the
 * line in their own words ("line 7", "Line number=3"), which editors cannot jump to.
 */
QString mujocoError(const QString &where, const char *message)
{
    static const QRegularExpression line(
        QStringLiteral(",?\\s*\\b[Ll]ine(?: number)?\\s*=?\\s*(\\d+)"));
    QString text = QString::fromUtf8(message).trimmed();
    const QRegularExpressionMatch m = line.match(text);
    QString location = where;
    if (m.hasMatch()) {
        location += QLatin1Char(':') + m.captured(1);
        text.remove(m.capturedStart(), m.capturedLength());
    }
    text.replace(QRegularExpression(QStringLiteral("\\s*\\n+\\s*")), QStringLiteral("; "));
    text.replace(QStringLiteral(":; "), QStringLiteral(": "));
    return location + QStringLiteral(": ") + text;
}

/** Where `<tag attribute="…">` is in the MJCF: `:LINE`, or nothing when it is not. */
QString locationOf(const QByteArray &xml, QLatin1String tag, QLatin1String attribute)
{
    QXmlStreamReader reader(xml);
    while (!reader.atEnd()) {
        if (reader.readNext() == QXmlStreamReader::StartElement && reader.name() == tag &&
            reader.attributes().hasAttribute(attribute))
            return QStringLiteral(":%1").arg(reader.lineNumber());
    }
    return QString();
}

/**
 * Refuses a model semhap cannot step sensibly: a time step that is not a number or lies
 * outside 10 µs … 50 ms would simulate nothing, or nothing a gripper could hold.
 */
MjModelPtr checked(MjModelPtr model, const QByteArray &xml, const QString &where, QString *error)
{
    if (!model)
        return model;
    const double step = model->opt.timestep;
    if (!(step >= SceneLibrary::MinTimestep && step <= SceneLibrary::MaxTimestep)) {
        *error = where + locationOf(xml, QLatin1String("option"), QLatin1String("timestep")) +
                 QStringLiteral(": timestep %1 s is outside %2 to %3 s")
                     .arg(step)
                     .arg(SceneLibrary::MinTimestep)
                     .arg(SceneLibrary::MaxTimestep);
        return nullptr;
    }
    return model;
}

const QRegularExpression &cubeName()
{
    static const QRegularExpression re(QStringLiteral("^cube_(\\d+)$"));
    return re;
}

/** The scene's own default cube count, or -1 when it declares none. */
int declaredCubes(const QByteArray &xml)
{
    static const QRegularExpression re(
        QStringLiteral("<numeric\\s+name=\"semhap:cubes\"\\s+data=\"(\\d+)\""));
    const QRegularExpressionMatch m = re.match(QString::fromUtf8(xml));
    return m.hasMatch() ? m.captured(1).toInt() : -1;
}

/**
 * Copies the MJCF without the cube bodies from `count` on (and their fragile numerics),
 * setting semhap:cubes to `count`. Streaming, so comments and layout survive.
 */
bool keepCubes(const QByteArray &xml, int count, QByteArray *out, int *available, QString *error)
{
    QXmlStreamReader reader(xml);
    QXmlStreamWriter writer(out);
    *available = 0;
    while (!reader.atEnd()) {
        reader.readNext();
        if (reader.hasError())
            break;
        if (reader.isStartElement()) {
            const QString name = reader.attributes().value(QLatin1String("name")).toString();
            const QString tag = reader.name().toString();
            QString object = name;
            if (tag == QLatin1String("numeric") && name.startsWith(QLatin1String("fragile:")))
                object = name.mid(8);
            const QRegularExpressionMatch m = cubeName().match(object);
            if (m.hasMatch() &&
                (tag == QLatin1String("body") || tag == QLatin1String("numeric"))) {
                if (tag == QLatin1String("body"))
                    ++*available;
                if (m.captured(1).toInt() >= count) {
                    reader.skipCurrentElement();
                    continue;
                }
            }
            if (tag == QLatin1String("numeric") && name == QLatin1String("semhap:cubes")) {
                writer.writeStartElement(tag);
                writer.writeAttribute(QStringLiteral("name"), name);
                writer.writeAttribute(QStringLiteral("data"), QString::number(count));
                continue;
            }
        }
        writer.writeCurrentToken(reader);
    }
    if (reader.hasError()) {
        *error = QStringLiteral("%1:%2: %3")
                     .arg(reader.lineNumber())
                     .arg(reader.columnNumber())
                     .arg(reader.errorString());
        return false;
    }
    return true;
}

/**
 * Compiles `xml` held in memory (a scene with cubes dropped, a bundled one). `file` is where
 * MuJoCo takes it to be: for a scene on disk its own path, so its <include>s and asset
 * folders resolve against its folder, as when MuJoCo reads the file itself.
 */
MjModelPtr compile(const QByteArray &xml, const QByteArray &file, const QString &where,
                   QString *error)
{
    MjVfsPtr vfs(new mjVFS);
    mj_defaultVFS(vfs.get());
    if (mj_makeEmptyFileVFS(vfs.get(), file.constData(), int(xml.size())) != 0) {
        *error = where + QStringLiteral(": cannot hold the scene in MuJoCo's file system");
        return nullptr;
    }
    const int index = mj_findFileVFS(vfs.get(), file.constData());
    std::memcpy(vfs->filedata[index], xml.constData(), size_t(xml.size()));
    char message[1000] = "";
    MjModelPtr model(mj_loadXML(file.constData(), vfs.get(), message, sizeof message));
    if (!model)
        *error = mujocoError(where, message);
    return checked(std::move(model), xml, where, error);
}

} // namespace

QStringList SceneLibrary::builtinNames()
{
    QStringList names;
    const QStringList files =
        QDir(QStringLiteral(":/semhap/scenes")).entryList({QStringLiteral("*.xml")}, QDir::Files);
    for (const QString &file : files)
        names.append(file.chopped(4));
    return names;
}

QString SceneLibrary::routerPreset(const QString &nameOrPath)
{
    const bool isPath = InputFile::namesFile(nameOrPath, QLatin1String(".xml"));
    QByteArray xml;
    QString reason;
    if (!InputFile::readDocument(isPath ? nameOrPath
                                        : QStringLiteral(":/semhap/scenes/%1.xml").arg(nameOrPath),
                                 &xml, &reason))
        return QString();
    QXmlStreamReader reader(xml);
    while (!reader.atEnd()) {
        if (reader.readNext() == QXmlStreamReader::StartElement &&
            reader.name() == QLatin1String("text") &&
            reader.attributes().value(QLatin1String("name")) == QLatin1String("semhap:router"))
            return reader.attributes().value(QLatin1String("data")).toString();
    }
    return QString();
}

MjModelPtr SceneLibrary::load(const QString &nameOrPath, const SceneOptions &options,
                              const GripperAdapter *gripper, const GripperComposer::Mount &mount,
                              QString *error)
{
    installMujocoHandlers();
    // MuJoCo 2.2's XML compiler keeps global state; runs load in parallel (compare), step
    // in parallel, but compile one at a time.
    static std::mutex compiling;
    const std::lock_guard<std::mutex> lock(compiling);
    const bool isPath = InputFile::namesFile(nameOrPath, QLatin1String(".xml"));
    const QString path =
        isPath ? nameOrPath : QStringLiteral(":/semhap/scenes/%1.xml").arg(nameOrPath);
    QByteArray xml;
    QString reason;
    if (!InputFile::readDocument(path, &xml, &reason)) {
        *error = isPath ? QStringLiteral("%1: cannot read: %2").arg(nameOrPath, reason)
                        : QStringLiteral("%1: no such scene (scenes: %2)")
                              .arg(nameOrPath, builtinNames().join(QStringLiteral(", ")));
        return nullptr;
    }
    // Malformed XML is told where and why, as a text editor would; MuJoCo's parser says
    // only its own error code and line.
    QXmlStreamReader wellFormed(xml);
    while (!wellFormed.atEnd())
        wellFormed.readNext();
    if (wellFormed.hasError()) {
        *error = QStringLiteral("%1:%2:%3: %4")
                     .arg(nameOrPath)
                     .arg(wellFormed.lineNumber())
                     .arg(wellFormed.columnNumber() + 1) // Qt counts from 0
                     .arg(wellFormed.errorString());
        return nullptr;
    }
    const int count = options.cubes >= 0 ? options.cubes : declaredCubes(xml);
    const QByteArray file = isPath ? QFile::encodeName(QFileInfo(path).absoluteFilePath())
                                   : QByteArrayLiteral("scene.xml");
    if (count < 0 && !gripper) {
        // A file on disk compiles from its own folder, so its <include>s and meshes resolve.
        if (isPath) {
            char message[1000] = "";
            MjModelPtr model(mj_loadXML(file.constData(), nullptr, message, sizeof message));
            if (!model)
                *error = mujocoError(nameOrPath, message);
            return checked(std::move(model), xml, nameOrPath, error);
        }
        return compile(xml, file, nameOrPath, error);
    }
    if (count >= 0) {
        QByteArray filtered;
        int available = 0;
        QString xmlError;
        if (!keepCubes(xml, count, &filtered, &available, &xmlError)) {
            *error = nameOrPath + QLatin1Char(':') + xmlError;
            return nullptr;
        }
        if (count > available) {
            *error = QStringLiteral("%1: asked for %2 cubes, the scene has %3")
                         .arg(nameOrPath)
                         .arg(count)
                         .arg(available);
            return nullptr;
        }
        xml = filtered;
    }
    if (!gripper)
        return compile(xml, file, nameOrPath, error);
    MjcfElement scene;
    if (!MjcfElement::parse(xml, &scene, &reason)) {
        *error = nameOrPath + QLatin1Char(':') + reason;
        return nullptr;
    }
    if (!GripperComposer::compose(&scene, *gripper, mount, &reason)) {
        *error = nameOrPath + QStringLiteral(": ") + reason;
        return nullptr;
    }
    // MuJoCo's lines are the composed document's, which no editor has: no line numbers.
    QString where = nameOrPath + QStringLiteral(" with ") + gripper->file;
    const QByteArray composed = scene.toXml();
    MjModelPtr model = compile(composed, file, where, error);
    if (!model)
        error->replace(QRegularExpression(QStringLiteral("^([^:]*):\\d+:")),
                       QStringLiteral("\\1:"));
    return model;
}

MjModelPtr SceneLibrary::load(const QString &nameOrPath, const SceneOptions &options,
                              QString *error)
{
    return load(nameOrPath, options, nullptr, GripperComposer::Mount(), error);
}

} // namespace semhap
