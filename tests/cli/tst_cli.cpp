// SPDX-License-Identifier: MIT
// The `semhap` command line as users meet it: exit codes, one-line errors, render output.
#include "clitool.h"
#include "emulatedband.h"
#include "shard.h"
#include "transportscheme.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <csignal>

using namespace semhap;

namespace {

const QString Trace = QStringLiteral(SEMHAP_RESOURCES "/traces/demo.jsonl");
const QString Data = QStringLiteral(SEMHAP_TEST_DATA);

struct Result
{
    int code;
    QByteArray out;
    QByteArray err;
};

Result semhapRun(const QStringList &arguments, const QByteArray &input = {})
{
    QByteArray in = input;
    QBuffer inBuffer(&in);
    inBuffer.open(QIODevice::ReadOnly);
    Result r{0, {}, {}};
    QBuffer outBuffer(&r.out);
    QBuffer errBuffer(&r.err);
    outBuffer.open(QIODevice::WriteOnly);
    errBuffer.open(QIODevice::WriteOnly);
    CliTool tool({&inBuffer, &outBuffer, &errBuffer});
    r.code = tool.run(arguments);
    return r;
}

QStringList csvRow(const QByteArray &csv, int row)
{
    return QString::fromUtf8(csv.split('\n').at(row)).split(',');
}

} // namespace

class TestCli : public QObject
{
    Q_OBJECT

private slots:
    void errors_data();
    void errors();
    void help();
    void rejectedLinesAreReportedNotFatal();
    void renderGeigerPulses();
    void renderReleaseRamp();
    void renderToFile();
    void validate();
    void devicesListsEveryTransport();
    void probeAsksTheBand();
    void realBinaryReadsStdin();
    void aKilledCompareResumes();
    void shards_data();
    void shards();
};

