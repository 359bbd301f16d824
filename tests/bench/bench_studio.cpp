// SPDX-License-Identifier: MIT
// The cost of watching: the real semhap-studio on its defaults (box_and_block, C3, the
// scripted operator at real time) in the display this runs in, for SECONDS (600 unless
// told), at each window size asked for (1280x800 unless told). Every minute it prints the
// studio's CPU over that minute (% of one core, every thread: the simulation, the window,
// software GL's renderers) and its resident memory; then the mean CPU after the first
// minute and the largest memory. Run it in a virtual display with software GL, as
// scripts/bench.sh does:
//   LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s '-screen 0 1920x1200x24' bench_studio [SECONDS] [SIZE...]
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace {

/** A process's CPU time so far, every thread (s); negative once it is gone. */
double cpuSeconds(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return -1.0;
    // The command name may hold spaces: the fields count from after its closing parenthesis.
    const QByteArray line = stat.readAll();
    const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return -1.0;
    const double ticks = double(sysconf(_SC_CLK_TCK));
    return (fields[11].toDouble() + fields[12].toDouble()) / ticks; // utime, stime
}

/** A process's resident memory (MB); negative once it is gone. */
double residentMegabytes(qint64 pid)
{
    QFile status(QStringLiteral("/proc/%1/status").arg(pid));
    if (!status.open(QIODevice::ReadOnly))
        return -1.0;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').front().toDouble() / 1024.0;
    }
    return -1.0;
}

/** Watches the studio at `size` for `seconds`; false when it did not run throughout. */
bool watch(const QString &size, int seconds)
{
    QTemporaryDir config; // its own settings and workspace: the defaults, every time
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
    env.insert(QStringLiteral("XDG_DATA_HOME"), config.path());
    QProcess studio;
    studio.setProcessEnvironment(env);
    studio.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    studio.start(QStringLiteral(SEMHAP_STUDIO_BINARY),
                 {QStringLiteral("--size"), size, QStringLiteral("--pose-port"),
                  QStringLiteral("0")});
    if (!studio.waitForStarted()) {
        std::fprintf(stderr, "bench_studio: cannot start %s\n", SEMHAP_STUDIO_BINARY);
        return false;
    }
    const qint64 pid = studio.processId();
    std::printf("semhap-studio at %s, real time, box_and_block, C3:\n", qPrintable(size));
    std::printf("%8s %10s %10s\n", "minute", "CPU %", "RSS MB");
    QThread::sleep(5); // past the start: the scene loaded, the window shown
    double lastCpu = cpuSeconds(pid);
    QElapsedTimer clock;
    clock.start();
    qint64 lastWall = 0;
    double sumCpu = 0.0;
    double sumWall = 0.0;
    double largest = 0.0;
    for (int minute = 1; minute * 60 <= std::max(seconds, 60); ++minute) {
        // Memory sampled every 5 s: its largest, not only the minute's end.
        for (int k = 0; k < 12; ++k) {
            QThread::sleep(5);
            largest = std::max(largest, residentMegabytes(pid));
        }
        const double cpu = cpuSeconds(pid);
        const qint64 wall = clock.elapsed();
        if (cpu < 0.0 || studio.state() != QProcess::Running) {
            std::fprintf(stderr, "bench_studio: the studio went after %d minute(s)\n", minute);
            return false;
        }
        const double share = (cpu - lastCpu) / (double(wall - lastWall) / 1000.0) * 100.0;
        std::printf("%8d %10.0f %10.0f\n", minute, share, residentMegabytes(pid));
        std::fflush(stdout);
        if (minute > 1) { // the first minute warms up: caches, the plots' first window
            sumCpu += cpu - lastCpu;
            sumWall += double(wall - lastWall) / 1000.0;
        }
        lastCpu = cpu;
        lastWall = wall;
    }
    studio.terminate();
    studio.waitForFinished(10000);
    if (sumWall > 0.0)
        std::printf("mean CPU after the first minute: %.0f %% of a core; largest RSS %.0f MB\n",
                    sumCpu / sumWall * 100.0, largest);
    else
        std::printf("largest RSS %.0f MB (run 2 minutes or more for the mean CPU)\n", largest);
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QStringList args = app.arguments().mid(1);
    bool ok = false;
    const int seconds = args.isEmpty() ? 600 : args.first().toInt(&ok);
    if (!args.isEmpty() && (!ok || seconds <= 0)) {
        std::fprintf(stderr, "usage: bench_studio [SECONDS] [WIDTHxHEIGHT...]\n");
        return 2;
    }
    if (!args.isEmpty())
        args.removeFirst();
    if (args.isEmpty())
        args.append(QStringLiteral("1280x800"));
    for (const QString &size : args) {
        if (!watch(size, seconds))
            return 1;
    }
    return 0;
}
