// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

namespace semhap {

/**
 * Joins the shards of a study simulated on many machines (`semhap study simulate --shard`,
 * docs/cluster.md) into one study, as one machine would have made it: every participant with
 * its row of the scheme, its trials in their order and their sessions, the participants in
 * the order of their numbers.
 */
class StudyMerge
{
public:
    /**
     * Merges `shards` into a new study at `out` (with its sessions folder). Refused, with
     * `error` naming the shard and the participant, when the shards are not of one protocol
     * and one simulation, when two hold the same participant, when a participant is missing
     * or unfinished, or when `out` exists or is a shard. Nothing is left at `out` on failure.
     */
    static bool merge(const QString &out, const QStringList &shards, QString *error);
};

} // namespace semhap
