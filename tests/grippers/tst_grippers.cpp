// SPDX-License-Identifier: MIT
// Gripper adapters (docs/grippers.md): a model semhap did not write goes into a scene's wrist
// unedited, its geometry is measured, and its pads press with the commanded force. The test
// grippers in this folder have the traits of real ones (their MJCF says which).
#include "eventbuffer.h"
#include "gripperadapter.h"
#include "grippercheck.h"
#include "router.h"
#include "simrun.h"
#include "world.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <map>

using namespace semhap;

namespace {

QByteArray hashOf(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return QByteArray();
    return QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256);
}

/** The folders of a MuJoCo Menagerie checkout the shipped adapters use, when it is given. */
const QStringList &shippedAdapters()
{
    static const QStringList names = qEnvironmentVariableIsSet("SEMHAP_MENAGERIE")
                                         ? QStringList{"robotiq_2f85", "franka_hand"}
                                         : QStringList();
    return names;
}

void copyFolder(const QDir &from, const QString &to)
{
    QDir().mkpath(to);
    for (const QString &file : from.entryList(QDir::Files))
        QFile::copy(from.filePath(file), to + QLatin1Char('/') + file);
    for (const QString &sub : from.entryList(QDir::Dirs | QDir::NoDotAndDotDot))
        copyFolder(QDir(from.filePath(sub)), to + QLatin1Char('/') + sub);
}

/**
 * Copies a test gripper's folder, or a shipped adapter with its model's Menagerie folder
 * (SEMHAP_MENAGERIE), into `dir`: loaded from elsewhere than where they were written.
 */
QString copyGripper(const QString &name, const QTemporaryDir &dir)
{
    if (shippedAdapters().contains(name)) {
        const QString adapter = QStringLiteral(SEMHAP_RESOURCES "/grippers/") + name + ".json";
        QFile::copy(adapter, dir.filePath(name + ".json"));
        const QString model = name == "franka_hand" ? "franka_emika_panda" : name;
        copyFolder(QDir(qEnvironmentVariable("SEMHAP_MENAGERIE") + '/' + model),
                   dir.filePath(model));
        return dir.filePath(name + ".json");
    }
    const QDir source(QStringLiteral(SEMHAP_TEST_DATA "/") + name);
    QDir(dir.path()).mkpath(name + QStringLiteral("/assets"));
    for (const QString &file : source.entryList(QDir::Files))
        QFile::copy(source.filePath(file), dir.filePath(name + QLatin1Char('/') + file));
    for (const QString &file :
         QDir(source.filePath(QStringLiteral("assets"))).entryList(QDir::Files))
        QFile::copy(source.filePath(QStringLiteral("assets/") + file),
                    dir.filePath(name + QStringLiteral("/assets/") + file));
    return dir.filePath(name + QLatin1Char('/') + name + QStringLiteral(".json"));
}

/**
 * Writes `source`'s text to `target` (the same file or another) with each of the
 * `|`-separated texts of `from` replaced by its counterpart in `to`; false with the text it
 * did not find, or the file it could not read or write, in `missing`.
 */
bool edit(const QString &source, const QString &target, const QString &from, const QString &to,
          QString *missing)
{
    QFile in(source);
    if (!in.open(QIODevice::ReadOnly)) {
        *missing = source;
        return false;
    }
    QString text = QString::fromUtf8(in.readAll());
    in.close();
    const QStringList froms = from.split('|'), tos = to.split('|');
    for (int i = 0; i < froms.size(); ++i) {
        if (!text.contains(froms[i])) {
            *missing = froms[i];
            return false;
        }
        text.replace(froms[i], tos.value(i));
    }
    QFile out(target);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) || out.write(text.toUtf8()) < 0) {
        *missing = target;
        return false;
    }
    return true;
}

std::unique_ptr<World> load(const QString &gripper, int cubes = -1)
{
    SceneOptions options;
    options.cubes = cubes;
    options.gripper = gripper;
    QString error;
    std::unique_ptr<World> world = World::load(QStringLiteral("box_and_block"), options, &error);
    if (!world)
        qWarning("%s", qPrintable(error));
    return world;
}

void steps(World &world, double seconds, const std::function<void(double)> &each = {})
{
    const int count = int(std::lround(seconds / world.timestep()));
    for (int k = 1; k <= count; ++k) {
        if (each)
            each(double(k) / count);
        world.step();
    }
}

