// SPDX-License-Identifier: MIT
#pragma once

#include <QProcess>
#include <QProcessEnvironment>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>
#include <vector>

/**
 * A one-node Slurm cluster on this machine, in a folder of its own: Debian's munged,
 * slurmctld and slurmd, started by start() and stopped (jobs cancelled first) when it is
 * destroyed. Its daemons run as root, so it needs root; unavailable() says why not.
 */
class SlurmCluster
{
public:
    /** Why no cluster can start here (not root, a program missing), or empty if one can. */
    static QString unavailable();

    SlurmCluster() = default;
    ~SlurmCluster();
    SlurmCluster(const SlurmCluster &) = delete;
    SlurmCluster &operator=(const SlurmCluster &) = delete;

    /** Starts the daemons with a node of `cpus` CPUs and waits until the node is idle. */
    bool start(int cpus, QString *error);
    /** The environment its commands and their jobs run in (SLURM_CONF names its slurm.conf). */
    QProcessEnvironment environment() const { return m_environment; }
    /**
     * Submits `script ARGS` with sbatch as the job array `array` (`--array`'s value) and
     * `options`, from `workDir` (where the tasks' output files go), and waits until every task
     * has ended. False, with the failed tasks' states and output, unless every one exited 0.
     */
    bool runArray(const QString &array, const QStringList &options, const QString &script,
                  const QStringList &args, const QString &workDir, QString *error);

private:
    bool startDaemon(const QString &program, const QStringList &args, QString *error);
    /** A Slurm client program's standard output; false with its errors if it failed. */
    bool client(const QString &program, const QStringList &args, QByteArray *out,
                QString *error) const;
    QString logs() const;

    QTemporaryDir m_dir;
    QProcessEnvironment m_environment;
    std::vector<std::unique_ptr<QProcess>> m_daemons; ///< in start order
    QStringList m_jobs;                               ///< submitted, cancelled when stopping
};
