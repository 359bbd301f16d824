// SPDX-License-Identifier: MIT
#include "sentfeed.h"

#include "devicemanager.h"
#include "runhistory.h"

namespace semhap {

void SentFeed::start(const QStringList &devices, const DeviceManager &manager)
{
    m_readers.clear();
    rebind(devices, manager);
}

void SentFeed::rebind(const QStringList &devices, const DeviceManager &manager)
{
    std::vector<Reader> readers;
    for (const QString &name : devices) {
        Reader reader;
        reader.transport = manager.sharedTransport(name);
        if (reader.transport)
            reader.next = reader.transport->sent().count();
        for (const Reader &old : m_readers) {
            if (reader.transport && old.transport == reader.transport)
                reader.next = old.next;
        }
        readers.push_back(reader);
    }
    m_readers = std::move(readers);
}

void SentFeed::drainInto(RunHistory &history)
{
    for (size_t d = 0; d < m_readers.size(); ++d) {
        Reader &reader = m_readers[d];
        if (!reader.transport)
            continue;
        m_frames.clear();
        m_lost += reader.transport->sent().readSince(&reader.next, &m_frames);
        for (DeviceFrame &frame : m_frames) {
            frame.device = int(d); // an audition's or a stop-all's frames name no device
            history.append(frame);
        }
    }
}

} // namespace semhap
