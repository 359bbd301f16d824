// SPDX-License-Identifier: MIT
#pragma once

#include "conditionorder.h"
#include "loaderror.h"
#include "simrun.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace semhap {

/**
 * A user study's protocol (`semhap.study/1`, docs/studies.md): the scene, the conditions (a
 * router each), the order scheme, each condition's practice and timed trials, and the
 * questionnaires after each condition and at the end.
 */
struct StudyProtocol
{
    static constexpr const char *Format = "semhap.study/1";
    /** The longest a practice, a trial or a break may last (s): a day. */
    static constexpr double MaxSeconds = 86400.0;
    /** The most conditions a study may compare. */
    static constexpr int MaxConditions = 16;

    /** One feedback condition: what the participant gets. */
    struct Condition
    {
        QString id;         ///< short, in tables and file names (`[A-Za-z0-9_.-]`)
        QString label;      ///< what the experimenter and the participant read
        QString router;     ///< a preset, or a router file relative to the protocol
        QStringList levels; ///< its level of each factor, in the factors' order
    };

    /** A factor of a factorial design: what the conditions cross (docs/studies.md). */
    struct Factor
    {
        QString id;
        QStringList levels;
    };

    /** One questionnaire item. */
    struct Question
    {
        enum class Kind
        {
            NasaTlx,
            Likert,
            Ranking,
            Notes
        };
        Kind kind = Kind::Notes;
        QString id;          ///< the measure's name in exports (NASA-TLX: its six subscales)
        QString text;        ///< the question (Likert, notes)
        QStringList anchors; ///< Likert: the two ends' words
        int points = 7;      ///< Likert: the scale's length
        /**
         * The ids of the conditions the item is about: a ranking ranks them (all of them); an
         * afterCondition item is asked after these only (empty: after each), so "the feedback
         * was realistic" is not asked after a condition without feedback.
         */
        QStringList conditions;

        /** Whether the item is asked after condition `condition` (afterCondition items). */
        bool asksAfter(const QString &condition) const
        {
            return conditions.isEmpty() || conditions.contains(condition);
        }

        /**
         * The measures the item gives, as exports name them: the six `tlx.*` subscales for
         * NASA-TLX, the id for the others (a ranking gives its id once per condition).
         */
        QStringList measures() const;
        /** Whether the answer is text (notes) rather than a number. */
        bool isText() const { return kind == Kind::Notes; }
        /** The lowest and highest answer a measure of the item takes. */
        double lowest() const;
        double highest() const;
    };

    /** The NASA-TLX subscales' measure names, in the questionnaire's order. */
    static const QStringList &tlxSubscales();

    /** One step of a participant's way through the study. */
    struct Step
    {
        enum class Kind
        {
            Practice,      ///< the condition's practice round
            Trial,         ///< a timed trial (`trial` 1..trials)
            Questionnaire, ///< the afterCondition items asked after `condition`
            Final,         ///< the atTheEnd items
            Done           ///< nothing left
        };
        Kind kind = Kind::Done;
        int condition = -1; ///< index into conditions; -1 for Final and Done
        int trial = 0;      ///< Trial: 1-based
        bool operator==(const Step &other) const
        {
            return kind == other.kind && condition == other.condition && trial == other.trial;
        }
    };

    QString file;      ///< the protocol, as the user named it
    QByteArray source; ///< the file's bytes, as read (a study keeps the protocol it began with)
    QString name;      ///< what the experimenter's view shows
    QString scene;     ///< a bundled scene, or an MJCF file (absolute once read)
    SceneOptions sceneOptions;
    std::vector<Condition> conditions;
    std::vector<Factor> factors; ///< empty, or the 1–2 factors every condition is a cell of
    ConditionOrder::Scheme scheme = ConditionOrder::Scheme::Latin;
    std::uint64_t seed = 1;       ///< of the random scheme
    int practiceTransfers = 0;    ///< practice until this many transfers (0: no such goal)
    double practiceSeconds = 0.0; ///< or this long (0: no practice)
    int trials = 2;
    double trialSeconds = 60.0;
    double breakSeconds = 0.0; ///< an optional break offered between trials
    std::vector<Question> afterCondition;
    std::vector<Question> atTheEnd;

    /** The afterCondition items asked after condition `condition` (an index), in order. */
    std::vector<Question> questionsAfter(int condition) const;

    /** The order scheme over this protocol's conditions. */
    ConditionOrder order() const { return ConditionOrder(scheme, int(conditions.size()), seed); }
    /** Whether `text` may be a condition's or a participant's id: 1–32 of `A-Z a-z 0-9 _ . -`. */
    static bool isId(const QString &text);
    /** The index of the condition `id`, or -1. */
    int conditionIndex(const QString &id) const;

    /**
     * The steps of a participant who meets the conditions in `order`: per condition its
     * practice (when the protocol has one), its trials and its questionnaire (when an item is
     * asked after it), then the final questionnaire (when it has items).
     */
    std::vector<Step> steps(const std::vector<int> &order) const;
    /** The transfers a practice round's goal counts in a run's `metrics`. */
    static int transfers(const QJsonObject &metrics);
    /** Whether a practice round that got `metrics` after `seconds` has reached its goal. */
    bool practiceDone(const QJsonObject &metrics, double seconds) const;
    /**
     * How long `step` (Practice or Trial) may run (s): a trial's seconds, a practice round's,
     * or MaxSeconds for a practice round with a transfer goal only.
     */
    double seconds(const Step &step) const;
    /** The run of `condition`: the scene, its options and the condition's router. */
    RunOptions runOptions(int condition) const;

    /** How much parse() checks beyond the format. */
    enum class Checks
    {
        Full,     ///< the routers compile, the scene and gripper load, measures are free
        Structure ///< only the document: what reading a study's results needs
    };

    /**
     * Reads and checks a protocol (its routers compile, its scene loads with its gripper,
     * no item takes a task metric's name); false with `FILE: /pointer: reason` in `error`.
     */
    static bool read(const QString &path, StudyProtocol *out, LoadError *error);
    /**
     * Checks a protocol's bytes as read() does, `path` saying where it came from (errors
     * name it; its folder holds the scene and router files it names).
     */
    static bool parse(const QByteArray &source, const QString &path, StudyProtocol *out,
                      LoadError *error, Checks checks = Checks::Full);
};

} // namespace semhap
