// SPDX-License-Identifier: MIT
#include "studyprotocol.h"

#include "gripperlibrary.h"
#include "inputfile.h"
#include "jsonreader.h"
#include "router.h"
#include "taskmonitor.h"
#include "world.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

constexpr int MaxTrials = 20;
constexpr int MaxTransfers = 1000;
constexpr int MaxQuestions = 100;

/** A number at `key` (when present) within [low, high]; a whole one when `whole`. */
bool bounded(JsonReader &reader, const QJsonObject &object, const QString &pointer,
             QLatin1String key, double low, double high, bool whole, double *out)
{
    if (!object.contains(key))
        return true;
    if (!reader.number(object, pointer, key, out))
        return false;
    if (*out < low || *out > high || (whole && *out != std::floor(*out)))
        return reader.fail(pointer + QLatin1Char('/') + key,
                           QStringLiteral("must be %1from %2 to %3, got %4")
                               .arg(whole ? QStringLiteral("a whole number ") : QString())
                               .arg(low)
                               .arg(high)
                               .arg(*out));
    return true;
}

bool readQuestions(JsonReader &reader, const QJsonObject &json, const QString &pointer,
                   QLatin1String key, const std::vector<StudyProtocol::Condition> &conditions,
                   std::vector<StudyProtocol::Question> *out)
{
    QJsonArray items;
    if (!reader.array(json, pointer, key, &items, false))
        return false;
    const QString at = pointer + QLatin1Char('/') + key;
    if (items.size() > MaxQuestions)
        return reader.fail(at, QStringLiteral("at most %1 items").arg(MaxQuestions));
    for (int i = 0; i < items.size(); ++i) {
        const QString item = jsonPointerChild(at, i);
        if (!items[i].isObject())
            return reader.fail(item, QStringLiteral("must be an object"));
        const QJsonObject q = items[i].toObject();
        StudyProtocol::Question question;
        QString type;
        double points = 7;
        if (!reader.checkKeys(q, item,
                              {QLatin1String("type"), QLatin1String("id"), QLatin1String("text"),
                               QLatin1String("anchors"), QLatin1String("points"),
                               QLatin1String("conditions")}) ||
            !reader.string(q, item, QLatin1String("type"), &type) ||
            !reader.string(q, item, QLatin1String("id"), &question.id, false) ||
            !reader.string(q, item, QLatin1String("text"), &question.text, false) ||
            !reader.strings(q, item, QLatin1String("anchors"), &question.anchors, false) ||
            !bounded(reader, q, item, QLatin1String("points"), 2, 11, true, &points) ||
            !reader.strings(q, item, QLatin1String("conditions"), &question.conditions, false))
            return false;
        question.points = int(points);
        if (type == QLatin1String("nasa_tlx")) {
            question.kind = StudyProtocol::Question::Kind::NasaTlx;
            question.id = QStringLiteral("tlx");
        } else if (type == QLatin1String("likert")) {
            question.kind = StudyProtocol::Question::Kind::Likert;
            if (question.id.isEmpty() || question.text.isEmpty())
                return reader.fail(item, QStringLiteral("a likert item needs an id and a text"));
            if (question.anchors.size() != 2)
                return reader.fail(item + QStringLiteral("/anchors"),
                                   QStringLiteral("must name the scale's two ends, got %1")
                                       .arg(question.anchors.size()));
        } else if (type == QLatin1String("ranking")) {
            question.kind = StudyProtocol::Question::Kind::Ranking;
            if (key != QLatin1String("atTheEnd"))
                return reader.fail(item + QStringLiteral("/type"),
                                   QStringLiteral("a ranking of the conditions belongs in "
                                                  "atTheEnd, once they are all done"));
            if (question.id.isEmpty())
                question.id = QStringLiteral("rank");
            if (question.conditions.isEmpty())
                for (const StudyProtocol::Condition &c : conditions)
                    question.conditions.append(c.id);
            for (const StudyProtocol::Condition &c : conditions) {
                if (question.conditions.count(c.id) != 1)
                    return reader.fail(
                        item + QStringLiteral("/conditions"),
                        question.conditions.contains(c.id)
                            ? QStringLiteral("names condition %1 twice").arg(quoted(c.id))
                            : QStringLiteral("leaves out condition %1").arg(quoted(c.id)));
            }
            if (question.conditions.size() != int(conditions.size()))
                return reader.fail(item + QStringLiteral("/conditions"),
                                   QStringLiteral("names a condition the protocol does not have"));
        } else if (type == QLatin1String("notes")) {
            question.kind = StudyProtocol::Question::Kind::Notes;
            if (question.id.isEmpty())
                question.id = QStringLiteral("notes");
        } else {
            return reader.fail(item + QStringLiteral("/type"),
                               QStringLiteral("must be nasa_tlx, likert, ranking or notes, got %1")
                                   .arg(quoted(type)));
        }
        if (question.kind != StudyProtocol::Question::Kind::Ranking &&
            q.contains(QLatin1String("conditions"))) {
            // Asked after some conditions only: each named once, each the protocol's.
            if (key != QLatin1String("afterCondition"))
                return reader.fail(item + QStringLiteral("/conditions"),
                                   QStringLiteral("only an afterCondition item is asked after "
                                                  "some conditions"));
            if (question.conditions.isEmpty())
                return reader.fail(item + QStringLiteral("/conditions"),
                                   QStringLiteral("names no condition: leave it out to ask "
                                                  "after each"));
            for (int c = 0; c < question.conditions.size(); ++c) {
                const QString &id = question.conditions[c];
                const bool known = std::any_of(conditions.begin(), conditions.end(),
                                               [&id](const StudyProtocol::Condition &condition) {
                                                   return condition.id == id;
                                               });
                if (!known || question.conditions.indexOf(id) != c)
                    return reader.fail(
                        jsonPointerChild(item + QStringLiteral("/conditions"), c),
                        known ? QStringLiteral("names condition %1 twice").arg(quoted(id))
                              : QStringLiteral("%1 is not a condition of the protocol")
                                    .arg(quoted(id)));
            }
        }
        out->push_back(question);
    }
    return true;
}

