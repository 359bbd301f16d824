// SPDX-License-Identifier: MIT
#pragma once

#include "cdrwriter.h"
#include "contactframe.h"
#include "pipeline.h"

#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>
#include <vector>

namespace semhap {

class ActorTable;
class FoxgloveServer;
class Router;
struct HandCommand;

/**
 * The pipeline's streams, live, on a FoxgloveServer: every contact frame, event, band frame
 * and hand command as it comes, none decimated, on the topics and types of an MCAP export
 * (SemhapMessages). The events' and the bands' channels are advertised at once, a
 * gripper's by advertise() or with its first frame, a hand's with its first command.
 */
class FoxglovePublisher : public PipelineSink
{
public:
    /**
     * Publishes `router`'s streams on `server`, which outlives it; stamps are `origin` (ns
     * since the epoch) plus each value's t.
     */
    FoxglovePublisher(FoxgloveServer &server, const Router &router, const ActorTable &actors,
                      std::int64_t origin);

    /**
     * Advertises `gripper`'s contact and wrench channels now, so a viewer can subscribe
     * before its first frame.
     */
    void advertise(Gripper gripper);
    /** Stamps from now on are `origin` plus each value's t. */
    void setOrigin(std::int64_t origin) { m_origin = origin; }

    void onContactFrame(const ContactFrame &frame);
    void onEvent(const SemanticEvent &event) override;
    void onDeviceFrame(const DeviceFrame &frame) override;
    void onHandCommand(const HandCommand &command);

private:
    struct Band
    {
        int channel = -1;
        QString name, model;
        std::vector<QByteArray> channels;
    };
    struct Hand
    {
        int contact = -1, input = -1;
        std::array<int, 2> wrench{-1, -1};
    };

    int channel(int &id, const char *type, const QString &topic);
    std::uint64_t stamp(double t) const;

    FoxgloveServer &m_server;
    const ActorTable &m_actors;
    std::int64_t m_origin;
    QStringList m_nodes;
    int m_events = -1;
    std::vector<Band> m_bands;
    std::array<Hand, 2> m_hands;
    CdrWriter m_cdr;
};

} // namespace semhap
