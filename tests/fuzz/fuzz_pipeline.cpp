// SPDX-License-Identifier: MIT
// Contact frames through a whole pipeline (C3: detectors, router, player, seven devices):
// whatever the frames' times and values, every frame costs bounded work (libFuzzer's
// -timeout catches one that does not) and every device value stays within its limits.
#include "contactframereader.h"
#include "pipeline.h"

#include <QBuffer>

#include <cmath>
#include <cstdlib>

namespace {

/** Checks each device value against its model's limits; counts what passes. */
class CheckingSink : public semhap::PipelineSink
{
public:
    explicit CheckingSink(const semhap::Player &player) : m_player(player) {}
    void onEvent(const semhap::SemanticEvent &event) override
    {
        if (!std::isfinite(event.t) || !(event.intensity >= 0.0 && event.intensity <= 1.0))
            std::abort();
    }
    void onDeviceFrame(const semhap::DeviceFrame &frame) override
    {
        const semhap::DeviceModel &model = m_player.deviceModel(frame.device);
        for (int c = 0; c < frame.channelCount; ++c) {
            const semhap::ChannelSpec &channel = model.channels()[size_t(c)];
            const double v = frame.values[size_t(c)];
            if (!(v >= channel.min && v <= channel.max))
                std::abort();
        }
    }

private:
    const semhap::Player &m_player;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QByteArray input(reinterpret_cast<const char *>(data), qsizetype(size));
    QBuffer in(&input);
    in.open(QIODevice::ReadOnly);
    semhap::ContactFrameReader reader(&in, QStringLiteral("fuzz"));
    semhap::LoadError error;
    std::unique_ptr<semhap::Router> router = semhap::loadRouter(QStringLiteral("C3"), {}, &error);
    if (!router)
        std::abort();
    semhap::Pipeline pipeline(std::move(router));
    CheckingSink sink(pipeline.router().player());
    semhap::ContactFrame frame;
    while (reader.next(&frame))
        pipeline.process(frame, sink);
    pipeline.flush(sink);
    return 0;
}
