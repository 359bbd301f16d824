// SPDX-License-Identifier: MIT
#include "audiotransport.h"

#include "audiorenderer.h"
#include "audiosystem.h"
#include "framerate.h"
#include "monotonic.h"

#include <portaudio.h>

#include <QStringList>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** The card has not asked for samples for this long: the device is not answering. */
constexpr double ResponseTimeout = 0.5;
/** How long close() lets the fade and a buffer of silence reach the card. */
constexpr double SilenceTimeout = 0.25;
constexpr auto WorkerPeriod = std::chrono::milliseconds(10);
/** How old the listing of sound cards may be (s): a panel polls every second. */
constexpr double ListAge = 5.0;

int renderCallback(const void *, void *output, unsigned long frames,
                   const PaStreamCallbackTimeInfo *time, PaStreamCallbackFlags flags, void *data)
{
    auto *renderer = static_cast<AudioRenderer *>(data);
    if (flags & paOutputUnderflow)
        renderer->countUnderflow();
    // The DAC time and the current time are on the stream's clock; only their difference
    // is used, against the monotonic clock that stamped send().
    const double delay = time->outputBufferDacTime > 0.0 && time->currentTime > 0.0
                             ? std::max(0.0, time->outputBufferDacTime - time->currentTime)
                             : 0.0;
    renderer->render(static_cast<float *>(output), frames, delay, monotonicSeconds());
    return paContinue;
}

void finishedCallback(void *data)
{
    static_cast<AudioRenderer *>(data)->markEnded();
}

QString portAudioError(PaError error)
{
    QString text = QString::fromUtf8(Pa_GetErrorText(error));
    const PaHostErrorInfo *host = Pa_GetLastHostErrorInfo();
    if (error == paUnanticipatedHostError && host && host->errorText)
        text += QStringLiteral(": ") + QString::fromUtf8(host->errorText);
    return text;
}

} // namespace

AudioTransport::AudioTransport(const DeviceUri &uri, DeviceModelPtr model)
    : Transport(model), m_uri(uri), m_safety(model)
{
    m_commanded.channelCount = model->channelCount();
    m_lastSafe = model->restFrame(0.0);
}

AudioTransport::~AudioTransport()
{
    close();
}

QString AudioTransport::uri() const
{
    return m_uri.toString();
}

bool AudioTransport::fits(const DeviceUri &uri, const DeviceModel &model, QString *error)
{
    const size_t channels =
        uri.outputChannels.empty() ? size_t(model.channelCount()) : uri.outputChannels.size();
    if (uri.outputChannels.size() > size_t(model.channelCount())) {
        *error = QStringLiteral("%1: %2 output channels for the %3 channels of %4")
                     .arg(uri.toString())
                     .arg(uri.outputChannels.size())
                     .arg(model.channelCount())
                     .arg(model.name());
        return false;
    }
    if (uri.carriers.size() > 1 && uri.carriers.size() != channels) {
        *error = QStringLiteral("%1: %2 carriers for %3 channels of %4: give one for all, or "
                                "one per channel")
                     .arg(uri.toString())
                     .arg(uri.carriers.size())
                     .arg(channels)
                     .arg(model.name());
        return false;
    }
    return true;
}

