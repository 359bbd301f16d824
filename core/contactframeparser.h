// SPDX-License-Identifier: MIT
#pragma once

#include "actortable.h"
#include "contactframe.h"

#include <QByteArray>
#include <QString>

#include <array>

class QJsonObject;

namespace semhap {

/**
 * Parses contact frames (spec section 1) from JSON text or objects, wherever they come
 * from — a JSON Lines file, a UDP datagram — and keeps what validity depends on: each
 * gripper's last `t` (strictly increasing, within MaxTime, and no more than the maximum gap
 * past the stream's latest) and the actor names seen. A rejected frame changes neither.
 */
class ContactFrameParser
{
public:
    /** The largest |t| a frame may carry (s): about 317 years, so Unix time fits. */
    static constexpr double MaxTime = 1e10;
    /** How far past the stream's latest `t` a frame may jump, unless set otherwise (s). */
    static constexpr double DefaultMaxGap = 10.0;

    /** How far past the stream's latest `t` a frame may jump (s, > 0). */
    void setMaxGap(double seconds) { m_maxGap = seconds; }
    double maxGap() const { return m_maxGap; }
    /**
     * Forgets the stream's clock: the next frame starts it again, at any `t`, as the first
     * did (a live sender that fell silent may come back on another clock).
     */
    void restartClock() { m_seen = {}; }

    /** Parses one JSON object's text; false with a one-sentence `reason`. */
    bool parse(const QByteArray &json, ContactFrame *frame, QString *reason);
    /** Parses an already decoded object; false with a one-sentence `reason`. */
    bool parse(const QJsonObject &json, ContactFrame *frame, QString *reason);

    /**
     * Checks a frame built from numbers (a session's block row) by the rules a line is
     * checked by, and takes it: names its fingertips' actors (`leftActor`, `rightActor`; null
     * for none, as the tips' `actor` -1 says) and moves the clock on. False with a
     * one-sentence `reason`, changing nothing.
     */
    bool accept(ContactFrame *frame, const QString &leftActor, const QString &rightActor,
                QString *reason);
    /** False with the reason when `name` cannot name a signal. */
    static bool checkSignalName(const QString &name, QString *reason);

    /** The actors named so far; frames refer to them by id. */
    const ActorTable &actors() const { return m_actors; }
    ActorTable &actors() { return m_actors; }

private:
    static bool checkFingertip(const Fingertip &tip, QLatin1String name, QString *reason);
    bool checkClock(const ContactFrame &frame, QString *reason) const;
    void take(ContactFrame *frame, const QString &leftActor, const QString &rightActor);
    static bool parseSignals(const QJsonObject &json, FrameSignals *signalValues, QString *reason);
    bool parseFingertip(const QJsonObject &json, QLatin1String name, Fingertip *tip,
                        QString *actor, QString *reason) const;

    ActorTable m_actors;
    std::array<double, 2> m_lastT{}; ///< per gripper, for the strictly-increasing rule
    std::array<bool, 2> m_seen{};
    double m_maxGap = DefaultMaxGap;
};

} // namespace semhap