void TestCli::errors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("firstLine");
    const QString broken = Data + "/broken-router.json";
    const QString syntax = Data + "/syntax-error.json";

    QTest::newRow("no command") << QStringList{} << 2 << "Usage: semhap COMMAND [OPTIONS]";
    QTest::newRow("unknown command")
        << QStringList{"frobnicate"} << 2 << "semhap: unknown command 'frobnicate'";
    QTest::newRow("unknown option")
        << QStringList{"route", "--bogus"} << 2 << "semhap route: Unknown option 'bogus'.";
    QTest::newRow("route without router")
        << QStringList{"route", "--frames", Trace} << 2 << "semhap route: --router is required";
    QTest::newRow("route without frames")
        << QStringList{"route", "--router", "C3"} << 2 << "semhap route: --frames is required";
    QTest::newRow("two outputs on stdout")
        << QStringList{"route", "--router",        "C3", "--frames", Trace, "--events",
                       "-",     "--device-frames", "-"}
        << 2 << "semhap route: at most one output may be '-' (standard output)";
    QTest::newRow("unknown preset")
        << QStringList{"route", "--router", "C5", "--frames", Trace} << 1
        << "C5: no such router preset (presets: C1, C2, C3, C3p, C4, C4p, none, sensory, usb, "
           "visual, wipe)";
    QTest::newRow("missing frames file")
        << QStringList{"route", "--router", "C3", "--frames", "/nonexistent/frames.jsonl"} << 1
        << "/nonexistent/frames.jsonl: cannot read: No such file or directory";
    QTest::newRow("bad override")
        << QStringList{"route",
                       "--router",
                       "C3",
                       "--frames",
                       Trace,
                       "--set",
                       "right.force.break=200"}
        << 1
        << "--set right.force.break=200: node 'right.force' (force): must be greater than break "
           "(200), got 120";
    QTest::newRow("broken router file")
        << QStringList{"route", "--router", broken, "--frames", Trace} << 1
        << broken + ": /links/0/to: dangling link: no node 'nowhere'";
    QTest::newRow("router syntax error")
        << QStringList{"route", "--router", syntax, "--frames", Trace} << 1
        << syntax + ":3:17: invalid JSON: unterminated object";
    QTest::newRow("render without pattern")
        << QStringList{"render"} << 2 << "semhap render: a pattern name or file is required";
    QTest::newRow("render without duration")
        << QStringList{"render", "vib.geiger", "--rate", "1000"} << 2
        << "semhap render: --duration is required";
    QTest::newRow("render bad number")
        << QStringList{"render", "vib.geiger", "--duration", "x", "--rate", "10"} << 2
        << "semhap render: --duration expects a number, got 'x'";
    QTest::newRow("render intensity range")
        << QStringList{"render", "vib.geiger", "--duration",  "1",
                       "--rate", "10",         "--intensity", "2"}
        << 2 << "semhap render: --intensity must be within [0, 1]";
    QTest::newRow("render unknown pattern")
        << QStringList{"render", "vib.geigr", "--duration", "1", "--rate", "10"} << 1
        << "vib.geigr: no built-in pattern of that name (there are air.proportional, "
           "air.pulse5hz, air.squeeze, vib.geiger, vib.rampup, visual.blink, visual.confirm)";
    QTest::newRow("validate nothing")
        << QStringList{"validate"} << 2 << "semhap validate: no files given";
    QTest::newRow("validate scene without gripper")
        << QStringList{"validate", Data + "/no-gripper.xml"} << 1
        << Data + "/no-gripper.xml: no gripper (a body left.gripper or right.gripper; see "
                  "sim/README.md)";
    QTest::newRow("validate broken scene")
        << QStringList{"validate", Data + "/broken-scene.xml"} << 1
        << Data + "/broken-scene.xml:4:1: Premature end of document.";
    QTest::newRow("validate a scene with a tag unclosed")
        << QStringList{"validate", Data + "/unclosed-scene.xml"} << 1
        << Data + "/unclosed-scene.xml:4:15: Opening and ending tag mismatch.";
    QTest::newRow("validate a scene stepping by 0.5 s")
        << QStringList{"validate", Data + "/slow-scene.xml"} << 1
        << Data + "/slow-scene.xml:2: timestep 0.5 s is outside 1e-05 to 0.05 s";
    QTest::newRow("validate broken pattern")
        << QStringList{"validate", Data + "/broken-pattern.json"} << 1
        << Data + "/broken-pattern.json: /tracks: pattern 'broken' drives channel 'm5', which "
                  "model lra4 does not have (channels: m1, m2, m3, m4)";
    QTest::newRow("bandsim without model")
        << QStringList{"bandsim", "--pty"} << 2
        << "semhap bandsim: MODEL is required (lra4, pneumatic6)";
    QTest::newRow("bandsim of a model without a board")
        << QStringList{"bandsim", "fingertips2", "--pty"} << 2
        << "semhap bandsim: no reference board 'fingertips2' (boards: lra4, pneumatic6)";
    QTest::newRow("bandsim without --pty")
        << QStringList{"bandsim", "lra4"} << 2
        << "semhap bandsim: --pty is required (the simulated band's only link for now)";
    QTest::newRow("bandsim of a missing image")
        << QStringList{"bandsim", "lra4", "--pty", "--firmware", "/nonexistent/lra4.hex"} << 1
        << "/nonexistent/lra4.hex: cannot read: No such file or directory";
    QTest::newRow("bandsim of a damaged image")
        << QStringList{"bandsim", "lra4", "--pty", "--firmware", Data + "/broken-image.hex"} << 1
        << Data + "/broken-image.hex:2:1: checksum mismatch";
    QTest::newRow("bandsim of an image with a stray character")
        << QStringList{"bandsim", "lra4", "--pty", "--firmware", Data + "/badchar-image.hex"} << 1
        << Data + "/badchar-image.hex:2:12: not a hexadecimal digit";
    QTest::newRow("bandsim of a truncated image")
        << QStringList{"bandsim", "lra4", "--pty", "--firmware", Data + "/truncated-image.hex"}
        << 1 << Data + "/truncated-image.hex: no end-of-file record (a truncated image?)";
    QTest::newRow("play for more than an hour")
        << QStringList{"play", "vib.geiger", "--device", "virtual:x", "--duration", "4000"} << 2
        << "semhap play: --duration must be within [0, 3600]";
    QTest::newRow("probe of a malformed URI") << QStringList{"devices", "--probe", "bogus:x"} << 2
                                              << "semhap devices: bogus:x: unknown device scheme "
                                                 "'bogus' (virtual, serial, hid, udp, tcp, audio)";
    QTest::newRow("probe of a virtual band")
        << QStringList{"devices", "--probe", "virtual:x"} << 1
        << "virtual:x: no band on a link there to answer (a virtual band or a sound output)";
}

