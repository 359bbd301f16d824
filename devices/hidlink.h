// SPDX-License-Identifier: MIT
#pragma once

#include "link.h"
#include "transportscheme.h"

#include <memory>
#include <vector>

struct hid_device_;

namespace semhap {

/** A HID interface as `semhap devices` lists it. */
struct HidDeviceInfo
{
    QString path;
    int vendorId = 0;
    int productId = 0;
    int usagePage = 0;
    QString manufacturer;
    QString product;
    QString serial;
};

/**
 * A band on USB HID (hidapi, hidraw backend): each frame goes out as 64-byte reports
 * (`hidreport.h`), input reports feed the same decoder as a serial stream. hidapi has no
 * descriptor to poll, so the transport reads it every 2 ms.
 */
class HidLink : public Link
{
public:
    HidLink(int vendorId, int productId);
    ~HidLink() override;

    QString uri() const override;
    bool open(QString *error) override;
    void close() override;
    int pollFd() const override { return -1; }
    bool writeFrame(const std::uint8_t *data, int size, QString *error) override;
    int read(std::uint8_t *buffer, int size, QString *error) override;

    /**
     * HID interfaces matching `vendorId`/`productId` (0: any) and `usagePage` (0: any).
     * Empty when there are none (or hidapi cannot start).
     */
    static std::vector<HidDeviceInfo> enumerate(int vendorId, int productId, int usagePage);
    /** `VID:PID` (hex), what follows `hid:`, into the IDs; false with a reason. */
    static bool parseAddress(const QString &address, DeviceUri *uri, QString *error);
    /** The same, spelled: four hex digits each. */
    static QString formatAddress(const DeviceUri &uri);
    /** Appends the bands on the protocol's usage page, as listed to the user. */
    static void present(std::vector<PortInfo> *out);

private:
    struct DeviceDeleter
    {
        void operator()(hid_device_ *device) const;
    };

    int m_vendorId;
    int m_productId;
    std::unique_ptr<hid_device_, DeviceDeleter> m_device;
};

} // namespace semhap
