// SPDX-License-Identifier: MIT
#pragma once

#include "fdlink.h"
#include "transportscheme.h"

#include <QString>

#include <memory>
#include <vector>

struct sp_port;

namespace semhap {

/** A serial port as `semhap devices` lists it. */
struct SerialPortInfo
{
    QString path;
    QString description;
    int vendorId = -1; ///< USB only; -1 otherwise
    int productId = -1;
};

/**
 * A serial port: real ports through libserialport (which knows their USB identity), and
 * pseudo-terminals — emulators, socat links — or anything else it cannot open through
 * plain termios in raw mode, since libserialport 0.1.1 cannot open a pty.
 */
class SerialLink : public FdLink
{
public:
    SerialLink(const QString &path, int baud);
    ~SerialLink() override;

    QString uri() const override;
    bool open(QString *error) override;

    /** The serial ports libserialport sees (real ports; not ptys). */
    static std::vector<SerialPortInfo> enumerate();
    /** `PATH[?baud=N]`, what follows `serial:`, into the name and baud; false with a reason. */
    static bool parseAddress(const QString &address, DeviceUri *uri, QString *error);
    /** The same, spelled: the baud only when it is not the default. */
    static QString formatAddress(const DeviceUri &uri);
    /** Appends the ports enumerate() finds, as listed to the user. */
    static void present(std::vector<PortInfo> *out);

private:
    struct PortDeleter
    {
        void operator()(sp_port *port) const;
    };

    void release() override;
    bool openWithLibrary(const QByteArray &path, QString *error);
    bool openWithTermios(const QByteArray &path, QString *error);

    QString m_path;
    int m_baud;
    std::unique_ptr<sp_port, PortDeleter> m_port;
};

} // namespace semhap
