// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

struct avr_t;
struct avr_irq_t;

namespace semhap {

/**
 * lra4's I2C bus as simavr's TWI master sees it: a TCA9548A multiplexer at 0x70 and a
 * DRV2605L haptic driver at 0x5A on each of its channels 0…3. Both acknowledge their
 * addresses (the drivers only while the multiplexer connects at least one of them; a write
 * goes to every connected driver, as on the wire), keep their registers, and every register
 * write is reported. The drivers' EN is the chip's pin D2 (PD2), pulled down on the
 * board: while the chip does not drive it high (a reset, the boot loader) every driver is
 * shut down — no output, no acknowledge. A driver drives nothing (0) in standby, outside
 * real-time playback
 * (MODE 5) or when not set for an LRA (FEEDBACK bit 7); in real-time playback its output
 * is RTP_INPUT read as the datasheet says: unsigned (CONTROL3 bit 3) and unidirectional
 * (CONTROL2 bit 7 clear), RTP / 255; unsigned and bidirectional, (RTP − 128) / 127, the
 * lower half braking, no drive; signed, RTP / 127 for 0…127, negative values braking.
 */
class Drv2605lBus
{
public:
    /** What a driver register write did: written to `channel`'s driver. */
    using WriteHandler = std::function<void(int channel, std::uint8_t reg, std::uint8_t value)>;
    /** A channel's output changed. */
    using OutputHandler = std::function<void(int channel, double output)>;

    static constexpr std::uint8_t MuxAddress = 0x70;
    static constexpr std::uint8_t DriverAddress = 0x5A;
    static constexpr std::uint8_t Mode = 0x01;
    static constexpr std::uint8_t RtpInput = 0x02;
    static constexpr std::uint8_t Feedback = 0x1A;
    static constexpr std::uint8_t Control2 = 0x1C;
    static constexpr std::uint8_t Control3 = 0x1D;

    /** Attaches `channels` drivers (at most 8) to `avr`'s TWI. */
    Drv2605lBus(avr_t *avr, int channels, WriteHandler written, OutputHandler changed);

    double output(int channel) const { return m_outputs[size_t(channel)]; }
    /**
     * Reads EN from the chip's port D; when it has changed, every output follows (0 while
     * low). Called at the model's rate and before every bus transfer.
     */
    void followEnable();
    /** Driver `channel`'s register `reg` as it holds it now. */
    std::uint8_t reg(int channel, std::uint8_t reg) const
    {
        return m_registers[size_t(channel)][reg];
    }

private:
    enum class Target
    {
        None,
        Mux,
        Drivers
    };

    static void onMessage(avr_irq_t *irq, std::uint32_t value, void *param);
    void message(std::uint8_t kind, std::uint8_t address, std::uint8_t data);
    void write(std::uint8_t data);
    std::uint8_t read();
    void writeDriver(int channel, std::uint8_t reg, std::uint8_t value);
    /** Driver `channel`'s output from its registers and EN; reports a change. */
    void update(int channel);
    void acknowledge(std::uint8_t address);

    avr_t *m_avr;
    bool m_enabled = false;
    avr_irq_t *m_toMaster;
    WriteHandler m_written;
    OutputHandler m_changed;
    std::vector<std::array<std::uint8_t, 256>> m_registers;
    std::vector<double> m_outputs;
    std::uint8_t m_muxControl = 0; ///< the TCA9548A's one register: a bit per channel
    Target m_target = Target::None;
    std::uint8_t m_address = 0; ///< the addressed device, 8-bit form (R/W in bit 0)
    std::uint8_t m_pointer = 0; ///< the drivers' register pointer
    bool m_pointerSet = false;  ///< a write transfer's first byte sets the pointer
};

} // namespace semhap
