// SPDX-License-Identifier: MIT
#include "slurmcluster.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHostAddress>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QSysInfo>
#include <QTcpServer>
#include <QThread>

#include <unistd.h>

namespace {

const char *const Programs[] = {"munged",   "slurmctld", "slurmd", "sbatch",
                                "scontrol", "scancel",   "squeue"};

/** A program of Debian's munge or slurm-wlm: daemons live in sbin, off a user's PATH. */
QString program(const QString &name)
{
    const QString found = QStandardPaths::findExecutable(name);
    return found.isEmpty()
               ? QStandardPaths::findExecutable(name, {"/usr/sbin", "/usr/bin", "/sbin"})
               : found;
}

/** A TCP port free on loopback now (the daemons bind it a moment later). */
quint16 freePort()
{
    QTcpServer server;
    return server.listen(QHostAddress::Any, 0) ? server.serverPort() : 0;
}

/** A job's tasks end in one of these states (scontrol's JobState); the rest are on the way. */
bool ended(const QByteArray &state)
{
    for (const char *s : {"COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL",
                          "OUT_OF_MEMORY", "BOOT_FAIL", "DEADLINE", "PREEMPTED"}) {
        if (state == s)
            return true;
    }
    return false;
}

/** The value of `key=` in one line of `scontrol -o show job`. */
QByteArray field(const QByteArray &line, const char *key)
{
    const QByteArray prefix = QByteArray(key) + '=';
    for (const QByteArray &word : line.split(' ')) {
        if (word.startsWith(prefix))
            return word.mid(prefix.size());
    }
    return {};
}

QByteArray tail(const QString &path, int bytes)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    if (file.size() > bytes)
        file.seek(file.size() - bytes);
    return file.readAll();
}

// Bounds on waiting for things that happen in a second or two: only a broken set-up meets them.
constexpr int StartMs = 60'000;
constexpr int JobMs = 20 * 60'000;
constexpr int PollMs = 200;

} // namespace

QString SlurmCluster::unavailable()
{
    if (geteuid() != 0)
        return QStringLiteral("a one-node Slurm cluster runs its daemons as root, and this is "
                              "not root (CI runs as root)");
    for (const char *name : Programs) {
        if (program(QLatin1String(name)).isEmpty())
            return QStringLiteral("%1 is not installed (scripts/deps.sh installs munge and "
                                  "slurm-wlm)")
                .arg(QLatin1String(name));
    }
    return {};
}

