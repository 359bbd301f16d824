// SPDX-License-Identifier: MIT
#include "spacemouseinput.h"

#include <QFile>
#include <QFileInfo>
#include <QStringList>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <ctime>

#include <pthread.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

// Last: spnav.h pulls in Xlib.h, whose macros (None, Bool, KeyPress …) clash with Qt's names.
#include <spnav.h>

namespace semhap {

namespace {

// One event on the wire, in both protocols: eight 32-bit integers.
constexpr int EventSize = 8 * int(sizeof(std::int32_t));
// Events read before the event loop gets a turn (a device sends one every 8 to 16 ms).
constexpr int BatchSize = 64;
// The one instance that holds libspnav's global connection.
SpaceMouseInput *s_owner = nullptr;

/**
 * The sockets spnav_open() tries, in its order: $SPNAV_SOCKET, the `socket = …` line of
 * /etc/spnavrc, spacenavd's default.
 */
QStringList daemonSockets()
{
    QStringList paths;
    const QString variable = qEnvironmentVariable("SPNAV_SOCKET");
    if (!variable.isEmpty())
        paths << variable;
    QFile rc(QStringLiteral("/etc/spnavrc"));
    if (rc.open(QIODevice::ReadOnly | QIODevice::Text)) {
        while (!rc.atEnd()) {
            const QString line = QString::fromLocal8Bit(rc.readLine()).trimmed();
            const qsizetype equals = line.indexOf(QLatin1Char('='));
            const QString path = line.mid(equals + 1).trimmed();
            if (line.startsWith(QLatin1String("socket")) && equals > 0 && !path.isEmpty()) {
                paths << path;
                break;
            }
        }
    }
    paths << QStringLiteral("/var/run/spnav.sock");
    return paths;
}

/**
 * Whether spnav_open() may succeed. Each failed spnav_open() leaks its event queue (48 bytes
 * in libspnav 1.0), so while spacenavd is not running (its socket absent) no retry calls it.
 */
bool daemonSocketExists()
{
    const QStringList paths = daemonSockets();
    return std::any_of(paths.begin(), paths.end(),
                       [](const QString &path) { return QFileInfo::exists(path); });
}

/**
 * Blocks SIGPIPE on this thread around a libspnav call that writes: libspnav uses write(),
 * and a daemon that hangs up at the wrong moment would otherwise end the studio. A SIGPIPE
 * the call raised is taken before the old mask comes back.
 */
class SigpipeGuard
{
public:
    SigpipeGuard()
    {
        sigemptyset(&m_pipe);
        sigaddset(&m_pipe, SIGPIPE);
        sigset_t pending;
        sigpending(&pending);
        m_wasPending = sigismember(&pending, SIGPIPE) == 1;
        pthread_sigmask(SIG_BLOCK, &m_pipe, &m_old);
    }
    ~SigpipeGuard()
    {
        sigset_t pending;
        sigpending(&pending);
        if (!m_wasPending && sigismember(&pending, SIGPIPE) == 1) {
            const timespec now{};
            while (sigtimedwait(&m_pipe, nullptr, &now) == -1 && errno == EINTR) {
            }
        }
        pthread_sigmask(SIG_SETMASK, &m_old, nullptr);
    }
    SigpipeGuard(const SigpipeGuard &) = delete;
    SigpipeGuard &operator=(const SigpipeGuard &) = delete;

private:
    sigset_t m_pipe;
    sigset_t m_old;
    bool m_wasPending = false;
};

double axisRate(int value, int fullScale, double deadZone)
{
    const double deflection = std::clamp(double(value) / fullScale, -1.0, 1.0);
    const double magnitude = std::abs(deflection);
    if (magnitude <= deadZone)
        return 0.0;
    return std::copysign((magnitude - deadZone) / (1.0 - deadZone), deflection);
}

bool sameRates(const DriveRates &a, const DriveRates &b)
{
    return a.forward == b.forward && a.right == b.right && a.up == b.up && a.turn == b.turn &&
           a.tilt == b.tilt && a.roll == b.roll;
}

} // namespace

QString SpaceMouseInput::genericName()
{
    return tr("3D mouse");
}

SpaceMouseInput::SpaceMouseInput(QObject *parent) : QObject(parent)
{
    m_deviceName = genericName();
    m_retry.setInterval(DefaultRetryInterval);
    connect(&m_retry, &QTimer::timeout, this, [this] {
        if (connectToDaemon())
            m_retry.stop();
    });
    connect(&m_notifier, &QSocketNotifier::activated, this, &SpaceMouseInput::readEvents);
}

SpaceMouseInput::~SpaceMouseInput()
{
    stop();
}

void SpaceMouseInput::setDrive(HandDrive *drive)
{
    if (m_drive == drive)
        return;
    if (m_drive && !m_sent.isIdle())
        m_drive->setRates(DriveDevice::SpaceMouse, DriveRates());
    m_drive = drive;
    // The new drive gets the deflection with the next event, even an unchanged one.
    m_sent = DriveRates();
}

void SpaceMouseInput::setDeadZone(double fractionOfFullScale)
{
    m_deadZone = std::clamp(fractionOfFullScale, 0.0, 0.9);
}

void SpaceMouseInput::setFullScale(int counts)
{
    m_fullScale = std::max(counts, 1);
}

void SpaceMouseInput::setRetryInterval(int ms)
{
    m_retry.setInterval(std::max(ms, 1));
}

bool SpaceMouseInput::start()
{
    if (m_started)
        return true;
    if (s_owner) {
        qWarning("SpaceMouseInput: another instance holds libspnav's connection");
        return false;
    }
    s_owner = this;
    m_started = true;
    if (!connectToDaemon())
        m_retry.start();
    return true;
}

void SpaceMouseInput::stop()
{
    if (!m_started)
        return;
    m_started = false;
    s_owner = nullptr;
    m_retry.stop();
    if (closeConnection())
        emit connectionChanged(false);
}

DriveRates SpaceMouseInput::ratesFor(const std::array<int, 6> &motion, int fullScale,
                                     double deadZone)
{
    auto axis = [&](size_t index) { return axisRate(motion[index], fullScale, deadZone); };
    DriveRates rates;
    rates.right = axis(0);
    rates.up = axis(1);
    rates.forward = axis(2); // spacenavd's z points away from the user
    rates.tilt = axis(3);    // the top toward the user: the fingers below swing away
    rates.turn = axis(4);
    rates.roll = -axis(5); // the top to the right: the fingers swing left
    return rates;
}

bool SpaceMouseInput::connectToDaemon()
{
    if (m_connected || !daemonSocketExists())
        return false;
    {
        const SigpipeGuard guard;
        if (spnav_open() == -1)
            return false;
    }
    m_connected = true;
    readDeviceName();
    m_notifier.setSocket(spnav_fd());
    m_notifier.setEnabled(true);
    emit connectionChanged(true);
    return true;
}

void SpaceMouseInput::readDeviceName()
{
    m_deviceName = genericName();
    if (spnav_protocol() < 1)
        return;
    // Asks the daemon and waits for its answer (a few milliseconds, at most 400 ms a chunk).
    char name[128] = {};
    const SigpipeGuard guard;
    if (spnav_dev_name(name, int(sizeof name)) > 0)
        m_deviceName = QString::fromLocal8Bit(name);
}

void SpaceMouseInput::readEvents()
{
    const int fd = spnav_fd();
    for (int count = 0; count < BatchSize && m_connected; ++count) {
        char byte = 0;
        const ssize_t peeked = ::recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT);
        if (peeked < 0 && errno == EINTR)
            continue;
        if (peeked < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            break;
        if (peeked <= 0) { // the daemon hung up (0) or the connection broke
            connectionLost();
            return;
        }
        int available = 0;
        if (::ioctl(fd, FIONREAD, &available) == 0 && available < EventSize) {
            // A short packet (a daemon writes each event whole): dropped, see the class.
            char fragment[EventSize];
            const ssize_t dropped = ::recv(fd, fragment, sizeof fragment, MSG_DONTWAIT);
            Q_UNUSED(dropped)
            continue;
        }
        spnav_event event;
        switch (spnav_poll_event(&event)) {
        case SPNAV_EVENT_MOTION:
            m_rates = ratesFor({event.motion.x, event.motion.y, event.motion.z, event.motion.rx,
                                event.motion.ry, event.motion.rz},
                               m_fullScale, m_deadZone);
            break;
        case SPNAV_EVENT_BUTTON:
            if (event.button.press)
                handleButton(event.button.bnum);
            break;
        case SPNAV_EVENT_DEV:
            // spacenavd stays up when the device goes: its last deflection must not stay.
            if (event.dev.op == SPNAV_DEV_RM)
                m_rates = DriveRates();
            else if (event.dev.op == SPNAV_DEV_ADD)
                readDeviceName();
            break;
        default: // unknown types and events of a protocol we did not ask for
            break;
        }
    }
    sendRates();
}

void SpaceMouseInput::handleButton(int button)
{
    if (!m_drive)
        return;
    if (button == 0)
        m_drive->toggleGrip();
    else if (button == 1)
        m_drive->switchHand();
}

bool SpaceMouseInput::closeConnection()
{
    const bool wasConnected = m_connected;
    if (m_connected) {
        // Disabled before the descriptor closes: a notifier must never watch a closed one.
        m_notifier.setEnabled(false);
        spnav_close();
        m_connected = false;
    }
    m_deviceName = genericName();
    m_rates = DriveRates();
    sendRates();
    return wasConnected;
}

void SpaceMouseInput::connectionLost()
{
    closeConnection();
    emit connectionChanged(false);
    if (m_started)
        m_retry.start();
}

void SpaceMouseInput::sendRates()
{
    if (sameRates(m_rates, m_sent))
        return;
    m_sent = m_rates;
    if (m_drive)
        m_drive->setRates(DriveDevice::SpaceMouse, m_rates);
}

} // namespace semhap
