// SPDX-License-Identifier: MIT
#include "devicemodel.h"

#include "deviceframe.h"
#include "inputfile.h"
#include "jsonreader.h"

#include <QDir>
#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <map>

namespace semhap {

namespace {

constexpr double Pi = 3.14159265358979323846;
// A first-order lag reaches 10 % at tau·ln(10/9) and 90 % at tau·ln(10): 10–90 % = tau·ln 9.
const double RiseToTau = 1.0 / std::log(9.0);

bool readResponse(JsonReader &reader, const QJsonObject &response, double *latency, double *tau)
{
    const QString where = QStringLiteral("/response");
    if (!reader.checkKeys(
            response, where,
            {QLatin1String("latency"), QLatin1String("bandwidth"), QLatin1String("rise")}))
        return false;
    if (!reader.number(response, where, QLatin1String("latency"), latency, false))
        return false;
    if (*latency < 0 || *latency > 1)
        return reader.fail(where + QStringLiteral("/latency"),
                           QStringLiteral("must be between 0 and 1 s"));
    const bool hasBandwidth = response.contains(QStringLiteral("bandwidth"));
    const bool hasRise = response.contains(QStringLiteral("rise"));
    if (hasBandwidth && hasRise)
        return reader.fail(where, QStringLiteral("give bandwidth or rise, not both"));
    if (hasBandwidth) {
        double bandwidth = 0;
        if (!reader.number(response, where, QLatin1String("bandwidth"), &bandwidth))
            return false;
        if (bandwidth <= 0)
            return reader.fail(where + QStringLiteral("/bandwidth"),
                               QStringLiteral("must be positive (Hz)"));
        *tau = 1.0 / (2 * Pi * bandwidth);
    } else if (hasRise) {
        double rise = 0;
        if (!reader.number(response, where, QLatin1String("rise"), &rise))
            return false;
        if (rise < 0 || rise > 10)
            return reader.fail(where + QStringLiteral("/rise"),
                               QStringLiteral("must be between 0 and 10 s"));
        *tau = rise * RiseToTau;
    }
    return true;
}

} // namespace

std::shared_ptr<const DeviceModel> DeviceModel::fromJson(const QJsonObject &json,
                                                         const QString &file, LoadError *error)
{
    if (!checkFormat(json, file, QLatin1String(Format), error))
        return nullptr;
    auto model = std::make_shared<DeviceModel>();
    JsonReader reader(file);
    if (model->read(json, reader))
        return model;
    *error = reader.error();
    return nullptr;
}

bool DeviceModel::read(const QJsonObject &json, JsonReader &reader)
{
    const QString root;
    if (!reader.checkKeys(json, root,
                          {QLatin1String("format"), QLatin1String("name"),
                           QLatin1String("description"), QLatin1String("modality"),
                           QLatin1String("rate"), QLatin1String("channels"),
                           QLatin1String("response"), QLatin1String("actuator")}) ||
        !reader.string(json, root, QLatin1String("name"), &m_name) ||
        !reader.string(json, root, QLatin1String("description"), &m_description, false) ||
        !reader.string(json, root, QLatin1String("modality"), &m_modality, false) ||
        !reader.number(json, root, QLatin1String("rate"), &m_rate))
        return false;
    if (!m_modality.isEmpty() && !modalities().contains(m_modality))
        return reader.fail(QStringLiteral("/modality"),
                           QStringLiteral("unknown modality '%1' (modalities: %2)")
                               .arg(m_modality, modalities().join(QStringLiteral(", "))));
    if (m_name.isEmpty() || m_name.contains(QLatin1Char('/')))
        return reader.fail(QStringLiteral("/name"),
                           QStringLiteral("must be a non-empty name without '/'"));
    // Below 1 Hz a band would hold each value for seconds; the player's work per second of
    // input also stays bounded by the rate.
    if (!(m_rate >= 1 && m_rate <= 100000))
        return reader.fail(
            QStringLiteral("/rate"),
            QStringLiteral("must be between 1 and 100000 frames/s, got %1").arg(m_rate));

    QJsonArray channels;
    if (!reader.array(json, root, QLatin1String("channels"), &channels))
        return false;
    if (channels.isEmpty() || channels.size() > MaxChannels)
        return reader.fail(QStringLiteral("/channels"),
                           QStringLiteral("must list 1 to %1 channels").arg(MaxChannels));
    for (int i = 0; i < channels.size(); ++i) {
        const QString where = jsonPointerChild(QStringLiteral("/channels"), i);
        if (!channels.at(i).isObject())
            return reader.fail(where, QStringLiteral("expected a channel object, got ") +
                                          jsonTypeName(channels.at(i)));
        const QJsonObject c = channels.at(i).toObject();
        ChannelSpec spec;
        if (!reader.checkKeys(c, where,
                              {QLatin1String("name"), QLatin1String("unit"), QLatin1String("min"),
                               QLatin1String("max"), QLatin1String("angle")}) ||
            !reader.string(c, where, QLatin1String("name"), &spec.name) ||
            !reader.string(c, where, QLatin1String("unit"), &spec.unit, false) ||
            !reader.number(c, where, QLatin1String("min"), &spec.min, false) ||
            !reader.number(c, where, QLatin1String("max"), &spec.max, false) ||
            !reader.number(c, where, QLatin1String("angle"), &spec.angle, false))
            return false;
        if (c.contains(QLatin1String("angle")) && !(spec.angle >= 0 && spec.angle < 360))
            return reader.fail(where + QStringLiteral("/angle"),
                               QStringLiteral("must be at least 0 and below 360 degrees, got %1")
                                   .arg(spec.angle));
        if (spec.name.isEmpty())
            return reader.fail(where + QStringLiteral("/name"), QStringLiteral("is empty"));
        if (channelIndex(spec.name) >= 0)
            return reader.fail(where + QStringLiteral("/name"),
                               QStringLiteral("duplicate channel '%1'").arg(spec.name));
        if (!(spec.min < spec.max))
            return reader.fail(where, QStringLiteral("min must be below max"));
        m_channels.push_back(spec);
    }

    QJsonObject actuator;
    if (!reader.object(json, root, QLatin1String("actuator"), &actuator, false) ||
        !m_actuator.read(actuator, QStringLiteral("/actuator"), reader))
        return false;
    if (!reader.object(json, root, QLatin1String("response"), &m_response, false))
        return false;
    return readResponse(reader, m_response, &m_latency, &m_tau);
}

std::shared_ptr<const DeviceModel> DeviceModel::fromFile(const QString &path, LoadError *error)
{
    QJsonObject json;
    if (!readJsonObjectFile(path, &json, error))
        return nullptr;
    return fromJson(json, path, error);
}

QJsonObject DeviceModel::toJson() const
{
    QJsonArray channels;
    for (const ChannelSpec &c : m_channels) {
        QJsonObject o{{QStringLiteral("name"), c.name},
                      {QStringLiteral("min"), c.min},
                      {QStringLiteral("max"), c.max}};
        if (!c.unit.isEmpty())
            o.insert(QStringLiteral("unit"), c.unit);
        if (!std::isnan(c.angle))
            o.insert(QStringLiteral("angle"), c.angle);
        channels.append(o);
    }
    QJsonObject json{{QStringLiteral("format"), QLatin1String(Format)},
                     {QStringLiteral("name"), m_name},
                     {QStringLiteral("rate"), m_rate},
                     {QStringLiteral("channels"), channels}};
    if (!m_description.isEmpty())
        json.insert(QStringLiteral("description"), m_description);
    if (!m_modality.isEmpty())
        json.insert(QStringLiteral("modality"), m_modality);
    if (!m_actuator.isEmpty())
        json.insert(QStringLiteral("actuator"), m_actuator.toJson());
    if (!m_response.isEmpty())
        json.insert(QStringLiteral("response"), m_response);
    return json;
}

const QStringList &DeviceModel::modalities()
{
    static const QStringList names{QStringLiteral("vibration"), QStringLiteral("pressure"),
                                   QStringLiteral("sight")};
    return names;
}

QStringList DeviceModel::channelNames() const
{
    QStringList names;
    for (const ChannelSpec &c : m_channels)
        names.append(c.name);
    return names;
}

int DeviceModel::channelIndex(const QString &name) const
{
    for (size_t i = 0; i < m_channels.size(); ++i) {
        if (m_channels[i].name == name)
            return int(i);
    }
    return -1;
}

double DeviceModel::clamp(int channel, double value) const
{
    const ChannelSpec &c = m_channels[size_t(channel)];
    if (!(value >= c.min)) // also maps NaN to the lower limit: never send NaN to hardware
        return c.min;
    return value > c.max ? c.max : value;
}

DeviceFrame DeviceModel::restFrame(double t) const
{
    DeviceFrame frame;
    frame.t = t;
    frame.channelCount = std::min(channelCount(), MaxChannels);
    for (int c = 0; c < frame.channelCount; ++c)
        frame.values[size_t(c)] = m_channels[size_t(c)].min;
    return frame;
}

double DeviceModel::modulationLimit() const
{
    const double quarterRate = m_rate / 4;
    return m_tau > 0 ? std::min(quarterRate, 1.0 / (2 * Pi * m_tau)) : quarterRate;
}

std::vector<double> DeviceModel::predict(const std::vector<double> &commanded,
                                         double sampleRate) const
{
    ResponseFilter filter(*this, sampleRate);
    std::vector<double> delivered;
    delivered.reserve(commanded.size());
    for (double u : commanded)
        delivered.push_back(filter.step(u));
    return delivered;
}

ResponseFilter::ResponseFilter(const DeviceModel &model, double sampleRate)
{
    const double dt = 1.0 / sampleRate;
    const auto delaySamples = size_t(std::lround(model.latency() * sampleRate));
    m_delay.assign(delaySamples, 0.0);
    if (model.timeConstant() > 0)
        m_alpha = 1.0 - std::exp(-dt / model.timeConstant());
}

double ResponseFilter::step(double command)
{
    double delayed = command;
    if (!m_delay.empty()) {
        delayed = m_delay[m_head];
        m_delay[m_head] = command;
        m_head = (m_head + 1) % m_delay.size();
    }
    m_value += m_alpha * (delayed - m_value);
    return m_value;
}

void ResponseFilter::reset()
{
    std::fill(m_delay.begin(), m_delay.end(), 0.0);
    m_head = 0;
    m_value = 0.0;
}

namespace {

const std::map<QString, DeviceModelPtr> &builtinModels()
{
    static const std::map<QString, DeviceModelPtr> models = [] {
        std::map<QString, DeviceModelPtr> result;
        const QDir dir(QStringLiteral(":/semhap/devices"));
        const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files);
        for (const QString &file : files) {
            LoadError error;
            if (DeviceModelPtr model = DeviceModel::fromFile(dir.filePath(file), &error))
                result.emplace(model->name(), model);
            else
                qFatal("built-in device model is broken: %s", qPrintable(error.toString()));
        }
        return result;
    }();
    return models;
}

} // namespace

QStringList DeviceModelLibrary::builtinNames()
{
    QStringList names;
    for (const auto &entry : builtinModels())
        names.append(entry.first);
    return names;
}

DeviceModelPtr DeviceModelLibrary::builtin(const QString &name)
{
    const auto &models = builtinModels();
    const auto it = models.find(name);
    return it == models.end() ? nullptr : it->second;
}

DeviceModelPtr DeviceModelLibrary::load(const QString &nameOrPath, LoadError *error)
{
    if (InputFile::namesFile(nameOrPath))
        return DeviceModel::fromFile(nameOrPath, error);
    if (DeviceModelPtr model = builtin(nameOrPath))
        return model;
    *error = LoadError::at(QString(), QString(),
                           QStringLiteral("unknown device model '%1' (built-in: %2)")
                               .arg(nameOrPath, builtinNames().join(QStringLiteral(", "))));
    return nullptr;
}

} // namespace semhap
