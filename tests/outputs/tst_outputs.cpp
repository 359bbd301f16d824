// SPDX-License-Identifier: MIT
// Nothing lost: the real `semhap` binary refuses an output that is one of its inputs or its
// session, reports every write error (a full disk, a file-size limit, a FIFO nobody reads)
// with exit 1 and leaves the old file whole, writes through symbolic links and into devices
// without replacing them, refuses inputs that are no regular files, and creates a session
// under a temporary name so a recording killed at once leaves nothing that will not open.
#include "sessionreader.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <sys/stat.h>
#include <unistd.h>

using namespace semhap;

namespace {

const QString Trace = QStringLiteral(SEMHAP_RESOURCES "/traces/demo.jsonl");

struct Result
{
    int code = -1;
    QByteArray out;
    QByteArray err;
};

/** How a run is started: what standard output is, and the limits it runs under. */
struct Launch
{
    QString stdoutFile;           ///< standard output goes here (e.g. /dev/full); empty: captured
    qint64 fileSizeLimit = 0;     ///< RLIMIT_FSIZE in bytes (prlimit); 0: none
    bool withoutOverride = false; ///< as root, without the right to ignore file permissions
};

Result runSemhap(const QStringList &arguments, const Launch &launch = {})
{
    QString program = QStringLiteral(SEMHAP_CLI_BINARY);
    QStringList args = arguments;
    if (launch.fileSizeLimit > 0) {
        args =
            QStringList{"--fsize=" + QString::number(launch.fileSizeLimit), "--", program} + args;
        program = "prlimit";
    }
    if (launch.withoutOverride) {
        // Root still, so the build tree stays readable wherever it is, but bound by the
        // files' permissions like any user.
        args = QStringList{"--bounding-set=-dac_override,-dac_read_search", "--", program} + args;
        program = "setpriv";
    }
    QProcess process;
    if (!launch.stdoutFile.isEmpty())
        process.setStandardOutputFile(launch.stdoutFile);
    process.start(program, args);
    Result r;
    if (!process.waitForStarted() || !process.waitForFinished(60000)) {
        process.kill();
        process.waitForFinished();
        r.err = "did not finish: " + program.toUtf8() + ' ' + args.join(' ').toUtf8();
        return r;
    }
    r.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    r.out = process.readAllStandardOutput();
    r.err = process.readAllStandardError();
    return r;
}

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("(missing)");
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

/** The folder's entries, hidden ones (temporaries) included. */
QStringList entries(const QString &folder)
{
    return QDir(folder).entryList(
        QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

bool isCharDevice(const QString &path)
{
    struct stat info = {};
    return ::stat(QFile::encodeName(path).constData(), &info) == 0 && S_ISCHR(info.st_mode);
}

} // namespace

class TestOutputs : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void outputIsAnInput_data();
    void outputIsAnInput();
    void fullDisk_data();
    void fullDisk();
    void failedWriteKeepsTheOldFile();
    void fifoWithoutReader();
    void fifoWithReader();
    void symlinkKeptTargetReplaced();
    void devicesAreNeverReplaced();
    void outputsMayShareACharacterDevice();
    void inputsMustBeFiles_data();
    void inputsMustBeFiles();
    void sessionKilledAtOnceLeavesNothingBroken();
    void interruptedRouteKeepsItsOutput();
    void readOnlySessionReplays();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
    QString m_session;
    QString m_frames;
    QString m_ahap;
};

void TestOutputs::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_session = path("recorded.db");
    const Result run =
        runSemhap({"run", "--scene", "box_and_block", "--router", "C3", "--operator", "scripted",
                   "--duration", "2", "--session", m_session});
    QVERIFY2(run.code == 0, run.err.constData());
    m_frames = path("frames.jsonl");
    QVERIFY(QFile::copy(Trace, m_frames));
    m_ahap = path("pulse.ahap");
    const Result convert =
        runSemhap({"convert", SEMHAP_RESOURCES "/patterns/vib.geiger.json", m_ahap});
    QVERIFY2(convert.code == 0, convert.err.constData());
}

