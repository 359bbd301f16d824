// SPDX-License-Identifier: MIT
#include "emulator.h"

#include "band.h"
#include "monotonic.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace semhap {

namespace {

QString errnoText()
{
    return QString::fromLocal8Bit(std::strerror(errno));
}

} // namespace

Emulator::Emulator(const EmulatorOptions &options)
    : m_options(options), m_bandModel(std::make_unique<semhap_band_model>()),
      m_hw(std::make_unique<semhap_band_hw>()), m_band(std::make_unique<semhap_band>())
{
    const DeviceModel &model = *options.model;
    const int channels = model.channelCount();
    m_filters.assign(size_t(channels), ResponseFilter(model, model.rate()));
    m_state.setpoints.assign(size_t(channels), 0.0);
    m_state.values.assign(size_t(channels), 0.0);
    // The firmware keeps pointers to the names: they live as long as the emulator.
    m_names.push_back(model.name().toStdString());
    for (const ChannelSpec &c : model.channels())
        m_names.push_back(c.name.toStdString());
    m_channels = std::make_unique<semhap_band_channel[]>(size_t(std::max(channels, 1)));
    for (int c = 0; c < channels; ++c) {
        const ChannelSpec &spec = model.channels()[size_t(c)];
        m_channels[size_t(c)] = {m_names[size_t(c + 1)].c_str(), float(spec.min), float(spec.max),
                                 0xFFFF};
    }
    *m_bandModel = {m_names.front().c_str(),
                    {1, 0, 0},
                    std::uint8_t(std::min(channels, 255)),
                    m_channels.get(),
                    std::uint16_t(std::lround(options.watchdog * 1000.0)),
                    -1,
                    0};
    *m_hw = {this, &Emulator::write, &Emulator::millis, &Emulator::setOutput, nullptr};
}

Emulator::~Emulator()
{
    if (m_options.udp && m_fd >= 0)
        ::close(m_fd);
}

bool Emulator::open(QString *error)
{
    m_start = monotonicSeconds();
    if (semhap_band_init(m_band.get(), m_bandModel.get(), m_hw.get()) != 0) {
        *error = QStringLiteral("%1: the model cannot be described on the wire (at most %2 "
                                "channels, names of at most %3 bytes)")
                     .arg(m_options.model->name())
                     .arg(SEMHAP_MAX_CHANNELS)
                     .arg(SEMHAP_MAX_NAME);
        return false;
    }
    if (m_options.udp) {
        if (!openUdp(error))
            return false;
    } else {
        if (!m_pty.open(m_options.link, error))
            return false;
        m_fd = m_pty.fd();
    }
    return m_options.logPath.isEmpty() || m_log.open(m_options.logPath, error);
}

bool Emulator::openUdp(QString *error)
{
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    hints.ai_flags = AI_PASSIVE;
    addrinfo *found = nullptr;
    const QByteArray port = QByteArray::number(m_options.port);
    const int rc =
        ::getaddrinfo(m_options.host.toLocal8Bit().constData(), port.constData(), &hints, &found);
    if (rc != 0) {
        *error =
            QStringLiteral("%1: %2").arg(m_options.host, QString::fromLocal8Bit(gai_strerror(rc)));
        return false;
    }
    for (addrinfo *a = found; a && m_fd < 0; a = a->ai_next) {
        const int fd =
            ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
        if (fd >= 0 && ::bind(fd, a->ai_addr, a->ai_addrlen) == 0)
            m_fd = fd;
        else if (fd >= 0)
            ::close(fd);
    }
    ::freeaddrinfo(found);
    if (m_fd < 0) {
        *error = QStringLiteral("%1:%2: cannot bind: %3")
                     .arg(m_options.host)
                     .arg(m_options.port)
                     .arg(errnoText());
        return false;
    }
    sockaddr_storage bound{};
    socklen_t length = sizeof bound;
    ::getsockname(m_fd, reinterpret_cast<sockaddr *>(&bound), &length);
    char service[NI_MAXSERV] = {};
    ::getnameinfo(reinterpret_cast<sockaddr *>(&bound), length, nullptr, 0, service,
                  sizeof service, NI_NUMERICSERV);
    m_boundPort = QByteArray(service).toInt();
    return true;
}

