// SPDX-License-Identifier: MIT
#include "seriallink.h"

#include <libserialport.h>

#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace semhap {

namespace {

speed_t termiosSpeed(int baud)
{
    switch (baud) {
    case 9600:
        return B9600;
    case 19200:
        return B19200;
    case 38400:
        return B38400;
    case 57600:
        return B57600;
    case 230400:
        return B230400;
    case 460800:
        return B460800;
    case 921600:
        return B921600;
    case 1000000:
        return B1000000;
    default:
        return B115200;
    }
}

QString errnoText()
{
    return QString::fromLocal8Bit(std::strerror(errno));
}

} // namespace

void SerialLink::PortDeleter::operator()(sp_port *port) const
{
    sp_close(port);
    sp_free_port(port);
}

SerialLink::SerialLink(const QString &path, int baud) : m_path(path), m_baud(baud) {}

SerialLink::~SerialLink()
{
    close();
}

QString SerialLink::uri() const
{
    return QStringLiteral("serial:") + m_path;
}

bool SerialLink::open(QString *error)
{
    close();
    // A --link symlink is followed afresh on every attempt: a restarted emulator moves it.
    const QByteArray path = QFileInfo(m_path).canonicalFilePath().toLocal8Bit();
    if (path.isEmpty()) {
        *error = QStringLiteral("%1: no such device").arg(m_path);
        return false;
    }
    QString libraryError;
    if (!path.startsWith("/dev/pts/") && openWithLibrary(path, &libraryError))
        return true;
    return openWithTermios(path, error);
}

bool SerialLink::openWithLibrary(const QByteArray &path, QString *error)
{
    sp_port *port = nullptr;
    if (sp_get_port_by_name(path.constData(), &port) != SP_OK) {
        *error = QStringLiteral("libserialport does not know %1").arg(m_path);
        return false;
    }
    std::unique_ptr<sp_port, PortDeleter> owned(port);
    if (sp_open(port, SP_MODE_READ_WRITE) != SP_OK || sp_set_baudrate(port, m_baud) != SP_OK ||
        sp_set_bits(port, 8) != SP_OK || sp_set_parity(port, SP_PARITY_NONE) != SP_OK ||
        sp_set_stopbits(port, 1) != SP_OK ||
        sp_set_flowcontrol(port, SP_FLOWCONTROL_NONE) != SP_OK) {
        char *message = sp_last_error_message();
        *error = QString::fromLocal8Bit(message);
        sp_free_error_message(message);
        return false;
    }
    int fd = -1;
    if (sp_get_port_handle(port, &fd) != SP_OK || fd < 0) {
        *error = QStringLiteral("%1: no descriptor").arg(m_path);
        return false;
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    sp_flush(port, SP_BUF_BOTH);
    m_port = std::move(owned);
    m_fd = fd;
    return true;
}

bool SerialLink::openWithTermios(const QByteArray &path, QString *error)
{
    const int fd = ::open(path.constData(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        *error = QStringLiteral("%1: %2").arg(m_path, errnoText());
        return false;
    }
    termios tio{};
    if (::tcgetattr(fd, &tio) != 0) {
        *error = QStringLiteral("%1: not a terminal: %2").arg(m_path, errnoText());
        ::close(fd);
        return false;
    }
    ::cfmakeraw(&tio);
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    ::cfsetspeed(&tio, termiosSpeed(m_baud));
    ::tcsetattr(fd, TCSANOW, &tio);
    ::tcflush(fd, TCIOFLUSH);
    m_fd = fd;
    return true;
}

void SerialLink::release()
{
    if (m_port) {
        m_port.reset(); // sp_close closes the descriptor
        m_fd = -1;
    }
}

std::vector<SerialPortInfo> SerialLink::enumerate()
{
    std::vector<SerialPortInfo> out;
    sp_port **ports = nullptr;
    if (sp_list_ports(&ports) != SP_OK)
        return out;
    for (int i = 0; ports[i]; ++i) {
        SerialPortInfo info;
        info.path = QString::fromLocal8Bit(sp_get_port_name(ports[i]));
        if (const char *description = sp_get_port_description(ports[i]))
            info.description = QString::fromLocal8Bit(description);
        int vid = 0;
        int pid = 0;
        if (sp_get_port_transport(ports[i]) == SP_TRANSPORT_USB &&
            sp_get_port_usb_vid_pid(ports[i], &vid, &pid) == SP_OK) {
            info.vendorId = vid;
            info.productId = pid;
        }
        out.push_back(info);
    }
    sp_free_port_list(ports);
    return out;
}

bool SerialLink::parseAddress(const QString &address, DeviceUri *uri, QString *error)
{
    const qsizetype query = address.indexOf(QLatin1Char('?'));
    uri->name = address.left(query);
    if (uri->name.isEmpty()) {
        *error = QStringLiteral("a serial device needs a path (serial:/dev/ttyACM0)");
        return false;
    }
    if (query >= 0) {
        const QString option = address.mid(query + 1);
        bool ok = false;
        const int baud = option.startsWith(QLatin1String("baud=")) ? option.mid(5).toInt(&ok) : 0;
        if (!ok || baud <= 0) {
            *error =
                QStringLiteral("unknown option '%1' (serial takes ?baud=N, N > 0)").arg(option);
            return false;
        }
        uri->baud = baud;
    }
    return true;
}

QString SerialLink::formatAddress(const DeviceUri &uri)
{
    return uri.baud == DeviceUri::DefaultBaud
               ? uri.name
               : QStringLiteral("%1?baud=%2").arg(uri.name).arg(uri.baud);
}

void SerialLink::present(std::vector<PortInfo> *out)
{
    for (const SerialPortInfo &port : enumerate())
        out->push_back({QStringLiteral("serial:") + port.path, QStringLiteral("serial"),
                        port.description, port.vendorId, port.productId});
}

} // namespace semhap