void TestOutputs::outputIsAnInput_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("kept"); ///< the file that must come through unchanged
    QTest::addColumn<QString>("message");

    const QString frames = path("frames.jsonl");
    const QString session = path("recorded.db");
    const QString ahap = path("pulse.ahap");
    QTest::newRow("route: events onto the frames")
        << QStringList{"route", "--router", "C3", "--frames", frames, "--events", frames} << frames
        << "cannot write: it is the same file as the input " + frames;
    QTest::newRow("route: the frames by another spelling")
        << QStringList{"route",
                       "--router",
                       "C3",
                       "--frames",
                       frames,
                       "--device-frames",
                       path("./sub/../frames.jsonl")}
        << frames << "it is the same file as the input";
    QTest::newRow("route: two outputs on one file")
        << QStringList{"route",
                       "--router",
                       "C3",
                       "--frames",
                       frames,
                       "--events",
                       path("out.jsonl"),
                       "--device-frames",
                       path("out.jsonl")}
        << frames << "it is the same file as the output " + path("out.jsonl");
    QTest::newRow("replay: events onto the session")
        << QStringList{"replay", session, "--events", session} << session
        << "it is the same file as the input " + session;
    QTest::newRow("run: events onto an existing session")
        << QStringList{"run",        "--scene",  "box_and_block", "--router", "C3",
                       "--operator", "scripted", "--duration",    "1",        "--session",
                       session,      "--events", session}
        << session << "it is the same file as the session " + session;
    QTest::newRow("convert: onto itself")
        << QStringList{"convert", ahap, ahap} << ahap << "it is the same file as the input";
    QTest::newRow("render: onto its pattern")
        << QStringList{"render", path("mine.json"), "--duration",     "1", "--rate",
                       "100",    "--out",           path("mine.json")}
        << path("mine.json") << "it is the same file as the input";
    QTest::newRow("emulate: the live log onto its model")
        << QStringList{"emulate",     "--model", path("model.json"), "--udp",
                       "127.0.0.1:0", "--log",   path("model.json")}
        << path("model.json") << "it is the same file as the input";
    QTest::newRow("bandsim: the live log onto its image")
        << QStringList{"bandsim",          "lra4",  "--pty",           "--firmware",
                       path("model.json"), "--log", path("model.json")}
        << path("model.json") << "it is the same file as the input";
}

void TestOutputs::outputIsAnInput()
{
    QFETCH(QStringList, args);
    QFETCH(QString, kept);
    QFETCH(QString, message);
    QDir().mkpath(path("sub"));
    QFile::remove(path("mine.json"));
    QVERIFY(QFile::copy(SEMHAP_RESOURCES "/patterns/vib.geiger.json", path("mine.json")));
    QFile::remove(path("model.json"));
    QVERIFY(QFile::copy(SEMHAP_RESOURCES "/devices/lra4.json", path("model.json")));
    const QByteArray before = contents(kept);
    const Result r = runSemhap(args);
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(message.toUtf8()) && r.err.contains("nothing was written"),
             r.err.constData());
    QCOMPARE(contents(kept), before);
    QVERIFY(!QFileInfo::exists(path("out.jsonl")));
}