bool AudioTransport::parseAddress(const QString &address, DeviceUri *uri, QString *error)
{
    const qsizetype query = address.indexOf(QLatin1Char('?'));
    uri->name = address.left(query);
    if (uri->name.isEmpty()) {
        *error = QStringLiteral("an audio device needs an output (audio:default, or a name "
                                "`semhap devices` lists)");
        return false;
    }
    if (query < 0)
        return true;
    for (const QString &option : address.mid(query + 1).split(QLatin1Char('&'))) {
        const QString key = option.section(QLatin1Char('='), 0, 0);
        const QStringList values = option.section(QLatin1Char('='), 1).split(QLatin1Char(','));
        if (key == QLatin1String("channels")) {
            uri->outputChannels.clear();
            for (const QString &value : values) {
                bool ok = false;
                const int channel = value.toInt(&ok);
                if (!ok || channel < 1) {
                    *error = QStringLiteral("channels= takes the card's output channels, from 1, "
                                            "comma-separated (channels=1,2,3,4)");
                    return false;
                }
                if (std::find(uri->outputChannels.begin(), uri->outputChannels.end(), channel) !=
                    uri->outputChannels.end()) {
                    *error = QStringLiteral("output channel %1 is given twice").arg(channel);
                    return false;
                }
                uri->outputChannels.push_back(channel);
            }
            if (int(uri->outputChannels.size()) > MaxChannels) {
                *error = QStringLiteral("at most %1 channels").arg(MaxChannels);
                return false;
            }
        } else if (key == QLatin1String("carrier")) {
            uri->carriers.clear();
            for (const QString &value : values) {
                bool ok = false;
                const double carrier = value.toDouble(&ok);
                if (!ok || !std::isfinite(carrier) || carrier <= 0.0) {
                    *error = QStringLiteral("carrier= takes frequencies above 0 Hz, one for all "
                                            "channels or one per channel (carrier=170 or "
                                            "carrier=170,170,200,200)");
                    return false;
                }
                uri->carriers.push_back(carrier);
            }
        } else {
            *error = QStringLiteral("unknown option '%1' (audio takes "
                                    "?channels=1,2,…&carrier=HZ,…)")
                         .arg(option);
            return false;
        }
    }
    if (uri->carriers.size() > 1 && !uri->outputChannels.empty() &&
        uri->carriers.size() != uri->outputChannels.size()) {
        *error = QStringLiteral("%1 carriers for %2 channels: give one for all, or one per "
                                "channel")
                     .arg(uri->carriers.size())
                     .arg(uri->outputChannels.size());
        return false;
    }
    return true;
}

QString AudioTransport::formatAddress(const DeviceUri &uri)
{
    QStringList options;
    QStringList list;
    for (const int channel : uri.outputChannels)
        list.append(QString::number(channel));
    if (!list.isEmpty())
        options.append(QStringLiteral("channels=") + list.join(QLatin1Char(',')));
    list.clear();
    for (const double carrier : uri.carriers)
        list.append(QString::number(carrier));
    if (!list.isEmpty() &&
        !(uri.carriers.size() == 1 && uri.carriers[0] == DeviceUri::DefaultCarrier))
        options.append(QStringLiteral("carrier=") + list.join(QLatin1Char(',')));
    return uri.name +
           (options.isEmpty() ? QString() : QLatin1Char('?') + options.join(QLatin1Char('&')));
}

void AudioTransport::present(std::vector<PortInfo> *out)
{
    for (const AudioOutputInfo &output : AudioSystem::list(ListAge)) {
        DeviceUri uri;
        uri.scheme = QStringLiteral("audio");
        uri.name = output.name;
        out->push_back({uri.toString(), uri.scheme, output.hostApi, -1, -1, output.channels,
                        output.sampleRate});
    }
}

bool AudioTransport::open(QString *error)
{
    if (m_thread.joinable())
        return true;
    const bool ok = connect(error);
    m_quit = false;
    m_thread = std::thread([this] { run(); });
    return ok;
}

