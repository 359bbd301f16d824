// SPDX-License-Identifier: MIT
#include "poseinput.h"

#include "driveoperator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cmath>

namespace semhap {

namespace {

// Datagrams read before the event loop gets a turn: a flood must not freeze the GUI.
constexpr int BatchSize = 256;
// Room for a burst of a rig's datagrams while the GUI thread is busy painting.
constexpr int ReceiveBuffer = 1 << 20;

/** Reads `value` as `count` finite numbers; false when it is anything else. */
template<size_t N> bool numbers(const QJsonValue &value, std::array<double, N> *out)
{
    const QJsonArray array = value.toArray();
    if (!value.isArray() || array.size() != qsizetype(N))
        return false;
    for (size_t i = 0; i < N; ++i) {
        const QJsonValue item = array.at(qsizetype(i));
        if (!item.isDouble() || !std::isfinite(item.toDouble()))
            return false;
        (*out)[i] = item.toDouble();
    }
    return true;
}

} // namespace

PoseInput::PoseInput(QObject *parent) : QObject(parent)
{
    connect(&m_socket, &QUdpSocket::readyRead, this, &PoseInput::readPending);
    m_buffer.resize(MaxDatagramSize);
}

PoseInput::~PoseInput() = default;

void PoseInput::setWorld(const World *world)
{
    m_world = world;
    m_hasPos = {};
    m_pose = {};
    m_driving = false;
}

bool PoseInput::listen(quint16 port, const QHostAddress &address)
{
    close();
    if (!m_socket.bind(address, port))
        return false;
    m_socket.setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, ReceiveBuffer);
    m_driving = false;
    m_rateClock.start();
    return true;
}

void PoseInput::close()
{
    m_socket.close();
}

bool PoseInput::isListening() const
{
    return m_socket.state() == QAbstractSocket::BoundState;
}

quint16 PoseInput::port() const
{
    return m_socket.localPort();
}

double PoseInput::rate() const
{
    if (!m_rateClock.isValid())
        return 0.0;
    // A sliding second: this window's datagrams plus the part of the last window's that
    // still falls within it. A rig that stopped sending fades to 0 within a second.
    const double elapsed = double(m_rateClock.elapsed()) / 1000.0;
    if (elapsed >= 2.0)
        return 0.0;
    if (elapsed >= 1.0)
        return double(m_windowCount) * (2.0 - elapsed);
    return double(m_windowCount) + double(m_lastWindowCount) * (1.0 - elapsed);
}

void PoseInput::countForRate()
{
    const qint64 elapsed = m_rateClock.elapsed();
    if (elapsed >= 1000) {
        m_lastWindowCount = elapsed < 2000 ? m_windowCount : 0;
        m_windowCount = 0;
        m_rateClock.restart();
    }
    ++m_windowCount;
}

void PoseInput::readPending()
{
    m_readScheduled = false;
    for (int n = 0; n < BatchSize && m_socket.hasPendingDatagrams(); ++n) {
        ++m_datagrams;
        countForRate();
        const qint64 size = m_socket.pendingDatagramSize();
        if (size > MaxDatagramSize) {
            m_socket.readDatagram(nullptr, 0); // discards it
            refuse(tr("%1 bytes, larger than the limit of %2").arg(size).arg(MaxDatagramSize));
            continue;
        }
        const qint64 read = m_socket.readDatagram(m_buffer.data(), MaxDatagramSize);
        if (read < 0) {
            refuse(m_socket.errorString());
            continue;
        }
        handle(QByteArray::fromRawData(m_buffer.constData(), qsizetype(read)));
    }
    if (m_socket.hasPendingDatagrams() && !m_readScheduled) {
        m_readScheduled = true;
        QTimer::singleShot(0, this, &PoseInput::readPending);
    }
}

