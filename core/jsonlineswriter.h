// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "deviceframe.h"
#include "semanticevent.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <array>
#include <vector>

class QIODevice;

namespace semhap {

class ActorTable;
class NameTable;

/**
 * Writes events, device frames and contact frames as JSON Lines (spec section 1): one
 * compact object per line, numbers in their shortest round-trip form. Builds each line in
 * one reused buffer, so a long run writes without per-line allocations.
 */
class JsonLinesWriter
{
public:
    /** Writes to `device`, which the caller opened and keeps alive. */
    explicit JsonLinesWriter(QIODevice *device);

    /** Names of router nodes, indexed by SemanticEvent::node; unknown indices write null. */
    void setNodeNames(const QStringList &names);
    /** Names of device instances, indexed by DeviceFrame::device. */
    void setDeviceNames(const QStringList &names);
    /** Where contact frames' actor ids are named; may grow while writing, must outlive us. */
    void setActorTable(const ActorTable *actors) { m_actors = actors; }

    /** Writes one event line; false when the device refused it. */
    bool write(const SemanticEvent &event);
    /** Writes one device frame line; false when the device refused it. */
    bool write(const DeviceFrame &frame);
    /** Writes one contact frame line, both fingertips explicit; false on a write error. */
    bool write(const ContactFrame &frame);

    /** Appends `value` in the shortest form that parses back to it; null if not finite. */
    static void appendNumber(QByteArray &out, double value);
    /** Appends `text` as a quoted JSON string. */
    static void appendString(QByteArray &out, const QString &text);

private:
    void appendFingertip(const char *key, const Fingertip &tip);
    const QByteArray &actorName(int actor);
    /** `id`'s name in `table`, encoded once into `cache`; null for an id never given. */
    static const QByteArray &tableName(const NameTable &table, std::vector<QByteArray> &cache,
                                       int id);
    bool writeLine();

    QIODevice *m_device;
    QByteArray m_line;
    std::vector<QByteArray> m_nodes; ///< names already encoded as JSON strings
    std::vector<QByteArray> m_devices;
    const ActorTable *m_actors = nullptr;
    std::vector<QByteArray> m_actorNames; ///< encoded lazily, as the table grows
    std::array<QByteArray, 2> m_grippers;
    std::vector<QByteArray> m_kinds;    ///< detectorKindNames(), the node-type table's
    std::vector<QByteArray> m_messages; ///< messageNames(), encoded lazily
    std::vector<QByteArray> m_signals;  ///< signalNames(), encoded lazily
    std::array<QByteArray, 2> m_categories;
    std::array<QByteArray, 3> m_phases;
};

} // namespace semhap
