// SPDX-License-Identifier: MIT
#pragma once

#include "driveoperator.h"
#include "world.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QHostAddress>
#include <QObject>
#include <QUdpSocket>

#include <array>

namespace semhap {

/** What one datagram says about a hand: its command, and which parts of it it sets. */
struct PoseUpdate
{
    HandCommand command; ///< the parts not set are left as they were
    bool hasPos = false;
    bool hasQuat = false;
    bool hasGrip = false;
};

/**
 * Wrist poses and grips from a tracking rig (VR, motion capture, a script) over UDP: one
 * JSON object per datagram, as studio/README.md describes, applied to a DriveOperator.
 * Bad datagrams are counted and described, never fatal; a flood is read in batches so the
 * GUI's event loop keeps running.
 */
class PoseInput : public QObject
{
    Q_OBJECT

public:
    /** Larger datagrams are refused unread: a pose is well under a hundred bytes. */
    static constexpr qint64 MaxDatagramSize = 2048;
    /** Positions farther out than this (m) are taken for a unit mistake (millimetres). */
    static constexpr double MaxCoordinate = 2.0;

    explicit PoseInput(QObject *parent = nullptr);
    ~PoseInput() override;

    /** Where valid commands go (null: nowhere). Not owned. */
    void setOperator(DriveOperator *op) { m_operator = op; }
    /** The scene driven (null: any hand goes): a hand it lacks is an error. */
    void setWorld(const World *world);

    /** Starts listening; false with errorString() when the port cannot be bound. */
    bool listen(quint16 port, const QHostAddress &address = QHostAddress::LocalHost);
    void close();
    bool isListening() const;
    /** The bound port (useful after listening on port 0). */
    quint16 port() const;
    QString errorString() const { return m_socket.errorString(); }

    /**
     * Parses one datagram into `command`; false with `error` saying which key is wrong and
     * why. A datagram without "pos" turns or grips the hand where it is.
     */
    static bool parse(const QByteArray &datagram, PoseUpdate *update, QString *error);

    /** The next valid datagram starts driving again (and emits driveStarted()). */
    void endDrive() { m_driving = false; }
    bool isDriving() const { return m_driving; }

    quint64 datagramCount() const { return m_datagrams; }
    quint64 acceptedCount() const { return m_accepted; }
    quint64 malformedCount() const { return m_malformed; }
    /** The last refusal: "datagram 12: key 'pos': expected an array of 3 numbers". */
    QString lastError() const { return m_lastError; }
    /** Datagrams per second over the last second. */
    double rate() const;

signals:
    /** The first valid datagram after listen() or endDrive(): the rig takes the grippers. */
    void driveStarted();
    /** A datagram was refused; lastError() says why. */
    void malformed(const QString &error);

private:
    void readPending();
    void handle(const QByteArray &datagram);
    void refuse(const QString &error);
    void countForRate();

    QUdpSocket m_socket;
    const World *m_world = nullptr;
    DriveOperator *m_operator = nullptr;
    /** What each hand was last sent: a datagram without a key keeps its value. */
    std::array<Pose, 2> m_pose{};
    std::array<bool, 2> m_hasPos{};
    QByteArray m_buffer;
    bool m_readScheduled = false;
    bool m_driving = false;
    quint64 m_datagrams = 0;
    quint64 m_accepted = 0;
    quint64 m_malformed = 0;
    QString m_lastError;
    QElapsedTimer m_rateClock;
    quint64 m_windowCount = 0;
    quint64 m_lastWindowCount = 0;
};

} // namespace semhap