void TestOutputs::fullDisk_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("stdoutFile");
    QTest::addColumn<QString>("message");
    QTest::addColumn<qint64>("limit"); ///< a file-size limit in bytes, 0: none

    const QString full = "/dev/full";
    const QString nospace = "cannot write: No space left on device";
    const QStringList run{"run",        "--scene",  "box_and_block", "--router", "C3",
                          "--operator", "scripted", "--duration",    "1"};
    QTest::newRow("route --events")
        << QStringList{"route", "--router", "C3", "--frames", Trace, "--events", full} << ""
        << full + ": " + nospace << qint64(0);
    QTest::newRow("route to standard output")
        << QStringList{"route", "--router", "C3", "--frames", Trace, "--events", "-"} << full
        << "standard output: " + nospace << qint64(0);
    QTest::newRow("replay --device-frames")
        << QStringList{"replay", path("recorded.db"), "--device-frames", full} << ""
        << full + ": " + nospace << qint64(0);
    QTest::newRow("replay --metrics")
        << QStringList{"replay", path("recorded.db"), "--metrics", full} << ""
        << full + ": " + nospace << qint64(0);
    QTest::newRow("render --out") << QStringList{"render", "vib.geiger", "--duration", "1",
                                                 "--rate", "1000",       "--out",      full}
                                  << "" << full + ": " + nospace << qint64(0);
    QTest::newRow("render to standard output")
        << QStringList{"render", "vib.geiger", "--duration", "1", "--rate", "1000"} << full
        << "standard output: " + nospace << qint64(0);
    QTest::newRow("run --metrics")
        << run + QStringList{"--metrics", full} << "" << full + ": " + nospace << qint64(0);
    QTest::newRow("run --frames") << run + QStringList{"--frames", full} << ""
                                  << full + ": " + nospace << qint64(0);
    QTest::newRow("run --metrics -") << run + QStringList{"--metrics", "-"} << full
                                     << "standard output: " + nospace << qint64(0);
    QTest::newRow("export --csv") << QStringList{"export", path("recorded.db"), "--csv",
                                                 path("csv")}
                                  << ""
                                  << "File too large" << qint64(40000);
    QTest::newRow("export --jsonl")
        << QStringList{"export", path("recorded.db"), "--jsonl", path("jsonl")} << ""
        << "File too large" << qint64(40000);
    QTest::newRow("export --xdf") << QStringList{"export", path("recorded.db"), "--xdf", full}
                                  << "" << full + ": " + nospace << qint64(0);
    QTest::newRow("export --xdf, too large")
        << QStringList{"export", path("recorded.db"), "--xdf", path("big.xdf")} << ""
        << path("big.xdf") + ": cannot write: File too large" << qint64(40000);
    QTest::newRow("convert") << QStringList{"convert",
                                            SEMHAP_RESOURCES "/patterns/vib.geiger.json",
                                            path("big.ahap")}
                             << "" << path("big.ahap") + ": cannot write: File too large"
                             << qint64(2000);
    QTest::newRow("emulate --log")
        << QStringList{"emulate", "--model", "lra4", "--pty", "--log", full} << ""
        << full + ": " + nospace << qint64(0);
    QTest::newRow("bandsim --log") << QStringList{"bandsim", "pneumatic6", "--pty", "--log", full}
                                   << "" << full + ": " + nospace << qint64(0);
    QTest::newRow("compare --csv") << QStringList{"compare",    "--scene", "box_and_block",
                                                  "--routers",  "none",    "--operator",
                                                  "scripted",   "--seeds", "1",
                                                  "--duration", "1",       "--csv",
                                                  full}
                                   << "" << full + ": " + nospace << qint64(0);
}

void TestOutputs::fullDisk()
{
    // /dev/full for the outputs written directly; a file-size limit for the regular files
    // written through a temporary (a full disk, as far as the writer can tell), above the
    // 32 KiB index SQLite keeps beside a session it reads.
    QFETCH(QStringList, args);
    QFETCH(QString, stdoutFile);
    QFETCH(QString, message);
    QFETCH(qint64, limit);
    Launch launch;
    launch.stdoutFile = stdoutFile;
    launch.fileSizeLimit = limit;
    const Result r = runSemhap(args, launch);
    QVERIFY2(r.code == 1 && r.err.contains(message.toUtf8()),
             qPrintable(QString("exit %1: %2").arg(r.code).arg(QString::fromUtf8(r.err))));
    // Every line says where and why: no empty messages.
    for (const QByteArray &line : r.err.trimmed().split('\n'))
        QVERIFY2(line.contains(": "), r.err.constData());
    // Nothing of the command's own is left beside a device (a compare's journal, its sidecar).
    for (const char *left : {"/dev/full.partial", "/dev/full.provenance.json"})
        QVERIFY2(!QFileInfo::exists(left), left);
}

void TestOutputs::failedWriteKeepsTheOldFile()
{
    const QString events = path("kept-events.jsonl");
    QVERIFY(writeFile(events, "the old events\n"));
    Launch limited;
    limited.fileSizeLimit = 1000;
    const Result r =
        runSemhap({"route", "--router", "C3", "--frames", Trace, "--events", events}, limited);
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains((events + ": cannot write: File too large").toUtf8()),
             r.err.constData());
    QCOMPARE(contents(events), QByteArray("the old events\n"));
    // No temporary is left behind.
    QVERIFY2(!entries(m_dir.path()).join(' ').contains("kept-events.jsonl."),
             qPrintable(entries(m_dir.path()).join(' ')));
    // Without the limit the same command replaces it whole.
    const Result ok =
        runSemhap({"route", "--router", "C3", "--frames", Trace, "--events", events});
    QCOMPARE(ok.code, 0);
    QVERIFY(contents(events).startsWith("{\"t\":"));
}

void TestOutputs::fifoWithoutReader()
{
    const QString fifo = path("nobody-reads");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    QElapsedTimer clock;
    clock.start();
    const Result r = runSemhap({"route", "--router", "C3", "--frames", Trace, "--events", fifo});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains((fifo + ": cannot write: no process reads the FIFO").toUtf8()),
             r.err.constData());
    QVERIFY(clock.elapsed() < 20000);
}

