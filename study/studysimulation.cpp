// SPDX-License-Identifier: MIT
#include "studysimulation.h"

#include "sessionwriter.h"
#include "simrun.h"

#include <algorithm>

namespace semhap {

namespace {

using Kind = StudyProtocol::Step::Kind;

/** Records everything a run streams into its session. */
class Recorder : public RunSink
{
public:
    explicit Recorder(SessionWriter &session) : m_session(session) {}
    void onContactFrame(const ContactFrame &frame) override
    {
        m_session.recordContactFrame(frame, qQNaN());
    }
    void onEvent(const SemanticEvent &event) override { m_session.onEvent(event); }
    void onDeviceFrame(const DeviceFrame &frame) override { m_session.onDeviceFrame(frame); }

private:
    SessionWriter &m_session;
};

/** How often a practice round looks at its goal (simulated s): metrics are not free. */
constexpr double GoalPeriod = 0.1;

/** Runs one practice round or trial of participant `number` (1-based) into the study. */
bool runStep(StudyDatabase &study, const QString &participant, int number,
             const StudyProtocol::Step &step, const StudySimulation::Options &simulation,
             QString *error)
{
    const StudyProtocol &protocol = study.protocol();
    const bool practice = step.kind == Kind::Practice;
    RunOptions options = protocol.runOptions(step.condition);
    options.operatorName = simulation.operatorName;
    options.person = simulation.person;
    options.seed = StudySimulation::seed(number, step.trial);
    // A simulated operator that never reaches a practice goal must not run for a day.
    options.duration = protocol.seconds(step);
    if (practice && protocol.practiceSeconds <= 0)
        options.duration = StudySimulation::PracticeLimit;
    if (simulation.maxSeconds > 0)
        options.duration = std::min(options.duration, simulation.maxSeconds);
    QString reason;
    const std::unique_ptr<SimRun> run = SimRun::create(options, &reason);
    if (!run) {
        *error = QStringLiteral("%1: %2").arg(protocol.file, reason);
        return false;
    }
    const QString path = study.newSessionPath(participant, step, error);
    if (path.isEmpty())
        return false;
    SessionInfo info = run->sessionInfo();
    info.source = QStringLiteral("simulate");
    study.tagSession(participant, step, &info);
    const std::unique_ptr<SessionWriter> session =
        SessionWriter::create(path, info, run->pipeline().router(), error);
    if (!session)
        return false;
    session->setActorTable(&run->world().actors());
    const qint64 id = study.beginTrial(participant, step, path, error);
    if (id == 0)
        return false;
    Recorder recorder(*session);
    double nextGoalCheck = GoalPeriod;
    bool cancelled = false;
    while (run->step(recorder)) {
        run->recordSceneState(*session);
        if (practice && run->time() >= nextGoalCheck) {
            nextGoalCheck += GoalPeriod;
            if (protocol.practiceDone(run->metrics(), run->time()))
                break;
        }
        if (simulation.cancelled && simulation.cancelled()) {
            cancelled = true;
            break;
        }
    }
    if (!session->finish(&reason)) {
        QString ignored;
        study.abortTrial(id, run->time(), reason, &ignored);
        *error = reason;
        return false;
    }
    if (cancelled) {
        if (!study.abortTrial(id, run->time(), QStringLiteral("the simulation was cancelled"),
                              error))
            return false;
        *error = QStringLiteral("%1: cancelled at %2 s of %3's %4")
                     .arg(study.path())
                     .arg(run->time())
                     .arg(participant, practice ? QStringLiteral("practice round")
                                                : QStringLiteral("trial %1").arg(step.trial));
        return false;
    }
    if (!study.finishTrial(id, run->time(), run->metrics(), error))
        return false;
    if (simulation.progress) {
        const std::vector<StudyDatabase::Trial> trials = study.trials(participant);
        simulation.progress(trials.back());
    }
    return true;
}

} // namespace

std::uint64_t StudySimulation::seed(int participant, int trial)
{
    return std::uint64_t(participant) * 100u + std::uint64_t(trial);
}

QString StudySimulation::participantName(int number, int participants)
{
    const int width = std::max(2, int(QString::number(participants).size()));
    return QStringLiteral("P%1").arg(number, width, 10, QLatin1Char('0'));
}

QStringList StudySimulation::operatorNames()
{
    return {QStringLiteral("reactive"), QStringLiteral("perceiving")};
}

bool StudySimulation::run(StudyDatabase &study, const Options &options, QString *error)
{
    const QStringList present = study.participants();
    if (!present.isEmpty() && !options.resume) {
        *error = QStringLiteral("%1: has participants already; simulate into a new study")
                     .arg(study.path());
        return false;
    }
    for (const QString &participant : present) {
        bool ours = false;
        for (int number = 1; number <= options.participants && !ours; ++number)
            ours = (number - 1) % options.shards == options.shard - 1 &&
                   participantName(number, options.participants) == participant &&
                   study.position(participant) == number - 1;
        if (!ours) {
            *error = QStringLiteral("%1: %2 is not a participant this simulation would make")
                         .arg(study.path(), participant);
            return false;
        }
    }
    for (int number = 1; number <= options.participants; ++number) {
        if ((number - 1) % options.shards != options.shard - 1)
            continue;
        // Their name, seed and row of the scheme are their number's, in any shard.
        const QString participant = participantName(number, options.participants);
        if (!present.contains(participant) &&
            !study.addParticipant(participant, number - 1, error))
            return false;
        for (const StudyProtocol::Step &step : study.protocol().steps(study.order(participant))) {
            if (step.kind != Kind::Practice && step.kind != Kind::Trial)
                continue;
            if (present.contains(participant) && study.isDone(participant, step))
                continue;
            if (!runStep(study, participant, number, step, options, error))
                return false;
        }
    }
    return true;
}

} // namespace semhap