void TestCli::errors()
{
    QFETCH(QStringList, args);
    QFETCH(int, code);
    QFETCH(QString, firstLine);
    const Result r = semhapRun(args);
    QCOMPARE(r.code, code);
    QCOMPARE(QString::fromUtf8(r.err.split('\n').first()), firstLine);
}

void TestCli::help()
{
    const Result top = semhapRun({"--help"});
    QCOMPARE(top.code, 0);
    for (const char *command : {"route", "render", "validate"})
        QVERIFY(top.out.contains(command));
    for (const char *command : {"route", "render", "validate"}) {
        const Result r = semhapRun({command, "--help"});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains(QByteArray(QByteArray("Usage: semhap ") + command)),
                 r.out.constData());
        QVERIFY(r.err.isEmpty());
    }
}

void TestCli::rejectedLinesAreReportedNotFatal()
{
    const QString frames = Data + "/bad-lines.jsonl";
    const Result r = semhapRun({"route", "--router", "C3", "--frames", frames, "--events", "-"});
    QCOMPARE(r.code, 0);
    const QList<QByteArray> err = r.err.trimmed().split('\n');
    QCOMPARE(err.size(), 3);
    QVERIFY(err[0].startsWith(QByteArray(frames.toUtf8() + ":2: ")));
    QVERIFY(err[1].startsWith(QByteArray(frames.toUtf8() + ":3: ")));
    QCOMPARE(err[2], frames.toUtf8() + ": 2 line(s) rejected");
    // grasp begins at 0, ends at 0.3 (F = 10): the rejected lines changed nothing.
    QCOMPARE(r.out.count('\n'), 2);
}

void TestCli::renderGeigerPulses()
{
    const Result r = semhapRun({"render", "vib.geiger", "--intensity", "0.5", "--duration", "3",
                                "--rate", "1000", "--out", "-"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.err.isEmpty());
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.first(), QByteArray("t,m1,m2,m3,m4"));
    QCOMPARE(lines.size(), 3001);
    int pulses = 0;
    int high = 0;
    bool previous = false;
    for (int k = 1; k < lines.size(); ++k) {
        const QStringList row = QString::fromUtf8(lines[k]).split(',');
        QCOMPARE(row[0].toDouble(), (k - 1) / 1000.0);
        QCOMPARE(row[1], row[4]); // all four motors together
        const bool on = row[1].toDouble() > 0.5;
        pulses += on && !previous;
        high += on;
        previous = on;
    }
    QCOMPARE(pulses, 33);    // 2 + 18 · 0.5 = 11 Hz for 3 s
    QCOMPARE(high, 33 * 25); // 25 ms each
}

void TestCli::renderReleaseRamp()
{
    const Result r = semhapRun(
        {"render", "air.squeeze", "--release-at", "0.5", "--duration", "1.2", "--rate", "10"});
    QCOMPARE(r.code, 0);
    const double expected[] = {0, 0.2, 0.4, 0.6, 0.8, 1.0, 0.8, 0.6, 0.4, 0.2, 0, 0};
    QCOMPARE(csvRow(r.out, 0).size(), 7);
    for (int k = 0; k < 12; ++k) {
        const QStringList row = csvRow(r.out, k + 1);
        QVERIFY2(std::abs(row[1].toDouble() - expected[k]) < 1e-9,
                 qPrintable(QString("t=%1: %2").arg(row[0], row[1])));
    }
}

void TestCli::renderToFile()
{
    const QString path = QDir::temp().filePath("semhap-tst-cli-render.csv");
    const Result r =
        semhapRun({"render", "air.pulse5hz", "--duration", "0.4", "--rate", "20", "--out", path});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.isEmpty());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray csv = file.readAll();
    file.remove();
    QCOMPARE(csvRow(csv, 0).join(','), QString("t,b1,b2,b3,b4,b5,b6"));
    // 5 Hz, 50 % duty, high first: 2 samples high, 2 low at 20 Hz.
    QStringList column;
    for (int k = 1; k <= 8; ++k)
        column.append(csvRow(csv, k)[1]);
    QCOMPARE(column, (QStringList{"1", "1", "0", "0", "1", "1", "0", "0"}));
}

