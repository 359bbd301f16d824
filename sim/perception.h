// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "operator.h"
#include "pipeline.h"

#include <vector>

namespace semhap {

/**
 * What the operator's hands perceive of the device output: each device frame passes
 * through its model's response (dead time and lag), so a warning is felt when the band
 * actually moves, not when it is commanded. Devices named `left.*` / `right.*` belong to
 * that hand; what a device means follows the priority class sounding on it (exception:
 * warning, confirmation, continuous: pressure); the overlay's `<hand>.confirm` and
 * `<hand>.warn` channels are what the operator can see.
 */
class Perception : public PipelineSink
{
public:
    /** A cue counts as perceived from this level of full scale on. */
    static constexpr double Noticeable = 0.25;
    /**
     * Pulses of one warning come at least this often (the Geiger's slowest rate is 2 Hz):
     * a pulsed warning is one cue while its pulses keep coming.
     */
    static constexpr double PulseGap = 0.6;

    /** One band as it is felt now, for a person who tells its patterns apart. */
    struct Band
    {
        int hand = -1;      ///< Gripper, or -1 for the overlay or others
        double level = 0.0; ///< delivered (after the response), max over its felt channels
        int priority = -1;  ///< Player::soundingPriority
        int pattern = -1;   ///< Router::soundingPattern
    };

    explicit Perception(const Router &router);

    void onDeviceFrame(const DeviceFrame &frame) override;
    Feeling feeling(Gripper hand) const { return m_feelings[size_t(hand)]; }
    /** Each device of the router's player, in its order. */
    const std::vector<Band> &bands() const { return m_bands; }
    /** The router whose output this perceives. */
    const Router &router() const { return m_router; }

private:
    struct Device
    {
        std::vector<ResponseFilter> filters; ///< per channel
        std::vector<int> shown;              ///< overlay: per channel, 0 confirm, 1 warn, -1
        std::vector<int> shownHand;
    };

    void update();

    const Router &m_router;
    const Player &m_player;
    std::vector<Device> m_devices;
    std::vector<Band> m_bands;
    std::array<Feeling, 2> m_feelings{};
};

} // namespace semhap