/** Puts the cube alone on the floor of box A and closes the right gripper on it with `force`. */
void grasp(World &world, double force)
{
    // The cube alone on the floor of box A; the pads' centre comes down to its centre.
    const std::array<double, 3> cube{-0.15, 0.0, 0.0251};
    world.restoreObject(0, cube);
    const double drop = world.padDrop(Gripper::Right, 0.05);
    Pose above = world.target(Gripper::Right);
    const Pose start = above;
    world.setGrip(Gripper::Right, -10);
    steps(world, 0.6, [&](double s) {
        Pose p = start;
        for (int i = 0; i < 3; ++i)
            p.pos[size_t(i)] =
                start.pos[size_t(i)] +
                s * ((i == 2 ? cube[2] + drop : cube[size_t(i)]) - start.pos[size_t(i)]);
        world.setTarget(Gripper::Right, p);
    });
    steps(world, 0.3);
    steps(world, 0.5, [&](double s) { world.setGrip(Gripper::Right, -10 + s * (force + 10)); });
}

} // namespace

class TestGrippers : public QObject
{
    Q_OBJECT

private slots:
    void loadsTheModelAsItIs_data();
    void loadsTheModelAsItIs();
    void padsPressWithTheCommand_data();
    void padsPressWithTheCommand();
    void steadyHoldGivesOneConfirmation_data();
    void steadyHoldGivesOneConfirmation();
    void validateWarns_data();
    void validateWarns();
    void badAdaptersAreRefused_data();
    void badAdaptersAreRefused();
};

void TestGrippers::loadsTheModelAsItIs_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("model");
    QTest::addColumn<double>("openGap");    // mm, from the model's dimensions
    QTest::addColumn<double>("closedGap");  // mm
    QTest::addColumn<double>("closedDrop"); // mm below the wrist, pads' centre
    QTest::addColumn<int>("fullContacts");
    // Linkage: pivots 15 mm off the middle, pads 40 mm out and 40 mm down the link, 8 mm
    // to their faces; closed 35 degrees: each face at 15 + 40 (cos - sin) - 8 mm.
    const double a = 35 * M_PI / 180;
    QTest::newRow("linkage") << "linkage"
                             << "linkage.xml" << 94.0
                             << 2 * (15 + 40 * (std::cos(a) - std::sin(a)) - 8)
                             << 60 + 40 * (std::sin(a) + std::cos(a) - 1) << 2;
    // Slider: fingers 40 mm of travel each, faces 5 mm off the finger's origin at 10 mm.
    QTest::newRow("slider") << "slider"
                            << "slider.xml" << 90.0 << 10.0 << 60.0 << 2;
}

void TestGrippers::loadsTheModelAsItIs()
{
    QFETCH(QString, name);
    QFETCH(QString, model);
    QFETCH(double, openGap);
    QFETCH(double, closedGap);
    QFETCH(double, closedDrop);
    QFETCH(int, fullContacts);
    QTemporaryDir dir;
    const QString adapter = copyGripper(name, dir);
    const QString modelPath = QFileInfo(adapter).absoluteDir().filePath(model);
    const QByteArray before = hashOf(modelPath);
    // From another folder: the model, its meshes and includes resolve where the adapter is.
    QTemporaryDir elsewhere;
    const QString previous = QDir::currentPath();
    QDir::setCurrent(elsewhere.path());
    std::unique_ptr<World> world = load(adapter);
    QDir::setCurrent(previous);
    QVERIFY(world);
    QCOMPARE(hashOf(modelPath), before);
    const GripperGeometry &g = world->gripperGeometry(Gripper::Right);
    qDebug() << name << "gap" << g.openGap() << g.closedGap() << "drop" << g.drop(g.openGap())
             << g.drop(g.closedGap()) << "contacts" << world->fullContacts(Gripper::Right);
    // Mounted so that the fingers point down and close along y, pads' centre 6 cm below.
    QVERIFY(std::abs(g.closingAxis()[1] - 1) < 1e-6);
    QVERIFY(std::abs(g.approachAxis()[2] + 1) < 1e-6);
    QVERIFY(std::abs(g.drop(g.openGap()) - 0.06) < 1e-6);
    QVERIFY2(std::abs(g.openGap() * 1000 - openGap) < 0.5,
             qPrintable(QString::number(g.openGap())));
    QVERIFY2(std::abs(g.closedGap() * 1000 - closedGap) < 0.5,
             qPrintable(QString::number(g.closedGap())));
    QVERIFY2(std::abs(g.drop(g.closedGap()) * 1000 - closedDrop) < 0.5,
             qPrintable(QString::number(g.drop(g.closedGap()))));
    QCOMPARE(world->fullContacts(Gripper::Right), fullContacts);
    // The bundled gripper, measured the same way: 4 x 4 taxels a side, 6 cm below the wrist.
    QString error;
    std::unique_ptr<World> bundled = World::load(QStringLiteral("box_and_block"), {}, &error);
    QCOMPARE(bundled->fullContacts(Gripper::Right), 32);
    QVERIFY(std::abs(bundled->padDrop(Gripper::Right, 0.05) - 0.06) < 1e-9);
}

