// SPDX-License-Identifier: MIT
#pragma once

#include "cdrdecoder.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace semhap {

/**
 * The numbers a topic map reads from one topic's messages, by their schema as the recording
 * or the live server describes it: `cdr` messages with a `ros2msg` schema, or `json`
 * messages (any schema). A path gives a number, a time (`sec`, `nanosec`) as seconds, or a
 * vector of numbers (x, y, z; or a JSON array).
 */
class TopicDecoder
{
public:
    /** One path wanted, with how many numbers it must give. */
    struct Want
    {
        QString path;
        int width = 1;
        /// A path the type may lack (a header stamp): it then reads as NaN, not an error.
        bool optional = false;
    };

    /** The schema and encoding of a topic's messages. */
    struct Description
    {
        QString topic;
        QString schemaName;
        QString schemaEncoding;
        QByteArray schema;
        QString messageEncoding;
    };

    /** Resolves `wants` in the topic's schema; false with `error` saying what is wrong. */
    bool compile(const Description &description, const std::vector<Want> &wants, QString *error);

    /** Times are read as seconds since `seconds` (CdrDecoder::setEpoch). */
    void setEpoch(std::int64_t seconds);

    /** Where want `i`'s numbers begin in decode()'s values. */
    int offset(int i) const { return m_offsets[size_t(i)]; }
    /** How many numbers decode() writes. */
    int valueCount() const { return m_valueCount; }

    /** Decodes one message; a number the message lacks is NaN. False with `error` if bad. */
    bool decode(const char *data, std::size_t size, double *values, QString *error);

private:
    bool decodeJson(const char *data, std::size_t size, double *values, QString *error) const;

    bool m_json = false;
    CdrDecoder m_cdr;
    std::vector<Want> m_wants;
    std::vector<int> m_offsets;
    std::vector<int> m_cdrOffsets; ///< want i's first number among the CDR decoder's; -1: absent
    std::vector<double> m_scratch;
    int m_valueCount = 0;
    std::int64_t m_epoch = 0;
};

} // namespace semhap