/** The protocol's `factors`: 1 or 2, each with 2–8 distinct levels. */
bool readFactors(JsonReader &reader, const QJsonArray &factors,
                 std::vector<StudyProtocol::Factor> *out)
{
    const QString at = QStringLiteral("/factors");
    if (factors.size() > 2)
        return reader.fail(
            at,
            QStringLiteral("at most 2 factors (a two-way design), got %1").arg(factors.size()));
    for (int i = 0; i < factors.size(); ++i) {
        const QString item = jsonPointerChild(at, i);
        if (!factors[i].isObject())
            return reader.fail(item, QStringLiteral("must be an object"));
        const QJsonObject f = factors[i].toObject();
        StudyProtocol::Factor factor;
        if (!reader.checkKeys(f, item, {QLatin1String("id"), QLatin1String("levels")}) ||
            !reader.nonEmptyString(f, item, QLatin1String("id"), &factor.id) ||
            !reader.strings(f, item, QLatin1String("levels"), &factor.levels))
            return false;
        if (factor.levels.size() < 2 || factor.levels.size() > 8)
            return reader.fail(
                item + QStringLiteral("/levels"),
                QStringLiteral("must list 2 to 8 levels, got %1").arg(factor.levels.size()));
        if (factor.levels.removeDuplicates() > 0)
            return reader.fail(item + QStringLiteral("/levels"),
                               QStringLiteral("names a level twice"));
        for (const StudyProtocol::Factor &other : *out) {
            if (other.id == factor.id)
                return reader.fail(
                    item + QStringLiteral("/id"),
                    QStringLiteral("%1 is already a factor").arg(quoted(factor.id)));
        }
        out->push_back(factor);
    }
    return true;
}