QString Emulator::address() const
{
    return m_options.udp ? QStringLiteral("%1:%2").arg(m_options.host).arg(m_boundPort)
                         : m_pty.path();
}

QString Emulator::uri() const
{
    if (m_options.udp)
        return QStringLiteral("udp:") + address();
    return QStringLiteral("serial:") + (m_options.link.isEmpty() ? m_pty.path() : m_options.link);
}

Emulator::State Emulator::state() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_state;
}

bool Emulator::run(const std::function<bool()> &quit)
{
    const double period = 1.0 / m_options.model->rate();
    double nextTick = monotonicSeconds();
    while (!quit()) {
        if (!m_logError.isEmpty())
            return false;
        const double now = monotonicSeconds();
        if (now >= nextTick) {
            tick(now);
            nextTick += period;
            if (nextTick < now) // fell behind (a stopped debugger): do not race to catch up
                nextTick = now + period;
        }
        pollfd fd{m_fd, POLLIN, 0};
        const int ms = int(std::ceil(std::max(0.0, nextTick - monotonicSeconds()) * 1000.0));
        if (::poll(&fd, 1, ms) > 0 && (fd.revents & POLLIN))
            receive();
    }
    return true;
}

void Emulator::receive()
{
    std::array<std::uint8_t, 2048> buffer{};
    for (int round = 0; round < 16; ++round) {
        ssize_t n = 0;
        if (m_options.udp) {
            sockaddr_storage from{};
            socklen_t length = sizeof from;
            n = ::recvfrom(m_fd, buffer.data(), buffer.size(), 0,
                           reinterpret_cast<sockaddr *>(&from), &length);
            if (n >= 0) {
                const auto *bytes = reinterpret_cast<const unsigned char *>(&from);
                m_peer.assign(bytes, bytes + length);
            }
        } else {
            n = ::read(m_fd, buffer.data(), buffer.size());
        }
        if (n <= 0)
            return;
        std::lock_guard<std::mutex> lock(m_mutex);
        semhap_band_receive(m_band.get(), buffer.data(), size_t(n));
        readStatus();
    }
}

void Emulator::readStatus()
{
    protocol::DeviceStatus &status = m_state.status;
    status.flags = m_band->flags;
    status.framesReceived = m_band->received;
    status.framesDropped = m_band->dropped;
    status.framesGarbled = semhap_band_garbled(m_band.get());
    status.acknowledged = m_band->last_sequence;
    m_state.watchdogTrips = int(m_band->watchdog_trips);
}

void Emulator::write(void *context, const std::uint8_t *bytes, size_t size)
{
    auto *self = static_cast<Emulator *>(context);
    if (self->m_options.udp) {
        if (!self->m_peer.empty())
            ::sendto(self->m_fd, bytes, size, 0,
                     reinterpret_cast<const sockaddr *>(self->m_peer.data()),
                     socklen_t(self->m_peer.size()));
        return;
    }
    // A full pty (no host reading) drops the reply, as a UART would.
    [[maybe_unused]] const ssize_t n = ::write(self->m_fd, bytes, size);
}

std::uint32_t Emulator::millis(void *context)
{
    const auto *self = static_cast<const Emulator *>(context);
    return std::uint32_t(std::llround((monotonicSeconds() - self->m_start) * 1000.0));
}

void Emulator::setOutput(void *context, std::uint8_t channel, std::uint16_t value)
{
    // Called from inside the band, with m_mutex held by the caller.
    auto *self = static_cast<Emulator *>(context);
    const ChannelSpec &spec = self->m_options.model->channels()[channel];
    self->m_state.setpoints[channel] = protocol::fromWire(value, spec.min, spec.max);
}

void Emulator::tick(double now)
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        semhap_band_poll(m_band.get());
        readStatus();
        for (size_t c = 0; c < m_filters.size(); ++c)
            m_state.values[c] = m_filters[c].step(m_state.setpoints[c]);
    }
    log(now);
}

void Emulator::log(double now)
{
    if (!m_log.isOpen())
        return;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_logged.setpoints = m_state.setpoints; // assigned into, so no allocation per tick
        m_logged.values = m_state.values;
    }
    if (!m_log.write(now - m_start, m_logged.setpoints, m_logged.values))
        m_logError = m_log.error();
}

} // namespace semhap