void TestCli::validate()
{
    QStringList files;
    for (const char *dir : {"routers", "patterns", "devices", "scenes", "studies"}) {
        const QDir d(QString(SEMHAP_RESOURCES "/") + dir);
        for (const QString &f : d.entryList({"*.json", "*.xml"}))
            files.append(d.filePath(f));
    }
    const Result ok = semhapRun(QStringList{"validate"} + files);
    QCOMPARE(ok.code, 0);
    QCOMPARE(ok.out.count('\n'), files.size());
    // The one warning: usb plays one squeeze for two messages (docs/presets.md).
    QCOMPARE(QString::fromUtf8(ok.err),
             QString(SEMHAP_RESOURCES "/routers/usb.json: warning: on right.air, "
                     "right.force:grasp and right.aligned:plug.aligned feel 0.00 JND apart: a "
                     "person will confuse them (semhap distinct)\n"));
    // A factorial protocol says its design.
    QVERIFY2(ok.out.contains("comparison.json: valid study protocol 'Semantic haptics comparison "
                             "(grasp x break modality)' (4 conditions: 2 grasp × 2 break; 4 "
                             "orders, participants take them in turn)"),
             ok.out.constData());

    const Result bad = semhapRun(
        {"validate", files.first(), Data + "/broken-router.json", Data + "/syntax-error.json"});
    QCOMPARE(bad.code, 1);
    QCOMPARE(bad.out.count('\n'), 1);
    QCOMPARE(bad.err.count('\n'), 2); // one line per broken file

    // A scene with another gripper: valid, with what will not work well as warnings.
    const QString linkage =
        QStringLiteral(SEMHAP_RESOURCES "/../tests/grippers/linkage/linkage.json");
    const Result adapted =
        semhapRun({"validate", "--gripper", linkage,
                   QStringLiteral(SEMHAP_RESOURCES "/scenes/box_and_block.xml")});
    QCOMPARE(adapted.code, 0);
    QCOMPARE(adapted.out.count('\n'), 1);
    QVERIFY2(adapted.err.contains("box_and_block.xml: warning: gripper 'right': a full grasp "
                                  "touches only 2 pad geoms"),
             adapted.err.constData());

    // An old spelling is valid, with a located warning.
    const Result old = semhapRun({"validate", Data + "/old-spelling-router.json"});
    QCOMPARE(old.code, 0);
    QCOMPARE(old.out.count('\n'), 1);
    QVERIFY2(old.err.contains("old-spelling-router.json: /nodes/1/type: deprecated: node type "
                              "\"hysteresis\" is now \"debounce\""),
             old.err.constData());
}

void TestCli::devicesListsEveryTransport()
{
    // Each registered scheme: its syntax at the start of a line, its help from column 27 on
    // (on the next line for a syntax wider than its column), every line within 80 columns.
    const Result r = semhapRun({"devices"});
    QCOMPARE(r.code, 0);
    const QString out = QString::fromUtf8(r.out);
    QVERIFY(out.contains(QStringLiteral("Present:")));
    const QStringList lines = out.section(QStringLiteral("\n\n"), 0, 0).split(QLatin1Char('\n'));
    for (const QString &line : lines)
        QVERIFY2(line.size() <= 80, qPrintable(line));
    for (const TransportScheme &scheme : TransportScheme::all()) {
        const QString syntax = QStringLiteral("  ") + QString::fromUtf8(scheme.syntax);
        const auto at = std::find_if(lines.begin(), lines.end(), [&](const QString &line) {
            return line == syntax || line.startsWith(syntax + QLatin1Char(' '));
        });
        QVERIFY2(at != lines.end(), scheme.syntax);
        const QString help = *at == syntax ? *(at + 1) : *at;
        const QString firstWord = QString::fromUtf8(scheme.help).section(QLatin1Char(' '), 0, 0);
        QCOMPARE(help.mid(27).section(QLatin1Char(' '), 0, 0), firstWord);
        QCOMPARE(help.left(27).trimmed(), (*at == syntax ? QString() : syntax.trimmed()));
    }
}

