// SPDX-License-Identifier: MIT
// Haptic files: read as AHAP and as .haptic; whatever reads must convert to a pattern that
// loads, render back to a timeline and write out again.
#include "ahapformat.h"
#include "hapticconverter.h"
#include "jsonreader.h"
#include "metahapticformat.h"
#include "pattern.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QJsonObject json;
    semhap::LoadError error;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    if (!semhap::parseJsonObject(bytes, QStringLiteral("fuzz"), &json, &error))
        return 0;
    semhap::ConvertOptions options;
    options.modulationLimit = 29.0;
    options.duration = 5.0; // keep each run short whatever the envelope says
    for (const bool ahap : {true, false}) {
        semhap::HapticTimeline timeline;
        const bool read = ahap ? semhap::AhapFormat::read(json, QStringLiteral("fuzz"), &timeline,
                                                          nullptr, &error)
                               : semhap::MetaHapticFormat::read(json, QStringLiteral("fuzz"),
                                                                &timeline, nullptr, &error);
        if (!read || timeline.intensity.endTime() > 60.0)
            continue;
        const QJsonObject pattern =
            semhap::HapticConverter::timelineToPattern(timeline, options, QStringLiteral("fuzz"));
        if (!semhap::Pattern::fromJson(pattern, QStringLiteral("fuzz"), &error))
            std::abort();
        semhap::HapticTimeline back;
        if (!semhap::HapticConverter::patternToTimeline(pattern, QStringLiteral("fuzz"), options,
                                                        &back, nullptr, &error))
            std::abort();
        semhap::AhapFormat::write(back, QStringLiteral("fuzz"));
        semhap::MetaHapticFormat::write(back, QStringLiteral("fuzz"));
    }
    return 0;
}
