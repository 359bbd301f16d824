// SPDX-License-Identifier: MIT
#include "emulator.h"

#include "jsonlineswriter.h"
#include "monotonic.h"

#include <QFileInfo>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

namespace semhap {

namespace {

QString errnoText()
{
    return QString::fromLocal8Bit(std::strerror(errno));
}

/** Values are logged to 1e-4 so that a settling lag stops producing lines. */
double rounded(double v)
{
    return std::round(v * 1e4) / 1e4;
}

void appendArray(QByteArray &line, const std::vector<double> &values)
{
    line += '[';
    for (size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            line += ',';
        JsonLinesWriter::appendNumber(line, rounded(values[i]));
    }
    line += ']';
}

} // namespace

Emulator::Emulator(const EmulatorOptions &options) : m_options(options)
{
    const int channels = options.model->channelCount();
    m_filters.assign(size_t(channels), ResponseFilter(*options.model, options.model->rate()));
    m_state.setpoints.assign(size_t(channels), 0.0);
    m_state.values.assign(size_t(channels), 0.0);
}

Emulator::~Emulator()
{
    if (!m_options.link.isEmpty() && !m_ptyPath.isEmpty() &&
        QFileInfo(m_options.link).symLinkTarget() == m_ptyPath)
        QFile::remove(m_options.link);
    if (m_slaveFd >= 0)
        ::close(m_slaveFd);
    if (m_fd >= 0)
        ::close(m_fd);
}

bool Emulator::open(QString *error)
{
    if (!(m_options.udp ? openUdp(error) : openPty(error)))
        return false;
    if (!m_options.logPath.isEmpty()) {
        m_log.setFileName(m_options.logPath);
        if (!m_log.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
            *error =
                QStringLiteral("%1: cannot write: %2").arg(m_options.logPath, m_log.errorString());
            return false;
        }
    }
    m_start = monotonicSeconds();
    return true;
}

bool Emulator::openPty(QString *error)
{
    m_fd = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (m_fd < 0 || ::grantpt(m_fd) != 0 || ::unlockpt(m_fd) != 0) {
        *error = QStringLiteral("cannot create a pseudo-terminal: %1").arg(errnoText());
        return false;
    }
    m_ptyPath = QString::fromLocal8Bit(::ptsname(m_fd));
    m_slaveFd = ::open(m_ptyPath.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (m_slaveFd < 0) {
        *error = QStringLiteral("%1: %2").arg(m_ptyPath, errnoText());
        return false;
    }
    // Raw from the start: an echoing line discipline would send the host's bytes back.
    termios tio{};
    ::tcgetattr(m_slaveFd, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(m_slaveFd, TCSANOW, &tio);
    ::fcntl(m_fd, F_SETFL, ::fcntl(m_fd, F_GETFL) | O_NONBLOCK);
    if (m_options.link.isEmpty())
        return true;
    const QFileInfo existing(m_options.link);
    if (existing.exists() && !existing.isSymLink()) {
        *error = QStringLiteral("%1: exists and is not a symlink; not replacing it")
                     .arg(m_options.link);
        return false;
    }
    // A new link renamed over the old one, so a host never sees the path missing.
    const QByteArray temporary = (m_options.link + QStringLiteral(".new")).toLocal8Bit();
    ::unlink(temporary.constData());
    if (::symlink(m_ptyPath.toLocal8Bit().constData(), temporary.constData()) != 0 ||
        ::rename(temporary.constData(), m_options.link.toLocal8Bit().constData()) != 0) {
        *error = QStringLiteral("%1: cannot link: %2").arg(m_options.link, errnoText());
        return false;
    }
    return true;
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
                         : m_ptyPath;
}

QString Emulator::uri() const
{
    if (m_options.udp)
        return QStringLiteral("udp:") + address();
    return QStringLiteral("serial:") + (m_options.link.isEmpty() ? m_ptyPath : m_options.link);
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
            receive(monotonicSeconds());
    }
    return true;
}

void Emulator::receive(double now)
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
        m_decoder.feed(buffer.data(), size_t(n),
                       [this, now](const protocol::Message &m) { handle(m, now); });
        std::lock_guard<std::mutex> lock(m_mutex);
        m_state.status.framesGarbled = m_decoder.counters().errors();
    }
}

