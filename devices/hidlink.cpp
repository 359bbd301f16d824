// SPDX-License-Identifier: MIT
#include "hidlink.h"

#include "hidreport.h"

#include <QStringList>

#include <hidapi.h>

#include <array>
#include <cwchar>

namespace semhap {

namespace {

QString fromWide(const wchar_t *text)
{
    return text ? QString::fromWCharArray(text) : QString();
}

QString hidError(hid_device *device)
{
    const QString text = fromWide(hid_error(device));
    return text.isEmpty() ? QStringLiteral("HID error") : text;
}

/** hidapi wants hid_init once per process before anything else. */
bool ensureInit()
{
    static const bool ok = hid_init() == 0;
    return ok;
}

} // namespace

void HidLink::DeviceDeleter::operator()(hid_device_ *device) const
{
    hid_close(device);
}

HidLink::HidLink(int vendorId, int productId) : m_vendorId(vendorId), m_productId(productId) {}

HidLink::~HidLink() = default;

QString HidLink::uri() const
{
    return QStringLiteral("hid:%1:%2")
        .arg(m_vendorId, 4, 16, QLatin1Char('0'))
        .arg(m_productId, 4, 16, QLatin1Char('0'));
}

bool HidLink::open(QString *error)
{
    close();
    if (!ensureInit()) {
        *error = QStringLiteral("hidapi could not start");
        return false;
    }
    // Pick the interface on our usage page; a composite device has several.
    const std::vector<HidDeviceInfo> found =
        enumerate(m_vendorId, m_productId, hidreport::UsagePage);
    if (found.empty()) {
        *error = QStringLiteral("%1: no such HID device").arg(uri());
        return false;
    }
    hid_device *device = hid_open_path(found.front().path.toLocal8Bit().constData());
    if (!device) {
        *error = QStringLiteral("%1: %2").arg(uri(), hidError(nullptr));
        return false;
    }
    hid_set_nonblocking(device, 1);
    m_device.reset(device);
    return true;
}

void HidLink::close()
{
    m_device.reset();
}

bool HidLink::writeFrame(const std::uint8_t *data, int size, QString *error)
{
    std::array<std::uint8_t, hidreport::ReportSize> report{};
    for (int pos = 0; pos < size;) {
        pos += hidreport::pack(data + pos, size - pos, report.data());
        if (hid_write(m_device.get(), report.data(), report.size()) < 0) {
            *error = hidError(m_device.get());
            return false;
        }
    }
    return true;
}

int HidLink::read(std::uint8_t *buffer, int size, QString *error)
{
    std::array<std::uint8_t, hidreport::ReportSize> report{};
    const int n = hid_read(m_device.get(), report.data(), report.size());
    if (n < 0) {
        *error = hidError(m_device.get());
        return -1;
    }
    const std::uint8_t *data = nullptr;
    const int length = n > 0 ? hidreport::unpack(report.data(), n, &data) : 0;
    if (length <= 0)
        return 0;
    const int copied = std::min(length, size);
    std::copy(data, data + copied, buffer);
    return copied;
}

std::vector<HidDeviceInfo> HidLink::enumerate(int vendorId, int productId, int usagePage)
{
    std::vector<HidDeviceInfo> out;
    if (!ensureInit())
        return out;
    hid_device_info *list = hid_enumerate(std::uint16_t(vendorId), std::uint16_t(productId));
    for (hid_device_info *d = list; d; d = d->next) {
        if (usagePage != 0 && d->usage_page != usagePage)
            continue;
        HidDeviceInfo info;
        info.path = QString::fromLocal8Bit(d->path);
        info.vendorId = d->vendor_id;
        info.productId = d->product_id;
        info.usagePage = d->usage_page;
        info.manufacturer = fromWide(d->manufacturer_string);
        info.product = fromWide(d->product_string);
        info.serial = fromWide(d->serial_number);
        out.push_back(info);
    }
    hid_free_enumeration(list);
    return out;
}

bool HidLink::parseAddress(const QString &address, DeviceUri *uri, QString *error)
{
    const auto hexId = [](const QString &text, int *value) {
        bool ok = false;
        const uint parsed = text.toUInt(&ok, 16);
        if (!ok || text.isEmpty() || text.size() > 4 || text.startsWith(QLatin1Char('+')))
            return false;
        *value = int(parsed);
        return true;
    };
    const QStringList ids = address.split(QLatin1Char(':'));
    if (ids.size() != 2 || !hexId(ids[0], &uri->vendorId) || !hexId(ids[1], &uri->productId)) {
        *error = QStringLiteral("a HID device is hid:VID:PID, each up to four hex digits "
                                "(hid:1234:5678)");
        return false;
    }
    return true;
}

QString HidLink::formatAddress(const DeviceUri &uri)
{
    return QStringLiteral("%1:%2")
        .arg(uri.vendorId, 4, 16, QLatin1Char('0'))
        .arg(uri.productId, 4, 16, QLatin1Char('0'));
}

void HidLink::present(std::vector<PortInfo> *out)
{
    for (const HidDeviceInfo &hid : enumerate(0, 0, hidreport::UsagePage)) {
        DeviceUri uri;
        uri.scheme = QStringLiteral("hid");
        uri.vendorId = hid.vendorId;
        uri.productId = hid.productId;
        out->push_back({uri.toString(), uri.scheme,
                        QString(hid.manufacturer + QLatin1Char(' ') + hid.product).trimmed(),
                        hid.vendorId, hid.productId});
    }
}

} // namespace semhap
