// SPDX-License-Identifier: MIT
#pragma once

#include "conditionorder.h"
#include "loaderror.h"
#include "sceneoptions.h"

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

    /** One feedback condition: what the participant gets. */
    struct Condition
    {
        QString id;     ///< short, in tables and file names (`[A-Za-z0-9_.-]`)
        QString label;  ///< what the experimenter and the participant read
        QString router; ///< a preset, or a router file relative to the protocol
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
        QStringList ranked;  ///< Ranking: the condition ids ranked (all of them)
    };

    QString file;  ///< the protocol, as the user named it
    QString name;  ///< what the experimenter's view shows
    QString scene; ///< a bundled scene, or an MJCF file (absolute once read)
    SceneOptions sceneOptions;
    std::vector<Condition> conditions;
    ConditionOrder::Scheme scheme = ConditionOrder::Scheme::Latin;
    std::uint64_t seed = 1;       ///< of the random scheme
    int practiceTransfers = 0;    ///< practice until this many transfers (0: no such goal)
    double practiceSeconds = 0.0; ///< or this long (0: no practice)
    int trials = 2;
    double trialSeconds = 60.0;
    double breakSeconds = 0.0; ///< an optional break offered between trials
    std::vector<Question> afterCondition;
    std::vector<Question> atTheEnd;

    /** The order scheme over this protocol's conditions. */
    ConditionOrder order() const { return ConditionOrder(scheme, int(conditions.size()), seed); }

    /**
     * Reads and checks a protocol (its routers compile, its scene exists); false with
     * `FILE: /pointer: reason` in `error`.
     */
    static bool read(const QString &path, StudyProtocol *out, LoadError *error);
};

} // namespace semhap
