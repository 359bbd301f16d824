// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QString>

#include <vector>

/**
 * The wire protocol's test vectors (tests/vectors/protocol.json), which the host's tests
 * and the band firmware's read alike, so that the two sides cannot drift apart.
 */
namespace protocolvectors {

/** Bytes the CRC and COBS must map onto each other. */
struct BytePair
{
    QString name;
    QByteArray in;
    QByteArray out;
};

/** A valid message and its exact encoding, delimiter included. */
struct Frame
{
    QString name;
    QJsonObject message; ///< "type", "sequence" and the type's fields
    QByteArray encoded;
};

/** A stream without a valid frame and the decoder counter it must raise (empty: none). */
struct Rejected
{
    QString name;
    QByteArray stream;
    QString error; ///< cobs, truncated, crc, version, unknown_type, malformed, oversize, any
};

struct Vectors
{
    std::vector<BytePair> crc; ///< in: data, out: the CRC, big-endian
    std::vector<BytePair> cobs;
    std::vector<Frame> frames;
    std::vector<Rejected> rejected;
};

/** Reads the vectors; a broken file fails the calling test with its reason. */
const Vectors &load();

/** The first frame of `type` ("identify-reply"). */
const Frame &firstOf(const QString &type);

} // namespace protocolvectors
