// SPDX-License-Identifier: MIT
#include "grippercomposer.h"

#include "inputfile.h"
#include "jsonreader.h"
#include "mjcfelement.h"

#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QSet>

#include <cstring>

#include <cmath>

namespace semhap {

namespace {

constexpr double Pi = 3.14159265358979323846;
// Includes nest a few levels in any real model; deeper is a loop or a hostile file.
constexpr int MaxIncludeDepth = 8;

const QStringList &handNames()
{
    static const QStringList names{QStringLiteral("left"), QStringLiteral("right")};
    return names;
}

/** Attributes whose value names another element of the model (renamed with it). */
bool isReference(const QString &attribute)
{
    static const QSet<QString> references{
        QStringLiteral("class"),      QStringLiteral("childclass"),    QStringLiteral("mesh"),
        QStringLiteral("material"),   QStringLiteral("texture"),       QStringLiteral("hfield"),
        QStringLiteral("joint"),      QStringLiteral("joint1"),        QStringLiteral("joint2"),
        QStringLiteral("body"),       QStringLiteral("body1"),         QStringLiteral("body2"),
        QStringLiteral("geom"),       QStringLiteral("geom1"),         QStringLiteral("geom2"),
        QStringLiteral("site"),       QStringLiteral("tendon"),        QStringLiteral("objname"),
        QStringLiteral("refname"),    QStringLiteral("target"),        QStringLiteral("cranksite"),
        QStringLiteral("slidersite"), QStringLiteral("jointinparent"), QStringLiteral("name")};
    return references.contains(attribute);
}

/** The compiler settings that change how the rest of a model reads. */
struct Compiler
{
    bool radian = false;     // MuJoCo's default unit is the degree
    bool autolimits = false; // MuJoCo 2.2's default
    QString meshdir, texturedir;

    static Compiler of(const MjcfElement &root)
    {
        Compiler c;
        for (const MjcfElement &e : root.children()) {
            if (e.tag() != QLatin1String("compiler"))
                continue;
            if (e.has(QStringLiteral("angle")))
                c.radian = e.attribute(QStringLiteral("angle")) == QLatin1String("radian");
            if (e.has(QStringLiteral("autolimits")))
                c.autolimits = e.attribute(QStringLiteral("autolimits")) == QLatin1String("true");
            if (e.has(QStringLiteral("assetdir")))
                c.meshdir = c.texturedir = e.attribute(QStringLiteral("assetdir"));
            if (e.has(QStringLiteral("meshdir")))
                c.meshdir = e.attribute(QStringLiteral("meshdir"));
            if (e.has(QStringLiteral("texturedir")))
                c.texturedir = e.attribute(QStringLiteral("texturedir"));
        }
        return c;
    }
};

/** Replaces each <include file> by the top-level elements of the file, recursively. */
bool inlineIncludes(MjcfElement *element, const QDir &folder, int depth, const QString &file,
                    QString *error)
{
    for (size_t i = 0; i < element->children().size(); ++i) {
        MjcfElement &child = element->children()[i];
        if (child.tag() != QLatin1String("include")) {
            if (!inlineIncludes(&child, folder, depth, file, error))
                return false;
            continue;
        }
        const QString path = folder.filePath(child.attribute(QStringLiteral("file")));
        QByteArray xml;
        QString reason;
        MjcfElement included;
        if (depth >= MaxIncludeDepth) {
            *error = QStringLiteral("%1:%2: includes nested deeper than %3")
                         .arg(file)
                         .arg(child.line())
                         .arg(MaxIncludeDepth);
            return false;
        }
        if (!InputFile::readDocument(path, &xml, &reason) ||
            !MjcfElement::parse(xml, &included, &reason)) {
            *error = QStringLiteral("%1:%2: include %3: %4")
                         .arg(file)
                         .arg(child.line())
                         .arg(child.attribute(QStringLiteral("file")), reason);
            return false;
        }
        if (!inlineIncludes(&included, folder, depth + 1, path, error))
            return false;
        std::vector<MjcfElement> parts = included.children();
        element->children().erase(element->children().begin() + long(i));
        element->children().insert(element->children().begin() + long(i), parts.begin(),
                                   parts.end());
        i += parts.size();
        --i;
    }
    return true;
}

/** The model's default classes by name, each with its parent, to look attributes up. */
class Defaults
{
public:
    explicit Defaults(const MjcfElement &root)
    {
        for (const MjcfElement &e : root.children()) {
            if (e.tag() == QLatin1String("default"))
                collect(e, QString());
        }
    }

