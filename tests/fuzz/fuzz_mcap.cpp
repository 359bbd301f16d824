// SPDX-License-Identifier: MIT
// MCAP recordings: any bytes are read to their end or to a located error, in bounded time
// and memory (a chunk's claimed size is capped), never a crash.
#include "mcapreader.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray input =
        QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
    semhap::McapReader reader(input, QStringLiteral("fuzz.mcap"));
    if (!reader.open()) {
        if (!reader.error().startsWith(QLatin1String("fuzz.mcap: offset ")))
            std::abort();
        return 0;
    }
    semhap::McapMessage message;
    unsigned sum = 0;
    while (reader.next(&message)) {
        if (!reader.channel(message.channelId))
            std::abort();
        // Every byte of a message lies within the file or a chunk the reader still holds.
        for (std::size_t i = 0; i < message.size; ++i)
            sum += unsigned(message.data[i]);
    }
    if (reader.atEnd() != reader.error().isEmpty())
        std::abort();
    if (!reader.atEnd() && !reader.error().startsWith(QLatin1String("fuzz.mcap: offset ")))
        std::abort();
    return sum == 1u ? 1 : 0; // uses the sum, so that the reads stay
}
