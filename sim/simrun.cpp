// SPDX-License-Identifier: MIT
#include "simrun.h"

#include "jsonreader.h"
#include "sessionwriter.h"
#include "sinklist.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace semhap {

QJsonObject RunOptions::toJson() const
{
    QJsonObject json{{QStringLiteral("scene"), scene},
                     {QStringLiteral("router"), router},
                     {QStringLiteral("overrides"), QJsonArray::fromStringList(overrides)},
                     {QStringLiteral("operator"), operatorName},
                     {QStringLiteral("seed"), double(seed)},
                     {QStringLiteral("reaction_time"), reactionTime}};
    if (sceneOptions.cubes >= 0)
        json.insert(QStringLiteral("cubes"), sceneOptions.cubes);
    if (horizon != DefaultHorizon)
        json.insert(QStringLiteral("horizon"), horizon);
    if (!sceneOptions.gripper.isEmpty())
        json.insert(QStringLiteral("gripper"), sceneOptions.gripper);
    if (!person.toJson().isEmpty())
        json.insert(QStringLiteral("person"), person.toJson());
    return json;
}

bool RunOptions::fromJson(JsonReader &reader, const QJsonObject &json, const QString &pointer,
                          RunOptions *options)
{
    RunOptions o = *options;
    double seed = double(o.seed);
    double cubes = o.sceneOptions.cubes;
    if (!reader.checkKeys(json, pointer,
                          {QLatin1String("scene"), QLatin1String("cubes"),
                           QLatin1String("gripper"), QLatin1String("router"),
                           QLatin1String("overrides"), QLatin1String("operator"),
                           QLatin1String("seed"), QLatin1String("reaction_time"),
                           QLatin1String("horizon"), QLatin1String("person")}) ||
        !reader.string(json, pointer, QLatin1String("scene"), &o.scene, false) ||
        !reader.string(json, pointer, QLatin1String("gripper"), &o.sceneOptions.gripper, false) ||
        !reader.number(json, pointer, QLatin1String("cubes"), &cubes, false) ||
        !reader.string(json, pointer, QLatin1String("router"), &o.router, false) ||
        !reader.strings(json, pointer, QLatin1String("overrides"), &o.overrides, false) ||
        !reader.string(json, pointer, QLatin1String("operator"), &o.operatorName, false) ||
        !reader.number(json, pointer, QLatin1String("seed"), &seed, false) ||
        !reader.number(json, pointer, QLatin1String("reaction_time"), &o.reactionTime, false) ||
        !reader.number(json, pointer, QLatin1String("horizon"), &o.horizon, false))
        return false;
    QJsonObject person;
    if (!reader.object(json, pointer, QLatin1String("person"), &person, false) ||
        (json.contains(QLatin1String("person")) &&
         !PersonParameters::fromJson(
             reader, person, jsonPointerChild(pointer, QStringLiteral("person")), &o.person)))
        return false;
    const auto whole = [](double v, double low, double high) {
        return v >= low && v <= high && v == std::floor(v);
    };
    if (!whole(seed, 0, MaxSeed))
        return reader.fail(
            jsonPointerChild(pointer, QStringLiteral("seed")),
            QStringLiteral("expected a whole number from 0 to %1").arg(MaxSeed, 0, 'g', 3));
    if (json.contains(QLatin1String("cubes")) && !whole(cubes, 0, MaxCubes))
        return reader.fail(jsonPointerChild(pointer, QStringLiteral("cubes")),
                           QStringLiteral("expected a whole number from 0 to %1").arg(MaxCubes));
    if (!(o.reactionTime >= 0 && o.reactionTime <= SessionInfo::MaxReactionTime))
        return reader.fail(
            jsonPointerChild(pointer, QStringLiteral("reaction_time")),
            QStringLiteral("expected seconds from 0 to %1").arg(SessionInfo::MaxReactionTime));
    if (!(o.horizon > 0 && o.horizon <= MaxHorizon))
        return reader.fail(jsonPointerChild(pointer, QStringLiteral("horizon")),
                           QStringLiteral("expected seconds above 0, at most %1").arg(MaxHorizon));
    o.seed = std::uint64_t(seed);
    o.sceneOptions.cubes = int(cubes);
    *options = o;
    return true;
}

std::unique_ptr<SimRun> SimRun::create(const RunOptions &options, QString *error)
{
    std::unique_ptr<SimRun> run(new SimRun);
    run->m_options = options;
    run->m_world = World::load(options.scene, options.sceneOptions, error);
    if (!run->m_world)
        return nullptr;
    LoadError loadError;
    std::unique_ptr<Router> router =
        loadRouter(options.router, options.overrides, &loadError,
                   routerContext(*run->m_world, options.reactionTime));
    if (!router) {
        *error = loadError.toString();
        return nullptr;
    }
    // The task first: it may lay the scene out (seeded) before the operator looks at it.
    run->m_task =
        makeTask(*run->m_world, options.seed, options.reactionTime, options.horizon, error);
    if (!run->m_task)
        return nullptr;
    run->m_operator = makeOperator(options.operatorName, *run->m_world, options.seed,
                                   options.reactionTime, options.person, error);
    if (!run->m_operator)
        return nullptr;
    run->m_perception = std::make_unique<Perception>(*router);
    run->m_pipeline = std::make_unique<Pipeline>(std::move(router));
    run->m_totalSteps = std::lround(options.duration / run->m_world->timestep());
    return run;
}

RouterContext SimRun::routerContext(const World &world, double reactionTime)
{
    RouterContext context;
    context.reactionTime = reactionTime;
    context.knowsSignals = true;
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        context.signalNames[size_t(g)] = world.signalNames(g);
        if (world.hasGripper(g))
            context.grippers[size_t(g)] = world.gripperTraits(g);
    }
    return context;
}