/** A condition's `levels`: one of each factor's, for every factor. */
bool readLevels(JsonReader &reader, const QJsonObject &condition, const QString &at,
                const std::vector<StudyProtocol::Factor> &factors, QStringList *out)
{
    QJsonObject levels;
    if (!reader.object(condition, at, QLatin1String("levels"), &levels, !factors.empty()))
        return false;
    const QString pointer = at + QStringLiteral("/levels");
    if (factors.empty()) {
        if (condition.contains(QLatin1String("levels")))
            return reader.fail(pointer, QStringLiteral("the protocol declares no factors"));
        return true;
    }
    for (auto it = levels.begin(); it != levels.end(); ++it) {
        const bool known =
            std::any_of(factors.begin(), factors.end(),
                        [&](const StudyProtocol::Factor &f) { return f.id == it.key(); });
        if (!known)
            return reader.fail(jsonPointerChild(pointer, it.key()),
                               QStringLiteral("no such factor"));
    }
    for (const StudyProtocol::Factor &factor : factors) {
        const QJsonValue level = levels.value(factor.id);
        if (level.isUndefined())
            return reader.fail(pointer, QStringLiteral("missing key %1").arg(quoted(factor.id)));
        if (!level.isString() || !factor.levels.contains(level.toString()))
            return reader.fail(
                jsonPointerChild(pointer, factor.id),
                QStringLiteral("%1 is not a level of %2 (%3)")
                    .arg(level.isString() ? quoted(level.toString()) : jsonTypeName(level),
                         quoted(factor.id), factor.levels.join(QStringLiteral(", "))));
        out->append(level.toString());
    }
    return true;
}

} // namespace

const QStringList &StudyProtocol::tlxSubscales()
{
    static const QStringList names{
        QStringLiteral("tlx.mental"),   QStringLiteral("tlx.physical"),
        QStringLiteral("tlx.temporal"), QStringLiteral("tlx.performance"),
        QStringLiteral("tlx.effort"),   QStringLiteral("tlx.frustration")};
    return names;
}

QStringList StudyProtocol::Question::measures() const
{
    return kind == Kind::NasaTlx ? tlxSubscales() : QStringList{id};
}

double StudyProtocol::Question::lowest() const
{
    return kind == Kind::Likert || kind == Kind::Ranking ? 1.0 : 0.0;
}

double StudyProtocol::Question::highest() const
{
    switch (kind) {
    case Kind::NasaTlx:
        return 100.0;
    case Kind::Likert:
        return points;
    case Kind::Ranking:
        return double(conditions.size());
    case Kind::Notes:
        break;
    }
    return 0.0;
}

bool StudyProtocol::isId(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral("^[A-Za-z0-9_.-]{1,32}$"));
    return pattern.match(text).hasMatch();
}

int StudyProtocol::conditionIndex(const QString &id) const
{
    for (size_t i = 0; i < conditions.size(); ++i) {
        if (conditions[i].id == id)
            return int(i);
    }
    return -1;
}

std::vector<StudyProtocol::Question> StudyProtocol::questionsAfter(int condition) const
{
    std::vector<Question> questions;
    for (const Question &q : afterCondition) {
        if (q.asksAfter(conditions[size_t(condition)].id))
            questions.push_back(q);
    }
    return questions;
}

std::vector<StudyProtocol::Step> StudyProtocol::steps(const std::vector<int> &order) const
{
    std::vector<Step> out;
    for (int condition : order) {
        if (practiceSeconds > 0 || practiceTransfers > 0)
            out.push_back({Step::Kind::Practice, condition, 0});
        for (int trial = 1; trial <= trials; ++trial)
            out.push_back({Step::Kind::Trial, condition, trial});
        if (!questionsAfter(condition).empty())
            out.push_back({Step::Kind::Questionnaire, condition, 0});
    }
    if (!atTheEnd.empty())
        out.push_back({Step::Kind::Final, -1, 0});
    return out;
}

int StudyProtocol::transfers(const QJsonObject &metrics)
{
    return metrics.value(QLatin1String(TaskMonitor::CubesTransferred)).toInt();
}

bool StudyProtocol::practiceDone(const QJsonObject &metrics, double seconds) const
{
    if (practiceSeconds > 0 && seconds >= practiceSeconds)
        return true;
    return practiceTransfers > 0 && transfers(metrics) >= practiceTransfers;
}

