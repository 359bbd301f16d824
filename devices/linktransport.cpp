// SPDX-License-Identifier: MIT
#include "linktransport.h"

#include "emergencystop.h"
#include "framerate.h"
#include "monotonic.h"

#include <algorithm>
#include <cmath>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

namespace semhap {

namespace {

constexpr double ResponseTimeout = 0.5;
constexpr int StatusEveryHeartbeats = 10;

} // namespace

LinkTransport::LinkTransport(std::unique_ptr<Link> link, DeviceModelPtr model)
    : Transport(model), m_link(std::move(link)), m_safety(model)
{
    m_slot.channelCount = model->channelCount();
}

LinkTransport::~LinkTransport()
{
    close();
}

QString LinkTransport::uri() const
{
    return m_link->uri();
}

bool LinkTransport::open(QString *error)
{
    if (m_thread.joinable())
        return true;
    m_wakeFd = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    const bool ok = connect(error);
    m_quit = false;
    m_thread = std::thread([this] { run(); });
    return ok;
}

void LinkTransport::close()
{
    if (!m_thread.joinable())
        return;
    m_quit = true;
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(m_wakeFd, &one, sizeof one);
    m_thread.join();
    ::close(m_wakeFd);
    m_wakeFd = -1;
}

void LinkTransport::send(const DeviceFrame &frame)
{
    {
        std::lock_guard<std::mutex> lock(m_slotMutex);
        if (m_slotFresh) {
            std::lock_guard<std::mutex> statusLock(m_statusMutex);
            ++m_status.framesSkipped;
        }
        m_slot = frame;
        m_slotFresh = true;
    }
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(m_wakeFd, &one, sizeof one);
}

void LinkTransport::stopAll()
{
    {
        std::lock_guard<std::mutex> lock(m_slotMutex);
        m_slot.values.fill(0.0);
        m_slotFresh = false;
    }
    ++m_stopRequests;
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(m_wakeFd, &one, sizeof one);
}

TransportStatus LinkTransport::status() const
{
    std::lock_guard<std::mutex> lock(m_statusMutex);
    TransportStatus s = m_status;
    s.armed = isArmed();
    s.responding = m_lastReply >= 0.0 && monotonicSeconds() - m_lastReply < ResponseTimeout;
    return s;
}

bool LinkTransport::connect(QString *error)
{
    if (!m_link->open(error)) {
        std::lock_guard<std::mutex> lock(m_statusMutex);
        m_status.lastError = *error;
        return false;
    }
    m_linkOpen = true;
    m_identified = false;
    m_decoder.reset();
    m_safety.reset();
    EmergencyStop::add(m_link->emergencyFd());
    // The first ends whatever half-frame the device holds, the second (an empty frame)
    // tells it that a new host's numbering starts: no gap back to 0 (PROTOCOL.md).
    const std::uint8_t delimiters[2] = {0, 0};
    writeFrame(delimiters, 2);
    writeMessage(protocol::MessageType::IdentifyRequest);
    std::lock_guard<std::mutex> lock(m_statusMutex);
    if (m_status.connected || m_status.framesSent > 0)
        ++m_status.reconnects;
    m_status.connected = true;
    m_status.lastError.clear();
    return true;
}

void LinkTransport::disconnect(const QString &reason)
{
    EmergencyStop::remove(m_link->emergencyFd());
    m_link->close();
    m_linkOpen = false;
    std::lock_guard<std::mutex> lock(m_statusMutex);
    m_status.connected = false;
    m_status.lastError = reason;
    ++m_linkErrors;
    m_status.errors = m_linkErrors + m_decoder.counters().errors();
}

void LinkTransport::wait(double until)
{
    const double timeout = std::max(0.0, until - monotonicSeconds());
    pollfd fds[2] = {{m_wakeFd, POLLIN, 0}, {m_linkOpen ? m_link->pollFd() : -1, POLLIN, 0}};
    // Links without a descriptor (HID) are read every 2 ms.
    int ms = int(std::ceil(timeout * 1000.0));
    if (m_linkOpen && m_link->pollFd() < 0)
        ms = std::min(ms, 2);
    ::poll(fds, 2, ms);
    std::uint64_t count = 0;
    [[maybe_unused]] const ssize_t n = ::read(m_wakeFd, &count, sizeof count);
}

void LinkTransport::writeFrame(const std::uint8_t *data, int size)
{
    QString error;
    if (m_linkOpen && !m_link->writeFrame(data, size, &error))
        disconnect(error);
}

void LinkTransport::writeMessage(protocol::MessageType type)
{
    protocol::Message message;
    message.type = type;
    message.sequence = m_sequence++;
    message.timestamp = monotonicMicros();
    QByteArray bytes;
    protocol::encode(message, &bytes);
    writeFrame(reinterpret_cast<const std::uint8_t *>(bytes.constData()), int(bytes.size()));
}

void LinkTransport::writeValues(double now)
{
    DeviceFrame frame;
    bool fresh = false;
    {
        std::lock_guard<std::mutex> lock(m_slotMutex);
        frame = m_slot;
        fresh = m_slotFresh;
        m_slotFresh = false;
    }
    DeviceFrame safe = frame;
    safe.channelCount = m_model->channelCount();
    m_safety.apply(frame.values.data(), frame.channelCount, now, gain(), isArmed(),
                   safe.values.data());
    std::array<std::uint16_t, MaxChannels> wire{};
    for (int c = 0; c < safe.channelCount; ++c) {
        const ChannelSpec &spec = m_model->channels()[size_t(c)];
        wire[size_t(c)] = protocol::toWire(safe.values[size_t(c)], spec.min, spec.max);
    }
    std::array<std::uint8_t, protocol::MaxEncodedFrame + 1> bytes{};
    const int size =
        protocol::encodeSetValues(m_sequence++, wire.data(), safe.channelCount, bytes.data());
    writeFrame(bytes.data(), size);
    if (m_linkOpen) {
        // A heartbeat's re-send of what the band has already is no news to a readout (and
        // would stamp a paused run's last time over and over).
        const DeviceFrame last = m_sent.last();
        const bool same = safe.t == last.t && safe.channelCount == last.channelCount &&
                          std::equal(safe.values.begin(), safe.values.begin() + safe.channelCount,
                                     last.values.begin());
        if (fresh || !same)
            m_sent.append(safe);
        std::lock_guard<std::mutex> lock(m_statusMutex);
        ++m_status.framesSent;
    }
}

void LinkTransport::writeStops()
{
    m_safety.reset();
    for (int i = 0; i < StopRepeats; ++i)
        writeMessage(protocol::MessageType::StopAll);
    if (!m_linkOpen)
        return;
    // The band is at rest from the latest time it was sent anything.
    m_sent.append(m_model->restFrame(m_sent.last().t));
}

void LinkTransport::readReplies(double now)
{
    std::array<std::uint8_t, 512> buffer{};
    for (int round = 0; round < 16 && m_linkOpen; ++round) {
        QString error;
        const int n = m_link->read(buffer.data(), int(buffer.size()), &error);
        if (n < 0) {
            disconnect(error);
            return;
        }
        if (n == 0)
            return;
        m_decoder.feed(buffer.data(), size_t(n),
                       [this, now](const protocol::Message &m) { onMessage(m, now); });
    }
}

void LinkTransport::onMessage(const protocol::Message &message, double now)
{
    std::lock_guard<std::mutex> lock(m_statusMutex);
    m_lastReply = now;
    switch (message.type) {
    case protocol::MessageType::HeartbeatReply:
        m_status.roundTripMs = double(monotonicMicros() - message.timestamp) / 1000.0;
        break;
    case protocol::MessageType::Status:
        m_status.device = message.status;
        break;
    case protocol::MessageType::IdentifyReply:
        m_identified = true;
        m_status.identity = message.identity.model;
        if (message.identity.model != m_model->name())
            m_status.lastError = QStringLiteral("the device says it is %1, not %2")
                                     .arg(message.identity.model, m_model->name());
        break;
    default:
        break;
    }
}

void LinkTransport::run()
{
    double nextHeartbeat = monotonicSeconds();
    double nextAttempt = nextHeartbeat + ReconnectPeriod;
    FrameRate rate;
    int heartbeats = 0;
    while (!m_quit) {
        const double now = monotonicSeconds();
        if (!m_linkOpen) {
            if (now >= nextAttempt) {
                QString error;
                connect(&error);
                nextAttempt = now + ReconnectPeriod;
            }
            if (!m_linkOpen) {
                wait(nextAttempt);
                continue;
            }
        }
        if (m_stopRequests.exchange(0) > 0)
            writeStops();
        readReplies(now);
        bool fresh = false;
        {
            std::lock_guard<std::mutex> lock(m_slotMutex);
            fresh = m_slotFresh;
        }
        const bool heartbeatDue = now >= nextHeartbeat;
        // Values go again with each heartbeat: a reconnected device, or one that lost a
        // frame, is back in step within 100 ms, and the inflation limit acts on held values.
        if (fresh || heartbeatDue)
            writeValues(now);
        if (heartbeatDue) {
            // Asked again until answered: opening the port of an Arduino resets it, and
            // the first request goes to its boot loader.
            if (!m_identified)
                writeMessage(protocol::MessageType::IdentifyRequest);
            writeMessage(protocol::MessageType::Heartbeat);
            if (++heartbeats % StatusEveryHeartbeats == 0)
                writeMessage(protocol::MessageType::StatusRequest);
            nextHeartbeat = now + HeartbeatPeriod;
        }
        {
            std::lock_guard<std::mutex> lock(m_statusMutex);
            rate.record(m_status.framesSent, now);
            m_status.framesPerSecond = rate.perSecond(m_status.framesSent, now);
            m_status.errors = m_linkErrors + m_decoder.counters().errors();
        }
        if (!m_linkOpen) {
            nextAttempt = now + ReconnectPeriod;
            continue;
        }
        wait(nextHeartbeat);
    }
    if (m_linkOpen) {
        writeStops();
        EmergencyStop::remove(m_link->emergencyFd());
        m_link->close();
        m_linkOpen = false;
    }
    std::lock_guard<std::mutex> lock(m_statusMutex);
    m_status.connected = false;
}

} // namespace semhap
