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
 * gripper's last `t` (strictly increasing) and the actor names seen. A rejected frame
 * changes neither.
 */
class ContactFrameParser
{
public:
    /** Parses one JSON object's text; false with a one-sentence `reason`. */
    bool parse(const QByteArray &json, ContactFrame *frame, QString *reason);
    /** Parses an already decoded object; false with a one-sentence `reason`. */
    bool parse(const QJsonObject &json, ContactFrame *frame, QString *reason);

    /** The actors named so far; frames refer to them by id. */
    const ActorTable &actors() const { return m_actors; }
    ActorTable &actors() { return m_actors; }

private:
    bool parseFingertip(const QJsonObject &json, QLatin1String name, Fingertip *tip,
                        QString *actor, QString *reason) const;

    ActorTable m_actors;
    std::array<double, 2> m_lastT{}; ///< per gripper, for the strictly-increasing rule
    std::array<bool, 2> m_seen{};
};

} // namespace semhap