bool PoseInput::parse(const QByteArray &datagram, PoseUpdate *update, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(datagram, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *error =
            tr("not JSON: %1 at byte %2").arg(parseError.errorString()).arg(parseError.offset);
        return false;
    }
    if (!document.isObject()) {
        *error = tr("expected a JSON object");
        return false;
    }
    const QJsonObject object = document.object();
    *update = PoseUpdate();
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString &key = it.key();
        const QJsonValue value = it.value();
        if (key == QLatin1String("hand")) {
            if (!gripperFromName(value.toString(), &update->command.hand)) {
                *error = tr("key 'hand': expected \"left\" or \"right\"");
                return false;
            }
        } else if (key == QLatin1String("pos")) {
            if (!numbers(value, &update->command.target.pos)) {
                *error = tr("key 'pos': expected an array of 3 numbers (metres)");
                return false;
            }
            for (double v : update->command.target.pos) {
                if (std::abs(v) > MaxCoordinate) {
                    *error = tr("key 'pos': %1 is beyond %2 m from the origin (positions "
                                "are in metres)")
                                 .arg(v)
                                 .arg(MaxCoordinate);
                    return false;
                }
            }
            update->hasPos = true;
        } else if (key == QLatin1String("quat")) {
            auto &q = update->command.target.quat;
            const bool valid = numbers(value, &q);
            const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!valid || norm < 1e-6) {
                *error = tr("key 'quat': expected an array of 4 numbers [w, x, y, z], not all 0");
                return false;
            }
            for (double &v : q)
                v /= norm;
            update->hasQuat = true;
        } else if (key == QLatin1String("yaw")) {
            if (!value.isDouble() || !std::isfinite(value.toDouble())) {
                *error = tr("key 'yaw': expected a number (radians)");
                return false;
            }
            update->command.target.quat = yawQuaternion(value.toDouble());
            update->hasQuat = true;
        } else if (key == QLatin1String("grip")) {
            if (!value.isDouble() || !std::isfinite(value.toDouble())) {
                *error = tr("key 'grip': expected a number (newtons)");
                return false;
            }
            update->command.grip = value.toDouble();
            update->hasGrip = true;
        } else {
            *error = tr("unknown key '%1' (expected hand, pos, quat or yaw, grip)").arg(key);
            return false;
        }
    }
    if (!object.contains(QLatin1String("hand"))) {
        *error = tr("key 'hand' is missing");
        return false;
    }
    if (object.contains(QLatin1String("quat")) && object.contains(QLatin1String("yaw"))) {
        *error = tr("keys 'quat' and 'yaw': give one of them");
        return false;
    }
    return true;
}

void PoseInput::handle(const QByteArray &datagram)
{
    PoseUpdate update;
    QString error;
    if (!parse(datagram, &update, &error)) {
        refuse(error);
        return;
    }
    const size_t hand = size_t(update.command.hand);
    if (m_world && !m_world->hasGripper(update.command.hand)) {
        refuse(
            tr("key 'hand': this scene has no %1 gripper").arg(gripperName(update.command.hand)));
        return;
    }
    if (update.hasQuat && !update.hasPos && !m_hasPos[hand]) {
        refuse(tr("key 'pos' is needed before the %1 hand can be turned on its own")
                   .arg(gripperName(update.command.hand)));
        return;
    }
    if (update.hasPos) {
        m_pose[hand].pos = update.command.target.pos;
        m_hasPos[hand] = true;
    }
    if (update.hasQuat)
        m_pose[hand].quat = update.command.target.quat;

    ++m_accepted;
    if (!m_driving) {
        m_driving = true;
        emit driveStarted();
    }
    if (!m_operator)
        return;
    if (update.hasPos || update.hasQuat)
        m_operator->setTarget(update.command.hand, m_pose[hand]);
    if (update.hasGrip)
        m_operator->setGrip(update.command.hand, update.command.grip);
}

void PoseInput::refuse(const QString &error)
{
    ++m_malformed;
    m_lastError = tr("datagram %1: %2").arg(m_datagrams).arg(error);
    emit malformed(m_lastError);
}

} // namespace semhap
