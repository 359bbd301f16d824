// SPDX-License-Identifier: MIT
#include "importprogress.h"

#include "router.h"
#include "sessioninfo.h"

#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QProgressDialog>
#include <QTimer>

#include <atomic>
#include <thread>

namespace semhap {

bool ImportProgress::run(QWidget *parent, const QString &recording, const QString &topics,
                         std::unique_ptr<Router> router, const SessionInfo &info,
                         const QString &session, RecordingImport::Result *result)
{
    QProgressDialog progress(
        tr("Importing %1 into %2…")
            .arg(QFileInfo(recording).fileName(), QFileInfo(session).fileName()),
        tr("Cancel"), 0, 1000, parent);
    progress.setObjectName(QStringLiteral("importProgress"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(300);
    std::atomic<int> done{0};
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
    bool imported = false;
    std::thread worker([&, router = std::move(router)]() mutable {
        imported = RecordingImport::run(
            recording, topics, std::move(router), info, session,
            [&](double share) {
                done = int(share * 1000);
                return !cancel.load();
            },
            result);
        finished = true;
    });
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        progress.setValue(std::min(done.load(), 999));
        if (progress.wasCanceled())
            cancel = true;
        if (finished)
            loop.quit();
    });
    poll.start(50);
    loop.exec();
    worker.join();
    progress.reset();
    if (imported && result->cancelled)
        QFile::remove(session); // the user stopped it: no half session left behind
    return imported;
}

} // namespace semhap
