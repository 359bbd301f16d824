// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>

namespace semhap {

/**
 * What one router node passes on from time t: the messages it lets through (a detector its
 * own, a filter those that match, a gate those it lets by, a pattern node those it plays)
 * and their highest intensity. The node editor's live wires show these, so they show what
 * really routed.
 */
struct NodeActivity
{
    double t = 0.0;
    int node = -1;       ///< index into Router::nodeIds
    double level = -1.0; ///< the highest intensity passed on; -1 when nothing passes
    /** The messages passed on (Message ids), ascending: the first MaxMessages of them. */
    std::array<int, 4> messages{};
    int messageCount = 0;
    bool exception = false; ///< whether any message passed on is an exception

    static constexpr int MaxMessages = 4;

    bool isActive() const { return level >= 0.0; }
    /** Adds message `id` to the list, keeping it ascending and without repeats. */
    void addMessage(int id)
    {
        int at = 0;
        while (at < messageCount && messages[size_t(at)] < id)
            ++at;
        if ((at < messageCount && messages[size_t(at)] == id) || at >= MaxMessages)
            return;
        for (int i = std::min(messageCount, MaxMessages - 1); i > at; --i)
            messages[size_t(i)] = messages[size_t(i - 1)];
        messages[size_t(at)] = id;
        messageCount = std::min(messageCount + 1, MaxMessages);
    }
    bool sameMessages(const NodeActivity &other) const
    {
        if (messageCount != other.messageCount)
            return false;
        for (int i = 0; i < messageCount; ++i) {
            if (messages[size_t(i)] != other.messages[size_t(i)])
                return false;
        }
        return true;
    }
};

} // namespace semhap