void TestGrippers::padsPressWithTheCommand_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("force");
    const QStringList names = QStringList{"linkage", "slider", ""} + shippedAdapters();
    for (const QString &name : names) {
        for (double force : {20.0, 60.0}) {
            QTest::addRow("%s %g N", name.isEmpty() ? "bundled" : qPrintable(name), force)
                << name << force;
        }
    }
}

void TestGrippers::padsPressWithTheCommand()
{
    QFETCH(QString, name);
    QFETCH(double, force);
    QTemporaryDir dir;
    std::unique_ptr<World> world = load(name.isEmpty() ? QString() : copyGripper(name, dir), 1);
    QVERIFY(world);
    grasp(*world, force);
    double sum = 0;
    int count = 0;
    steps(*world, 1.0, [&](double s) {
        if (s > 0.5) {
            sum += world->frame(Gripper::Right).totalForce();
            ++count;
        }
    });
    const double measured = sum / count;
    const ContactFrame &frame = world->frame(Gripper::Right);
    qDebug() << name << "command" << force << "pads" << measured << "n" << frame.left.n
             << frame.right.n;
    QCOMPARE(frame.left.actor, world->objects()[0].actor);
    QCOMPARE(frame.right.actor, world->objects()[0].actor);
    QVERIFY2(std::abs(measured - force) < 0.05 * force, qPrintable(QString::number(measured)));
}

void TestGrippers::steadyHoldGivesOneConfirmation_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("linkage") << "linkage";
    QTest::newRow("slider") << "slider";
    QTest::newRow("bundled") << "";
    for (const QString &name : shippedAdapters())
        QTest::newRow(qPrintable(name)) << name;
}

void TestGrippers::steadyHoldGivesOneConfirmation()
{
    // A cube taken, lifted and held for 10 s under C4 with its slip detector moved to the
    // right hand (the presets watch the left hand's hold for slips), compiled for this
    // gripper as semhap run does: one grasp confirmation from each detector, no warning of a
    // slip or a break the hold never had.
    QFETCH(QString, name);
    QTemporaryDir dir;
    std::unique_ptr<World> world = load(name.isEmpty() ? QString() : copyGripper(name, dir), 1);
    QVERIFY(world);
    LoadError error;
    std::unique_ptr<Router> router =
        loadRouter(QStringLiteral("C4"), {QStringLiteral("left.slip.gripper=right")}, &error,
                   SimRun::routerContext(*world, 0.25));
    QVERIFY2(router, qPrintable(error.toString()));
    std::vector<SemanticEvent> events;
    EventBuffer buffer;
    bool started = false;
    const auto route = [&](double) {
        const ContactFrame &frame = world->frame(Gripper::Right);
        if (!started) {
            router->start(frame.t);
            started = true;
        }
        buffer.clear();
        router->process(frame, buffer);
        events.insert(events.end(), buffer.begin(), buffer.end());
    };
    grasp(*world, 40.0);
    const Pose held = world->target(Gripper::Right);
    steps(*world, 1.0, [&](double s) {
        Pose p = held;
        p.pos[2] += 0.05 * s;
        world->setTarget(Gripper::Right, p);
        route(s);
    });
    steps(*world, 10.0, route);
    std::map<DetectorKind, int> confirmations;
    int exceptions = 0;
    for (const SemanticEvent &e : events) {
        if (e.phase != EventPhase::Begin)
            continue;
        confirmations[e.detector] += e.category == Category::Confirmation ? 1 : 0;
        exceptions += e.category == Category::Exception ? 1 : 0;
    }
    const ContactFrame &frame = world->frame(Gripper::Right);
    qDebug() << name << "confirmations" << confirmations[DetectorKind::Force]
             << confirmations[DetectorKind::Slip] << "exceptions" << exceptions << "n"
             << frame.left.n << frame.right.n << "F" << frame.totalForce();
    QCOMPARE(frame.left.actor, world->objects()[0].actor);
    QVERIFY(world->objectPosition(0)[2] > 0.06);
    QCOMPARE(confirmations[DetectorKind::Force], 1);
    QCOMPARE(confirmations[DetectorKind::Slip], 1);
    QCOMPARE(exceptions, 0);
}

