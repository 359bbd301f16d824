// SPDX-License-Identifier: MIT
// Pattern documents: parse, round-trip through toJson, and play a voice briefly.
#include "jsonreader.h"
#include "pattern.h"
#include "voice.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QJsonObject json;
    semhap::LoadError error;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    if (!semhap::parseJsonObject(bytes, QStringLiteral("fuzz"), &json, &error))
        return 0;
    semhap::PatternPtr pattern = semhap::Pattern::fromJson(json, QStringLiteral("fuzz"), &error);
    if (!pattern)
        return 0;
    if (!semhap::Pattern::fromJson(pattern->toJson(), QStringLiteral("again"), &error))
        std::abort();
    semhap::Voice voice(pattern);
    voice.begin(0.0);
    for (int k = 1; k < 200; ++k) {
        if (k == 100)
            voice.end(k * 0.005);
        voice.advance(k * 0.005);
    }
    return 0;
}
