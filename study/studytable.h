// SPDX-License-Identifier: MIT
#pragma once

#include "loaderror.h"
#include "studyprotocol.h"

#include <QByteArray>
#include <QHash>
#include <QString>
#include <QStringList>

#include <vector>

namespace semhap {

class StudyDatabase;

/**
 * A study's numbers in tidy form (docs/studies.md, "Export"): one row per participant,
 * condition, trial and measure — what `semhap study export` writes and `study analyze`
 * reads, from a study or from a CSV collected elsewhere.
 */
class StudyTable
{
public:
    /** One observation. */
    struct Row
    {
        QString participant;
        QString condition;
        int trial = 0; ///< 1..trials; 0 for a questionnaire's answer
        QString measure;
        double value = 0.0;
    };

    /**
     * One measure as the analysis takes it: each participant's mean per condition, over the
     * measure's conditions — those anyone has a value in (an item asked after some conditions
     * only is about those).
     */
    struct Matrix
    {
        std::vector<int> conditions;           ///< indices into conditions(), in their order
        QStringList participants;              ///< those with a value in each of them
        std::vector<std::vector<double>> rows; ///< per participant, per condition of the measure
        QStringList incomplete;                ///< participants left out: a condition missing
    };

    /** The most measures and participants a table takes (a CSV beyond is refused). */
    static constexpr int MaxMeasures = 1000;
    static constexpr int MaxParticipants = 10000;

    /** The CSV's one header line. */
    static constexpr const char *Header = "participant,condition,trial,measure,value";
    /** The raw NASA-TLX score's measure: the mean of the six subscales. */
    static constexpr const char *RawTlx = "tlx.raw";

    /**
     * The study's rows: each done trial's numeric metrics (practice rounds, aborted,
     * invalid and interrupted trials left out), each numeric answer, and the raw TLX of each
     * complete NASA-TLX.
     */
    static StudyTable fromStudy(const StudyDatabase &study);
    /**
     * Reads a tidy CSV (the header above, then a row per observation; an empty value or
     * `NA` is no observation; `trial` empty for one not tied to a trial); false with
     * `FILE:LINE:COL: reason` for a malformed row, a repeated observation, or more than
     * MaxConditions conditions, MaxMeasures measures or MaxParticipants participants.
     */
    static bool readCsv(const QString &path, StudyTable *out, LoadError *error);
    /** Reads a tidy CSV's bytes as readCsv() does, `path` naming them in errors. */
    static bool parseCsv(QByteArray bytes, const QString &path, StudyTable *out, LoadError *error);

    /** The CSV, header first. */
    QByteArray toCsv() const;

    const std::vector<Row> &rows() const { return m_rows; }
    /** The conditions: the protocol's order from a study, first seen from a CSV. */
    const QStringList &conditions() const { return m_conditions; }
    /** The measures, in the order first seen. */
    const QStringList &measures() const { return m_measures; }
    /** The participants: a study's in the order added, a CSV's in the order first seen. */
    const QStringList &participants() const { return m_participants; }
    /** The factorial design, when the study's protocol declares one (a CSV has none). */
    const std::vector<StudyProtocol::Factor> &factors() const { return m_factors; }
    /** Condition `i`'s level of each factor. */
    QStringList levels(int condition) const { return m_levels.value(condition); }

    /**
     * Each participant's mean over trials of `measure` per condition (conditions()); those
     * without a value in every condition, even in none, are `incomplete`.
     */
    Matrix matrix(const QString &measure) const;

private:
    /** Adds a row, indexing its names (which must be known or below their limits). */
    void add(const QString &participant, const QString &condition, int trial,
             const QString &measure, double value);

    std::vector<Row> m_rows;
    QStringList m_conditions;
    QStringList m_measures;
    QStringList m_participants;
    QHash<QString, int> m_conditionIndex;
    QHash<QString, int> m_participantIndex;
    QHash<QString, std::vector<size_t>> m_rowsOfMeasure;
    std::vector<StudyProtocol::Factor> m_factors;
    QList<QStringList> m_levels;
};

} // namespace semhap