void TestGrippers::validateWarns_data()
{
    // A scene (bundled, edited by replacing text) or a test gripper in box_and_block (its
    // adapter edited), and the warning it must give; none for the untouched ones.
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("gripper");
    QTest::addColumn<QString>("from"); // texts to replace, separated by |
    QTest::addColumn<QString>("to");
    QTest::addColumn<QString>("warning");
    const QString taxels = "contype=\"2\" conaffinity=\"1\"";
    QTest::newRow("bundled box_and_block") << "box_and_block"
                                           << ""
                                           << ""
                                           << ""
                                           << "";
    QTest::newRow("bundled bimanual_sorting") << "bimanual_sorting"
                                              << ""
                                              << ""
                                              << ""
                                              << "";
    QTest::newRow("bundled dish_wiping") << "dish_wiping"
                                         << ""
                                         << ""
                                         << ""
                                         << "";
    QTest::newRow("fingers that can collide")
        << "box_and_block"
        << "" << taxels + "|<exclude body1=\"right.finger.left\" body2=\"right.finger.right\"/>"
        << "contype=\"2\" conaffinity=\"3\"|"
        << "of the two fingers can collide: fingers closing on nothing push into each other "
           "and can lock; add <exclude body1=\"right.finger.left\" body2=\"right.finger.right\"/>";
    QTest::newRow("pads over the objects' priority")
        << "box_and_block"
        << "" << taxels << taxels + " priority=\"2\""
        << "pad geom right.tip.left.t00 has contact priority 2 and friction 1, object cube_0 "
           "priority 1 and friction 0.1";
    QTest::newRow("pads that let go")
        << "box_and_block"
        << "" << taxels + "|friction=\"1 0.005 0.0001\""
        << taxels + " solref=\"0.01 0.1\" priority=\"2\"|friction=\"0.1 0.005 0.0001\""
        << "a steady 40 N grip does not keep cube_0 between the pads";
    QTest::newRow("an object wider than the opening")
        << "box_and_block"
        << ""
        << "size=\"0.025 0.025 0.025\""
        << "size=\"0.05 0.05 0.05\""
        << "12 objects (cube_0, cube_1, cube_2, …) are up to 100 mm across at their narrowest, "
           "the pads open to 70 mm: this gripper cannot take them";
    QTest::newRow("few pad contacts") << "box_and_block"
                                      << "linkage"
                                      << ""
                                      << ""
                                      << "a full grasp touches only 2 pad geoms";
    QTest::newRow("fingers along another axis")
        << "box_and_block"
        << "linkage"
        << "\"root\": \"base\","
        << "\"root\": \"base\", \"mount\": {\"pos\": [0, 0, 0], \"quat\": [1, 0, 0, 0]},"
        << "the fingers close along (0.00, -1.00, 0.00)";
    QTest::newRow("closing the other way")
        << "box_and_block"
        << "slider"
        << "\"negative\""
        << "\"positive\""
        << "the adapter says \"closing\": \"positive\", but "
           "the fingers close as their joints' positions shrink";
}

