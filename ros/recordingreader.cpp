// SPDX-License-Identifier: MIT
#include "recordingreader.h"

#include "jsonreader.h"

namespace semhap {

RecordingReader::RecordingReader(const QString &path, const TopicMap &map, const QString &mapPath)
    : m_path(path), m_mapPath(mapPath), m_map(map), m_assembler(map, m_actors)
{}

bool RecordingReader::fail(const QString &error)
{
    m_error = error;
    m_done = true;
    return false;
}

bool RecordingReader::open()
{
    // The first reading checks every record, and decodes every mapped message.
    McapReader check(m_path);
    McapMessage message;
    if (!check.open())
        return fail(check.error());
    int topic = -1;
    while (check.next(&message)) {
        if (!decode(check, message, &topic))
            return false;
    }
    if (!check.atEnd())
        return fail(check.error());
    QStringList recorded;
    for (const auto &[id, channel] : check.channels())
        recorded << channel.topic;
    recorded.sort();
    // An export of semhap's own says where its t = 0 was (McapExport).
    for (const McapMetadata &m : check.metadata()) {
        const auto origin = m.values.find(QStringLiteral("time_origin"));
        if (m.name == QLatin1String("semhap") && origin != m.values.end())
            m_origin = origin->second.toLongLong();
    }
    const QStringList &topics = m_assembler.topics();
    QStringList channelled; // a mapped topic with a channel and no message is only quiet
    for (const auto &[id, channel] : check.channels())
        channelled << channel.topic;
    for (int t = 0; t < topics.size(); ++t) {
        if (!m_decoders[size_t(t)] && !channelled.contains(topics[t]) &&
            !m_assembler.isOptional(t))
            return fail(QStringLiteral("%1: %2: %3 has no topic %4; its topics: %5")
                            .arg(m_mapPath, m_assembler.topicPointer(t), m_path, quoted(topics[t]),
                                 recorded.isEmpty() ? QStringLiteral("none")
                                                    : recorded.join(QStringLiteral(", "))));
    }
    std::fill(m_messageCount.begin(), m_messageCount.end(), 0);
    if (m_origin >= 0 && m_epoch >= 0)
        m_assembler.setStart(double(m_origin - m_epoch * 1000000000) * 1e-9);
    m_reader = std::make_unique<McapReader>(m_path);
    if (!m_reader->open())
        return fail(m_reader->error());
    return true;
}

bool RecordingReader::decode(const McapReader &reader, const McapMessage &message, int *topic)
{
    const QStringList &topics = m_assembler.topics();
    m_decoders.resize(size_t(topics.size()));
    m_messageCount.resize(size_t(topics.size()), 0);
    if (message.channelId >= m_topicOf.size())
        m_topicOf.resize(size_t(message.channelId) + 1, Unseen);
    if (m_epoch < 0)
        m_epoch = std::int64_t(message.logTime / 1000000000u);
    int &t = m_topicOf[message.channelId];
    if (t == Unseen) {
        // The channel's first message: is it mapped, and does its schema have the fields?
        const McapChannel &channel = *reader.channel(message.channelId);
        t = m_assembler.topicIndex(channel.topic);
        if (t >= 0 && m_decoders[size_t(t)])
            return fail(QStringLiteral("%1: the topic %2 is recorded on two channels; the map "
                                       "cannot tell which")
                            .arg(m_path, quoted(channel.topic)));
        if (t >= 0) {
            const McapSchema *schema = reader.schema(channel.schemaId);
            const TopicDecoder::Description d{channel.topic, schema ? schema->name : QString(),
                                              schema ? schema->encoding : QString(),
                                              schema ? schema->data : QByteArray(),
                                              channel.messageEncoding};
            const std::vector<TopicDecoder::Want> &wants = m_assembler.wants(t);
            auto decoder = std::make_unique<TopicDecoder>();
            decoder->setEpoch(m_epoch);
            QString why;
            const bool compiled = decoder->compile(d, wants, &why);
            if (!compiled) {
                // Name the map's entry whose path the schema does not have.
                QString pointer = m_assembler.topicPointer(t);
                for (int w = 0; w < int(wants.size()); ++w) {
                    if (why.contains(QLatin1Char('\'') + wants[size_t(w)].path +
                                     QLatin1Char('\'')))
                        pointer = m_assembler.pointers(t)[w];
                }
                return fail(
                    QStringLiteral("%1: %2: in %3: %4").arg(m_mapPath, pointer, m_path, why));
            }
            m_values.resize(std::max(m_values.size(), size_t(decoder->valueCount())));
            m_decoders[size_t(t)] = std::move(decoder);
        }
    }
    *topic = t;
    if (t < 0)
        return true;
    const long long n = ++m_messageCount[size_t(t)];
    QString why;
    if (!m_decoders[size_t(t)]->decode(message.data, message.size, m_values.data(), &why))
        return fail(QStringLiteral("%1: %2 message %3: %4")
                        .arg(m_path, m_assembler.topics()[t])
                        .arg(n)
                        .arg(why));
    return true;
}

double RecordingReader::progress() const
{
    if (!m_reader || m_reader->size() == 0)
        return m_done ? 1.0 : 0.0;
    return m_done ? 1.0 : double(m_reader->position()) / double(m_reader->size());
}

bool RecordingReader::next(ContactFrame *frame)
{
    McapMessage message;
    while (!m_assembler.next(frame)) {
        if (m_done || !m_reader)
            return false;
        if (!m_reader->next(&message)) {
            if (!m_reader->atEnd())
                return fail(m_reader->error());
            m_assembler.finish();
            m_done = true;
            continue;
        }
        int topic = -1;
        if (!decode(*m_reader, message, &topic))
            return false;
        const double logTime = double(std::int64_t(message.logTime) - m_epoch * 1000000000) * 1e-9;
        if (topic >= 0)
            m_assembler.take(topic, logTime, m_values.data());
    }
    return true;
}

} // namespace semhap
