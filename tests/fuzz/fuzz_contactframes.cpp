// SPDX-License-Identifier: MIT
// Contact frame JSON Lines: any bytes are read without crashing, and every frame accepted
// survives being written and read again.
#include "contactframereader.h"
#include "jsonlineswriter.h"

#include <QBuffer>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QByteArray input(reinterpret_cast<const char *>(data), qsizetype(size));
    QBuffer in(&input);
    in.open(QIODevice::ReadOnly);
    semhap::ContactFrameReader reader(&in, QStringLiteral("fuzz"));
    QByteArray written;
    QBuffer out(&written);
    out.open(QIODevice::WriteOnly);
    semhap::JsonLinesWriter writer(&out);
    writer.setActorTable(&reader.actors());
    semhap::ContactFrame frame;
    int frames = 0;
    while (reader.next(&frame)) {
        writer.write(frame);
        ++frames;
    }
    out.close();

    QBuffer again(&written);
    again.open(QIODevice::ReadOnly);
    semhap::ContactFrameReader rereader(&again, QStringLiteral("rewritten"));
    int reread = 0;
    while (rereader.next(&frame))
        ++reread;
    if (reread != frames || rereader.rejectedCount() != 0)
        std::abort();
    return 0;
}