QJsonObject SimRun::metrics() const
{
    QJsonObject metrics = m_task->metrics();
    m_operator->addMetrics(&metrics);
    return metrics;
}

QJsonObject SimRun::report(double wallSeconds) const
{
    QJsonObject report = metrics();
    report.insert(QStringLiteral("scene"), m_options.scene);
    report.insert(QStringLiteral("router"), m_options.router);
    report.insert(QStringLiteral("operator"), m_options.operatorName);
    report.insert(QStringLiteral("seed"), double(m_options.seed));
    report.insert(QStringLiteral("sim_seconds"), time());
    report.insert(QStringLiteral("wall_seconds"), wallSeconds);
    report.insert(QStringLiteral("realtime_factor"), time() / std::max(1e-9, wallSeconds));
    return report;
}

bool SimRun::isDone() const
{
    return m_steps >= m_totalSteps;
}

void SimRun::setDuration(double seconds)
{
    m_options.duration = seconds;
    m_totalSteps = std::lround(seconds / m_world->timestep());
}

double SimRun::time() const
{
    return m_world->time();
}

bool SimRun::step(RunSink &sink)
{
    if (isDone())
        return false;
    Operator &driver = m_driveOperator ? *m_driveOperator : *m_operator;
    if (m_acting && m_acting != &driver)
        driver.engage(*m_world);
    m_acting = &driver;
    driver.act(*m_world);
    m_world->step();
    // The operator feels what the bands deliver; the caller gets everything.
    SinkList tee{m_perception.get(), &sink};
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        if (!m_world->hasGripper(g))
            continue;
        const ContactFrame &frame = m_world->frame(g);
        sink.onContactFrame(frame);
        m_pipeline->process(frame, tee);
    }
    m_pipeline->flush(tee);
    m_task->observe(*m_world);
    // What the operator acts on next step: this tick's output, as the hands perceive it.
    const double t = m_world->frame(Gripper::Right).t;
    driver.sense(*m_perception, *m_task, t);
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        const Feeling feeling = m_perception->feeling(g);
        driver.feel(g, feeling, t);
        m_task->feel(g, feeling, t);
    }
    ++m_steps;
    return !isDone();
}

void SimRun::setRouter(std::unique_ptr<Router> router, RunSink &sink)
{
    m_pipeline->setRouter(std::move(router), sink);
    // The perception reads the player of the router it was made for: replace both together.
    m_perception = std::make_unique<Perception>(m_pipeline->router());
}

SceneState SimRun::sceneState() const
{
    SceneState state;
    state.t = time();
    state.pose = m_world->sceneState();
    const Feeling left = m_perception->feeling(Gripper::Left);
    const Feeling right = m_perception->feeling(Gripper::Right);
    state.overlay = {left.shownConfirmation, left.shownWarning, right.shownConfirmation,
                     right.shownWarning};
    return state;
}

void SimRun::recordSceneState(SessionWriter &session)
{
    const double t = time();
    if (t < m_nextSceneState)
        return;
    // On a fixed grid, so the rate is exact; a recording started late begins at once.
    m_nextSceneState += SceneStatePeriod;
    if (m_nextSceneState <= t)
        m_nextSceneState = t + SceneStatePeriod;
    session.recordSceneState(sceneState());
}

SessionInfo SimRun::sessionInfo() const
{
    SessionInfo info;
    info.scene = m_options.scene;
    info.routerSource = m_options.router;
    info.overrides = m_options.overrides;
    info.operatorName = m_options.operatorName;
    info.seed = QString::number(m_options.seed);
    info.extra.insert(QStringLiteral("duration"), QString::number(m_options.duration));
    info.routerContext.reactionTime = m_options.reactionTime;
    for (Gripper g : {Gripper::Left, Gripper::Right}) {
        if (m_world->hasGripper(g))
            info.routerContext.grippers[size_t(g)] = m_world->gripperTraits(g);
    }
    if (!m_options.sceneOptions.gripper.isEmpty())
        info.extra.insert(QStringLiteral("gripper"), m_options.sceneOptions.gripper);
    if (m_options.sceneOptions.cubes >= 0)
        info.extra.insert(QStringLiteral("cubes"), QString::number(m_options.sceneOptions.cubes));
    if (!m_options.person.toJson().isEmpty())
        info.extra.insert(
            QStringLiteral("person"),
            QString::fromUtf8(
                QJsonDocument(m_options.person.toJson()).toJson(QJsonDocument::Compact)));
    return info;
}

const std::vector<MetricSpec> &SimRun::metricSpecs()
{
    static const std::vector<MetricSpec> specs = {
        {"sim_seconds", MetricUnit::Seconds, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Simulated time"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Simulated time so far."), MetricRole::Measure},
        {"wall_seconds", MetricUnit::Seconds, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Wall time"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Real time so far."), MetricRole::Measure},
        {"realtime_factor", MetricUnit::Factor, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Real-time factor"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Simulated seconds per real second."),
         MetricRole::Measure},
        {"scene", MetricUnit::Text, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Scene"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "The task that runs."), MetricRole::Input},
        {"router", MetricUnit::Text, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Router"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "The router the run was loaded with."),
         MetricRole::Input},
        {"operator", MetricUnit::Text, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Operator"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Who drives the grippers when you do not."),
         MetricRole::Input},
        {"seed", MetricUnit::Count, MetricBetter::Neither,
         QT_TRANSLATE_NOOP("semhap::MetricSpec", "Seed"),
         QT_TRANSLATE_NOOP("semhap::MetricSpec",
                           "The seed of the operator and of a laid-out scene."),
         MetricRole::Input},
    };
    return specs;
}

} // namespace semhap
