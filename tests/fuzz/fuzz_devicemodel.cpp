// SPDX-License-Identifier: MIT
// Device model documents: parse, round-trip, and predict a step response.
#include "devicemodel.h"
#include "jsonreader.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QJsonObject json;
    semhap::LoadError error;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    if (!semhap::parseJsonObject(bytes, QStringLiteral("fuzz"), &json, &error))
        return 0;
    semhap::DeviceModelPtr model =
        semhap::DeviceModel::fromJson(json, QStringLiteral("fuzz"), &error);
    if (!model)
        return 0;
    if (!semhap::DeviceModel::fromJson(model->toJson(), QStringLiteral("again"), &error))
        std::abort();
    const std::vector<double> out = model->predict(std::vector<double>(64, 1.0), 1000.0);
    for (double v : out) {
        if (!(v >= 0.0 && v <= 1.0))
            std::abort();
    }
    return 0;
}