    /** `attribute` of element kind `tag` in class `cls`, through its ancestors; empty if unset. */
    QString lookup(QString cls, const QString &tag, const QString &attribute) const
    {
        while (m_classes.contains(cls)) {
            const Entry &entry = m_classes[cls];
            if (const MjcfElement *e = entry.element->child(tag)) {
                if (e->has(attribute))
                    return e->attribute(attribute);
            }
            if (cls.isEmpty())
                break;
            cls = entry.parent;
        }
        return QString();
    }

private:
    struct Entry
    {
        const MjcfElement *element = nullptr;
        QString parent;
    };

    void collect(const MjcfElement &e, const QString &parent)
    {
        // The top-level <default> is the class "main" (named here by the empty string).
        const QString name = e.has(QStringLiteral("class")) &&
                                     e.attribute(QStringLiteral("class")) != QLatin1String("main")
                                 ? e.attribute(QStringLiteral("class"))
                                 : QString();
        m_classes.insert(name, Entry{&e, parent});
        for (const MjcfElement &child : e.children()) {
            if (child.tag() == QLatin1String("default"))
                collect(child, name);
        }
    }

    QHash<QString, Entry> m_classes;
};

/** Appends `body`'s own geoms that collide (its classes say how) to `out`. */
void bodyGeoms(MjcfElement &body, const QString &inherited, const Defaults &defaults,
               std::vector<MjcfElement *> *out)
{
    const QString cls = body.has(QStringLiteral("childclass"))
                            ? body.attribute(QStringLiteral("childclass"))
                            : inherited;
    for (MjcfElement &child : body.children()) {
        if (child.tag() != QLatin1String("geom"))
            continue;
        const QString own =
            child.has(QStringLiteral("class")) ? child.attribute(QStringLiteral("class")) : cls;
        auto value = [&](const QString &key) {
            const QString v = child.has(key) ? child.attribute(key)
                                             : defaults.lookup(own, QStringLiteral("geom"), key);
            return v.isEmpty() ? 1 : v.toInt();
        };
        if (value(QStringLiteral("contype")) != 0 || value(QStringLiteral("conaffinity")) != 0)
            out->push_back(&child);
    }
}

/** The class each body of the subtree passes on, to find a nested body's geoms' class. */
MjcfElement *findBody(MjcfElement &element, const QString &name, const QString &inherited,
                      QString *cls)
{
    for (MjcfElement &child : element.children()) {
        if (child.tag() != QLatin1String("body"))
            continue;
        const QString passed = child.has(QStringLiteral("childclass"))
                                   ? child.attribute(QStringLiteral("childclass"))
                                   : inherited;
        if (child.attribute(QStringLiteral("name")) == name) {
            *cls = inherited;
            return &child;
        }
        if (MjcfElement *found = findBody(child, name, passed, cls))
            return found;
    }
    return nullptr;
}

QString numbersText(const std::vector<double> &values)
{
    QStringList parts;
    for (double v : values)
        parts.append(QString::number(v, 'g', 12));
    return parts.join(QLatin1Char(' '));
}

std::vector<double> numbersOf(const QString &text)
{
    std::vector<double> values;
    for (const QString &part : text.split(QLatin1Char(' '), Qt::SkipEmptyParts))
        values.push_back(part.toDouble());
    return values;
}

/**
 * A model read for composing: its tree with includes inlined, its compiler settings, its
 * folder; `where` names it in errors.
 */
struct Model
{
    MjcfElement root;
    Compiler compiler;
    QDir folder;
    QString where;
};

bool readModel(const GripperAdapter &adapter, Model *model, QString *error)
{
    model->where = adapter.file + QStringLiteral(": model ") + adapter.modelName;
    QByteArray xml;
    QString reason;
    if (!InputFile::readDocument(adapter.model, &xml, &reason)) {
        *error = model->where + QStringLiteral(": cannot read: ") + reason;
        return false;
    }
    if (!MjcfElement::parse(xml, &model->root, &reason)) {
        *error = adapter.model + QLatin1Char(':') + reason;
        return false;
    }
    model->folder = QFileInfo(adapter.model).absoluteDir();
    if (!inlineIncludes(&model->root, model->folder, 0, adapter.model, error))
        return false;
    model->compiler = Compiler::of(model->root);
    for (const MjcfElement &e : model->root.children()) {
        if (e.tag() == QLatin1String("compiler") &&
            e.attribute(QStringLiteral("coordinate")) == QLatin1String("global")) {
            *error = QStringLiteral("%1:%2: coordinate=\"global\" is not supported")
                         .arg(adapter.model)
                         .arg(e.line());
            return false;
        }
    }
    return true;
}

/** One hand's copy of the model, renamed, with its pads and fingers found. */
class HandCopy
{
public:
    HandCopy(const Model &model, const GripperAdapter &adapter, const QString &hand,
             const Compiler &scene)
        : m_model(model), m_adapter(adapter), m_hand(hand), m_scene(scene),
          m_prefix(hand + QStringLiteral(".model.")), m_root(model.root)
    {}

