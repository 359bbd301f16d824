// SPDX-License-Identifier: MIT
// Contact frames through a whole pipeline (C3: detectors, router, player, seven devices; then
// a router of generic nodes on the frames' signals): whatever the frames' times, values and
// signals, every frame costs bounded work (libFuzzer's -timeout catches one that does not)
// and every device value stays within its limits.
#include "contactframereader.h"
#include "pipeline.h"

#include <QBuffer>
#include <QJsonDocument>
#include <QJsonObject>

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

/** Thresholds of every condition on two signals, composed, into the squeeze and the geiger. */
std::unique_ptr<semhap::Router> genericRouter()
{
    const QJsonObject json = QJsonDocument::fromJson(R"({"format": "semhap.router/1", "nodes": [
        {"id": "angle", "type": "signal", "params": {"gripper": "right", "quantity": "plug.angle"}},
        {"id": "fz", "type": "signal", "params": {"gripper": "right", "quantity": "wrist.fz"}},
        {"id": "slope", "type": "predict", "params": {"horizon": 0.3}},
        {"id": "aligned", "type": "threshold", "params": {"gripper": "right",
         "message": "aligned", "category": "confirmation", "condition": "inside",
         "begin": [-0.05, 0.05], "end": [-0.06, 0.06], "minDuration": 0.02}},
        {"id": "hard", "type": "threshold", "params": {"gripper": "right", "message": "hard",
         "category": "exception", "begin": 20, "end": 15, "intensity": [20, 30]}},
        {"id": "off", "type": "threshold", "params": {"gripper": "right", "message": "off",
         "category": "exception", "condition": "outside", "begin": [-1, 1]}},
        {"id": "both", "type": "compose", "params": {"message": "both", "category": "exception",
         "mode": "any"}},
        {"id": "ready", "type": "compose", "params": {"message": "ready",
         "category": "confirmation", "mode": "while"}},
        {"id": "squeeze", "type": "pattern", "params": {"pattern": "air.squeeze"}},
        {"id": "geiger", "type": "pattern", "params": {"pattern": "vib.geiger"}},
        {"id": "right.air", "type": "device", "params": {"model": "pneumatic6"}},
        {"id": "right.vibro", "type": "device", "params": {"model": "lra4"}}],
      "links": [{"from": "angle", "to": "aligned"}, {"from": "fz", "to": "slope"},
        {"from": "slope", "to": "hard"}, {"from": "angle", "to": "off"},
        {"from": "hard", "to": "both:a"}, {"from": "off", "to": "both:b"},
        {"from": "aligned", "to": "ready:a"}, {"from": "hard", "to": "ready:b"},
        {"from": "ready", "to": "squeeze"}, {"from": "both", "to": "geiger"},
        {"from": "squeeze", "to": "right.air"}, {"from": "geiger", "to": "right.vibro"}]})")
                                 .object();
    semhap::RouterGraph graph;
    semhap::LoadError error;
    if (!semhap::RouterGraph::fromJson(json, QStringLiteral("generic"), &graph, &error))
        return nullptr;
    return semhap::Router::compile(graph, &error);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QByteArray input(reinterpret_cast<const char *>(data), qsizetype(size));
    semhap::LoadError error;
    std::unique_ptr<semhap::Router> routers[] = {
        semhap::loadRouter(QStringLiteral("C3"), {}, &error), genericRouter()};
    for (std::unique_ptr<semhap::Router> &router : routers) {
        if (!router)
            std::abort();
        QBuffer in(&input);
        in.open(QIODevice::ReadOnly);
        semhap::ContactFrameReader reader(&in, QStringLiteral("fuzz"));
        semhap::Pipeline pipeline(std::move(router));
        CheckingSink sink(pipeline.router().player());
        semhap::ContactFrame frame;
        while (reader.next(&frame))
            pipeline.process(frame, sink);
        pipeline.flush(sink);
    }
    return 0;
}
