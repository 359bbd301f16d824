// SPDX-License-Identifier: MIT
#pragma once

#include "handdrive.h"

#include <QObject>
#include <QPointer>
#include <QSocketNotifier>
#include <QString>
#include <QTimer>

#include <array>

namespace semhap {

/**
 * A 3D mouse (SpaceNavigator, SpaceMouse, Spaceball …) driving the active hand through
 * spacenavd, the free 3Dconnexion driver, and its client library libspnav: the cap's
 * deflection sets the HandDrive's rates, and the hand moves and turns the way the cap is
 * pushed and turned (3Dconnexion's "object mode", one rule for all six axes).
 *
 * spacenavd reports x to the right, y up and z away from the user (libspnav's own
 * spnav_posrot_moveobj() negates z and rz to reach a z-toward-the-viewer frame), each
 * rotation right-handed about its axis. Each axis is divided by fullScale(), clamped to
 * [-1, 1] and has deadZone() taken out:
 *
 * | cap                                              | spacenavd | DriveRates  |
 * | ------------------------------------------------ | --------- | ----------- |
 * | pushed right / left                              | +x / -x   | right ±     |
 * | pulled up / pressed down                         | +y / -y   | up ±        |
 * | pushed away / pulled toward the user             | +z / -z   | forward ±   |
 * | twisted counter-clockwise / clockwise from above | +ry / -ry | turn ±      |
 * | top tipped toward / away from the user           | +rx / -rx | tilt ±      |
 * | top tipped left / right                          | -rz / +rz | roll ±      |
 * | button 0 (left) pressed                          |           | toggleGrip  |
 * | button 1 (right) pressed                         |           | switchHand  |
 *
 * The fingers point down, so they swing against the cap's top: tipping the top away swings
 * them toward the user (tilt < 0), tipping it left swings them right (roll > 0).
 *
 * Safety: losing the daemon (it closes the socket), a device removal it reports and stop()
 * all send zero rates, so the arm never keeps a deflection nobody holds. A packet shorter
 * than an event is dropped before libspnav reads it: libspnav would make up the rest of the
 * event from whatever its stack held.
 *
 * libspnav keeps its one connection in global state: only one SpaceMouseInput in the
 * process may be started at a time. Connecting blocks the GUI thread briefly (up to 300 ms
 * with a spacenavd older than 1.0, which does not answer libspnav's protocol request).
 */
class SpaceMouseInput : public QObject
{
    Q_OBJECT

public:
    /** The fraction of full scale taken for the hand resting on the cap. */
    static constexpr double DefaultDeadZone = 0.05;
    /** What a SpaceNavigator reports at full deflection with spacenavd's default sensitivity. */
    static constexpr int DefaultFullScale = 350;
    /** How often a missing daemon is looked for (ms): spacenavd and devices come and go. */
    static constexpr int DefaultRetryInterval = 2000;
    /** The name of a device whose daemon cannot say (a protocol 0 spacenavd). */
    static QString genericName();

    explicit SpaceMouseInput(QObject *parent = nullptr);
    /** Stops (zero rates to the drive) and hands libspnav to the next instance. */
    ~SpaceMouseInput() override;

    /** Where the rates and button actions go (null: nowhere); the old drive gets zeros. */
    void setDrive(HandDrive *drive);
    /** Deflections below this fraction of full scale count as none (from the next event). */
    void setDeadZone(double fractionOfFullScale);
    double deadZone() const { return m_deadZone; }
    /** The count that means full speed, larger ones clamped (from the next event). */
    void setFullScale(int counts);
    int fullScale() const { return m_fullScale; }
    /** How long to wait between attempts to reach the daemon (ms). */
    void setRetryInterval(int ms);

    /**
     * Connects to spacenavd now and, until it succeeds and after every loss, again every
     * retry interval; false (and nothing done) when another instance holds libspnav.
     */
    bool start();
    /** Disconnects, stops retrying and zeroes the rates sent to the drive. */
    void stop();
    bool isStarted() const { return m_started; }
    bool isConnected() const { return m_connected; }
    /** The daemon's name for the device ("SpaceNavigator"), else genericName(). */
    QString deviceName() const { return m_deviceName; }

    /**
     * The rates for spacenavd's motion values {x, y, z, rx, ry, rz}, by the class's table:
     * each over `fullScale`, clamped to [-1, 1], with `deadZone` taken out and the rest
     * rescaled to reach 1 at full scale. No grip: the device has no analogue one.
     */
    static DriveRates ratesFor(const std::array<int, 6> &motion, int fullScale, double deadZone);

signals:
    /** The connection to spacenavd came or went: the user sees why the cap does nothing. */
    void connectionChanged(bool connected);

private:
    bool connectToDaemon();
    void readEvents();
    /** Closes libspnav's connection and zeroes the rates; true if one was open. */
    bool closeConnection();
    void connectionLost();
    void handleButton(int button);
    void readDeviceName();
    /** Sends m_rates to the drive if they differ from what it was sent last. */
    void sendRates();

    QPointer<HandDrive> m_drive;
    QSocketNotifier m_notifier{QSocketNotifier::Read};
    QTimer m_retry;
    DriveRates m_rates;
    DriveRates m_sent;
    double m_deadZone = DefaultDeadZone;
    int m_fullScale = DefaultFullScale;
    QString m_deviceName;
    bool m_started = false;
    bool m_connected = false;
};

} // namespace semhap
