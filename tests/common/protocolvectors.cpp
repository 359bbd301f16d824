// SPDX-License-Identifier: MIT
#include "protocolvectors.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

#include <cstdio>
#include <cstdlib>

namespace protocolvectors {

namespace {

[[noreturn]] void fail(const QString &why)
{
    std::fprintf(stderr, "%s\n", qPrintable(why));
    std::abort();
}

QByteArray hex(const QJsonValue &value)
{
    QByteArray text = value.toString().toLatin1();
    text.replace(' ', "");
    return QByteArray::fromHex(text);
}

Vectors read()
{
    const QString path = QStringLiteral(SEMHAP_VECTORS "/protocol.json");
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        fail(path + QStringLiteral(": ") + file.errorString());
    QJsonParseError error{};
    const QJsonObject root = QJsonDocument::fromJson(file.readAll(), &error).object();
    if (error.error != QJsonParseError::NoError ||
        root.value(QStringLiteral("format")).toString() !=
            QStringLiteral("semhap.protocol-vectors/1"))
        fail(path + QStringLiteral(": not semhap.protocol-vectors/1: ") + error.errorString());
    Vectors v;
    for (const QJsonValue item : root.value(QStringLiteral("crc")).toArray()) {
        const QJsonObject o = item.toObject();
        v.crc.push_back({o.value(QStringLiteral("name")).toString(),
                         o.value(QStringLiteral("ascii")).toString().toLatin1(),
                         hex(o.value(QStringLiteral("crc")))});
    }
    for (const QJsonValue item : root.value(QStringLiteral("cobs")).toArray()) {
        const QJsonObject o = item.toObject();
        v.cobs.push_back({o.value(QStringLiteral("name")).toString(),
                          hex(o.value(QStringLiteral("plain"))),
                          hex(o.value(QStringLiteral("encoded")))});
    }
    for (const QJsonValue item : root.value(QStringLiteral("frames")).toArray()) {
        const QJsonObject o = item.toObject();
        v.frames.push_back({o.value(QStringLiteral("name")).toString(),
                            o.value(QStringLiteral("message")).toObject(),
                            hex(o.value(QStringLiteral("encoded")))});
    }
    for (const QJsonValue item : root.value(QStringLiteral("rejected")).toArray()) {
        const QJsonObject o = item.toObject();
        v.rejected.push_back({o.value(QStringLiteral("name")).toString(),
                              hex(o.value(QStringLiteral("stream"))),
                              o.value(QStringLiteral("error")).toString()});
    }
    if (v.crc.empty() || v.cobs.empty() || v.frames.empty() || v.rejected.empty())
        fail(path + QStringLiteral(": a section is missing or empty"));
    return v;
}

} // namespace

const Vectors &load()
{
    static const Vectors vectors = read();
    return vectors;
}

const Frame &firstOf(const QString &type)
{
    for (const Frame &f : load().frames) {
        if (f.message.value(QStringLiteral("type")).toString() == type)
            return f;
    }
    fail(QStringLiteral("tests/vectors/protocol.json: no frame of type ") + type);
}

} // namespace protocolvectors
