// SPDX-License-Identifier: MIT
// The robot stack's speeds. A recording as a robot makes one: two grippers, each with two
// fingertip force/torque sensors publishing geometry_msgs/msg/WrenchStamped at 1 kHz (four
// topics), header stamps 2 ms behind the log, zstd chunks; one hour by default
// (`bench_ros SECONDS` for another length). Then: the MCAP writer alone (MB/s), the MCAP
// reader alone (messages/s), the topic map's frames (decode and assemble, frames/s), the
// import into a session (routed through C3, with its events and device frames), and the
// export of that session to MCAP (MB/s). Targets (issue 35): reader >= 2 million messages/s;
// an hour imported in <= 60 s; export >= 50 MB/s.
#include "cdrwriter.h"
#include "mcapexport.h"
#include "mcapreader.h"
#include "mcapwriter.h"
#include "recordingimport.h"
#include "recordingreader.h"
#include "rostypes.h"
#include "router.h"
#include "sessionreader.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace semhap;

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double megabytes(const QString &path)
{
    return double(QFileInfo(path).size()) / 1e6;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const double seconds = argc > 1 ? std::atof(argv[1]) : 3600.0;
    QTemporaryDir dir;
    const QString recording = dir.filePath("robot.mcap");
    const QString map = dir.filePath("robot.topics.json");
    const char *tips[4] = {"/left/left_tip/wrench", "/left/right_tip/wrench",
                           "/right/left_tip/wrench", "/right/right_tip/wrench"};
    {
        QFile out(recording);
        out.open(QIODevice::WriteOnly);
        McapWriter mcap(&out);
        mcap.begin(QStringLiteral("ros2"), QStringLiteral("bench_ros"));
        const std::uint16_t schema = mcap.addSchema(
            QStringLiteral("geometry_msgs/msg/WrenchStamped"), QStringLiteral("ros2msg"),
            RosTypes::schema(QStringLiteral("geometry_msgs/msg/WrenchStamped")));
        std::uint16_t channels[4];
        for (int c = 0; c < 4; ++c)
            channels[c] = mcap.addChannel(schema, QLatin1String(tips[c]), QStringLiteral("cdr"));
        const auto start = Clock::now();
        const std::int64_t t0 = 1700000000LL * 1000000000LL;
        CdrWriter cdr;
        const long long ticks = std::llround(seconds * 1000);
        for (long long k = 0; k < ticks; ++k) {
            const double t = double(k) * 1e-3;
            const std::int64_t log = t0 + k * 1000000;
            for (int c = 0; c < 4; ++c) {
                // Grasps of a few seconds, squeezes past the break line now and then.
                const double f =
                    std::max(0.0, 35 * std::sin(0.7 * t + c / 2) + 12 * std::sin(5.3 * t) + 5);
                cdr.clear();
                cdr.time(log - 2000000);
                cdr.string(QByteArrayView("tip"));
                for (double v : {0.05 * f, f, 0.02 * f, 0.0, 0.0, 0.001 * f})
                    cdr.float64(v);
                mcap.addMessage(channels[c], std::uint64_t(log), cdr.bytes());
            }
        }
        mcap.end();
        out.close();
        const double s = since(start);
        std::printf("write: %.0f s of 4 topics at 1 kHz, %llu messages, %.1f MB in %.2f s: "
                    "%.1f MB/s of file, %.2f M messages/s\n",
                    seconds, static_cast<unsigned long long>(mcap.messageCount()),
                    megabytes(recording), s, megabytes(recording) / s,
                    double(mcap.messageCount()) / s / 1e6);
    }
    {
        McapReader reader(recording);
        reader.open();
        McapMessage m;
        long long n = 0;
        const auto start = Clock::now();
        while (reader.next(&m))
            ++n;
        const double s = since(start);
        std::printf("read (MCAP reader alone, CRCs checked): %lld messages in %.2f s: "
                    "%.2f M messages/s (target >= 2)%s\n",
                    n, s, double(n) / s / 1e6, reader.atEnd() ? "" : " ERROR");
    }
    {
        QFile out(map);
        out.open(QIODevice::WriteOnly);
        out.write(R"({"format": "semhap.topics/1", "grippers": {
            "left": {"left": {"topic": "/left/left_tip/wrench"},
                     "right": {"topic": "/left/right_tip/wrench", "normal_axis": "-y"}},
            "right": {"left": {"topic": "/right/left_tip/wrench"},
                      "right": {"topic": "/right/right_tip/wrench", "normal_axis": "-y"}}}})");
    }
    {
        TopicMap topics;
        LoadError error;
        TopicMap::load(map, &topics, &error);
        RecordingReader reader(recording, topics, map);
        const auto start = Clock::now();
        reader.open();
        const double checked = since(start);
        ContactFrame frame;
        long long n = 0;
        while (reader.next(&frame))
            ++n;
        const double s = since(start);
        std::printf("frames (check pass, then decode and assemble): %lld frames in %.2f s "
                    "(%.2f s of it the check): %.2f M frames/s\n",
                    n, s, checked, double(n) / s / 1e6);
    }
    const QString session = dir.filePath("robot.db");
    {
        LoadError error;
        SessionInfo info;
        info.routerSource = QStringLiteral("C3");
        RecordingImport::Result result;
        const auto start = Clock::now();
        const bool ok =
            RecordingImport::run(recording, map, loadRouter(QStringLiteral("C3"), {}, &error),
                                 info, session, nullptr, &result);
        const double s = since(start);
        std::printf("import (routed through C3, events and device frames recorded): %lld "
                    "frames in %.2f s, %.0f x real time; session %.1f MB (target: an hour in "
                    "<= 60 s)%s\n",
                    result.frames, s, seconds / s, megabytes(session),
                    ok ? "" : qPrintable(QStringLiteral(" ERROR ") + result.error));
    }
    {
        // What the export reads, alone: every stream unpacked and checked.
        QString error;
        auto reader = SessionReader::open(session, &error);
        long long values = 0;
        const auto start = Clock::now();
        const bool ok =
            reader->readContactFrames([&](const ContactFrame &, double) { return ++values; },
                                      &error) &&
            reader->readEvents([&](const SemanticEvent &) { return ++values; }, &error) &&
            reader->readDeviceFrames([&](const DeviceFrame &) { return ++values; }, &error);
        std::printf("session read alone (what the export reads): %lld values in %.2f s%s\n",
                    values, since(start), ok ? "" : qPrintable(QStringLiteral(" ERROR ") + error));
    }
    {
        QString error;
        auto reader = SessionReader::open(session, &error);
        const QString exported = dir.filePath("export.mcap");
        QFile out(exported);
        out.open(QIODevice::WriteOnly);
        const auto start = Clock::now();
        const bool ok = McapExport::write(*reader, &out, &error);
        out.close();
        const double s = since(start);
        std::printf("export (session to MCAP): %.1f MB in %.2f s: %.1f MB/s (target >= 50)%s\n",
                    megabytes(exported), s, megabytes(exported) / s,
                    ok ? "" : qPrintable(QStringLiteral(" ERROR ") + error));
    }
    return 0;
}
