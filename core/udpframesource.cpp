// SPDX-License-Identifier: MIT
#include "udpframesource.h"

#include <QHostAddress>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUdpSocket>

#include <algorithm>
#include <cmath>

namespace semhap {

UdpFrameSource::UdpFrameSource(QObject *parent) : QObject(parent) {}

UdpFrameSource::~UdpFrameSource() = default;

bool UdpFrameSource::bind(const QString &address, int port, QString *error)
{
    QHostAddress host;
    if (!host.setAddress(address)) {
        *error = QStringLiteral("%1: not an IP address").arg(address);
        return false;
    }
    if (port < 0 || port > 65535) {
        *error = QStringLiteral("%1: not a UDP port").arg(port);
        return false;
    }
    auto socket = std::make_unique<QUdpSocket>();
    if (!socket->bind(host, quint16(port))) {
        *error = QStringLiteral("udp:%1:%2: %3").arg(address).arg(port).arg(socket->errorString());
        return false;
    }
    // A bigger kernel buffer rides out bursts while the pipeline is busy.
    socket->setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, 4 * 1024 * 1024);
    connect(socket.get(), &QUdpSocket::readyRead, this, &UdpFrameSource::datagramsPending);
    m_socket = std::move(socket);
    m_buffer.resize(64 * 1024);
    m_stats = Stats();
    m_lastFrame = -1.0;
    m_clock.start();
    return true;
}

int UdpFrameSource::port() const
{
    return m_socket ? int(m_socket->localPort()) : 0;
}

bool UdpFrameSource::waitForDatagrams(int msecs)
{
    if (!m_socket)
        return false;
    return m_socket->hasPendingDatagrams() || m_socket->waitForReadyRead(msecs);
}

int UdpFrameSource::poll(const FrameHandler &handler, int maxDatagrams)
{
    int frames = 0;
    for (int i = 0; m_socket && i < maxDatagrams && m_socket->hasPendingDatagrams(); ++i) {
        const qint64 size = m_socket->pendingDatagramSize();
        const qint64 read = m_socket->readDatagram(m_buffer.data(), m_buffer.size());
        if (read < 0)
            break;
        ++m_stats.datagrams;
        const double arrival = double(m_clock.nsecsElapsed()) * 1e-9;
        if (size > MaxDatagramSize) {
            ++m_stats.oversize;
            reject(QStringLiteral("datagram of %1 bytes is over the limit of %2")
                       .arg(size)
                       .arg(MaxDatagramSize));
            continue;
        }
        handle(QByteArray::fromRawData(m_buffer.constData(), read), arrival, handler, &frames);
    }
    return frames;
}

void UdpFrameSource::handle(const QByteArray &datagram, double arrival,
                            const FrameHandler &handler, int *frames)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(datagram, &error);
    if (error.error != QJsonParseError::NoError) {
        reject(QStringLiteral("invalid JSON at byte %1: %2")
                   .arg(error.offset + 1)
                   .arg(error.errorString()));
        return;
    }
    ContactFrame frame;
    QString reason;
    const auto take = [&](const QJsonObject &object) {
        if (!m_parser.parse(object, &frame, &reason))
            return false;
        ++m_stats.frames;
        ++*frames;
        m_lastFrame = arrival;
        handler(frame, arrival);
        return true;
    };
    if (document.isObject()) {
        if (!take(document.object()))
            reject(reason);
        return;
    }
    if (!document.isArray()) {
        reject(QStringLiteral("a datagram must hold a frame object or an array of them"));
        return;
    }
    // A batch stops at its first invalid frame: a sender that got one wrong most likely got
    // the rest wrong too, and a flood of them must cost one message, not hundreds.
    const QJsonArray batch = document.array();
    for (qsizetype i = 0; i < batch.size(); ++i) {
        const bool object = batch.at(i).isObject();
        if (object && take(batch.at(i).toObject()))
            continue;
        if (!object)
            reason = QStringLiteral("a contact frame must be a JSON object");
        const qsizetype dropped = batch.size() - i - 1;
        m_stats.rejected += quint64(dropped);
        reject(QStringLiteral("[%1]: ").arg(i) + reason +
               (dropped > 0
                    ? QStringLiteral(" (the batch's %1 later frame(s) dropped)").arg(dropped)
                    : QString()));
        return;
    }
}

bool UdpFrameSource::fellSilent()
{
    if (m_lastFrame < 0 || double(m_clock.nsecsElapsed()) * 1e-9 - m_lastFrame < m_silence)
        return false;
    m_lastFrame = -1.0;
    m_parser.restartClock();
    return true;
}

qint64 UdpFrameSource::msecsToSilence() const
{
    if (m_lastFrame < 0)
        return -1;
    const double left = m_lastFrame + m_silence - double(m_clock.nsecsElapsed()) * 1e-9;
    return std::max<qint64>(0, qint64(std::ceil(left * 1000.0)));
}

void UdpFrameSource::reject(const QString &reason)
{
    ++m_stats.rejected;
    if (m_onError)
        m_onError(QStringLiteral("udp:%1: ").arg(port()) + reason);
}

} // namespace semhap
