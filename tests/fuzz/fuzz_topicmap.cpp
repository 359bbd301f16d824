// SPDX-License-Identifier: MIT
// Topic maps (semhap.topics/1): any bytes are read as a map or refused with a located error;
// a map read drives the frame assembler with messages on each of its topics, in bounded
// memory (frames wait for at most FrameAssembler::MaxPending clock messages), never a crash.
#include "frameassembler.h"
#include "jsonreader.h"
#include "topicmap.h"

#include <cmath>
#include <cstdlib>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QJsonObject json;
    semhap::LoadError error;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    if (!semhap::parseJsonObject(bytes, QStringLiteral("fuzz.json"), &json, &error))
        return 0;
    semhap::JsonReader reader(QStringLiteral("fuzz.json"));
    semhap::TopicMap map;
    if (!semhap::TopicMap::fromJson(reader, json, &map)) {
        if (!reader.error().toString().startsWith(QLatin1String("fuzz.json: ")))
            std::abort();
        return 0;
    }
    semhap::ActorTable actors;
    semhap::FrameAssembler assembler(map, actors);
    // Each topic in turn, times that go forth and sometimes back, values from the input.
    std::vector<double> values(64, 0.0);
    semhap::ContactFrame frame;
    int frames = 0;
    for (int k = 0; k < 3000; ++k) {
        const int topic = k % int(assembler.topics().size());
        int count = 0;
        for (const auto &want : assembler.wants(topic))
            count += want.width;
        if (count > int(values.size()))
            std::abort(); // a map asks at most a stamp, a force, a count and signals per topic
        for (int i = 0; i < count; ++i)
            values[size_t(i)] = size > 0 ? double(data[size_t(k + i) % size]) - 100.0 : 0.0;
        const double t = k * 0.001 - ((k % 7 == 0) ? 0.01 : 0.0);
        // Now and then a message without a stamp (NaN), timed by its log time instead.
        values[0] = k % 5 == 0 ? std::nan("") : t;
        assembler.take(topic, t, values.data());
        while (assembler.next(&frame))
            ++frames;
    }
    assembler.finish();
    while (assembler.next(&frame))
        ++frames;
    return frames < 0 ? 1 : 0;
}
