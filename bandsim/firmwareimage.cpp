// SPDX-License-Identifier: MIT
#include "firmwareimage.h"

#include <QDir>
#include <QFile>

#include <cctype>

namespace semhap {

namespace {

const QString BuiltinFolder = QStringLiteral(":/semhap/firmware");

/** The flash of the largest chip an image may fill (the ATmega328P: 32 KiB). */
constexpr std::uint32_t MaxFlash = 32 * 1024;

int hexDigit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

/** A record's bytes after the colon, or false when a character is not a hex digit. */
bool decodeRecord(const QByteArray &line, std::vector<std::uint8_t> *bytes)
{
    if ((line.size() - 1) % 2 != 0)
        return false;
    bytes->clear();
    for (qsizetype i = 1; i + 1 < line.size(); i += 2) {
        const int high = hexDigit(line[i]);
        const int low = hexDigit(line[i + 1]);
        if (high < 0 || low < 0)
            return false;
        bytes->push_back(std::uint8_t(high * 16 + low));
    }
    return true;
}

} // namespace

QStringList FirmwareImage::builtinNames()
{
    QStringList names;
    const QStringList files = QDir(BuiltinFolder).entryList({QStringLiteral("*.hex")});
    for (const QString &file : files)
        names << file.chopped(4);
    return names;
}

bool FirmwareImage::builtin(const QString &model, FirmwareImage *image, QString *error)
{
    QFile file(BuiltinFolder + QLatin1Char('/') + model + QStringLiteral(".hex"));
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: no built-in firmware image (this semhap was built without "
                                "the AVR tools); give one with --firmware FILE.hex")
                     .arg(model);
        return false;
    }
    return parse(file.readAll(), model + QStringLiteral(".hex (built in)"), image, error);
}

bool FirmwareImage::load(const QString &path, FirmwareImage *image, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: cannot read: %2").arg(path, file.errorString());
        return false;
    }
    // An image is a few dozen KiB of text; anything far larger is not one.
    const QByteArray text = file.read(qint64(MaxFlash) * 4);
    if (!file.atEnd()) {
        *error =
            QStringLiteral("%1: not an Intel HEX image for a 32 KiB flash (too large)").arg(path);
        return false;
    }
    return parse(text, path, image, error);
}

bool FirmwareImage::parse(const QByteArray &text, const QString &name, FirmwareImage *image,
                          QString *error)
{
    image->m_flash.clear();
    image->m_name = name;
    std::uint32_t base = 0; // from extended segment (02) and linear (04) address records
    std::vector<std::uint8_t> record;
    const QList<QByteArray> lines = text.split('\n');
    for (qsizetype n = 0; n < lines.size(); ++n) {
        const QByteArray line = lines[n].trimmed();
        const qsizetype indent = lines[n].indexOf(line.isEmpty() ? '\n' : line[0]);
        // Columns count from the record's colon; errors about a whole record name it.
        const auto failAt = [&](qsizetype column, const QString &reason) {
            *error = QStringLiteral("%1:%2:%3: %4")
                         .arg(name)
                         .arg(n + 1)
                         .arg(indent + column + 1)
                         .arg(reason);
            return false;
        };
        const auto fail = [&](const QString &reason) { return failAt(0, reason); };
        if (line.isEmpty())
            continue;
        if (line[0] != ':')
            return fail(QStringLiteral("not an Intel HEX record (no ':' first)"));
        if (!decodeRecord(line, &record) || record.size() < 5) {
            qsizetype bad = 1;
            while (bad < line.size() && std::isxdigit(static_cast<unsigned char>(line[bad])))
                ++bad;
            return failAt(bad, bad < line.size()
                                   ? QStringLiteral("not a hexadecimal digit")
                                   : QStringLiteral("not an Intel HEX record (too short or "
                                                    "an odd number of digits)"));
        }
        const size_t length = record[0];
        if (record.size() != length + 5)
            return fail(QStringLiteral("the record's length byte says %1 data bytes, it has %2")
                            .arg(length)
                            .arg(record.size() - 5));
        std::uint8_t sum = 0;
        for (const std::uint8_t b : record)
            sum = std::uint8_t(sum + b);
        if (sum != 0)
            return fail(QStringLiteral("checksum mismatch"));
        const std::uint32_t offset = std::uint32_t(record[1]) << 8 | record[2];
        const std::uint8_t *data = record.data() + 4;
        switch (record[3]) {
        case 0x00: {
            const std::uint32_t address = base + offset;
            if (address + length > MaxFlash)
                return fail(QStringLiteral("data at 0x%1, beyond the 32 KiB flash")
                                .arg(address + length - 1, 0, 16));
            if (image->m_flash.size() < address + length)
                image->m_flash.resize(address + length, 0xFF);
            std::copy(data, data + length, image->m_flash.begin() + address);
            break;
        }
        case 0x01:
            if (image->m_flash.empty())
                return fail(QStringLiteral("the image ends before any data"));
            return true;
        case 0x02:
        case 0x04:
            if (length != 2)
                return fail(QStringLiteral("an address record with %1 data bytes").arg(length));
            base = (std::uint32_t(data[0]) << 8 | data[1]) << (record[3] == 0x02 ? 4 : 16);
            break;
        case 0x03:
        case 0x05:
            break; // a start address: an AVR always starts at its reset vector
        default:
            return fail(QStringLiteral("unknown record type %1").arg(record[3]));
        }
    }
    *error = QStringLiteral("%1: no end-of-file record (a truncated image?)").arg(name);
    return false;
}

} // namespace semhap
