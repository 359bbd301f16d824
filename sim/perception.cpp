// SPDX-License-Identifier: MIT
#include "perception.h"

#include "router.h"

#include <algorithm>

namespace semhap {

Perception::Perception(const Router &router) : m_router(router), m_player(router.player())
{
    for (int d = 0; d < m_player.deviceCount(); ++d) {
        const DeviceModel &model = m_player.deviceModel(d);
        Device device;
        Band band;
        Gripper hand = Gripper::Right;
        if (router.deviceHand(d, &hand))
            band.hand = int(hand);
        for (int c = 0; c < model.channelCount(); ++c) {
            device.filters.emplace_back(model, model.rate());
            const QString channel = model.channels()[size_t(c)].name;
            const QStringList parts = channel.split(QLatin1Char('.'));
            const bool overlay =
                parts.size() == 2 && gripperFromName(parts[0], &hand) &&
                (parts[1] == QLatin1String("confirm") || parts[1] == QLatin1String("warn"));
            device.shown.push_back(overlay ? (parts[1] == QLatin1String("warn") ? 1 : 0) : -1);
            device.shownHand.push_back(int(hand));
        }
        m_devices.push_back(std::move(device));
        m_bands.push_back(band);
    }
}

void Perception::onDeviceFrame(const DeviceFrame &frame)
{
    Device &device = m_devices[size_t(frame.device)];
    Band &band = m_bands[size_t(frame.device)];
    band.level = 0.0;
    for (int c = 0; c < frame.channelCount; ++c) {
        const double delivered = device.filters[size_t(c)].step(frame.values[size_t(c)]);
        if (device.shown[size_t(c)] < 0)
            band.level = std::max(band.level, delivered);
    }
    band.priority = m_player.soundingPriority(frame.device);
    band.pattern = m_router.soundingPattern(frame.device);
    update();
    // The overlay is seen as commanded: a screen has no lag worth modelling.
    for (int c = 0; c < frame.channelCount; ++c) {
        const int kind = device.shown[size_t(c)];
        if (kind < 0)
            continue;
        Feeling &feeling = m_feelings[size_t(device.shownHand[size_t(c)])];
        (kind == 1 ? feeling.shownWarning : feeling.shownConfirmation) = frame.values[size_t(c)];
    }
}

void Perception::update()
{
    for (Feeling &feeling : m_feelings) {
        feeling.confirmation = 0.0;
        feeling.warning = 0.0;
        feeling.pressure = 0.0;
    }
    for (const Band &band : m_bands) {
        if (band.hand < 0)
            continue;
        Feeling &feeling = m_feelings[size_t(band.hand)];
        double *target = &feeling.pressure;
        if (band.priority == PlayerInput::Exception)
            target = &feeling.warning;
        else if (band.priority == PlayerInput::Confirmation)
            target = &feeling.confirmation;
        else if (band.priority < 0)
            continue; // a fading output whose message is gone still moves the band a little
        *target = std::max(*target, band.level);
    }
}

} // namespace semhap
