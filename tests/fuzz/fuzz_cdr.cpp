// SPDX-License-Identifier: MIT
// ROS 2 .msg schemas and CDR messages: the input is a schema's text, a zero byte, then a
// message. Any of them is parsed, compiled for a path to each of the root's fields, and
// decoded in bounded time and memory, or refused with a located error; never a crash.
#include "cdrdecoder.h"
#include "msgschema.h"

#include <cstdlib>
#include <cstring>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *bytes = reinterpret_cast<const char *>(data);
    const auto *zero = static_cast<const char *>(std::memchr(bytes, 0, size));
    const size_t textSize = zero ? size_t(zero - bytes) : size;
    semhap::MsgSchema schema;
    QString error;
    if (!semhap::MsgSchema::parse(QStringLiteral("fuzz/msg/Root"),
                                  QByteArray(bytes, qsizetype(textSize)), &schema, &error)) {
        if (error.isEmpty() || !error.front().isDigit())
            std::abort();
        return 0;
    }
    QStringList paths;
    for (const semhap::MsgSchema::Field &field : schema.root().fields) {
        const QString path = field.array ? field.name + QStringLiteral("[1]") : field.name;
        semhap::CdrDecoder probe;
        if (semhap::CdrDecoder::compile(schema, {path}, &probe, &error))
            paths << path;
        else if (!error.startsWith(QLatin1Char('\'')))
            std::abort();
    }
    semhap::CdrDecoder decoder;
    if (!semhap::CdrDecoder::compile(schema, paths, &decoder, &error))
        std::abort(); // each path compiled alone
    const char *message = zero ? zero + 1 : bytes + size;
    const size_t messageSize = zero ? size - textSize - 1 : 0;
    std::vector<double> values(size_t(decoder.valueCount()));
    if (!decoder.decode(message, messageSize, values.data(), &error) &&
        !error.startsWith(QLatin1String("byte ")))
        std::abort();
    return 0;
}