void TestGrippers::validateWarns()
{
    QFETCH(QString, scene);
    QFETCH(QString, gripper);
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(QString, warning);
    QTemporaryDir dir;
    QString path = scene;
    QString adapterPath;
    QString missing;
    if (gripper.isEmpty() && !from.isEmpty()) {
        path = dir.filePath(scene + ".xml");
        QVERIFY2(edit(QStringLiteral(SEMHAP_RESOURCES "/scenes/") + scene + ".xml", path, from, to,
                      &missing),
                 qPrintable(missing));
    } else if (!gripper.isEmpty()) {
        adapterPath = copyGripper(gripper, dir);
        QVERIFY2(edit(adapterPath, adapterPath, from, to, &missing), qPrintable(missing));
    }
    SceneOptions options;
    options.gripper = adapterPath;
    QString error;
    std::unique_ptr<World> world = World::load(path, options, &error);
    QVERIFY2(world, qPrintable(error));
    GripperAdapter adapter;
    LoadError adapterError;
    const bool adapted = !adapterPath.isEmpty();
    QVERIFY(!adapted || GripperAdapter::read(adapterPath, &adapter, &adapterError));
    const QStringList warnings =
        GripperCheck::warnings(*world, path, adapted ? &adapter : nullptr);
    qDebug() << warnings;
    if (warning.isEmpty()) {
        QVERIFY2(warnings.isEmpty(), qPrintable(warnings.join('\n')));
    } else {
        QCOMPARE(warnings.filter(warning).size(), 1);
    }
}

void TestGrippers::badAdaptersAreRefused_data()
{
    QTest::addColumn<QString>("file"); // of the linkage gripper: its adapter or its model
    QTest::addColumn<QString>("from");
    QTest::addColumn<QString>("to");
    QTest::addColumn<QString>("error");
    QTest::newRow("format") << "linkage.json"
                            << "semhap.gripper/1"
                            << "semhap.gripper/9"
                            << "linkage.json: /format: unsupported format 'semhap.gripper/9'";
    QTest::newRow("no model") << "linkage.json"
                              << "\"linkage.xml\""
                              << "\"missing/linkage.xml\""
                              << "linkage.json: model missing/linkage.xml: cannot read";
    QTest::newRow("root") << "linkage.json"
                          << "\"base\""
                          << "\"palm\""
                          << "linkage.json: /root: linkage.xml has no body 'palm'";
    QTest::newRow("joint") << "linkage.json"
                           << "\"driver_a\""
                           << "\"driver_x\""
                           << "linkage.json: /fingers/left/joint: linkage.xml has no joint "
                              "'driver_x'";
    QTest::newRow("pad") << "linkage.json"
                         << "[\"pad_b\"]"
                         << "[\"pad_c\"]"
                         << "linkage.json: /fingers/right/pads/0: linkage.xml has no body or "
                            "geom 'pad_c'";
    QTest::newRow("closing") << "linkage.json"
                             << "\"positive\""
                             << "\"inwards\""
                             << "linkage.json: /closing: must be 'positive' or 'negative'";
    QTest::newRow("same joint") << "linkage.json"
                                << "\"driver_b\""
                                << "\"driver_a\""
                                << "linkage.json: /fingers/right/joint: must differ";
    QTest::newRow("typo") << "linkage.json"
                          << "\"closing\""
                          << "\"closng\""
                          << "linkage.json: unknown key 'closng'";
    QTest::newRow("collisions") << "linkage.json"
                                << "\"closing\""
                                << "\"collisions\": \"some\", \"closing\""
                                << "linkage.json: /collisions: must be 'all'";
    QTest::newRow("force") << "linkage.json"
                           << "\"max\": 200"
                           << "\"max\": -1"
                           << "linkage.json: /force/max: must be above 0";
    QTest::newRow("a finger that does not close") << "linkage.xml"
                                                  << "range=\"0 35\""
                                                  << "range=\"0 0.01\""
                                                  << "does not close the gripper";
}

void TestGrippers::badAdaptersAreRefused()
{
    QFETCH(QString, file);
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(QString, error);
    QTemporaryDir dir;
    const QString adapter = copyGripper(QStringLiteral("linkage"), dir);
    const QString edited = QFileInfo(adapter).absoluteDir().filePath(file);
    QString missing;
    QVERIFY2(edit(edited, edited, from, to, &missing), qPrintable(missing));
    SceneOptions options;
    options.gripper = adapter;
    QString message;
    QVERIFY(!World::load(QStringLiteral("box_and_block"), options, &message));
    QVERIFY2(message.contains(error), qPrintable(message));
}

QTEST_GUILESS_MAIN(TestGrippers)
#include "tst_grippers.moc"
