// SPDX-License-Identifier: MIT
#include "studydocument.h"

#include "engine.h"
#include "outputfile.h"
#include "sessioninfo.h"
#include "studyanalysis.h"
#include "studyexport.h"
#include "studytable.h"

#include <QDir>
#include <QFileInfo>
#include <QLocale>

#include <cmath>

namespace semhap {

namespace {

using Kind = StudyProtocol::Step::Kind;

} // namespace

StudyDocument::StudyDocument(Engine &engine, QObject *parent) : QObject(parent), m_engine(engine)
{
    m_breakTimer.setSingleShot(true);
    connect(&m_breakTimer, &QTimer::timeout, this, [this] {
        emit message(tr("The break is over."));
        emit breakChanged();
    });
    // The run reached the step's seconds (its duration): the step is done.
    connect(&m_engine, &Engine::finished, this, [this] {
        if (isTrialRunning())
            finishTrial();
    });
    connect(&m_engine.history(), &RunHistory::metricsChanged, this, [this] {
        if (isTrialRunning() && m_step.kind == Kind::Practice &&
            protocol().practiceDone(m_engine.history().metrics(), elapsed()))
            finishTrial();
    });
    // Whatever ends the trial's recording but the study — a reset, another scene or router,
    // Record pressed — ends the trial: what runs is no longer the condition's run.
    connect(&m_engine, &Engine::recordingChanged, this, [this](bool recording) {
        if (!recording && isTrialRunning())
            abortByItself(QStringLiteral("the run was changed during the trial (its recording "
                                         "stopped)"));
    });
}

StudyDocument::~StudyDocument() = default;

bool StudyDocument::create(const QString &protocol, const QString &path, QString *error)
{
    StudyProtocol read;
    LoadError loadError;
    if (!StudyProtocol::read(protocol, &read, &loadError)) {
        *error = loadError.toString();
        return false;
    }
    std::unique_ptr<StudyDatabase> study = StudyDatabase::create(path, read, error);
    if (!study)
        return false; // the study open stays
    install(std::move(study));
    return true;
}

bool StudyDocument::open(const QString &path, QString *error)
{
    // The study open already is open: its own lock would refuse it.
    if (m_study &&
        QFileInfo(m_study->path()).canonicalFilePath() == QFileInfo(path).canonicalFilePath())
        return true;
    std::unique_ptr<StudyDatabase> study =
        StudyDatabase::open(path, StudyDatabase::Access::Write, error);
    if (!study)
        return false; // the study open stays
    install(std::move(study));
    return true;
}

void StudyDocument::install(std::unique_ptr<StudyDatabase> study)
{
    close();
    m_study = std::move(study);
    // The newest participant is the one most likely to go on.
    const QStringList participants = m_study->participants();
    m_participant = participants.isEmpty() ? QString() : participants.last();
    emit studyChanged();
    emit changed();
}

void StudyDocument::close(const QString &reason)
{
    if (!m_study)
        return;
    if (isTrialRunning()) {
        QString error;
        if (!abortTrial(reason, &error))
            emit failed(tr("The trial that ran could not be stored as aborted"), error);
    }
    skipBreak();
    m_study.reset();
    m_participant.clear();
    emit studyChanged();
    emit changed();
}

void StudyDocument::setParticipant(const QString &id)
{
    const QString chosen = m_study && m_study->participants().contains(id) ? id : QString();
    if (chosen == m_participant || isTrialRunning())
        return;
    m_participant = chosen;
    emit changed();
}

bool StudyDocument::addParticipant(const QString &id, QString *error)
{
    if (!m_study) {
        *error = tr("no study is open");
        return false;
    }
    if (!m_study->addParticipant(id, error))
        return false;
    m_participant = id;
    emit changed();
    return true;
}

StudyProtocol::Step StudyDocument::nextStep() const
{
    return m_study && !m_participant.isEmpty() ? m_study->nextStep(m_participant) : Step();
}

bool StudyDocument::startTrial(QString *error)
{
    if (!m_study || m_participant.isEmpty()) {
        *error = tr("choose a participant first");
        return false;
    }
    if (isTrialRunning()) {
        *error = tr("a trial runs already");
        return false;
    }
    if (isOnBreak()) {
        *error = tr("the break is on: skip it to go on at once");
        return false;
    }
    const Step step = m_study->nextStep(m_participant);
    if (step.kind != Kind::Practice && step.kind != Kind::Trial) {
        *error = tr("the next step is no practice round or trial");
        return false;
    }
    // The step's seconds bound this run only: what the studio runs after the trial, even
    // this run reset, lasts as long as the studio's runs do.
    RunOptions options = protocol().runOptions(step.condition);
    options.duration = m_engine.options().duration;
    if (!m_engine.load(options, error))
        return false;
    m_engine.setDuration(protocol().seconds(step));
    const QString session = m_study->newSessionPath(m_participant, step, error);
    if (session.isEmpty())
        return false;
    SessionInfo tags;
    m_study->tagSession(m_participant, step, &tags);
    const QString notes =
        QStringLiteral("%1: %2, %3").arg(protocol().name, m_participant, describe(step));
    if (!m_engine.startRecording(session, notes, error, tags.extra))
        return false;
    m_trial = m_study->beginTrial(m_participant, step, session, error);
    if (m_trial == 0) {
        m_engine.stopRecording();
        return false;
    }
    m_step = step;
    // The participant drives (keys, gamepad, 3D mouse, pose input): the task is theirs.
    m_engine.setDriving(true);
    m_engine.run();
    emit trialChanged();
    emit changed();
    return true;
}

double StudyDocument::elapsed() const
{
    return isTrialRunning() ? m_engine.simTime() : 0.0;
}

double StudyDocument::limit() const
{
    return isTrialRunning() ? protocol().seconds(m_step) : 0.0;
}

void StudyDocument::pause()
{
    if (!isTrialRunning())
        return;
    m_engine.stopAll();
    emit trialChanged();
}

void StudyDocument::resume()
{
    if (!isTrialRunning())
        return;
    m_engine.run();
    emit trialChanged();
}

qint64 StudyDocument::stopTrial(double *seconds)
{
    // No longer running first: stopping its recording is not the run changed under it.
    const qint64 id = std::exchange(m_trial, 0);
    if (id == 0)
        return 0;
    // The bands go to zero with the run; the recording ends with their rest.
    m_engine.stopAll();
    *seconds = m_engine.simTime();
    m_engine.stopRecording();
    // The run left behind goes on as an ordinary one when Run is pressed.
    m_engine.setDuration(m_engine.options().duration);
    return id;
}

void StudyDocument::finishTrial()
{
    const QJsonObject metrics = m_engine.metrics();
    const Step step = m_step;
    double seconds = 0.0;
    const qint64 id = stopTrial(&seconds);
    if (id == 0)
        return;
    QString error;
    if (!m_study->finishTrial(id, seconds, metrics, &error))
        emit failed(tr("The end of %1 could not be stored").arg(describe(step)), error);
    else
        emit message(tr("%1: done.").arg(describe(step)));
    // A break between two trials of a condition, when the protocol offers one.
    const Step next = m_study->nextStep(m_participant);
    if (step.kind == Kind::Trial && protocol().breakSeconds > 0 && next.kind == Kind::Trial &&
        next.condition == step.condition) {
        m_breakClock.start();
        m_breakTimer.start(int(std::lround(protocol().breakSeconds * 1000.0)));
        emit breakChanged();
    }
    emit trialChanged();
    emit changed();
}

bool StudyDocument::abortTrial(const QString &reason, QString *error)
{
    double seconds = 0.0;
    const qint64 id = stopTrial(&seconds);
    if (id == 0) {
        *error = tr("no trial runs");
        return false;
    }
    const bool stored = m_study->abortTrial(id, seconds, reason, error);
    emit trialChanged();
    emit changed();
    return stored;
}

void StudyDocument::abortByItself(const QString &reason)
{
    const QString what = describe(m_step);
    QString error;
    if (abortTrial(reason, &error))
        emit failed(tr("%1 was aborted").arg(what), reason);
    else
        emit failed(tr("%1 could not be stored as aborted").arg(what), error);
}

bool StudyDocument::invalidateTrial(qint64 id, const QString &reason, QString *error)
{
    if (!m_study) {
        *error = tr("no study is open");
        return false;
    }
    if (!m_study->invalidateTrial(id, reason, error))
        return false;
    // The step is due again: a break waiting for the next trial waits for nothing now.
    skipBreak();
    emit changed();
    return true;
}

double StudyDocument::breakLeft() const
{
    if (!isOnBreak())
        return 0.0;
    return std::max(0.0, protocol().breakSeconds - double(m_breakClock.elapsed()) / 1000.0);
}

void StudyDocument::skipBreak()
{
    if (!isOnBreak())
        return;
    m_breakTimer.stop();
    emit breakChanged();
}

bool StudyDocument::exportResults(const QString &dir, QStringList *written, QString *error) const
{
    if (!m_study) {
        *error = tr("no study is open");
        return false;
    }
    std::vector<StudyExport::File> files = StudyExport::results(*m_study, error);
    if (files.empty())
        return false;
    StudyAnalysis analysis = StudyAnalysis::run(StudyTable::fromStudy(*m_study));
    analysis.name = m_study->protocol().name;
    analysis.source = QFileInfo(m_study->path()).fileName();
    for (StudyExport::File &file : StudyExport::report(analysis)) {
        file.name = QLatin1String(StudyExport::ReportFolder) + QLatin1Char('/') + file.name;
        files.push_back(file);
    }
    const QDir folder(dir);
    for (const StudyExport::File &file : files) {
        const QString path = folder.filePath(file.name);
        LoadError writeError;
        if (!QDir().mkpath(QFileInfo(path).absolutePath())) {
            *error = tr("%1: cannot create the folder").arg(QFileInfo(path).absolutePath());
            return false;
        }
        if (!OutputFile::write(path, file.bytes, &writeError)) {
            *error = writeError.toString();
            return false;
        }
        written->append(file.name);
    }
    return true;
}

bool StudyDocument::answer(const StudyDatabase::Answer &answer, QString *error)
{
    if (!m_study) {
        *error = tr("no study is open");
        return false;
    }
    if (!m_study->answer(answer, error))
        return false;
    emit changed();
    return true;
}

QString StudyDocument::describe(const Step &step) const
{
    if (!m_study)
        return QString();
    const StudyProtocol &p = protocol();
    const QLocale locale;
    const QString label =
        step.condition >= 0 ? p.conditions[size_t(step.condition)].label : QString();
    switch (step.kind) {
    case Kind::Practice: {
        const QString seconds = locale.toString(p.practiceSeconds);
        QString goal;
        if (p.practiceTransfers > 0 && p.practiceSeconds > 0)
            goal = tr("until %n transfer(s) or %1 s", nullptr, p.practiceTransfers).arg(seconds);
        else if (p.practiceTransfers > 0)
            goal = tr("until %n transfer(s)", nullptr, p.practiceTransfers);
        else
            goal = tr("%1 s").arg(seconds);
        return tr("Practice — %1 (%2)").arg(label, goal);
    }
    case Kind::Trial:
        return tr("Trial %1 of %2 — %3 (%4 s)")
            .arg(step.trial)
            .arg(p.trials)
            .arg(label, locale.toString(p.trialSeconds));
    case Kind::Questionnaire:
        return tr("Questionnaire after %1").arg(label);
    case Kind::Final:
        return tr("Final questionnaire");
    case Kind::Done:
        break;
    }
    return tr("All steps done");
}

} // namespace semhap
