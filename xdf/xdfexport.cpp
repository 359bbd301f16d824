// SPDX-License-Identifier: MIT
#include "xdfexport.h"

#include "sessionclock.h"
#include "sessionreader.h"
#include "xdfwriter.h"

#include <QIODevice>
#include <QSysInfo>
#include <QUuid>
#include <QXmlStreamWriter>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** Seconds of session time a Samples chunk holds, and how many go between Boundary chunks. */
constexpr double ChunkSeconds = 1.0;
constexpr int ChunksPerBoundary = 10;

/** One channel of a stream's header. */
struct Channel
{
    QString label;
    QString unit;
    QString type;
};

/** One XDF stream: what its header says, the window's samples, and what it has written. */
struct Stream
{
    QString key; ///< unique within the file, for its source_id
    QString name;
    QString type;
    std::vector<Channel> channels; ///< one, of type Marker, for a marker stream
    bool markers = false;

    quint32 id = 0; ///< 0 until its header is written, with its first samples
    std::vector<double> stamps;
    std::vector<float> values;
    QList<QByteArray> strings;

    qint64 count = 0;
    double first = 0.0;
    double last = 0.0;
    std::vector<std::pair<double, double>> offsets; ///< (collection time, value) written
};

Channel channel(const QString &label, const char *unit, const char *type)
{
    return {label, QLatin1String(unit), QLatin1String(type)};
}

QString number(double value)
{
    return QString::number(value, 'g', 17);
}

/** The nominal rate of samples stamped `stamps`: one over their median spacing; 0 when irregular.
 */
double nominalRate(std::vector<double> stamps)
{
    if (stamps.size() < 2)
        return 0.0;
    std::vector<double> gaps;
    for (size_t i = 1; i < stamps.size(); ++i)
        gaps.push_back(stamps[i] - stamps[i - 1]);
    std::nth_element(gaps.begin(), gaps.begin() + long(gaps.size() / 2), gaps.end());
    const double gap = gaps[gaps.size() / 2];
    return gap > 0.0 ? std::round(1.0 / gap) : 0.0;
}

QByteArray headerXml(const Stream &stream, double rate, const QString &session)
{
    QByteArray xml;
    QXmlStreamWriter w(&xml);
    w.writeStartDocument();
    w.writeStartElement(QStringLiteral("info"));
    w.writeTextElement(QStringLiteral("name"), stream.name);
    w.writeTextElement(QStringLiteral("type"), stream.type);
    w.writeTextElement(QStringLiteral("channel_count"), QString::number(stream.channels.size()));
    w.writeTextElement(QStringLiteral("nominal_srate"), number(rate));
    w.writeTextElement(QStringLiteral("channel_format"),
                       stream.markers ? QStringLiteral("string") : QStringLiteral("float32"));
    w.writeTextElement(QStringLiteral("source_id"),
                       QStringLiteral("semhap:%1:%2").arg(session, stream.key));
    w.writeTextElement(QStringLiteral("version"), QStringLiteral("1.1"));
    w.writeTextElement(QStringLiteral("created_at"), number(stream.first));
    w.writeTextElement(QStringLiteral("uid"), QUuid::createUuid().toString(QUuid::WithoutBraces));
    w.writeTextElement(QStringLiteral("session_id"), QStringLiteral("default"));
    w.writeTextElement(QStringLiteral("hostname"), QSysInfo::machineHostName());
    w.writeStartElement(QStringLiteral("desc"));
    w.writeStartElement(QStringLiteral("channels"));
    for (const Channel &channel : stream.channels) {
        w.writeStartElement(QStringLiteral("channel"));
        w.writeTextElement(QStringLiteral("label"), channel.label);
        if (!channel.unit.isEmpty())
            w.writeTextElement(QStringLiteral("unit"), channel.unit);
        w.writeTextElement(QStringLiteral("type"), channel.type);
        w.writeEndElement();
    }
    w.writeEndElement();
    w.writeStartElement(QStringLiteral("acquisition"));
    w.writeTextElement(QStringLiteral("manufacturer"), QStringLiteral("semhap"));
    w.writeEndElement();
    w.writeEndElement();
    w.writeEndElement();
    w.writeEndDocument();
    return xml;
}

QByteArray footerXml(const Stream &stream)
{
    QByteArray xml;
    QXmlStreamWriter w(&xml);
    w.writeStartDocument();
    w.writeStartElement(QStringLiteral("info"));
    w.writeTextElement(QStringLiteral("first_timestamp"), number(stream.first));
    w.writeTextElement(QStringLiteral("last_timestamp"), number(stream.last));
    w.writeTextElement(QStringLiteral("sample_count"), QString::number(stream.count));
    w.writeStartElement(QStringLiteral("clock_offsets"));
    for (const auto &[time, value] : stream.offsets) {
        w.writeStartElement(QStringLiteral("offset"));
        w.writeTextElement(QStringLiteral("time"), number(time));
        w.writeTextElement(QStringLiteral("value"), number(value));
        w.writeEndElement();
    }
    w.writeEndElement();
    w.writeEndElement();
    w.writeEndDocument();
    return xml;
}