void TestCli::probeAsksTheBand()
{
    EmulatedBand band("lra4");
    QString error;
    QVERIFY2(band.start(&error), qPrintable(error));
    const Result r = semhapRun({"devices", "--probe", band.uri()});
    QCOMPARE(r.code, 0);
    // The probe's own two requests are all the band has received.
    QCOMPARE(QString::fromUtf8(r.out), band.uri() + ": lra4, firmware 1.0.0, channels:\n"
                                                    "  m1        0 … 1\n"
                                                    "  m2        0 … 1\n"
                                                    "  m3        0 … 1\n"
                                                    "  m4        0 … 1\n"
                                                    "status: 2 frames received, 0 dropped, 0 "
                                                    "garbled; flags: none\n");
}

void TestCli::realBinaryReadsStdin()
{
    QProcess semhap;
    semhap.start(SEMHAP_CLI_BINARY, {"route", "--router", "C3", "--frames", "-", "--events", "-"});
    QVERIFY(semhap.waitForStarted());
    QFile trace(Trace);
    QVERIFY(trace.open(QIODevice::ReadOnly));
    semhap.write(trace.readAll());
    semhap.closeWriteChannel();
    QVERIFY(semhap.waitForFinished(30000));
    QCOMPARE(semhap.exitCode(), 0);
    QCOMPARE(semhap.readAllStandardError(), QByteArray());
    QCOMPARE(semhap.readAllStandardOutput().count('\n'), 170); // reference_events.py's count
}