double StudyProtocol::seconds(const Step &step) const
{
    if (step.kind == Step::Kind::Trial)
        return trialSeconds;
    return practiceSeconds > 0 ? practiceSeconds : MaxSeconds;
}

RunOptions StudyProtocol::runOptions(int condition) const
{
    RunOptions options;
    options.scene = scene;
    options.sceneOptions = sceneOptions;
    options.router = conditions[size_t(condition)].router;
    return options;
}

bool StudyProtocol::read(const QString &path, StudyProtocol *out, LoadError *error)
{
    QByteArray source;
    QString reason;
    if (!InputFile::readDocument(path, &source, &reason)) {
        *error = LoadError::at(path, QString(), QStringLiteral("cannot read: ") + reason);
        return false;
    }
    return parse(source, path, out, error);
}

bool StudyProtocol::parse(const QByteArray &source, const QString &path, StudyProtocol *out,
                          LoadError *error, Checks checks)
{
    const bool full = checks == Checks::Full;
    QJsonObject json;
    if (!parseJsonObject(source, path, &json, error) ||
        !checkFormat(json, path, QLatin1String(Format), error))
        return false;
    JsonReader reader(path);
    StudyProtocol p;
    p.file = path;
    p.source = source;
    const QDir folder = QFileInfo(path).absoluteDir();
    QJsonObject options, order, practice, trials, questionnaires;
    QJsonArray conditions, factors;
    QString scheme = QStringLiteral("latin");
    double cubes = -1, seed = 1, transfers = 0, count = p.trials;
    bool ok =
        reader.checkKeys(json, QString(),
                         {QLatin1String("format"), QLatin1String("name"), QLatin1String("scene"),
                          QLatin1String("options"), QLatin1String("conditions"),
                          QLatin1String("order"), QLatin1String("practice"),
                          QLatin1String("trials"), QLatin1String("questionnaires"),
                          QLatin1String("factors")}) &&
        reader.nonEmptyString(json, QString(), QLatin1String("name"), &p.name) &&
        reader.nonEmptyString(json, QString(), QLatin1String("scene"), &p.scene) &&
        reader.object(json, QString(), QLatin1String("options"), &options, false) &&
        reader.checkKeys(options, QStringLiteral("/options"),
                         {QLatin1String("cubes"), QLatin1String("gripper")}) &&
        bounded(reader, options, QStringLiteral("/options"), QLatin1String("cubes"), 0, 24, true,
                &cubes) &&
        reader.string(options, QStringLiteral("/options"), QLatin1String("gripper"),
                      &p.sceneOptions.gripper, false) &&
        reader.array(json, QString(), QLatin1String("conditions"), &conditions) &&
        reader.array(json, QString(), QLatin1String("factors"), &factors, false) &&
        reader.object(json, QString(), QLatin1String("order"), &order, false) &&
        reader.checkKeys(order, QStringLiteral("/order"),
                         {QLatin1String("scheme"), QLatin1String("seed")}) &&
        reader.string(order, QStringLiteral("/order"), QLatin1String("scheme"), &scheme, false) &&
        bounded(reader, order, QStringLiteral("/order"), QLatin1String("seed"), 0, 1e15, true,
                &seed) &&
        reader.object(json, QString(), QLatin1String("practice"), &practice, false) &&
        reader.checkKeys(practice, QStringLiteral("/practice"),
                         {QLatin1String("transfers"), QLatin1String("seconds")}) &&
        bounded(reader, practice, QStringLiteral("/practice"), QLatin1String("transfers"), 0,
                MaxTransfers, true, &transfers) &&
        bounded(reader, practice, QStringLiteral("/practice"), QLatin1String("seconds"), 0,
                MaxSeconds, false, &p.practiceSeconds) &&
        reader.object(json, QString(), QLatin1String("trials"), &trials) &&
        reader.checkKeys(
            trials, QStringLiteral("/trials"),
            {QLatin1String("count"), QLatin1String("seconds"), QLatin1String("break")}) &&
        bounded(reader, trials, QStringLiteral("/trials"), QLatin1String("count"), 1, MaxTrials,
                true, &count) &&
        reader.require(trials, QStringLiteral("/trials"), QLatin1String("seconds")) &&
        bounded(reader, trials, QStringLiteral("/trials"), QLatin1String("seconds"), 1, MaxSeconds,
                false, &p.trialSeconds) &&
        bounded(reader, trials, QStringLiteral("/trials"), QLatin1String("break"), 0, MaxSeconds,
                false, &p.breakSeconds);
    p.sceneOptions.cubes = int(cubes);
    // A gripper adapter file is the protocol's neighbour; a name is the library's.
    if (p.sceneOptions.gripper.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        p.sceneOptions.gripper = folder.absoluteFilePath(p.sceneOptions.gripper);
    if (ok && full && !p.sceneOptions.gripper.isEmpty() &&
        GripperLibrary::find(p.sceneOptions.gripper).isEmpty())
        ok = reader.fail(QStringLiteral("/options/gripper"),
                         QStringLiteral("no gripper adapter %1 (adapters: %2)")
                             .arg(quoted(p.sceneOptions.gripper),
                                  GripperLibrary::names().join(QStringLiteral(", "))));
    p.seed = std::uint64_t(seed);
    p.practiceTransfers = int(transfers);
    p.trials = int(count);
    // The scene: a bundled one, or a file beside the protocol.
    if (ok && !World::builtinScenes().contains(p.scene)) {
        const QString file = folder.absoluteFilePath(p.scene);
        if (full && !QFileInfo(file).isFile())
            ok = reader.fail(
                QStringLiteral("/scene"),
                QStringLiteral("no bundled scene %1 (%2) and no such file")
                    .arg(quoted(p.scene), World::builtinScenes().join(QStringLiteral(", "))));
        p.scene = file;
    }
    ok = ok && readFactors(reader, factors, &p.factors);
    if (ok && (conditions.isEmpty() || conditions.size() > StudyProtocol::MaxConditions))
        ok = reader.fail(
            QStringLiteral("/conditions"),
            QStringLiteral("must list 1 to %1 conditions").arg(StudyProtocol::MaxConditions));
    for (int i = 0; ok && i < conditions.size(); ++i) {
        const QString at = jsonPointerChild(QStringLiteral("/conditions"), i);
        if (!conditions[i].isObject()) {
            ok = reader.fail(at, QStringLiteral("must be an object"));
            break;
        }
        const QJsonObject c = conditions[i].toObject();
        Condition condition;
        ok = reader.checkKeys(c, at,
                              {QLatin1String("id"), QLatin1String("label"),
                               QLatin1String("router"), QLatin1String("levels")}) &&
             reader.nonEmptyString(c, at, QLatin1String("id"), &condition.id) &&
             reader.nonEmptyString(c, at, QLatin1String("label"), &condition.label) &&
             reader.nonEmptyString(c, at, QLatin1String("router"), &condition.router) &&
             readLevels(reader, c, at, p.factors, &condition.levels);
        if (!ok)
            break;
        if (!isId(condition.id)) {
            ok = reader.fail(at + QStringLiteral("/id"),
                             QStringLiteral("must be 1 to 32 of A-Z a-z 0-9 _ . -"));
            break;
        }
        for (const Condition &other : p.conditions) {
            if (other.id == condition.id)
                ok = reader.fail(
                    at + QStringLiteral("/id"),
                    QStringLiteral("%1 is already a condition").arg(quoted(condition.id)));
        }
        // A router file is the protocol's neighbour; a preset is a name.
        if (condition.router.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
            condition.router = folder.absoluteFilePath(condition.router);
        LoadError routerError;
        if (ok && full && !loadRouter(condition.router, {}, &routerError)) {
            ok = reader.fail(at + QStringLiteral("/router"), routerError.toString());
            break;
        }
        for (const Condition &other : p.conditions) {
            if (ok && !p.factors.empty() && other.levels == condition.levels)
                ok = reader.fail(
                    at + QStringLiteral("/levels"),
                    QStringLiteral("the same cell as condition %1").arg(quoted(other.id)));
        }
        if (!ok)
            break;
        p.conditions.push_back(condition);
    }
    if (ok && !p.factors.empty()) {
        int cells = 1;
        for (const Factor &factor : p.factors)
            cells *= int(factor.levels.size());
        if (cells != int(p.conditions.size()))
            ok = reader.fail(QStringLiteral("/conditions"),
                             QStringLiteral("the factors cross into %1 cells, the protocol has "
                                            "%2 conditions: each cell must be one condition")
                                 .arg(cells)
                                 .arg(p.conditions.size()));
    }
    if (ok) {
        if (scheme == QLatin1String("williams"))
            p.scheme = ConditionOrder::Scheme::Williams;
        else if (scheme == QLatin1String("latin"))
            p.scheme = ConditionOrder::Scheme::Latin;
        else if (scheme == QLatin1String("random"))
            p.scheme = ConditionOrder::Scheme::Random;
        else
            ok = reader.fail(
                QStringLiteral("/order/scheme"),
                QStringLiteral("must be williams, latin or random, got %1").arg(quoted(scheme)));
        if (ok && !ConditionOrder::accepts(p.scheme, int(p.conditions.size())))
            ok = reader.fail(QStringLiteral("/order/scheme"),
                             QStringLiteral("a Williams design needs an even number of "
                                            "conditions, the protocol has %1: use 'latin' (the "
                                            "design and its mirror, %2 orders)")
                                 .arg(p.conditions.size())
                                 .arg(2 * p.conditions.size()));
    }
    ok = ok &&
         reader.object(json, QString(), QLatin1String("questionnaires"), &questionnaires, false) &&
         reader.checkKeys(questionnaires, QStringLiteral("/questionnaires"),
                          {QLatin1String("afterCondition"), QLatin1String("atTheEnd")}) &&
         readQuestions(reader, questionnaires, QStringLiteral("/questionnaires"),
                       QLatin1String("afterCondition"), p.conditions, &p.afterCondition) &&
         readQuestions(reader, questionnaires, QStringLiteral("/questionnaires"),
                       QLatin1String("atTheEnd"), p.conditions, &p.atTheEnd);
    // Each measure has one name in the exports.
    QStringList measures;
    for (const auto *list : {&p.afterCondition, &p.atTheEnd}) {
        for (size_t i = 0; ok && i < list->size(); ++i) {
            for (const QString &measure : (*list)[i].measures()) {
                if (ok && measures.contains(measure))
                    ok = reader.fail(
                        jsonPointerChild(list == &p.atTheEnd
                                             ? QStringLiteral("/questionnaires/atTheEnd")
                                             : QStringLiteral("/questionnaires/afterCondition"),
                                         int(i)),
                        QStringLiteral("%1 is already a measure").arg(quoted(measure)));
                measures.append(measure);
            }
        }
    }
    // The run itself: the scene loads with its options, and no item takes a task metric's
    // name (the export would mix answers with trials under it).
    if (ok && full) {
        QString reason;
        const std::unique_ptr<SimRun> run = SimRun::create(p.runOptions(0), &reason);
        if (!run) {
            ok = reader.fail(QStringLiteral("/scene"), reason);
        } else {
            const QStringList metrics = run->metrics().keys();
            for (const auto *list : {&p.afterCondition, &p.atTheEnd}) {
                for (size_t i = 0; ok && i < list->size(); ++i) {
                    for (const QString &measure : (*list)[i].measures()) {
                        if (ok && metrics.contains(measure))
                            ok = reader.fail(
                                jsonPointerChild(
                                    list == &p.atTheEnd
                                        ? QStringLiteral("/questionnaires/atTheEnd")
                                        : QStringLiteral("/questionnaires/afterCondition"),
                                    int(i)),
                                QStringLiteral("%1 is the name of a task metric")
                                    .arg(quoted(measure)));
                    }
                }
            }
        }
    }
    if (!ok || reader.error().isSet()) {
        *error = reader.error();
        return false;
    }
    *out = p;
    return true;
}

} // namespace semhap