Stream stream(const QString &key, const QString &name, const char *type)
{
    Stream s;
    s.key = key;
    s.name = name;
    s.type = QLatin1String(type);
    return s;
}

/** The session's streams that may have samples, in the order their ids are given. */
std::vector<Stream> sessionStreams(const SessionReader &session)
{
    std::vector<Stream> streams;
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        const QString gripper = gripperName(g);
        Stream forces = stream(gripper + QStringLiteral("-forces"),
                               QStringLiteral("semhap %1 gripper forces").arg(gripper), "Force");
        for (const char *tip : {"left", "right"}) {
            const QString prefix = QLatin1String(tip) + QLatin1Char('_');
            forces.channels.push_back(channel(prefix + QLatin1Char('f'), "N", "Force"));
            forces.channels.push_back(channel(prefix + QLatin1Char('n'), "", "ContactCount"));
            for (const char *axis : {"fx", "fy", "fz"})
                forces.channels.push_back(channel(prefix + QLatin1String(axis), "N", "Force"));
        }
        streams.push_back(forces);
    }
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        const QString gripper = gripperName(g);
        Stream events = stream(gripper + QStringLiteral("-events"),
                               QStringLiteral("semhap %1 gripper events").arg(gripper), "Markers");
        events.channels.push_back(channel(QStringLiteral("event"), "", "Marker"));
        events.markers = true;
        streams.push_back(events);
    }
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        const QString hand = gripperName(g);
        Stream input = stream(hand + QStringLiteral("-input"),
                              QStringLiteral("semhap %1 hand input").arg(hand), "OperatorInput");
        for (const char *axis : {"x", "y", "z"})
            input.channels.push_back(channel(QLatin1String(axis), "m", "Position"));
        for (const char *part : {"qw", "qx", "qy", "qz"})
            input.channels.push_back(channel(QLatin1String(part), "", "Orientation"));
        input.channels.push_back(channel(QStringLiteral("grip"), "N", "Force"));
        streams.push_back(input);
    }
    for (int d = 0; d < session.deviceNames().size(); ++d) {
        const QString device = session.deviceNames().at(d);
        Stream output = stream(QStringLiteral("device-") + device,
                               QStringLiteral("semhap %1 output").arg(device), "Haptics");
        for (const QString &name : session.channelNames(d))
            output.channels.push_back(channel(name, "", "Drive"));
        streams.push_back(output);
    }
    return streams;
}

constexpr size_t ForcesOf(Gripper g)
{
    return size_t(g == Gripper::Right);
}
constexpr size_t EventsOf(Gripper g)
{
    return 2 + size_t(g == Gripper::Right);
}
constexpr size_t InputOf(Gripper g)
{
    return 4 + size_t(g == Gripper::Right);
}
constexpr size_t OutputOf(int device)
{
    return 6 + size_t(device);
}

void appendTip(std::vector<float> &values, const Fingertip &tip)
{
    values.push_back(float(tip.f));
    values.push_back(float(tip.n));
    for (double component : tip.fxyz)
        values.push_back(tip.hasFxyz ? float(component) : std::numeric_limits<float>::quiet_NaN());
}

} // namespace

QByteArray XdfExport::marker(const QString &message, const QString &phase, double intensity)
{
    return (message + QLatin1Char('/') + phase + QLatin1Char('/') +
            QString::number(intensity, 'f', 2))
        .toUtf8();
}