void TestOutputs::fifoWithReader()
{
    const QString fifo = path("read");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    QProcess reader;
    reader.start("cat", {fifo});
    QVERIFY(reader.waitForStarted());
    // cat opens the FIFO when it starts reading; give it the moment it needs.
    Result r;
    for (int attempt = 0; attempt < 50; ++attempt) {
        r = runSemhap({"route", "--router", "C3", "--frames", Trace, "--events", fifo});
        if (r.code == 0)
            break;
        QThread::msleep(100);
    }
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(reader.waitForFinished(10000));
    const QByteArray events = reader.readAllStandardOutput();
    QVERIFY(events.startsWith("{\"t\":"));
    QFileInfo info(fifo);
    QVERIFY(info.exists() && !info.isFile()); // still the FIFO
}

void TestOutputs::symlinkKeptTargetReplaced()
{
    QDir().mkpath(path("elsewhere"));
    const QString target = path("elsewhere/target.jsonl");
    QVERIFY(writeFile(target, "old\n"));
    const QString link = path("link.jsonl");
    QVERIFY(QFile::link(target, link));
    const Result r = runSemhap({"route", "--router", "C3", "--frames", Trace, "--events", link});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(QFileInfo(link).isSymLink());
    QCOMPARE(QFileInfo(link).symLinkTarget(), target);
    QVERIFY(contents(target).startsWith("{\"t\":"));
    QCOMPARE(entries(path("elsewhere")), QStringList{"target.jsonl"});
}

