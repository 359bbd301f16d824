// SPDX-License-Identifier: MIT
#include "protocol.h"

#include "wire.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace semhap {
namespace protocol {

namespace {

/** Appends little-endian fields to a payload under construction. */
class Writer
{
public:
    explicit Writer(std::vector<std::uint8_t> *bytes) : m_bytes(bytes) {}
    void u8(std::uint8_t v) { m_bytes->push_back(v); }
    void u16(std::uint16_t v)
    {
        u8(std::uint8_t(v & 0xFF));
        u8(std::uint8_t(v >> 8));
    }
    void u32(std::uint32_t v)
    {
        u16(std::uint16_t(v & 0xFFFF));
        u16(std::uint16_t(v >> 16));
    }
    void u64(std::uint64_t v)
    {
        u32(std::uint32_t(v & 0xFFFFFFFFu));
        u32(std::uint32_t(v >> 32));
    }
    void f32(float v)
    {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }
    void text(const QString &s)
    {
        const QByteArray utf8 = s.toUtf8().left(MaxNameLength);
        u8(std::uint8_t(utf8.size()));
        m_bytes->insert(m_bytes->end(), utf8.begin(), utf8.end());
    }

private:
    std::vector<std::uint8_t> *m_bytes;
};

/** Reads little-endian fields; any read past the end makes the whole payload malformed. */
class Reader
{
public:
    Reader(const std::uint8_t *data, int size) : m_data(data), m_size(size) {}
    bool ok() const { return m_ok; }
    bool atEnd() const { return m_pos == m_size; }
    std::uint8_t u8() { return take(1) ? m_data[m_pos - 1] : 0; }
    std::uint16_t u16()
    {
        const std::uint8_t lo = u8();
        return std::uint16_t(lo | (u8() << 8));
    }
    std::uint32_t u32()
    {
        const std::uint16_t lo = u16();
        return lo | (std::uint32_t(u16()) << 16);
    }
    std::uint64_t u64()
    {
        const std::uint32_t lo = u32();
        return lo | (std::uint64_t(u32()) << 32);
    }
    float f32()
    {
        const std::uint32_t bits = u32();
        float v = 0.0f;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    QString text()
    {
        const int length = u8();
        if (length > MaxNameLength || !take(length))
            return fail();
        return QString::fromUtf8(reinterpret_cast<const char *>(m_data + m_pos - length), length);
    }

private:
    bool take(int n)
    {
        if (!m_ok || m_size - m_pos < n) {
            m_ok = false;
            return false;
        }
        m_pos += n;
        return true;
    }
    QString fail()
    {
        m_ok = false;
        return {};
    }

    const std::uint8_t *m_data;
    int m_size;
    int m_pos = 0;
    bool m_ok = true;
};

void writePayload(const Message &m, Writer &w)
{
    switch (m.type) {
    case MessageType::IdentifyRequest:
    case MessageType::StopAll:
    case MessageType::StatusRequest:
        break;
    case MessageType::IdentifyReply: {
        const Identity &id = m.identity;
        w.u8(id.firmwareMajor);
        w.u8(id.firmwareMinor);
        w.u8(id.firmwarePatch);
        w.text(id.model);
        const size_t count = std::min<size_t>(id.channels.size(), MaxWireChannels);
        w.u8(std::uint8_t(count));
        for (size_t c = 0; c < count; ++c) {
            w.text(id.channels[c].name);
            w.f32(id.channels[c].min);
            w.f32(id.channels[c].max);
        }
        break;
    }
    case MessageType::SetValues: {
        const int count = std::clamp(m.channelCount, 0, MaxWireChannels);
        w.u8(std::uint8_t(count));
        for (int c = 0; c < count; ++c)
            w.u16(m.values[size_t(c)]);
        break;
    }
    case MessageType::Heartbeat:
    case MessageType::HeartbeatReply:
        w.u64(m.timestamp);
        break;
    case MessageType::Status:
        w.u16(m.status.flags);
        w.u16(m.status.acknowledged);
        w.u32(m.status.framesReceived);
        w.u32(m.status.framesDropped);
        w.u32(m.status.framesGarbled);
        break;
    }
}

bool readPayload(Reader &r, Message *m)
{
    switch (m->type) {
    case MessageType::IdentifyRequest:
    case MessageType::StopAll:
    case MessageType::StatusRequest:
        break;
    case MessageType::IdentifyReply: {
        Identity &id = m->identity;
        id.firmwareMajor = r.u8();
        id.firmwareMinor = r.u8();
        id.firmwarePatch = r.u8();
        id.model = r.text();
        const int count = r.u8();
        if (count > MaxWireChannels)
            return false;
        id.channels.clear();
        for (int c = 0; c < count && r.ok(); ++c) {
            WireChannel channel;
            channel.name = r.text();
            channel.min = r.f32();
            channel.max = r.f32();
            id.channels.push_back(channel);
        }
        break;
    }
    case MessageType::SetValues:
        m->channelCount = r.u8();
        if (m->channelCount > MaxWireChannels)
            return false;
        for (int c = 0; c < m->channelCount; ++c)
            m->values[size_t(c)] = r.u16();
        break;
    case MessageType::Heartbeat:
    case MessageType::HeartbeatReply:
        m->timestamp = r.u64();
        break;
    case MessageType::Status:
        m->status.flags = r.u16();
        m->status.acknowledged = r.u16();
        m->status.framesReceived = r.u32();
        m->status.framesDropped = r.u32();
        m->status.framesGarbled = r.u32();
        break;
    }
    return r.ok() && r.atEnd();
}

/** Header, payload and CRC into `frame`; returns the unencoded length. */
int assemble(MessageType type, std::uint16_t sequence, const std::uint8_t *payload, int size,
             std::uint8_t *frame)
{
    if (size > 0)
        std::memcpy(frame + HeaderSize, payload, size_t(size));
    return int(semhap_seal_frame(frame, std::uint8_t(type), sequence, size_t(size)));
}

} // namespace

std::uint16_t crc16(const std::uint8_t *data, size_t size, std::uint16_t crc)
{
    return semhap_crc16(data, size, crc);
}

std::uint16_t toWire(double value, double min, double max)
{
    if (!(max > min) || !(value > min))
        return 0;
    if (value >= max)
        return 65535;
    return std::uint16_t(std::lround((value - min) / (max - min) * 65535.0));
}

double fromWire(std::uint16_t value, double min, double max)
{
    return min + (max - min) * double(value) / 65535.0;
}

int cobsEncode(const std::uint8_t *in, int size, std::uint8_t *out)
{
    return int(semhap_cobs_encode(in, size_t(size), out));
}

int cobsDecode(const std::uint8_t *in, int size, std::uint8_t *out)
{
    return int(semhap_cobs_decode(in, size_t(size), out));
}

void encode(const Message &message, QByteArray *out)
{
    std::vector<std::uint8_t> payload;
    Writer writer(&payload);
    writePayload(message, writer);
    const int size = std::min(int(payload.size()), MaxPayload);
    std::array<std::uint8_t, MaxFrame> frame{};
    const int length =
        assemble(message.type, message.sequence, payload.data(), size, frame.data());
    std::array<std::uint8_t, MaxEncodedFrame + 1> encoded{};
    const int n = cobsEncode(frame.data(), length, encoded.data());
    encoded[size_t(n)] = 0;
    out->append(reinterpret_cast<const char *>(encoded.data()), n + 1);
}

int encodeSetValues(std::uint16_t sequence, const std::uint16_t *values, int count,
                    std::uint8_t *out)
{
    count = std::clamp(count, 0, MaxWireChannels);
    std::array<std::uint8_t, 1 + 2 * MaxWireChannels> payload{};
    payload[0] = std::uint8_t(count);
    for (int c = 0; c < count; ++c) {
        payload[size_t(1 + 2 * c)] = std::uint8_t(values[c] & 0xFF);
        payload[size_t(2 + 2 * c)] = std::uint8_t(values[c] >> 8);
    }
    std::array<std::uint8_t, HeaderSize + 1 + 2 * MaxWireChannels + CrcSize> frame{};
    const int length =
        assemble(MessageType::SetValues, sequence, payload.data(), 1 + 2 * count, frame.data());
    const int n = cobsEncode(frame.data(), length, out);
    out[n] = 0;
    return n + 1;
}

bool decodeFrame(const std::uint8_t *frame, int size, Message *message, FrameError *error)
{
    // The band's own check (firmware/core/wire.c), so that host and band agree on every frame.
    switch (semhap_check_frame(frame, size_t(size))) {
    case SEMHAP_FRAME_OK:
        *error = FrameError::None;
        break;
    case SEMHAP_FRAME_COBS:
        *error = FrameError::Cobs;
        return false;
    case SEMHAP_FRAME_TRUNCATED:
        *error = FrameError::Truncated;
        return false;
    case SEMHAP_FRAME_CRC:
        *error = FrameError::Crc;
        return false;
    case SEMHAP_FRAME_VERSION:
        *error = FrameError::Version;
        return false;
    case SEMHAP_FRAME_UNKNOWN_TYPE:
        *error = FrameError::UnknownType;
        return false;
    case SEMHAP_FRAME_MALFORMED:
        *error = FrameError::Malformed;
        return false;
    case SEMHAP_FRAME_OVERSIZE:
        *error = FrameError::Oversize;
        return false;
    }
    // The decoder reuses one message: fields of another type must not survive.
    message->channelCount = 0;
    message->timestamp = 0;
    message->status = {};
    message->type = MessageType(frame[1]);
    message->sequence = std::uint16_t(frame[2] | (frame[3] << 8));
    Reader reader(frame + HeaderSize, size - HeaderSize - CrcSize);
    if (!readPayload(reader, message)) {
        *error = FrameError::Malformed;
        return false;
    }
    return true;
}

QString typeName(MessageType type)
{
    switch (type) {
    case MessageType::IdentifyRequest:
        return QStringLiteral("identify-request");
    case MessageType::IdentifyReply:
        return QStringLiteral("identify-reply");
    case MessageType::SetValues:
        return QStringLiteral("set-values");
    case MessageType::StopAll:
        return QStringLiteral("stop-all");
    case MessageType::Heartbeat:
        return QStringLiteral("heartbeat");
    case MessageType::HeartbeatReply:
        return QStringLiteral("heartbeat-reply");
    case MessageType::StatusRequest:
        return QStringLiteral("status-request");
    case MessageType::Status:
        return QStringLiteral("status");
    }
    return QStringLiteral("unknown");
}

} // namespace protocol
} // namespace semhap
