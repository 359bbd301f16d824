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

    explicit Perception(const Router &router);

    void onDeviceFrame(const DeviceFrame &frame) override;
    Feeling feeling(Gripper hand) const { return m_feelings[size_t(hand)]; }

private:
    struct Device
    {
        int hand = -1;                       ///< Gripper, or -1 for the overlay or others
        std::vector<ResponseFilter> filters; ///< per channel
        std::vector<int> shown;              ///< overlay: per channel, 0 confirm, 1 warn, -1
        std::vector<int> shownHand;
        double level = 0.0; ///< delivered, max over channels
        int priority = -1;
    };

    void update();

    const Player &m_player;
    std::vector<Device> m_devices;
    std::array<Feeling, 2> m_feelings{};
};

} // namespace semhap
