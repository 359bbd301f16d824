// SPDX-License-Identifier: MIT
#pragma once

#include "engine.h"

#include <QObject>
#include <QString>

namespace semhap {

class PatternDocument;
class RouterDocument;

/**
 * What the user works on, apart from any window: the engine (the run with its scene and
 * running router, the devices with their addresses, bindings and armed state, the
 * recording), the router editor's document and the pattern designer's, and the next
 * recording's name and notes. The studio rebuilds its window around the same workspace
 * (another interface language), so none of it is lost; the device addresses the user
 * added are also kept for the next start.
 */
class Workspace : public QObject
{
    Q_OBJECT

public:
    /**
     * Adds the device addresses saved by earlier sessions to the device listing (those that
     * no longer parse are left out, with a warning naming the settings file).
     */
    explicit Workspace(QObject *parent = nullptr);
    ~Workspace() override;

    Engine &engine() { return m_engine; }
    RouterDocument &routerDocument() { return *m_routerDocument; }
    PatternDocument &patternDocument() { return *m_patternDocument; }

    /** Keeps the device addresses the user added (DeviceManager::configured) for next time. */
    void saveDeviceAddresses();

    /** The next recording's name and notes, as typed in the toolbar. */
    QString sessionName() const { return m_sessionName; }
    void setSessionName(const QString &name) { m_sessionName = name; }
    QString sessionNotes() const { return m_sessionNotes; }
    void setSessionNotes(const QString &notes) { m_sessionNotes = notes; }

private:
    Engine m_engine;
    RouterDocument *m_routerDocument;
    PatternDocument *m_patternDocument;
    QString m_sessionName;
    QString m_sessionNotes;
};

} // namespace semhap
