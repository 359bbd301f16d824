// SPDX-License-Identifier: MIT
#pragma once

#include "actuator.h"
#include "deviceframe.h"
#include "loaderror.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <limits>
#include <memory>
#include <vector>

namespace semhap {

class JsonReader;

/** One output channel of a device model. */
struct ChannelSpec
{
    QString name;
    QString unit;
    double min = 0.0;
    double max = 1.0;
    /**
     * Where the channel's actuator sits around the band, in degrees (0 on the back of the
     * wrist, 90 towards the thumb, 180 on the palm side); NaN when the model does not say.
     */
    double angle = std::numeric_limits<double>::quiet_NaN();
};

/**
 * A wristband (or overlay) as data (`"format": "semhap.device/1"`): its channels and limits,
 * its update rate, and how its output follows a command — a dead time followed by a
 * first-order lag. The same description drives previews ("how it will feel"), the player's
 * clamping and the emulator.
 */
class DeviceModel
{
public:
    static constexpr const char *Format = "semhap.device/1";

    static std::shared_ptr<const DeviceModel> fromJson(const QJsonObject &json,
                                                       const QString &file, LoadError *error);
    static std::shared_ptr<const DeviceModel> fromFile(const QString &path, LoadError *error);
    QJsonObject toJson() const;

    const QString &name() const { return m_name; }
    const QString &description() const { return m_description; }
    /**
     * The sense its output reaches: `vibration`, `pressure` or `sight` (Modalities); empty
     * when the model does not say, and then it cannot be compared by perception.
     */
    const QString &modality() const { return m_modality; }
    /** The modalities a model may name, in the order docs list them. */
    static const QStringList &modalities();
    const std::vector<ChannelSpec> &channels() const { return m_channels; }
    int channelCount() const { return int(m_channels.size()); }
    QStringList channelNames() const;
    int channelIndex(const QString &name) const; ///< -1 when the model has no such channel
    /** Its actuators as their datasheet gives them (empty when the model does not say). */
    const Actuator &actuator() const { return m_actuator; }
    /** Frames per second the device accepts. */
    double rate() const { return m_rate; }
    /** Dead time before the output starts to follow a command (s). */
    double latency() const { return m_latency; }
    /** Time constant of the first-order lag (s); 0 when the output follows at once. */
    double timeConstant() const { return m_tau; }
    /**
     * How long a command takes to be felt (s): the dead time plus the lag's time constant,
     * when the output has come 63 % of the way.
     */
    double responseDelay() const { return m_latency + m_tau; }

    double clamp(int channel, double value) const;
    /** Every channel at its lower limit, at time `t`: the device at rest (a stop-all). */
    DeviceFrame restFrame(double t) const;
    /**
     * The fastest amplitude modulation the output still follows (Hz): the lag's corner
     * frequency, at most a quarter of the rate. Imported sharpness is mapped below it.
     */
    double modulationLimit() const;

    /**
     * Predicts the delivered output of one channel for a command sampled at `sampleRate`:
     * the command delayed by the latency, then low-passed. Starts at rest (0).
     */
    std::vector<double> predict(const std::vector<double> &commanded, double sampleRate) const;

private:
    bool read(const QJsonObject &json, JsonReader &reader);

    QString m_name;
    QString m_description;
    QString m_modality;
    std::vector<ChannelSpec> m_channels;
    double m_rate = 100.0;
    double m_latency = 0.0;
    double m_tau = 0.0;
    Actuator m_actuator;
    QJsonObject m_response; ///< as written, so toJson keeps bandwidth vs rise
};

using DeviceModelPtr = std::shared_ptr<const DeviceModel>;

/**
 * The response of one channel as a stream: feed commands at a fixed sample rate, read the
 * delivered value. Memory is taken once, in the constructor.
 */
class ResponseFilter
{
public:
    ResponseFilter(const DeviceModel &model, double sampleRate);
    double step(double command);
    void reset();

private:
    std::vector<double> m_delay; ///< ring buffer of the last `latency` worth of commands
    size_t m_head = 0;
    double m_alpha = 1.0; ///< exact discretisation of the lag: 1 - exp(-dt / tau)
    double m_value = 0.0;
};

/** The built-in device models (`:/semhap/devices/NAME.json`) and the name-or-path loader. */
class DeviceModelLibrary
{
public:
    static QStringList builtinNames();
    static DeviceModelPtr builtin(const QString &name);
    static DeviceModelPtr load(const QString &nameOrPath, LoadError *error);
};

} // namespace semhap
