// SPDX-License-Identifier: MIT
// Router documents: parse, compile, and run a few frames through what compiled.
#include "jsonreader.h"
#include "pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QJsonObject json;
    semhap::LoadError error;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    semhap::RouterGraph graph;
    if (!semhap::parseJsonObject(bytes, QStringLiteral("fuzz"), &json, &error) ||
        !semhap::RouterGraph::fromJson(json, QStringLiteral("fuzz"), &graph, &error))
        return 0;
    std::unique_ptr<semhap::Router> router = semhap::Router::compile(graph, &error);
    if (!router)
        return 0;
    semhap::Pipeline pipeline(std::move(router));
    semhap::PipelineSink sink;
    for (int k = 0; k < 50; ++k) {
        semhap::ContactFrame frame;
        frame.t = k * 0.01;
        frame.gripper = k % 2 ? semhap::Gripper::Left : semhap::Gripper::Right;
        frame.left = {double(k * 3 % 140), k % 33, 0, false, {}};
        frame.right = frame.left;
        pipeline.process(frame, sink);
        pipeline.flush(sink);
    }
    return 0;
}