    bool build(QString *error);

    MjcfElement rootBody;
    std::vector<MjcfElement> defaults, assets, contacts, tendons, equalities, sensors;
    std::array<QString, 2> fingerJoints;
    std::array<QSet<QString>, 2> padBodies;

private:
    QString renamed(const QString &value) const
    {
        if (value == QLatin1String("main"))
            return m_prefix + QStringLiteral("main");
        return m_names.value(value, m_prefix + value);
    }
    void rename(MjcfElement &element) const
    {
        element.forEach([this](MjcfElement &e) {
            for (const auto &[key, value] : std::vector(e.attributes())) {
                if (isReference(key) && !value.isEmpty() &&
                    !(key == QLatin1String("target") && e.tag() != QLatin1String("camera")))
                    e.setAttribute(key, renamed(value));
            }
        });
    }
    bool findPads(MjcfElement &root, const QString &rootClass, QString *error);
    void convertUnits(MjcfElement &root, const QString &rootClass);
    void takeAssets();
    /** Every colliding geom of the subtree but the pads stops colliding. */
    void keepPadsColliding(MjcfElement &root, const QString &rootClass);

    const Model &m_model;
    const GripperAdapter &m_adapter;
    QString m_hand;
    Compiler m_scene;
    QString m_prefix;
    MjcfElement m_root; // the model's own tree, edited freely
    QHash<QString, QString> m_names;
};

bool HandCopy::findPads(MjcfElement &root, const QString &rootClass, QString *error)
{
    const Defaults classes(m_root);
    static const char *const sides[] = {"left", "right"};
    for (int side = 0; side < 2; ++side) {
        const GripperAdapter::Finger &finger = m_adapter.fingers[size_t(side)];
        std::vector<MjcfElement *> pads;
        for (int i = 0; i < finger.pads.size(); ++i) {
            const QString &pad = finger.pads[i];
            QString cls = rootClass;
            MjcfElement *body = root.attribute(QStringLiteral("name")) == pad
                                    ? &root
                                    : findBody(root, pad, rootClass, &cls);
            std::vector<MjcfElement *> found;
            if (body) {
                bodyGeoms(*body,
                          body->has(QStringLiteral("childclass"))
                              ? body->attribute(QStringLiteral("childclass"))
                              : cls,
                          classes, &found);
                padBodies[size_t(side)].insert(pad);
            } else if (MjcfElement *geom = root.find(QStringLiteral("geom"), pad)) {
                found.push_back(geom);
            }
            if (found.empty()) {
                *error = QStringLiteral("%1: /fingers/%2/pads/%3: %4 has no %5 %6 below %7")
                             .arg(m_adapter.file, QLatin1String(sides[side]))
                             .arg(i)
                             .arg(m_adapter.modelName,
                                  body ? QStringLiteral("colliding geom in body")
                                       : QStringLiteral("body or geom"),
                                  quoted(pad), quoted(m_adapter.root));
                return false;
            }
            pads.insert(pads.end(), found.begin(), found.end());
        }
        for (size_t k = 0; k < pads.size(); ++k) {
            const QString name =
                QStringLiteral("%1.tip.%2.%3").arg(m_hand, QLatin1String(sides[side])).arg(k);
            MjcfElement &geom = *pads[k];
            // semhap's objects set their own friction by contact priority (sim/README.md): a
            // pad with the same priority (the 2F-85's) would win the tie with its larger one.
            geom.setAttribute(QStringLiteral("priority"), QStringLiteral("0"));
            if (geom.has(QStringLiteral("name")))
                m_names.insert(geom.attribute(QStringLiteral("name")), name);
            geom.setAttribute(QStringLiteral("name"), name);
            m_names.insert(name, name);
        }
        // The pad bodies of a finger not named as bodies: the bodies holding its pad geoms.
        root.forEach([&](MjcfElement &body) {
            if (body.tag() != QLatin1String("body"))
                return;
            for (const MjcfElement &g : body.children()) {
                if (g.tag() == QLatin1String("geom") &&
                    g.attribute(QStringLiteral("name"))
                        .startsWith(m_hand + QStringLiteral(".tip.") + QLatin1String(sides[side])))
                    padBodies[size_t(side)].insert(body.attribute(QStringLiteral("name")));
            }
        });
        const QString joint = finger.joint;
        if (!root.find(QStringLiteral("joint"), joint)) {
            *error = QStringLiteral("%1: /fingers/%2/joint: %3 has no joint %4 below %5")
                         .arg(m_adapter.file, QLatin1String(sides[side]), m_adapter.modelName,
                              quoted(joint), quoted(m_adapter.root));
            return false;
        }
        fingerJoints[size_t(side)] = joint;
    }
    return true;
}

void HandCopy::convertUnits(MjcfElement &root, const QString &rootClass)
{
    const bool angles = m_model.compiler.radian != m_scene.radian;
    const double scale = m_model.compiler.radian ? 180.0 / Pi : Pi / 180.0;
    const Defaults classes(m_root);
    // Joints: their range and reference angles, with what their classes give, made explicit.
    std::function<void(MjcfElement &, const QString &, bool)> walk =
        [&](MjcfElement &body, const QString &inherited, bool self) {
            const QString cls = body.has(QStringLiteral("childclass"))
                                    ? body.attribute(QStringLiteral("childclass"))
                                    : inherited;
            std::vector<MjcfElement *> elements;
            if (self)
                elements.push_back(&body);
            for (MjcfElement &e : body.children())
                elements.push_back(&e);
            for (MjcfElement *each : elements) {
                MjcfElement &e = *each;
                const QString own =
                    e.has(QStringLiteral("class")) ? e.attribute(QStringLiteral("class")) : cls;
                if (angles) {
                    for (const char *key : {"euler", "axisangle"}) {
                        if (!e.has(QLatin1String(key)))
                            continue;
                        std::vector<double> v = numbersOf(e.attribute(QLatin1String(key)));
                        for (size_t i = key[0] == 'e' ? 0 : 3; i < v.size(); ++i)
                            v[i] *= scale;
                        e.setAttribute(QLatin1String(key), numbersText(v));
                    }
                }
                if (e.tag() == QLatin1String("joint")) {
                    auto value = [&](const QString &key) {
                        return e.has(key) ? e.attribute(key)
                                          : classes.lookup(own, QStringLiteral("joint"), key);
                    };
                    const QString type = value(QStringLiteral("type"));
                    const bool angular = type.isEmpty() || type == QLatin1String("hinge") ||
                                         type == QLatin1String("ball");
                    for (const char *key : {"range", "ref", "springref"}) {
                        const QString text = value(QLatin1String(key));
                        if (text.isEmpty())
                            continue;
                        std::vector<double> v = numbersOf(text);
                        if (angles && angular)
                            for (double &x : v)
                                x *= scale;
                        e.setAttribute(QLatin1String(key), numbersText(v));
                    }
                    if (!e.has(QStringLiteral("limited")) &&
                        !value(QStringLiteral("range")).isEmpty()) {
                        const QString limited = value(QStringLiteral("limited"));
                        e.setAttribute(QStringLiteral("limited"),
                                       limited.isEmpty() ? (m_model.compiler.autolimits
                                                                ? QStringLiteral("true")
                                                                : QStringLiteral("false"))
                                                         : limited);
                    }
                }
                if (each != &body && e.tag() == QLatin1String("body"))
                    walk(e, cls, false);
            }
        };
    // The root's own orientation, then everything below it (each body's in its parent's walk).
    walk(root, rootClass, true);
}

void HandCopy::takeAssets()
{
    for (const MjcfElement &section : m_root.children()) {
        if (section.tag() != QLatin1String("asset"))
            continue;
        for (MjcfElement asset : section.children()) {
            if (asset.tag() == QLatin1String("texture") &&
                asset.attribute(QStringLiteral("type")) == QLatin1String("skybox"))
                continue;
            const bool mesh = asset.tag() == QLatin1String("mesh") ||
                              asset.tag() == QLatin1String("skin") ||
                              asset.tag() == QLatin1String("hfield");
            const QString dir = mesh ? m_model.compiler.meshdir : m_model.compiler.texturedir;
            for (const char *key : {"file", "fileright", "fileleft", "fileup", "filedown",
                                    "filefront", "fileback"}) {
                if (!asset.has(QLatin1String(key)))
                    continue;
                const QString file = asset.attribute(QLatin1String(key));
                // MuJoCo names an unnamed mesh or height field after its file.
                if (std::strcmp(key, "file") == 0 && !asset.has(QStringLiteral("name")) &&
                    asset.tag() != QLatin1String("texture"))
                    asset.setAttribute(QStringLiteral("name"), QFileInfo(file).completeBaseName());
                asset.setAttribute(QLatin1String(key),
                                   QDir::isAbsolutePath(file)
                                       ? file
                                       : QDir::cleanPath(m_model.folder.absoluteFilePath(
                                             QDir(dir).filePath(file))));
            }
            if (!asset.has(QStringLiteral("class")) &&
                (asset.tag() == QLatin1String("mesh") || asset.tag() == QLatin1String("material")))
                asset.setAttribute(QStringLiteral("class"), QStringLiteral("main"));
            rename(asset);
            assets.push_back(asset);
        }
    }
}

void HandCopy::keepPadsColliding(MjcfElement &root, const QString &rootClass)
{
    const Defaults classes(m_root);
    const QString tips = m_hand + QStringLiteral(".tip.");
    std::function<void(MjcfElement &, const QString &)> walk = [&](MjcfElement &body,
                                                                   const QString &inherited) {
        const QString cls = body.has(QStringLiteral("childclass"))
                                ? body.attribute(QStringLiteral("childclass"))
                                : inherited;
        std::vector<MjcfElement *> colliding;
        bodyGeoms(body, cls, classes, &colliding);
        for (MjcfElement *geom : colliding) {
            if (!geom->attribute(QStringLiteral("name")).startsWith(tips)) {
                geom->setAttribute(QStringLiteral("contype"), QStringLiteral("0"));
                geom->setAttribute(QStringLiteral("conaffinity"), QStringLiteral("0"));
            }
        }
        for (MjcfElement &child : body.children()) {
            if (child.tag() == QLatin1String("body"))
                walk(child, cls);
        }
    };
    walk(root, rootClass);
}

bool HandCopy::build(QString *error)
{
    MjcfElement *worldbody = m_root.child(QStringLiteral("worldbody"));
    QString rootClass;
    MjcfElement *root =
        worldbody ? findBody(*worldbody, m_adapter.root, QString(), &rootClass) : nullptr;
    if (!root) {
        *error = QStringLiteral("%1: /root: %2 has no body %3")
                     .arg(m_adapter.file, m_adapter.modelName, quoted(m_adapter.root));
        return false;
    }
    if (!findPads(*root, rootClass, error))
        return false;
    convertUnits(*root, rootClass);
    if (m_adapter.padsOnly)
        keepPadsColliding(*root, rootClass);
    if (!root->has(QStringLiteral("childclass")))
        root->setAttribute(QStringLiteral("childclass"),
                           rootClass.isEmpty() ? QStringLiteral("main") : rootClass);
    // The bodies of the gripper, to keep only what concerns them.
    QSet<QString> bodies;
    root->forEach([&](const MjcfElement &e) {
        if (e.tag() == QLatin1String("body"))
            bodies.insert(e.attribute(QStringLiteral("name")));
    });
    for (int side = 0; side < 2; ++side)
        fingerJoints[size_t(side)] = renamed(fingerJoints[size_t(side)]);
    std::array<QSet<QString>, 2> pads = padBodies;
    for (int side = 0; side < 2; ++side) {
        padBodies[size_t(side)].clear();
        for (const QString &b : pads[size_t(side)])
            padBodies[size_t(side)].insert(renamed(b));
    }

    takeAssets();
    for (const MjcfElement &section : m_root.children()) {
        if (section.tag() == QLatin1String("default")) {
            MjcfElement main = section;
            main.setAttribute(QStringLiteral("class"), QStringLiteral("main"));
            rename(main);
            defaults.push_back(main);
        }
        for (MjcfElement e : section.children()) {
            if (e.tag() == QLatin1String("include"))
                continue;
            if (section.tag() == QLatin1String("contact")) {
                if (e.tag() == QLatin1String("pair") && !e.has(QStringLiteral("class")))
                    e.setAttribute(QStringLiteral("class"), QStringLiteral("main"));
                rename(e);
                contacts.push_back(e);
            } else if (section.tag() == QLatin1String("tendon")) {
                if (!e.has(QStringLiteral("class")))
                    e.setAttribute(QStringLiteral("class"), QStringLiteral("main"));
                rename(e);
                tendons.push_back(e);
            } else if (section.tag() == QLatin1String("equality")) {
                if (!e.has(QStringLiteral("class")))
                    e.setAttribute(QStringLiteral("class"), QStringLiteral("main"));
                rename(e);
                equalities.push_back(e);
            } else if (section.tag() == QLatin1String("sensor") &&
                       !e.tag().startsWith(QLatin1String("actuator"))) {
                rename(e);
                sensors.push_back(e);
            }
        }
    }
    rootBody = *root;
    rename(rootBody);
    return true;
}

/** The names of the bodies, joints, geoms and sites in `element`'s subtree. */
QSet<QString> namesBelow(const MjcfElement &element)
{
    QSet<QString> names;
    element.forEach([&](const MjcfElement &e) {
        if (e.has(QStringLiteral("name")))
            names.insert(e.attribute(QStringLiteral("name")));
    });
    return names;
}

/**
 * Takes out of `wrist` what the scene's own gripper had there (its geoms and the bodies that
 * carry fingertips), and of the scene whatever names them; joints, sites and other bodies (a
 * tool) stay.
 */
void removeOwnGripper(MjcfElement *scene, MjcfElement *wrist, const QString &hand)
{
    QSet<QString> removed;
    const QString tips = hand + QStringLiteral(".tip.");
    wrist->removeChildren([&](const MjcfElement &child) {
        bool fingertips = false;
        child.forEach([&](const MjcfElement &e) {
            fingertips = fingertips || (e.tag() == QLatin1String("geom") &&
                                        e.attribute(QStringLiteral("name")).startsWith(tips));
        });
        const bool drop = child.tag() == QLatin1String("geom") ||
                          child.tag() == QLatin1String("inertial") ||
                          (child.tag() == QLatin1String("body") && fingertips);
        if (drop)
            removed.unite(namesBelow(child));
        return drop;
    });
    QSet<QString> tendons;
    if (MjcfElement *section = scene->child(QStringLiteral("tendon"))) {
        section->removeChildren([&](const MjcfElement &tendon) {
            bool uses = false;
            tendon.forEach([&](const MjcfElement &e) {
                for (const auto &[key, value] : e.attributes())
                    uses = uses || (key != QLatin1String("name") && removed.contains(value));
            });
            if (uses)
                tendons.insert(tendon.attribute(QStringLiteral("name")));
            return uses;
        });
    }
    removed.unite(tendons);
    for (const char *tag : {"contact", "equality", "actuator", "sensor"}) {
        if (MjcfElement *section = scene->child(QLatin1String(tag))) {
            section->removeChildren([&](const MjcfElement &e) {
                for (const auto &[key, value] : e.attributes()) {
                    if (key != QLatin1String("name") && isReference(key) &&
                        removed.contains(value))
                        return true;
                }
                return false;
            });
        }
    }
}

} // namespace

bool GripperComposer::compose(MjcfElement *scene, const GripperAdapter &adapter,
                              const Mount &mount, QString *error)
{
    Model model;
    if (!readModel(adapter, &model, error))
        return false;
    const Compiler sceneCompiler = Compiler::of(*scene);
    MjcfElement *worldbody = scene->child(QStringLiteral("worldbody"));
    int replaced = 0;
    for (const QString &hand : handNames()) {
        MjcfElement *wrist =
            worldbody ? worldbody->find(QStringLiteral("body"), hand + QStringLiteral(".gripper"))
                      : nullptr;
        if (!wrist)
            continue;
        HandCopy copy(model, adapter, hand, sceneCompiler);
        if (!copy.build(error))
            return false;
        removeOwnGripper(scene, wrist, hand);
        MjcfElement holder(QStringLiteral("body"));
        holder.setAttribute(QStringLiteral("name"), hand + QStringLiteral(".mount"));
        holder.setAttribute(QStringLiteral("pos"),
                            numbersText({mount.pos[0], mount.pos[1], mount.pos[2]}));
        holder.setAttribute(QStringLiteral("quat"), numbersText({mount.quat[0], mount.quat[1],
                                                                 mount.quat[2], mount.quat[3]}));
        holder.children().push_back(copy.rootBody);
        wrist->children().push_back(holder);
        // MuJoCo wants mass in the body that carries the wrist's free joint itself, not only
        // in the bodies fixed to it: 10 g, next to the model's hundreds.
        if (!wrist->child(QStringLiteral("inertial"))) {
            MjcfElement inertial(QStringLiteral("inertial"));
            inertial.setAttribute(QStringLiteral("pos"), QStringLiteral("0 0 0"));
            inertial.setAttribute(QStringLiteral("mass"), QStringLiteral("0.01"));
            inertial.setAttribute(QStringLiteral("diaginertia"), QStringLiteral("1e-6 1e-6 1e-6"));
            wrist->children().insert(wrist->children().begin(), inertial);
        }

        MjcfElement &defaults = scene->section(QStringLiteral("default"));
        defaults.children().insert(defaults.children().end(), copy.defaults.begin(),
                                   copy.defaults.end());
        MjcfElement &assets = scene->section(QStringLiteral("asset"));
        assets.children().insert(assets.children().end(), copy.assets.begin(), copy.assets.end());
        MjcfElement &contact = scene->section(QStringLiteral("contact"));
        contact.children().insert(contact.children().end(), copy.contacts.begin(),
                                  copy.contacts.end());
        // The fingers never touch each other in semhap's grippers: without this a finger
        // closing on nothing can lock into the other (sim/README.md).
        for (const QString &left : copy.padBodies[0]) {
            for (const QString &right : copy.padBodies[1]) {
                MjcfElement exclude(QStringLiteral("exclude"));
                exclude.setAttribute(QStringLiteral("body1"), left);
                exclude.setAttribute(QStringLiteral("body2"), right);
                contact.children().push_back(exclude);
            }
        }
        for (const auto &[tag, parts] :
             {std::pair<const char *, const std::vector<MjcfElement> *>{"tendon", &copy.tendons},
              {"equality", &copy.equalities},
              {"sensor", &copy.sensors}}) {
            if (parts->empty())
                continue;
            MjcfElement &section = scene->section(QLatin1String(tag));
            section.children().insert(section.children().end(), parts->begin(), parts->end());
        }
        MjcfElement &actuators = scene->section(QStringLiteral("actuator"));
        for (int side = 0; side < 2; ++side) {
            MjcfElement motor(QStringLiteral("motor"));
            motor.setAttribute(
                QStringLiteral("name"),
                hand + (side == 0 ? QStringLiteral(".grip.left") : QStringLiteral(".grip.right")));
            motor.setAttribute(QStringLiteral("joint"), copy.fingerJoints[size_t(side)]);
            motor.setAttribute(QStringLiteral("gear"), QString::number(adapter.closing));
            motor.setAttribute(QStringLiteral("ctrllimited"), QStringLiteral("true"));
            motor.setAttribute(QStringLiteral("ctrlrange"),
                               numbersText({-adapter.openForce / 2, adapter.maxForce / 2}));
            actuators.children().push_back(motor);
        }
        ++replaced;
    }
    if (replaced == 0) {
        *error = QStringLiteral("the scene has no gripper body left.gripper or right.gripper "
                                "to put %1 into")
                     .arg(adapter.file);
        return false;
    }
    return true;
}

} // namespace semhap