void Emulator::handle(const protocol::Message &message, double now)
{
    m_lastFrame = now;
    protocol::Message answer;
    answer.sequence = message.sequence;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        protocol::DeviceStatus &status = m_state.status;
        ++status.framesReceived;
        if (m_lastSequence >= 0 && message.sequence != std::uint16_t(m_lastSequence + 1))
            status.framesDropped += std::uint16_t(message.sequence - m_lastSequence - 1);
        m_lastSequence = message.sequence;
        switch (message.type) {
        case protocol::MessageType::SetValues: {
            const auto &channels = m_options.model->channels();
            if (message.channelCount != int(channels.size()))
                status.flags |= protocol::ChannelCountMismatch;
            const int n = std::min(message.channelCount, int(channels.size()));
            for (int c = 0; c < n; ++c)
                m_state.setpoints[size_t(c)] = m_options.model->clamp(
                    c, protocol::fromWire(message.values[size_t(c)], channels[size_t(c)].min,
                                          channels[size_t(c)].max));
            return;
        }
        case protocol::MessageType::StopAll:
            std::fill(m_state.setpoints.begin(), m_state.setpoints.end(), 0.0);
            answer.type = protocol::MessageType::Status;
            break;
        case protocol::MessageType::Heartbeat:
            answer.type = protocol::MessageType::HeartbeatReply;
            answer.timestamp = message.timestamp;
            break;
        case protocol::MessageType::StatusRequest:
            answer.type = protocol::MessageType::Status;
            break;
        case protocol::MessageType::IdentifyRequest: {
            answer.type = protocol::MessageType::IdentifyReply;
            answer.identity.model = m_options.model->name();
            answer.identity.firmwareMajor = 1;
            for (const ChannelSpec &c : m_options.model->channels())
                answer.identity.channels.push_back({c.name, float(c.min), float(c.max)});
            break;
        }
        default:
            return; // replies from another host: nothing to answer
        }
        if (answer.type == protocol::MessageType::Status) {
            answer.status = status;
            answer.status.acknowledged = message.sequence;
            status.flags = 0;
        }
    }
    reply(answer);
}

void Emulator::reply(const protocol::Message &message)
{
    QByteArray bytes;
    protocol::encode(message, &bytes);
    if (m_options.udp) {
        if (!m_peer.empty())
            ::sendto(m_fd, bytes.constData(), size_t(bytes.size()), 0,
                     reinterpret_cast<const sockaddr *>(m_peer.data()), socklen_t(m_peer.size()));
        return;
    }
    // A full pty (no host reading) drops the reply, as a UART would.
    [[maybe_unused]] const ssize_t n = ::write(m_fd, bytes.constData(), size_t(bytes.size()));
}

void Emulator::tick(double now)
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        const bool quiet = m_lastFrame < 0.0 || now - m_lastFrame > m_options.watchdog;
        if (quiet && std::any_of(m_state.setpoints.begin(), m_state.setpoints.end(),
                                 [](double v) { return v != 0.0; })) {
            std::fill(m_state.setpoints.begin(), m_state.setpoints.end(), 0.0);
            m_state.status.flags |= protocol::WatchdogTripped;
            ++m_state.watchdogTrips;
        }
        for (size_t c = 0; c < m_filters.size(); ++c)
            m_state.values[c] = m_filters[c].step(m_state.setpoints[c]);
    }
    log(now);
}

void Emulator::log(double now)
{
    if (!m_log.isOpen())
        return;
    QByteArray state;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        appendArray(state, m_state.setpoints);
        state += ", \"values\": ";
        appendArray(state, m_state.values);
    }
    if (state == m_lastLogged)
        return;
    m_lastLogged = state;
    QByteArray line = "{\"t\": ";
    JsonLinesWriter::appendNumber(line, now - m_start);
    line += ", \"setpoint\": " + state + "}\n";
    // Written line by line, for whoever follows the band live; a full disk ends the run.
    if (m_log.write(line) != line.size() || !m_log.flush()) {
        m_logError =
            QStringLiteral("%1: cannot write: %2").arg(m_options.logPath, m_log.errorString());
        m_log.close();
    }
}

} // namespace semhap
