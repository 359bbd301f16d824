// SPDX-License-Identifier: MIT
#pragma once

#include <array>

namespace semhap {

/** Upper bound on a device's channel count, so frames need no heap. */
constexpr int MaxChannels = 16;

/** One output frame of one device: a value per channel, clamped to the model's limits. */
struct DeviceFrame
{
    double t = 0.0;
    int device = -1; ///< index into the player's device table
    int channelCount = 0;
    std::array<double, MaxChannels> values{};
};

} // namespace semhap
