// SPDX-License-Identifier: MIT
// The band firmware's core under any bytes, fed in pieces with the clock moving: it must
// never write outside its buffers, never drive an output above its limit, answer only with
// valid frames, and count exactly what the host's decoder counts on the same stream.
#include "band.h"
#include "framedecoder.h"

#include <cstdlib>

namespace {

struct Board
{
    std::uint32_t now = 0;
    semhap::FrameDecoder replies;
    int written = 0;
};

constexpr std::uint16_t Limit = 60000;

void write(void *context, const std::uint8_t *bytes, size_t size)
{
    auto *board = static_cast<Board *>(context);
    ++board->written;
    // One whole frame per write, and a valid one.
    int frames = 0;
    board->replies.feed(bytes, size, [&frames](const semhap::protocol::Message &) { ++frames; });
    if (frames != 1 || board->replies.counters().errors() != 0)
        std::abort();
}

std::uint32_t millis(void *context)
{
    return static_cast<Board *>(context)->now;
}

void setOutput(void *, std::uint8_t channel, std::uint16_t value)
{
    if (channel >= 4 || value > Limit)
        std::abort();
}

std::uint16_t readSensor(void *context, std::uint8_t)
{
    // An overpressure now and then, driven by the clock the input moves.
    return (static_cast<Board *>(context)->now & 0x400) ? 0xFFFF : 0;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const semhap_band_channel channels[] = {{"m1", 0.0f, 1.0f, Limit},
                                                   {"m2", 0.0f, 1.0f, Limit},
                                                   {"m3", 0.0f, 1.0f, Limit},
                                                   {"m4", 0.0f, 1.0f, Limit}};
    static const semhap_band_model model = {"lra4", {1, 0, 0}, 4, channels, 0, 0, 0xF000};
    Board board;
    const semhap_band_hw hw = {&board, write, millis, setOutput, readSensor};
    static semhap_band band; // 1 kB: off the fuzzer's stack
    if (semhap_band_init(&band, &model, &hw) != 0)
        std::abort();
    semhap::FrameDecoder host;
    std::uint32_t hostFrames = 0;
    // Pieces of 1..16 bytes, the clock advancing by the piece's first byte in ms.
    for (size_t pos = 0; pos < size;) {
        const size_t n = std::min<size_t>(size - pos, 1 + (data[pos] & 0x0F));
        board.now += data[pos];
        semhap_band_receive(&band, data + pos, n);
        host.feed(data + pos, n,
                  [&hostFrames](const semhap::protocol::Message &) { ++hostFrames; });
        semhap_band_poll(&band);
        pos += n;
    }
    if (band.received != hostFrames || semhap_band_garbled(&band) != host.counters().errors())
        std::abort();
    return 0;
}
