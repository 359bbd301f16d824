// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace semhap {

/**
 * A firmware image as users flash it: Intel HEX text (what `avrdude -U flash:w:FILE:i`
 * writes), decoded into the bytes of the chip's flash. The reference boards' images are
 * built into semhap (`:/semhap/firmware/MODEL.hex`, made from firmware/boards at build time),
 * byte for byte the files the firmware target writes.
 */
class FirmwareImage
{
public:
    /** The models whose reference image this semhap carries (empty without the AVR tools). */
    static QStringList builtinNames();
    /** The built-in image of `model`; false with `error` when there is none. */
    static bool builtin(const QString &model, FirmwareImage *image, QString *error);
    /** Reads an Intel HEX file; false with `FILE: reason` or `FILE:LINE: reason`. */
    static bool load(const QString &path, FirmwareImage *image, QString *error);
    /**
     * Decodes Intel HEX text named `name` (data, end-of-file and extended address records;
     * every checksum checked); false with `NAME:LINE: reason`.
     */
    static bool parse(const QByteArray &text, const QString &name, FirmwareImage *image,
                      QString *error);

    /** Flash bytes from address 0 to the highest one written; gaps read 0xFF (erased). */
    const std::vector<std::uint8_t> &flash() const { return m_flash; }
    /** Where the image came from: a file name or `lra4.hex (built in)`. */
    const QString &name() const { return m_name; }

private:
    std::vector<std::uint8_t> m_flash;
    QString m_name;
};

} // namespace semhap