void AudioTransport::close()
{
    if (!m_thread.joinable())
        return;
    stopAll();
    {
        std::lock_guard<std::mutex> lock(m_wakeMutex);
        m_quit = true;
    }
    m_wake.notify_all();
    m_thread.join();
    if (m_stream) {
        // The fade and a buffer of silence reach the card before the stream stops; a card
        // that stopped asking for samples is not waited for.
        const double deadline = monotonicSeconds() + SilenceTimeout;
        while (!m_renderer->isSilent() && !m_renderer->ended() && monotonicSeconds() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        closeStream(m_renderer->isSilent());
    }
    std::lock_guard<std::mutex> lock(m_statusMutex);
    m_status.connected = false;
    m_responding = false;
}

void AudioTransport::send(const DeviceFrame &frame)
{
    const double now = monotonicSeconds();
    std::lock_guard<std::mutex> lock(m_sendMutex);
    m_commanded = frame;
    m_holding = true;
    pushSafe(now, true);
}

void AudioTransport::stopAll()
{
    const double now = monotonicSeconds();
    std::lock_guard<std::mutex> lock(m_sendMutex);
    m_safety.reset();
    m_holding = false;
    m_lastSafe = m_model->restFrame(m_lastSafe.t);
    if (m_renderer)
        m_renderer->stop(now);
}

void AudioTransport::pushSafe(double now, bool fresh)
{
    DeviceFrame safe = m_commanded;
    safe.channelCount = m_model->channelCount();
    m_safety.apply(m_commanded.values.data(), m_commanded.channelCount, now, gain(), isArmed(),
                   safe.values.data());
    m_lastPush = now;
    // A heartbeat's re-send of what is playing already is no news to the card or a readout.
    if (!fresh && safe.t == m_lastSafe.t &&
        std::equal(safe.values.begin(), safe.values.begin() + safe.channelCount,
                   m_lastSafe.values.begin()))
        return;
    m_lastSafe = safe;
    if (m_renderer)
        m_renderer->push(safe, now);
}

TransportStatus AudioTransport::status() const
{
    std::lock_guard<std::mutex> lock(m_statusMutex);
    TransportStatus s = m_status;
    s.armed = isArmed();
    s.responding = m_status.connected && m_responding;
    s.identity = m_model->name();
    return s;
}

double AudioTransport::latencyOf(std::uint64_t index) const
{
    std::lock_guard<std::mutex> lock(m_statusMutex);
    const std::uint64_t count = m_sent.count();
    if (index >= count || count - index > std::uint64_t(SentLog::Capacity))
        return -1.0;
    return m_latency[size_t(index % SentLog::Capacity)];
}

bool AudioTransport::connect(QString *error)
{
    const auto fail = [this, error](const QString &reason) {
        *error = reason;
        std::lock_guard<std::mutex> lock(m_statusMutex);
        m_status.lastError = reason;
        return false;
    };
    auto system = std::make_unique<AudioSystem>();
    if (!system->isOk())
        return fail(QStringLiteral("PortAudio cannot start: %1").arg(system->error()));
    std::lock_guard<std::recursive_mutex> guard(AudioSystem::lock());
    QString reason;
    const int device = system->find(m_uri.name, &reason);
    if (device < 0)
        return fail(reason);
    const PaDeviceInfo *info = Pa_GetDeviceInfo(device);
    const QString name = QString::fromUtf8(info->name);
    const double rate = info->defaultSampleRate;
    const int count =
        m_uri.outputChannels.empty() ? m_model->channelCount() : int(m_uri.outputChannels.size());
    std::vector<AudioRenderer::Channel> channels;
    int outputs = 0;
    for (int c = 0; c < count; ++c) {
        const int output = m_uri.outputChannels.empty() ? c + 1 : m_uri.outputChannels[size_t(c)];
        const double carrier = m_uri.carriers.empty()
                                   ? DeviceUri::DefaultCarrier
                                   : m_uri.carriers[m_uri.carriers.size() == 1 ? 0 : size_t(c)];
        if (output > info->maxOutputChannels)
            return fail(QStringLiteral("'%1' has %2 output channels: there is no channel %3 "
                                       "for %4 (channels= maps the model's channels onto "
                                       "them)")
                            .arg(name)
                            .arg(info->maxOutputChannels)
                            .arg(output)
                            .arg(m_model->channels()[size_t(c)].name));
        if (carrier >= rate / 2.0)
            return fail(QStringLiteral("a %1 Hz carrier cannot be played at the %2 Hz of "
                                       "'%3': it must be below %4 Hz")
                            .arg(carrier)
                            .arg(rate)
                            .arg(name)
                            .arg(rate / 2.0));
        channels.push_back({output - 1, carrier});
        outputs = std::max(outputs, output);
    }
    auto renderer = std::make_unique<AudioRenderer>(m_model, rate, outputs, channels);
    const PaStreamParameters parameters{device, outputs, paFloat32, info->defaultLowOutputLatency,
                                        nullptr};
    PaStream *stream = nullptr;
    PaError result =
        Pa_OpenStream(&stream, nullptr, &parameters, rate, paFramesPerBufferUnspecified,
                      paClipOff | paDitherOff, renderCallback, renderer.get());
    if (result != paNoError)
        return fail(QStringLiteral("'%1': %2").arg(name, portAudioError(result)));
    Pa_SetStreamFinishedCallback(stream, finishedCallback);
    {
        // A reconnected card plays what is held at once.
        std::lock_guard<std::mutex> lock(m_sendMutex);
        m_renderer = std::move(renderer);
        if (m_holding)
            pushSafe(monotonicSeconds(), true);
    }
    result = Pa_StartStream(stream);
    if (result != paNoError) {
        Pa_CloseStream(stream);
        std::lock_guard<std::mutex> lock(m_sendMutex);
        m_renderer.reset();
        return fail(QStringLiteral("'%1': %2").arg(name, portAudioError(result)));
    }
    m_system = std::move(system);
    m_stream = stream;
    m_lastSamples = 0;
    m_lastProgress = monotonicSeconds();
    std::lock_guard<std::mutex> lock(m_statusMutex);
    if (m_disconnects > 0)
        ++m_status.reconnects;
    m_status.connected = true;
    m_status.lastError.clear();
    m_responding = true;
    return true;
}

void AudioTransport::closeStream(bool drainFirst)
{
    {
        std::lock_guard<std::recursive_mutex> guard(AudioSystem::lock());
        if (drainFirst)
            Pa_StopStream(m_stream);
        else
            Pa_AbortStream(m_stream);
        Pa_CloseStream(m_stream);
    }
    m_stream = nullptr;
    drain();
    {
        std::lock_guard<std::mutex> lock(m_statusMutex);
        m_skippedBefore += m_renderer->skipped();
        m_underflowsBefore += m_renderer->underflows();
    }
    {
        std::lock_guard<std::mutex> lock(m_sendMutex);
        m_renderer.reset();
    }
    // Without a reference of ours, the next attempt may scan the cards afresh.
    m_system.reset();
}

void AudioTransport::disconnect(const QString &reason)
{
    closeStream(false);
    std::lock_guard<std::mutex> lock(m_statusMutex);
    ++m_disconnects;
    m_status.connected = false;
    m_status.lastError = reason;
    m_status.errors = m_disconnects + std::uint32_t(m_underflowsBefore);
    m_responding = false;
}

void AudioTransport::drain()
{
    RenderedFrame rendered;
    while (m_renderer->takeRendered(&rendered)) {
        // Only this thread appends: the count is the frame's index.
        const std::uint64_t index = m_sent.count();
        m_sent.append(rendered.frame);
        std::lock_guard<std::mutex> lock(m_statusMutex);
        m_latency[size_t(index % SentLog::Capacity)] = rendered.latency;
        m_status.latencyMs = rendered.latency * 1000.0;
        ++m_status.framesSent;
    }
    std::lock_guard<std::mutex> lock(m_statusMutex);
    m_status.framesSkipped = std::uint32_t(m_skippedBefore + m_renderer->skipped());
    m_status.errors = m_disconnects + std::uint32_t(m_underflowsBefore + m_renderer->underflows());
}

void AudioTransport::run()
{
    double nextAttempt = monotonicSeconds() + ReconnectPeriod;
    FrameRate rate;
    std::unique_lock<std::mutex> wake(m_wakeMutex);
    while (!m_quit) {
        wake.unlock();
        const double now = monotonicSeconds();
        if (m_stream) {
            drain();
            bool active = false;
            {
                std::lock_guard<std::recursive_mutex> guard(AudioSystem::lock());
                active = Pa_IsStreamActive(m_stream) == 1;
            }
            if (m_renderer->ended() || !active) {
                disconnect(QStringLiteral("'%1' stopped playing (unplugged?)").arg(m_uri.name));
                nextAttempt = now + ReconnectPeriod;
            } else {
                const std::uint64_t samples = m_renderer->samplesRendered();
                if (samples != m_lastSamples) {
                    m_lastSamples = samples;
                    m_lastProgress = now;
                }
                std::lock_guard<std::mutex> lock(m_statusMutex);
                m_responding = now - m_lastProgress < ResponseTimeout;
            }
            std::lock_guard<std::mutex> lock(m_sendMutex);
            // Held values go again: disarming, a gain or the inflation limit act on them.
            if (m_holding && now - m_lastPush >= HeartbeatPeriod)
                pushSafe(now, false);
        } else if (now >= nextAttempt) {
            QString error;
            connect(&error);
            nextAttempt = now + ReconnectPeriod;
        }
        {
            std::lock_guard<std::mutex> lock(m_statusMutex);
            rate.record(m_status.framesSent, now);
            m_status.framesPerSecond = rate.perSecond(m_status.framesSent, now);
        }
        wake.lock();
        m_wake.wait_for(wake, WorkerPeriod, [this] { return m_quit; });
    }
}

} // namespace semhap