SlurmCluster::~SlurmCluster()
{
    if (!m_jobs.isEmpty()) {
        // Cancelled, the jobs' tasks end before the daemons go: none outlives the cluster.
        QByteArray out;
        QString error;
        client(QStringLiteral("scancel"), m_jobs, &out, &error);
        QDeadlineTimer deadline(StartMs);
        while (!deadline.hasExpired() &&
               client(QStringLiteral("squeue"), {"--noheader", "--jobs", m_jobs.join(',')}, &out,
                      &error) &&
               !out.trimmed().isEmpty())
            QThread::msleep(PollMs);
    }
    // slurmd first, so that no job step outlives the daemons; munged last, as they need it.
    for (auto it = m_daemons.rbegin(); it != m_daemons.rend(); ++it) {
        (*it)->terminate();
        if (!(*it)->waitForFinished(15'000))
            (*it)->kill();
        (*it)->waitForFinished(5'000);
    }
}

bool SlurmCluster::startDaemon(const QString &program, const QStringList &args, QString *error)
{
    auto process = std::make_unique<QProcess>();
    process->setProcessEnvironment(m_environment);
    process->setProcessChannelMode(QProcess::MergedChannels);
    process->setStandardOutputFile(
        m_dir.filePath(QFileInfo(program).fileName() + QStringLiteral(".out")));
    process->start(program, args);
    if (!process->waitForStarted()) {
        *error = program + QStringLiteral(": ") + process->errorString();
        return false;
    }
    m_daemons.push_back(std::move(process));
    return true;
}

bool SlurmCluster::start(int cpus, QString *error)
{
    if (!m_dir.isValid()) {
        *error = QStringLiteral("no temporary folder: ") + m_dir.errorString();
        return false;
    }
    const auto path = [this](const char *name) { return m_dir.filePath(QLatin1String(name)); };
    for (const char *folder : {"state", "spool"})
        QDir().mkpath(path(folder));
    // munged's key: any secret, readable by its owner only (munged checks).
    {
        QFile key(path("munge.key"));
        QByteArray secret(1024, '\0');
        QRandomGenerator::system()->fillRange(reinterpret_cast<quint32 *>(secret.data()),
                                              secret.size() / 4);
        if (!key.open(QIODevice::WriteOnly) || key.write(secret) != secret.size() ||
            !key.setPermissions(QFile::ReadOwner | QFile::WriteOwner)) {
            *error = key.fileName() + QStringLiteral(": cannot write: ") + key.errorString();
            return false;
        }
    }
    const QString socket = path("munge.socket");
    // --force: the temporary folder's parents (/tmp) are not what munged calls secure.
    if (!startDaemon(program(QStringLiteral("munged")),
                     {"--foreground", "--force", "--socket=" + socket,
                      "--key-file=" + path("munge.key"), "--log-file=" + path("munged.log"),
                      "--pid-file=" + path("munged.pid"), "--seed-file=" + path("munged.seed")},
                     error))
        return false;
    QDeadlineTimer deadline(StartMs);
    while (!QFileInfo::exists(socket) && !deadline.hasExpired())
        QThread::msleep(PollMs / 4);
    if (!QFileInfo::exists(socket)) {
        *error = QStringLiteral("munged did not start:\n") + logs();
        return false;
    }

    // slurmctld knows itself as the controller by its short host name.
    const QString host = QSysInfo::machineHostName().section(QLatin1Char('.'), 0, 0);
    const quint16 controllerPort = freePort();
    quint16 nodePort = freePort();
    while (nodePort == controllerPort)
        nodePort = freePort();
    QFile conf(path("slurm.conf"));
    const QString text =
        QStringLiteral("ClusterName=semhap\n"
                       "SlurmctldHost=%1(127.0.0.1)\n"
                       "SlurmctldPort=%2\nSlurmdPort=%3\n"
                       "SlurmUser=root\nSlurmdUser=root\n"
                       "AuthType=auth/munge\nCredType=cred/munge\nAuthInfo=socket=%4\n"
                       "StateSaveLocation=%5/state\nSlurmdSpoolDir=%5/spool\n"
                       "SlurmctldPidFile=%5/slurmctld.pid\nSlurmdPidFile=%5/slurmd.pid\n"
                       "SlurmctldLogFile=%5/slurmctld.log\nSlurmdLogFile=%5/slurmd.log\n"
                       // No cgroups: a container's tasks are plain processes.
                       "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
                       "SelectType=select/cons_tres\nSelectTypeParameters=CR_Core\n"
                       "MpiDefault=none\nReturnToService=2\n"
                       "AccountingStorageType=accounting_storage/none\n"
                       "JobAcctGatherType=jobacct_gather/none\nJobCompType=jobcomp/none\n"
                       "NodeName=semhap NodeHostname=%1 NodeAddr=127.0.0.1 CPUs=%6 "
                       "State=UNKNOWN\n"
                       "PartitionName=semhap Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n")
            .arg(host)
            .arg(controllerPort)
            .arg(nodePort)
            .arg(socket, m_dir.path())
            .arg(cpus);
    if (!conf.open(QIODevice::WriteOnly) || conf.write(text.toUtf8()) < 0 || !conf.flush()) {
        *error = conf.fileName() + QStringLiteral(": cannot write: ") + conf.errorString();
        return false;
    }
    conf.close();
    m_environment = QProcessEnvironment::systemEnvironment();
    m_environment.insert(QStringLiteral("SLURM_CONF"), conf.fileName());
    if (!startDaemon(program(QStringLiteral("slurmctld")), {"-D"}, error) ||
        !startDaemon(program(QStringLiteral("slurmd")), {"-D", "-N", "semhap"}, error))
        return false;
    // The node is idle once slurmd has registered with the controller.
    QByteArray state;
    while (!deadline.hasExpired()) {
        QString ignored;
        if (client(QStringLiteral("scontrol"), {"-o", "show", "node", "semhap"}, &state,
                   &ignored) &&
            field(state.trimmed(), "State") == "IDLE")
            return true;
        QThread::msleep(PollMs);
    }
    *error = QStringLiteral("the node did not become idle (%1):\n")
                 .arg(QString::fromUtf8(field(state.trimmed(), "State"))) +
             logs();
    return false;
}

bool SlurmCluster::client(const QString &name, const QStringList &args, QByteArray *out,
                          QString *error) const
{
    QProcess process;
    process.setProcessEnvironment(m_environment);
    process.start(program(name), args);
    if (!process.waitForFinished(StartMs) || process.exitStatus() != QProcess::NormalExit ||
        process.exitCode() != 0) {
        *error = name + QLatin1Char(' ') + args.join(QLatin1Char(' ')) + QStringLiteral(": ") +
                 QString::fromUtf8(process.readAllStandardError()).trimmed();
        return false;
    }
    *out = process.readAllStandardOutput();
    return true;
}

bool SlurmCluster::runArray(const QString &array, const QStringList &options,
                            const QString &script, const QStringList &args, const QString &workDir,
                            QString *error)
{
    QByteArray out;
    if (!client(QStringLiteral("sbatch"),
                QStringList{"--parsable", "--array=" + array, "--chdir=" + workDir} + options +
                    QStringList{script} + args,
                &out, error))
        return false;
    const QString job = QString::fromUtf8(out.trimmed()).section(QLatin1Char(';'), 0, 0);
    m_jobs.append(job);
    QDeadlineTimer deadline(JobMs);
    QList<QByteArray> tasks;
    for (;;) {
        if (!client(QStringLiteral("scontrol"), {"-o", "show", "job", job}, &out, error))
            return false;
        tasks = out.trimmed().split('\n');
        bool all = true;
        for (const QByteArray &task : tasks)
            all = all && ended(field(task, "JobState"));
        if (all)
            break;
        if (deadline.hasExpired()) {
            *error =
                QStringLiteral("job %1 did not end in %2 minutes").arg(job).arg(JobMs / 60'000);
            return false;
        }
        QThread::msleep(PollMs);
    }
    QStringList failed;
    for (const QByteArray &task : tasks) {
        if (field(task, "JobState") == "COMPLETED" && field(task, "ExitCode") == "0:0")
            continue;
        const QString output = QString::fromUtf8(field(task, "StdOut"));
        failed.append(QStringLiteral("task %1: %2, exit %3:\n%4")
                          .arg(QString::fromUtf8(field(task, "ArrayTaskId")),
                               QString::fromUtf8(field(task, "JobState")),
                               QString::fromUtf8(field(task, "ExitCode")),
                               QString::fromUtf8(tail(output, 2000))));
    }
    if (failed.isEmpty())
        return true;
    *error = failed.join(QLatin1Char('\n'));
    return false;
}

QString SlurmCluster::logs() const
{
    QString text;
    for (const char *log : {"munged.log", "slurmctld.log", "slurmd.log"}) {
        const QByteArray last = tail(m_dir.filePath(QLatin1String(log)), 1500);
        if (!last.isEmpty())
            text += QStringLiteral("-- %1:\n").arg(QLatin1String(log)) + QString::fromUtf8(last);
    }
    return text;
}
