// SPDX-License-Identifier: MIT
// MPEG haptics files: whatever reads must write back and read again, and import as a pattern
// that loads and exports again, each perception and its first library effect, within the
// renderer's bounds.
#include "hjifconverter.h"
#include "jsonreader.h"
#include "pattern.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString file = QStringLiteral("fuzz.hjif");
    QJsonObject json;
    semhap::LoadError error;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    semhap::HjifDocument document;
    if (!semhap::parseJsonObject(bytes, file, &json, &error) ||
        !semhap::HjifDocument::fromJson(json, file, &document, nullptr, &error))
        return 0;
    semhap::HjifDocument again;
    if (!semhap::HjifDocument::fromJson(document.toJson(), file, &again, nullptr, &error) ||
        again.toJson() != document.toJson())
        std::abort();
    for (size_t i = 0; i < document.perceptions.size() && i < 4; ++i) {
        const semhap::HjifPerception &perception = document.perceptions[i];
        for (const int effect : {-1, perception.library.empty() ? -1 : perception.library[0].id}) {
            semhap::ConvertOptions options;
            options.perception = perception.id;
            options.effect = effect;
            QJsonObject pattern;
            if (!semhap::HjifConverter::documentToPattern(document, file, options, &pattern,
                                                          nullptr, &error))
                continue;
            if (!semhap::Pattern::fromJson(pattern, file, &error))
                std::abort();
            options.duration = 2.0; // keep each run short whatever the envelope says
            semhap::HjifDocument back;
            if (!semhap::HjifConverter::patternToDocument(pattern, file, options, &back, nullptr,
                                                          &error))
                std::abort();
            semhap::HjifConverter::serialize(back);
        }
    }
    return 0;
}
