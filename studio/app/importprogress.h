// SPDX-License-Identifier: MIT
#pragma once

#include "recordingimport.h"

#include <QCoreApplication>
#include <QString>

#include <memory>

class QWidget;

namespace semhap {

class Router;
struct SessionInfo;

/**
 * RecordingImport::run beside the window: on a thread of its own, while a window-modal
 * progress dialog (`importProgress`) shows how far it is and lets the user cancel. A
 * cancelled import leaves no session behind.
 */
class ImportProgress
{
    Q_DECLARE_TR_FUNCTIONS(semhap::ImportProgress)

public:
    /**
     * Imports `recording` through `topics` into a new session at `session`, routed by
     * `router`. False with the reason in `result->error`; `result->cancelled` when the user
     * stopped it.
     */
    static bool run(QWidget *parent, const QString &recording, const QString &topics,
                    std::unique_ptr<Router> router, const SessionInfo &info,
                    const QString &session, RecordingImport::Result *result);
};

} // namespace semhap