void TestOutputs::devicesAreNeverReplaced()
{
    // QSaveFile, run as root, renamed its temporary over /dev/full; /dev/null is the
    // harmless place to prove no device is replaced.
    const Result r =
        runSemhap({"route", "--router", "C3", "--frames", Trace, "--events", "/dev/null"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(isCharDevice("/dev/null"));
    const Result convert =
        runSemhap({"convert", SEMHAP_RESOURCES "/patterns/vib.geiger.json", "/dev/null"});
    QVERIFY(convert.code != 0 || isCharDevice("/dev/null"));
    QVERIFY(isCharDevice("/dev/null"));
}

void TestOutputs::outputsMayShareACharacterDevice()
{
    // How people discard what they don't need: /dev/null keeps nothing to lose.
    const Result r = runSemhap({"route", "--router", "C3", "--frames", Trace, "--events",
                                "/dev/null", "--device-frames", "/dev/null"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(isCharDevice("/dev/null"));
    // A regular file stays one output's only.
    const Result twice = runSemhap({"route", "--router", "C3", "--frames", Trace, "--events",
                                    path("twice.jsonl"), "--device-frames", path("twice.jsonl")});
    QCOMPARE(twice.code, 1);
    QVERIFY(twice.err.contains("it is the same file as the output"));
}

void TestOutputs::inputsMustBeFiles_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("router from /dev/zero")
        << QStringList{"route", "--router", "/dev/zero", "--frames", Trace}
        << "/dev/zero: cannot read: a device, not a regular file";
    QTest::newRow("frames from /dev/zero")
        << QStringList{"route", "--router", "C3", "--frames", "/dev/zero"}
        << "/dev/zero: cannot read: a device, not a regular file or a pipe";
    QTest::newRow("pattern from /dev/zero")
        << QStringList{"render", "/dev/zero", "--duration", "1", "--rate", "10"}
        << "/dev/zero: cannot read: a device, not a regular file";
    QTest::newRow("AHAP linked to /dev/zero")
        << QStringList{"convert", path("zero.ahap"), path("out.json")}
        << "zero.ahap: cannot read: a device, not a regular file";
    QTest::newRow("a folder as the router")
        << QStringList{"route", "--router", path("sub/"), "--frames", Trace}
        << "cannot read: a folder, not a regular file";
    QTest::newRow("a huge pattern")
        << QStringList{"render", path("huge.json"), "--duration", "1", "--rate", "10"}
        << "more than the 64 MiB a document may have";
    QTest::newRow("a scene from a FIFO")
        << QStringList{"run",        "--scene",  path("scene-fifo.xml"), "--router", "C3",
                       "--operator", "scripted", "--duration",           "1"}
        << "cannot read: a FIFO, not a regular file";
}

void TestOutputs::inputsMustBeFiles()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    QDir().mkpath(path("sub"));
    {
        QFile huge(path("huge.json"));
        QVERIFY(huge.open(QIODevice::WriteOnly));
        QVERIFY(huge.resize(65 * 1024 * 1024)); // sparse: no disk used
    }
    if (!QFileInfo(path("zero.ahap")).isSymLink())
        QVERIFY(QFile::link("/dev/zero", path("zero.ahap")));
    if (!QFileInfo::exists(path("scene-fifo.xml")))
        QVERIFY(::mkfifo(QFile::encodeName(path("scene-fifo.xml")).constData(), 0600) == 0);
    QElapsedTimer clock;
    clock.start();
    const Result r = runSemhap(args);
    QVERIFY2(clock.elapsed() < 30000, "it must not read without end");
    QVERIFY2(r.code == 1 && r.err.contains(message.toUtf8()), r.err.constData());
}

void TestOutputs::sessionKilledAtOnceLeavesNothingBroken()
{
    // Killed within its first milliseconds, a recording used to leave a file that neither
    // opened nor could be created again. Now the name appears only with the schema in.
    for (int delay : {0, 5, 10, 20, 40, 80}) {
        const QString session = path(QString("killed-%1.db").arg(delay));
        QProcess run;
        run.start(SEMHAP_CLI_BINARY,
                  {"run", "--scene", "box_and_block", "--router", "C3", "--operator", "scripted",
                   "--duration", "30", "--realtime", "--session", session});
        QVERIFY(run.waitForStarted());
        QThread::msleep(quint64(delay));
        run.kill();
        QVERIFY(run.waitForFinished(5000));
        if (QFileInfo::exists(session)) {
            QString error;
            QVERIFY2(SessionReader::open(session, &error), qPrintable(error));
        } else {
            const Result again =
                runSemhap({"run", "--scene", "box_and_block", "--router", "C3", "--operator",
                           "scripted", "--duration", "0.1", "--session", session});
            QVERIFY2(again.code == 0, again.err.constData());
        }
    }
}

void TestOutputs::interruptedRouteKeepsItsOutput()
{
    // A stream from a pipe may never end: a signal ends the run and hands the output over
    // (it is written through a temporary, so a kill would lose it).
    const QString events = path("interrupted.jsonl");
    QProcess route;
    route.start(SEMHAP_CLI_BINARY,
                {"route", "--router", "C3", "--frames", "-", "--events", events});
    QVERIFY(route.waitForStarted());
    QFile trace(Trace);
    QVERIFY(trace.open(QIODevice::ReadOnly));
    route.write(trace.readAll());
    // Once the whole trace is in the pipe, semhap has read and routed all but the pipe's
    // 64 KiB of its 420 KiB: events to hand over, however busy the machine.
    QTRY_VERIFY_WITH_TIMEOUT(route.bytesToWrite() == 0, 60000);
    route.terminate();         // SIGTERM, as a shell's Ctrl-C ends a whole pipeline
    route.closeWriteChannel(); // and the producer with it
    QVERIFY(route.waitForFinished(10000));
    QCOMPARE(route.exitStatus(), QProcess::NormalExit);
    QCOMPARE(route.exitCode(), 0);
    QVERIFY(contents(events).startsWith("{\"t\":"));
}

void TestOutputs::readOnlySessionReplays()
{
    // A session in a folder nobody may write: SQLite cannot put the write-ahead log's index
    // beside it, and the session used to be called damaged.
    const bool root = ::geteuid() == 0;
    // util-linux's setpriv drops root's right to ignore permissions.
    QVERIFY2(!root || !QStandardPaths::findExecutable("setpriv").isEmpty(), "no setpriv");
    const QString folder = path("readonly");
    QVERIFY(QDir().mkpath(folder));
    const QString session = folder + "/kept.db";
    QVERIFY(QFile::copy(m_session, session));
    const QString locked = folder + "/locked.db";
    QVERIFY(QFile::copy(m_session, locked));
    QVERIFY(::chmod(QFile::encodeName(locked).constData(), 0) == 0);
    QVERIFY(::chmod(QFile::encodeName(folder).constData(), 0555) == 0);
    QVERIFY(::chmod(QFile::encodeName(session).constData(), 0444) == 0);
    Launch launch;
    launch.withoutOverride = root;
    const Result r = runSemhap({"replay", session, "--metrics", "-"}, launch);
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("\"frames\""));
    // A file one may not read is said to be one.
    const Result denied = runSemhap({"replay", locked, "--metrics", "-"}, launch);
    QCOMPARE(denied.code, 1);
    QVERIFY2(denied.err.contains((locked + ": cannot read: Permission denied").toUtf8()),
             denied.err.constData());
    QVERIFY(::chmod(QFile::encodeName(folder).constData(), 0755) == 0);
}

QTEST_GUILESS_MAIN(TestOutputs)
#include "tst_outputs.moc"
