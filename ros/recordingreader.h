// SPDX-License-Identifier: MIT
#pragma once

#include "actortable.h"
#include "contactframe.h"
#include "frameassembler.h"
#include "mcapreader.h"
#include "topicdecoder.h"
#include "topicmap.h"

#include <QString>

#include <memory>
#include <vector>

namespace semhap {

/**
 * A robot's recording (rosbag2 in MCAP) read as contact frames through a topic map. open()
 * reads the whole file once to check it: its records and CRCs, that it has every topic the
 * map names and every field in their schemas, and that every mapped message decodes; so a
 * bad file or map is refused before any frame is routed. next() then reads it again, frame
 * by frame.
 */
class RecordingReader
{
public:
    /** `mapPath` names the map in errors about it. */
    RecordingReader(const QString &path, const TopicMap &map, const QString &mapPath);

    /** Checks the file against the map; false with error(). */
    bool open();
    /** The next frame; false at the end, or on an error that error() says. */
    bool next(ContactFrame *frame);

    /** `FILE: offset N: reason`, `MAP: /pointer: reason` or `FILE: TOPIC message N: reason`. */
    QString error() const { return m_error; }
    /** How much of the file next() has read, from 0 to 1. */
    double progress() const;
    /** The actors the frames name (the map's). */
    ActorTable &actors() { return m_actors; }
    /** The time of the frames' t = 0, in the recording's clock (s; Unix time for stamps). */
    double startTime() const { return double(m_epoch) + m_assembler.start(); }

private:
    bool fail(const QString &error);
    /**
     * Decodes `message` into m_values when its topic is mapped (`topic` is then the
     * assembler's index, else -1), compiling the topic's decoder on its first message.
     */
    bool decode(const McapReader &reader, const McapMessage &message, int *topic);

    static constexpr int Unseen = -2;

    QString m_path;
    QString m_mapPath;
    TopicMap m_map;
    ActorTable m_actors;
    FrameAssembler m_assembler;
    std::unique_ptr<McapReader> m_reader;
    std::vector<int> m_topicOf; ///< per channel id: the assembler's topic, -1, or Unseen
    std::vector<std::unique_ptr<TopicDecoder>> m_decoders; ///< per assembler topic
    std::vector<long long> m_messageCount;                 ///< per assembler topic
    std::vector<double> m_values;
    QString m_error;
    /// The recording's first whole second: times are read from it, to keep nanoseconds.
    std::int64_t m_epoch = -1;
    /// From an export's `semhap` metadata: the Unix time (ns) of its t = 0, or -1.
    std::int64_t m_origin = -1;
    bool m_done = false;
};

} // namespace semhap