void TestCli::aKilledCompareResumes()
{
    // A grid's runs go to CSV.partial as they end. Killed after two of eight, the compare
    // resumed keeps those, does the other six, and gives the CSV one call gives.
    QTemporaryDir dir;
    const QString csv = dir.filePath("grid.csv");
    const QString journal = csv + ".partial";
    const QStringList grid{
        "compare", "--scene", "box_and_block", "--routers", "none,C3", "--operator", "scripted",
        "--seeds", "4",       "--duration",    "3",         "--jobs",  "1"};
    QProcess killed;
    killed.start(SEMHAP_CLI_BINARY, grid + QStringList{"--csv", csv});
    QVERIFY(killed.waitForStarted());
    const auto lines = [&] {
        QFile file(journal);
        return file.open(QIODevice::ReadOnly) ? int(file.readAll().count('\n')) : 0;
    };
    QTRY_VERIFY_WITH_TIMEOUT(lines() >= 3 || killed.state() != QProcess::Running, 120000);
    QCOMPARE(killed.state(), QProcess::Running);
    QVERIFY(killed.processId() > 0); // never kill(0): that is this test's own group
    ::kill(pid_t(killed.processId()), SIGKILL);
    QVERIFY(killed.waitForFinished());
    QVERIFY(!QFileInfo::exists(csv));
    const int finished = lines() - 1;
    QVERIFY(finished >= 2 && finished < 8);

    // Not resumed, the journal is kept and the call refused.
    Result r = semhapRun(grid + QStringList{"--csv", csv});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("grid.csv.partial: is left from a compare that did not finish: "
                            "--resume keeps its runs, or remove it"),
             r.err.constData());
    r = semhapRun(grid + QStringList{"--csv", csv, "--resume"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(!QFileInfo::exists(journal));
    QFile sidecar(csv + ".provenance.json");
    QVERIFY(sidecar.open(QIODevice::ReadOnly));
    const QJsonObject provenance = QJsonDocument::fromJson(sidecar.readAll()).object();
    QCOMPARE(provenance.value("resumed").toInt(), finished);
    QCOMPARE(provenance.value("runs").toInt(), 8);
    for (const char *key : {"semhap", "command", "host", "started", "ended", "shard", "grid"})
        QVERIFY2(provenance.contains(key), key);

    // The same rows as one call's, in the grid's order, but for the wall-clock columns.
    r = semhapRun(grid + QStringList{"--csv", dir.filePath("whole.csv")});
    QVERIFY2(r.code == 0, r.err.constData());
    const auto runs = [](const QString &path) {
        QFile file(path);
        file.open(QIODevice::ReadOnly);
        QStringList rows;
        for (const QByteArray &line : file.readAll().trimmed().split('\n'))
            rows.append(QString::fromUtf8(line).section(',', 0, -3));
        return rows;
    };
    QCOMPARE(runs(csv).size(), 9);
    QCOMPARE(runs(csv), runs(dir.filePath("whole.csv")));

    // Resumed with another grid (longer runs), its rows are not this grid's.
    QStringList longer = grid;
    longer[longer.indexOf("--duration") + 1] = "4";
    r = semhapRun(longer + QStringList{"--csv", csv, "--resume"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("grid.csv: has a run of another grid (box_and_block,none,scripted,"
                            "1,3); resume with the grid it was made by"),
             r.err.constData());
}

void TestCli::shards_data()
{
    // --shard's text, the SLURM_ARRAY_TASK_* values (ID MIN MAX STEP COUNT, "" for none),
    // and the slice or the start of the error.
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("array");
    QTest::addColumn<QString>("slice");
    QTest::addColumn<QString>("error");
    QTest::newRow("I/N") << "3/10"
                         << ""
                         << "3/10"
                         << "";
    QTest::newRow("one of one") << "1/1"
                                << ""
                                << "1/1"
                                << "";
    QTest::newRow("I above N") << "4/3"
                               << ""
                               << ""
                               << "--shard expects I/N";
    QTest::newRow("I zero") << "0/3"
                            << ""
                            << ""
                            << "--shard expects I/N";
    QTest::newRow("not a slice") << "half"
                                 << ""
                                 << ""
                                 << "--shard expects I/N";
    QTest::newRow("first of 1-20") << "auto"
                                   << "1 1 20 1 20"
                                   << "1/20"
                                   << "";
    QTest::newRow("last of 0-19") << "auto"
                                  << "19 0 19 1 20"
                                  << "20/20"
                                  << "";
    QTest::newRow("stepped 1-39:2") << "auto"
                                    << "5 1 39 2 20"
                                    << "3/20"
                                    << "";
    QTest::newRow("a list without gaps") << "auto"
                                         << "7 7 9 1 3"
                                         << "1/3"
                                         << "";
    QTest::newRow("no array") << "auto"
                              << ""
                              << ""
                              << "--shard auto takes the slice from a Slurm job array";
    QTest::newRow("gaps 1,2,5") << "auto"
                                << "5 1 5 1 3"
                                << ""
                                << "--shard auto: the job array has gaps (3 tasks from 1 to 5 by "
                                   "steps of 1)";
    QTest::newRow("an index off the step") << "auto"
                                           << "2 1 5 2 3"
                                           << ""
                                           << "--shard auto: the job array has gaps";
    QTest::newRow("a task outside its array") << "auto"
                                              << "9 1 5 1 5"
                                              << ""
                                              << "--shard auto: the array's variables do not "
                                                 "describe one";
    QTest::newRow("a variable not a number") << "auto"
                                             << "1 1 x 1 3"
                                             << ""
                                             << "--shard auto: SLURM_ARRAY_TASK_MAX is 'x', not "
                                                "a whole number";
}

void TestCli::shards()
{
    QFETCH(QString, text);
    QFETCH(QString, array);
    QFETCH(QString, slice);
    QFETCH(QString, error);
    QProcessEnvironment environment;
    const QStringList values = array.split(' ', Qt::SkipEmptyParts);
    const char *const names[] = {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN",
                                 "SLURM_ARRAY_TASK_MAX", "SLURM_ARRAY_TASK_STEP",
                                 "SLURM_ARRAY_TASK_COUNT"};
    for (int i = 0; i < values.size(); ++i)
        environment.insert(names[i], values[i]);
    QString reason;
    const std::optional<semhap::Shard> shard = semhap::Shard::parse(text, environment, &reason);
    QCOMPARE(shard ? shard->text() : QString(), slice);
    QCOMPARE(reason.left(error.size()), error);
    QCOMPARE(reason.isEmpty(), error.isEmpty());
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