bool XdfExport::write(SessionReader &session, QIODevice *out, TimeBase time, QStringList *notes,
                      QString *error)
{
    SessionClock clock;
    QString reason;
    if (!SessionClock::fromInfo(session.info(), &clock, &reason)) {
        *error = session.path() + QStringLiteral(": ") + reason;
        return false;
    }
    if (!clock.followsClock()) {
        const QString why =
            clock.isEmpty()
                ? (session.info().source == QLatin1String("import")
                       ? QStringLiteral("it was imported from a recording, whose times are "
                                        "the recording's, not this machine's clock")
                       : QStringLiteral("it was recorded before sessions kept the steady "
                                        "clock"))
                : QStringLiteral("its time ran %1 times as fast as the clock (a simulation "
                                 "faster than real time): its times are simulated seconds")
                      .arg(clock.rate(), 0, 'f', 1);
        if (time == TimeBase::Lsl) {
            *error = session.path() + QStringLiteral(": cannot be put on the LSL clock: ") + why;
            return false;
        }
        notes->append(session.path() + QStringLiteral(": no clock offsets: ") + why +
                      QStringLiteral(", so it cannot be lined up with an LSL recording"));
    }
    const auto stamp = [&](double t) { return time == TimeBase::Lsl ? clock.toSteady(t) : t; };
    // The offsets a synchronising reader adds: on the session's clock, the steady clock's
    // lead; on LSL's, none.
    std::vector<std::pair<double, double>> offsets;
    if (clock.followsClock()) {
        for (const SessionClock::Sample &s : clock.samples())
            offsets.emplace_back(time == TimeBase::Lsl ? s.steady : s.t,
                                 time == TimeBase::Lsl ? 0.0 : s.steady - s.t);
    }

    XdfWriter writer(out);
    const auto failed = [&] {
        *error = QStringLiteral("cannot write: ") + out->errorString();
        return false;
    };
    {
        QByteArray xml;
        QXmlStreamWriter w(&xml);
        w.writeStartDocument();
        w.writeStartElement(QStringLiteral("info"));
        w.writeTextElement(QStringLiteral("version"), QStringLiteral("1.0"));
        w.writeTextElement(QStringLiteral("datetime"),
                           session.info().started.toString(Qt::ISODateWithMs));
        w.writeTextElement(QStringLiteral("writer"),
                           QStringLiteral("semhap ") + session.info().semhapVersion);
        w.writeEndElement();
        w.writeEndDocument();
        if (!writer.writeFileHeader(xml))
            return failed();
    }

    std::vector<Stream> streams = sessionStreams(session);
    const QString source = session.info().started.toString(Qt::ISODate);
    quint32 nextId = 1;
    size_t offsetsWritten = 0; ///< of `offsets`, written to every open stream
    const auto writeOffset = [&](Stream &stream, const std::pair<double, double> &offset) {
        stream.offsets.push_back(offset);
        return writer.writeClockOffset(stream.id, offset.first, offset.second);
    };

    const double start = session.startTime();
    const double end = session.endTime();
    for (int window = 0;; ++window) {
        // The first window takes whatever comes before the contact frames, the last whatever
        // comes after them.
        const double from = window == 0 ? -SessionReader::Forever : start + window * ChunkSeconds;
        const double to = start + (window + 1) * ChunkSeconds > end
                              ? SessionReader::Forever
                              : start + (window + 1) * ChunkSeconds;
        bool ok = session.readContactFrames(
            [&](const ContactFrame &frame, double) {
                Stream &s = streams[ForcesOf(frame.gripper)];
                s.stamps.push_back(stamp(frame.t));
                appendTip(s.values, frame.left);
                appendTip(s.values, frame.right);
                return true;
            },
            error, from, to);
        ok = ok && session.readEvents(
                       [&](const SemanticEvent &event) {
                           Stream &s = streams[EventsOf(event.gripper)];
                           s.stamps.push_back(stamp(event.t));
                           s.strings.append(marker(messageName(event.message),
                                                   eventPhaseName(event.phase), event.intensity));
                           return true;
                       },
                       error, from, to);
        ok = ok && session.readHandCommands(
                       [&](const HandCommand &input) {
                           Stream &s = streams[InputOf(input.hand)];
                           s.stamps.push_back(stamp(input.t));
                           for (double v : input.target.pos)
                               s.values.push_back(float(v));
                           for (double v : input.target.quat)
                               s.values.push_back(float(v));
                           s.values.push_back(float(input.grip));
                           return true;
                       },
                       error, from, to);
        ok = ok && session.readDeviceFrames(
                       [&](const DeviceFrame &frame) {
                           if (frame.device < 0 || OutputOf(frame.device) >= streams.size())
                               return true; // a device the devices table does not list
                           Stream &s = streams[OutputOf(frame.device)];
                           s.stamps.push_back(stamp(frame.t));
                           for (size_t c = 0; c < s.channels.size(); ++c)
                               s.values.push_back(int(c) < frame.channelCount
                                                      ? float(frame.values[c])
                                                      : std::numeric_limits<float>::quiet_NaN());
                           return true;
                       },
                       error, from, to);
        if (!ok)
            return false;

        for (Stream &s : streams) {
            if (s.stamps.empty())
                continue;
            if (s.id == 0) {
                // Opened with its first samples: an empty stream is never written (and
                // libxdf 0.99.8 does not survive one).
                s.id = nextId++;
                s.first = s.stamps.front();
                const double rate = s.markers ? 0.0 : nominalRate(s.stamps);
                if (!writer.writeStreamHeader(s.id, headerXml(s, rate, source)))
                    return failed();
                for (size_t i = 0; i < offsetsWritten; ++i) {
                    if (!writeOffset(s, offsets[i]))
                        return failed();
                }
            }
            const bool written = s.markers ? writer.writeStringSamples(s.id, s.stamps, s.strings)
                                           : writer.writeSamples(s.id, s.stamps, s.values);
            if (!written)
                return failed();
            s.count += qint64(s.stamps.size());
            s.last = s.stamps.back();
            s.stamps.clear();
            s.values.clear();
            s.strings.clear();
        }
        // The clock's samples of this window, for every stream open so far.
        for (; offsetsWritten < offsets.size(); ++offsetsWritten) {
            const double t = clock.samples()[offsetsWritten].t;
            if (to != SessionReader::Forever && t >= to)
                break;
            for (Stream &s : streams) {
                if (s.id != 0 && !writeOffset(s, offsets[offsetsWritten]))
                    return failed();
            }
        }
        if (to == SessionReader::Forever)
            break;
        if ((window + 1) % ChunksPerBoundary == 0 && !writer.writeBoundary())
            return failed();
    }
    for (const Stream &s : streams) {
        if (s.id != 0 && !writer.writeStreamFooter(s.id, footerXml(s)))
            return failed();
    }
    return true;
}

} // namespace semhap
