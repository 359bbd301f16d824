// SPDX-License-Identifier: MIT
// The wire protocol's stream decoder: any bytes, fed whole and as HID reports; every message
// it accepts must encode and decode back to itself.
#include "framedecoder.h"
#include "hidreport.h"

#include <cstdlib>

namespace {

void checkRoundTrip(const semhap::protocol::Message &message)
{
    QByteArray again;
    semhap::protocol::encode(message, &again);
    semhap::FrameDecoder decoder;
    int count = 0;
    decoder.feed(reinterpret_cast<const std::uint8_t *>(again.constData()), size_t(again.size()),
                 [&](const semhap::protocol::Message &m) {
                     if (m.type != message.type || m.sequence != message.sequence ||
                         m.channelCount != message.channelCount)
                         std::abort();
                     ++count;
                 });
    if (count != 1)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    semhap::FrameDecoder stream;
    stream.feed(data, size, checkRoundTrip);

    semhap::FrameDecoder reports;
    for (size_t pos = 0; pos < size; pos += semhap::hidreport::ReportSize) {
        const int n = int(std::min<size_t>(semhap::hidreport::ReportSize, size - pos));
        const std::uint8_t *bytes = nullptr;
        const int length = semhap::hidreport::unpack(data + pos, n, &bytes);
        if (length > 0)
            reports.feed(bytes, size_t(length), checkRoundTrip);
    }
    return 0;
}
