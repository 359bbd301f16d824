// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace semhap {

/**
 * The protocol over USB HID: the COBS byte stream of the serial link cut into fixed 64-byte
 * output/input reports, so one decoder serves both links and a frame longer than a report
 * simply continues in the next one.
 */
namespace hidreport {

constexpr int ReportSize = 64;
constexpr std::uint8_t ReportId = 0x01;
/** Stream bytes per report: the report ID and a length byte come first. */
constexpr int DataPerReport = ReportSize - 2;
/** Vendor-defined usage page the firmware declares, used to pick its interface. */
constexpr std::uint16_t UsagePage = 0xFF00;

/**
 * Fills `report` (ReportSize bytes) with up to DataPerReport bytes of `data`, zero-padded;
 * returns how many bytes of `data` it took.
 */
int pack(const std::uint8_t *data, int size, std::uint8_t *report);
/**
 * The stream bytes of a received report (`size` bytes, report ID first): sets `data` and
 * returns their count, or -1 when the report ID or length byte is not ours.
 */
int unpack(const std::uint8_t *report, int size, const std::uint8_t **data);

} // namespace hidreport
} // namespace semhap
