// SPDX-License-Identifier: MIT
#pragma once

#include "deviceframe.h"
#include "devicemodel.h"

#include <QString>

#include <vector>

namespace semhap {

/**
 * Something that feeds channels of one device: a pattern voice, a proportional mapping.
 * Its routes say which of its slots (a pattern's tracks) land on which device channel.
 */
class PlayerInput
{
public:
    /** Priority classes for the priority mix: exceptions over confirmations over the rest. */
    enum Priority
    {
        Continuous = 0,
        Confirmation = 1,
        Exception = 2
    };

    struct Route
    {
        int channel; ///< device channel index
        int slot;    ///< the input's own output index
    };

    virtual ~PlayerInput() = default;

    /** Brings the input to time t (seconds, never decreasing). */
    virtual void advance(double t) = 0;
    /** False when the input contributes nothing (an idle voice). */
    virtual bool isSounding() const = 0;
    virtual Priority priority() const = 0;
    /** The value of output `slot` at the last advance. */
    virtual double value(int slot) const = 0;

    std::vector<Route> routes;
};

/**
 * Mixes the inputs of each device at the device's update rate into DeviceFrames, on a
 * clock the caller drives: ask for the next instant, render it. Devices are kept sorted by
 * name so that frames of one instant come out in name order. Rendering never allocates.
 */
class Player
{
public:
    /** How voices that meet on one channel combine. */
    enum class MixPolicy
    {
        Priority, ///< the highest priority class sounding wins; within it, the maximum
        Max,      ///< the maximum of all sounding inputs
        Sum       ///< the sum, clamped to the channel's limits
    };
    static QString mixPolicyName(MixPolicy policy);
    static bool mixPolicyFromName(const QString &name, MixPolicy *policy);

    /** Adds a device; returns its index. Call before start(); indices follow name order. */
    int addDevice(const QString &name, DeviceModelPtr model, MixPolicy policy);
    /** Feeds `input` (owned by the caller, outliving the player) into device `device`. */
    void addInput(int device, PlayerInput *input);

    /** Sets every device's first instant to t0. */
    void start(double t0);
    bool isStarted() const { return m_started; }
    /** The earliest pending instant (infinity without devices or before start). */
    double nextInstant() const;
    /** Renders the earliest pending instant (ties: the device first in name order). */
    void renderNext(DeviceFrame *frame);
    /**
     * Leaves each device at most `keep` pending instants up to `t`, dropping the earlier
     * ones unrendered: a gap in the clock costs bounded work. The inputs catch up at the
     * next instant rendered.
     */
    void skipBefore(double t, long long keep);

    int deviceCount() const { return int(m_devices.size()); }
    const QString &deviceName(int device) const { return m_devices[size_t(device)].name; }
    const DeviceModel &deviceModel(int device) const { return *m_devices[size_t(device)].model; }
    int deviceIndex(const QString &name) const;
    /**
     * The highest priority class among the device's inputs sounding at its last frame, or
     * -1 when none is: what the device's output means right now (a warning, a confirmation).
     */
    int soundingPriority(int device) const;
    /** The last frame rendered for a device (all zero before the first). */
    const DeviceFrame &lastFrame(int device) const { return m_devices[size_t(device)].last; }

private:
    struct Device
    {
        QString name;
        DeviceModelPtr model;
        MixPolicy policy = MixPolicy::Priority;
        std::vector<PlayerInput *> inputs;
        double period = 0.01;
        long long next = 0; ///< index k of the next instant t0 + k / rate
        DeviceFrame last;
    };

    double instant(const Device &device) const;
    void mix(Device &device, double t, DeviceFrame *frame);

    std::vector<Device> m_devices;
    double m_t0 = 0.0;
    bool m_started = false;
};

} // namespace semhap
