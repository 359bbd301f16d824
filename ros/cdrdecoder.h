// SPDX-License-Identifier: MIT
#pragma once

#include "msgschema.h"

#include <QStringList>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace semhap {

/**
 * Reads chosen numbers out of CDR-encoded ROS 2 messages of one type, by paths into the
 * message: `wrench.force.z`, `header.stamp`, `data`, `points[2].x`. A path may end at a
 * number; at a time (a message of `sec` and `nanosec`, read as seconds); or at a message of
 * numbers alone, such as a Vector3, read as its numbers in order. Everything else in the
 * message is read past, so any message type carrying the paths works.
 */
class CdrDecoder
{
public:
    /**
     * Resolves `paths` in `schema`; false with `error` naming the path and what the type
     * offers instead.
     */
    static bool compile(const MsgSchema &schema, const QStringList &paths, CdrDecoder *decoder,
                        QString *error);

    /** How many numbers path `i` gives (1 for a number or a time, 3 for a Vector3). */
    int width(int i) const { return m_paths[size_t(i)].width; }
    /** Where path `i`'s numbers begin in decode()'s values. */
    int offset(int i) const { return m_paths[size_t(i)].offset; }
    /**
     * Times are read as seconds since `seconds` (e.g. a recording's first whole second), so
     * that Unix times keep their nanoseconds in a double. 0 by default.
     */
    void setEpoch(std::int64_t seconds) { m_epoch = seconds; }

    /** How many numbers decode() writes: the paths' widths summed. */
    int valueCount() const { return m_valueCount; }

    /**
     * Decodes one message (its 4-byte encapsulation header first) into `values`; false with
     * `error` (`byte N: reason`) on a message its schema does not describe.
     */
    bool decode(const char *data, std::size_t size, double *values, QString *error);

private:
    /** What is taken from one field of one type: a number into a slot, or a part within. */
    struct Take
    {
        int field = -1;
        int element = -1; ///< an array's element, or -1: the field itself
        int slot = -1;    ///< a number's place among the leaves
        int node = -1;    ///< a message field's own takes (m_nodes)
    };
    struct Node
    {
        std::vector<Take> takes;
    };
    struct Path
    {
        int width = 0;
        int offset = 0;
        bool time = false;       ///< leaves sec and nanosec, given as seconds
        std::vector<int> leaves; ///< slots, in order
    };
    struct Cursor;

    bool walk(Cursor &at, int type, int node);
    bool value(Cursor &at, const MsgSchema::Field &field, const Take *take);

    MsgSchema m_schema;
    std::vector<Node> m_nodes; ///< m_nodes[0] is the root message's
    std::vector<Path> m_paths;
    std::vector<double> m_leaves;
    std::vector<int> m_minSize; ///< per type: the fewest bytes one takes
    int m_valueCount = 0;
    std::int64_t m_epoch = 0;
};

} // namespace semhap
