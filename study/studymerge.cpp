// SPDX-License-Identifier: MIT
#include "studymerge.h"

#include "studydatabase.h"
#include "studysimulation.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <map>
#include <memory>
#include <vector>

namespace semhap {

namespace {

/** The keys of a simulation record that every shard of one study shares. */
const char *const Shared[] = {"participants", "operator", "trial_seconds", "person"};

QJsonObject simulationOf(const StudyDatabase &study)
{
    return QJsonDocument::fromJson(study.value(QStringLiteral("simulation")).toUtf8()).object();
}

/** Whether every practice round and trial of the participant's order is done. */
bool isFinished(const StudyDatabase &study, const QString &participant)
{
    for (const StudyProtocol::Step &step : study.protocol().steps(study.order(participant))) {
        if ((step.kind == StudyProtocol::Step::Kind::Practice ||
             step.kind == StudyProtocol::Step::Kind::Trial) &&
            !study.isDone(participant, step))
            return false;
    }
    return true;
}

} // namespace

bool StudyMerge::merge(const QString &out, const QStringList &shards, QString *error)
{
    if (shards.isEmpty()) {
        *error = QStringLiteral("%1: no shards to merge").arg(out);
        return false;
    }
    if (QFileInfo::exists(out)) {
        *error = QStringLiteral("%1: already exists (a study is never overwritten)").arg(out);
        return false;
    }
    // Every shard read and checked before anything is written.
    std::vector<std::unique_ptr<StudyDatabase>> studies;
    for (const QString &shard : shards) {
        std::unique_ptr<StudyDatabase> study =
            StudyDatabase::open(shard, StudyDatabase::Access::Read, error);
        if (!study)
            return false;
        studies.push_back(std::move(study));
    }
    const StudyDatabase &first = *studies.front();
    const QJsonObject simulation = simulationOf(first);
    std::map<QString, size_t> holder; // participant -> shard index
    for (size_t i = 0; i < studies.size(); ++i) {
        const StudyDatabase &study = *studies[i];
        const QJsonObject record = simulationOf(study);
        if (record.isEmpty()) {
            *error = QStringLiteral("%1: not a simulated study (semhap study simulate writes "
                                    "what merging needs)")
                         .arg(shards[int(i)]);
            return false;
        }
        if (study.value(QStringLiteral("protocol")) != first.value(QStringLiteral("protocol"))) {
            *error = QStringLiteral("%1: not of the protocol %2 is of")
                         .arg(shards[int(i)], shards.front());
            return false;
        }
        for (const char *key : Shared) {
            if (record.value(QLatin1String(key)) != simulation.value(QLatin1String(key))) {
                *error = QStringLiteral("%1: simulated with another %2 than %3")
                             .arg(shards[int(i)], QLatin1String(key), shards.front());
                return false;
            }
        }
        for (const QString &participant : study.participants()) {
            if (holder.count(participant)) {
                *error = QStringLiteral("%1: %2 is in %3 too")
                             .arg(shards[int(i)], participant, shards[int(holder[participant])]);
                return false;
            }
            if (!isFinished(study, participant)) {
                *error = QStringLiteral("%1: %2 is not finished (simulate that shard again "
                                        "with --resume)")
                             .arg(shards[int(i)], participant);
                return false;
            }
            holder[participant] = i;
        }
        if (!study.readError().isEmpty()) {
            *error = study.readError();
            return false;
        }
    }
    const int participants = simulation.value(QStringLiteral("participants")).toInt();
    QStringList order;
    for (int number = 1; number <= participants; ++number) {
        const QString participant = StudySimulation::participantName(number, participants);
        if (!holder.count(participant)) {
            *error = QStringLiteral("%1 is in none of the shards (of %2 participants)")
                         .arg(participant)
                         .arg(participants);
            return false;
        }
        order.append(participant);
    }
    if (int(holder.size()) != participants) {
        for (const auto &[participant, shard] : holder) {
            if (!order.contains(participant)) {
                *error = QStringLiteral("%1: %2 is not one of the study's %3 participants")
                             .arg(shards[int(shard)], participant)
                             .arg(participants);
                return false;
            }
        }
    }

    // Written beside the result under a name of its own, its sessions folder too, and
    // renamed into place once whole.
    const QFileInfo target(out);
    const QString temporary =
        target.absoluteDir().filePath(QStringLiteral(".%1.merging-%2.db")
                                          .arg(target.completeBaseName())
                                          .arg(QCoreApplication::applicationPid()));
    const QString finalFolder = StudyDatabase::sessionsFolder(out);
    const QString temporaryFolder = StudyDatabase::sessionsFolder(temporary);
    if (QFileInfo::exists(finalFolder)) {
        *error =
            QStringLiteral("%1: is left from another study: move it away first").arg(finalFolder);
        return false;
    }
    const auto cleanUp = [&] {
        for (const QString &left : QStringList{temporary, temporary + QStringLiteral("-wal"),
                                               temporary + QStringLiteral("-shm")})
            QFile::remove(left);
        QDir(temporaryFolder).removeRecursively();
    };
    {
        std::unique_ptr<StudyDatabase> merged =
            StudyDatabase::create(temporary, first.protocol(), error);
        if (!merged) {
            cleanUp();
            return false;
        }
        for (const QString &participant : order) {
            if (!merged->copyParticipant(*studies[holder[participant]], participant, error)) {
                merged.reset();
                cleanUp();
                return false;
            }
        }
        QJsonObject record = simulation;
        record.remove(QStringLiteral("shard"));
        QJsonArray from;
        for (size_t i = 0; i < studies.size(); ++i) {
            QJsonObject shard = simulationOf(*studies[i]);
            shard.insert(QStringLiteral("file"), QFileInfo(shards[int(i)]).absoluteFilePath());
            from.append(shard);
        }
        record.insert(QStringLiteral("merged"), from);
        if (!merged->setValue(
                QStringLiteral("simulation"),
                QString::fromUtf8(QJsonDocument(record).toJson(QJsonDocument::Compact)), error) ||
            !merged->relocateSessions(finalFolder, error)) {
            merged.reset();
            cleanUp();
            return false;
        }
    }
    if (!QDir().rename(temporaryFolder, finalFolder)) {
        *error = QStringLiteral("%1: cannot write: cannot rename %2 to it")
                     .arg(finalFolder, temporaryFolder);
        cleanUp();
        return false;
    }
    if (!QFile::rename(temporary, out)) {
        *error = QStringLiteral("%1: cannot write: cannot rename %2 to it").arg(out, temporary);
        QDir().rename(finalFolder, temporaryFolder);
        cleanUp();
        return false;
    }
    return true;
}

} // namespace semhap
