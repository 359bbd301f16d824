// SPDX-License-Identifier: MIT
#include "player.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace semhap {

namespace {

// Instants are t0 + k/rate computed afresh (no accumulated drift) and rounded to the
// nanosecond, so that 1.25 + 3/100 is written as 1.28 and not 1.2800000000000002.
double roundToNanosecond(double t)
{
    return std::round(t * 1e9) / 1e9;
}

} // namespace

QString Player::mixPolicyName(MixPolicy policy)
{
    switch (policy) {
    case MixPolicy::Priority:
        return QStringLiteral("priority");
    case MixPolicy::Max:
        return QStringLiteral("max");
    case MixPolicy::Sum:
        return QStringLiteral("sum");
    }
    return QString();
}

bool Player::mixPolicyFromName(const QString &name, MixPolicy *policy)
{
    for (MixPolicy p : {MixPolicy::Priority, MixPolicy::Max, MixPolicy::Sum}) {
        if (mixPolicyName(p) == name) {
            *policy = p;
            return true;
        }
    }
    return false;
}

int Player::addDevice(const QString &name, DeviceModelPtr model, MixPolicy policy)
{
    Device device;
    device.name = name;
    device.period = 1.0 / model->rate();
    device.model = std::move(model);
    device.policy = policy;
    device.last.channelCount = device.model->channelCount();
    const auto pos =
        std::lower_bound(m_devices.begin(), m_devices.end(), name,
                         [](const Device &d, const QString &n) { return d.name < n; });
    const auto index = pos - m_devices.begin();
    m_devices.insert(pos, std::move(device));
    for (size_t i = 0; i < m_devices.size(); ++i)
        m_devices[i].last.device = int(i);
    return int(index);
}

void Player::addInput(int device, PlayerInput *input)
{
    m_devices[size_t(device)].inputs.push_back(input);
}

int Player::deviceIndex(const QString &name) const
{
    for (size_t i = 0; i < m_devices.size(); ++i) {
        if (m_devices[i].name == name)
            return int(i);
    }
    return -1;
}

int Player::soundingPriority(int device) const
{
    int highest = -1;
    for (const PlayerInput *input : m_devices[size_t(device)].inputs) {
        if (input->isSounding())
            highest = std::max(highest, int(input->priority()));
    }
    return highest;
}

void Player::start(double t0)
{
    m_t0 = t0;
    for (Device &device : m_devices)
        device.next = 0;
    m_started = true;
}

double Player::instant(const Device &device) const
{
    return roundToNanosecond(m_t0 + double(device.next) * device.period);
}

double Player::nextInstant() const
{
    double best = std::numeric_limits<double>::infinity();
    if (!m_started)
        return best;
    for (const Device &device : m_devices)
        best = std::min(best, instant(device));
    return best;
}

void Player::skipBefore(double t, long long keep)
{
    if (!m_started || !std::isfinite(t))
        return;
    for (Device &device : m_devices) {
        // The index of the last instant at or before t, in doubles: a far t must not
        // overflow the integer before it is compared.
        const double last = std::floor((t - m_t0) / device.period);
        const double first = last - double(keep) + 1.0;
        if (first > double(device.next))
            device.next = static_cast<long long>(first);
    }
}

void Player::renderNext(DeviceFrame *frame)
{
    // Devices are in name order, so the first device at the earliest instant wins ties.
    Device *earliest = nullptr;
    double t = std::numeric_limits<double>::infinity();
    for (Device &device : m_devices) {
        const double ti = instant(device);
        if (ti < t) {
            t = ti;
            earliest = &device;
        }
    }
    if (!earliest)
        return;
    mix(*earliest, t, frame);
    earliest->last = *frame;
    ++earliest->next;
}

void Player::mix(Device &device, double t, DeviceFrame *frame)
{
    const DeviceModel &model = *device.model;
    const int channels = model.channelCount();
    frame->t = t;
    frame->device = int(&device - m_devices.data());
    frame->channelCount = channels;

    std::array<double, MaxChannels> value{};
    std::array<int, MaxChannels> level{};
    level.fill(-1);
    for (PlayerInput *input : device.inputs) {
        input->advance(t);
        if (!input->isSounding())
            continue;
        const int priority = device.policy == MixPolicy::Priority ? input->priority() : 0;
        for (const PlayerInput::Route &route : input->routes) {
            const auto c = size_t(route.channel);
            const double v = input->value(route.slot);
            if (priority > level[c]) {
                level[c] = priority;
                value[c] = v;
            } else if (priority == level[c]) {
                value[c] = device.policy == MixPolicy::Sum ? value[c] + v : std::max(value[c], v);
            }
        }
    }
    for (int c = 0; c < channels; ++c)
        frame->values[size_t(c)] = model.clamp(c, value[size_t(c)]);
}

} // namespace semhap
