// SPDX-License-Identifier: MIT
#include "playcommand.h"

#include "emergencystop.h"
#include "transportfactory.h"
#include "transportscheme.h"

#include <chrono>
#include <thread>

namespace semhap {

namespace {

// Longer than this is almost certainly a typo in --duration (a name of its own: Command's
// MaxDuration, a simulation's limit, would hide it).
constexpr double MaxPlaySeconds = 3600.0;
// How long to wait for a band to answer before playing anyway (it may not reply at all).
constexpr double AnswerTimeout = 1.0;

} // namespace

QString PlayCommand::summary() const
{
    return tr("Plays a pattern in real time on a device: begin at 0, end at --release-at, "
              "stop-all at the end.");
}

void PlayCommand::configure(QCommandLineParser &parser)
{
    addPatternArguments(parser);
    QStringList syntaxes;
    for (const TransportScheme &scheme : TransportScheme::all())
        syntaxes.append(QString::fromUtf8(scheme.syntax));
    parser.addOption({QStringLiteral("device"),
                      tr("Where to play: %1.").arg(syntaxes.join(QStringLiteral(", "))),
                      tr("URI")});
    parser.addOption({QStringLiteral("duration"),
                      tr("How long to play, in seconds (default: release-at + 1, or 2)."),
                      tr("S")});
    parser.addOption({QStringLiteral("gain"), tr("Master gain 0..1 (default 1)."), tr("G")});
}

int PlayCommand::execute(const QCommandLineParser &parser)
{
    QString pattern;
    RenderOptions options;
    if (!patternArguments(parser, &pattern, &options))
        return ExitUsage;
    if (!parser.isSet(QStringLiteral("device")))
        return usageError(tr("--device is required"));
    double gain = 1.0;
    options.duration = parser.isSet(QStringLiteral("release-at")) ? options.releaseAt + 1.0 : 2.0;
    if (!numberOption(parser, QStringLiteral("gain"), &gain) ||
        !numberOption(parser, QStringLiteral("duration"), &options.duration))
        return ExitUsage;
    if (gain < 0 || gain > 1)
        return usageError(tr("--gain must be within [0, 1]"));
    if (options.duration < 0 || options.duration > MaxPlaySeconds)
        return usageError(tr("--duration must be within [0, %1]").arg(MaxPlaySeconds));
    options.rate = 0.0; // the model's own rate
    RenderedPattern rendered;
    DeviceModelPtr model;
    if (!renderNamedPattern(pattern, options, &rendered, &model))
        return ExitInvalidInput;

    const QString uri = parser.value(QStringLiteral("device"));
    QString reason;
    std::unique_ptr<Transport> transport = TransportFactory::create(uri, model, &reason);
    if (!transport)
        return usageError(reason);
    EmergencyStop::install();
    if (!transport->open(&reason))
        return inputError(tr("%1: cannot open: %2").arg(uri, reason));
    using Clock = std::chrono::steady_clock;
    const Clock::time_point asked = Clock::now();
    while (!transport->status().responding &&
           Clock::now() - asked < std::chrono::duration<double>(AnswerTimeout))
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    transport->setGain(gain);
    transport->setArmed(true);

    DeviceFrame frame;
    frame.channelCount = model->channelCount();
    const Clock::time_point start = Clock::now();
    for (size_t k = 0; k < rendered.t.size(); ++k) {
        std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(rendered.t[k])));
        frame.t = rendered.t[k];
        for (int c = 0; c < frame.channelCount; ++c)
            frame.values[size_t(c)] = rendered.values[size_t(c)][k];
        transport->send(frame);
    }
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>(options.duration)));
    transport->stopAll();
    const TransportStatus status = transport->status();
    transport->close();
    // A band answers heartbeats (a round trip); a sound card reports its output time. Frames
    // a busy machine sent too late to matter were replaced by newer ones: said, not hidden.
    QString timing;
    if (status.framesSkipped > 0)
        timing += tr(", %1 skipped").arg(status.framesSkipped);
    if (status.roundTripMs >= 0.0)
        timing += tr(", round trip %1 ms").arg(status.roundTripMs, 0, 'f', 2);
    if (status.latencyMs >= 0.0)
        timing += tr(", latency %1 ms").arg(status.latencyMs, 0, 'f', 2);
    m_out << tr("%1 on %2: %3 frames%4%5\n")
                 .arg(pattern, transport->uri())
                 .arg(status.framesSent)
                 .arg(timing, status.lastError.isEmpty()
                                  ? QString()
                                  : QStringLiteral(" (") + status.lastError + QLatin1Char(')'));
    return ExitOk;
}

} // namespace semhap
