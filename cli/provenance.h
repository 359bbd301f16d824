// SPDX-License-Identifier: MIT
#pragma once

#include <QDateTime>
#include <QJsonObject>

namespace semhap {

/**
 * Where an output of a sweep or a simulated study came from (docs/cluster.md): semhap's
 * version and revision, the command line, the host, and when the command started and, once
 * it has, ended. Made as the command starts.
 */
class Provenance
{
public:
    Provenance();

    /** `semhap`, `command`, `host`, `started`, and `ended` when `ended` is true (now). */
    QJsonObject toJson(bool ended) const;

private:
    QDateTime m_started;
};

} // namespace semhap
