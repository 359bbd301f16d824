// SPDX-License-Identifier: MIT
#pragma once

#include "studydatabase.h"

#include <QWidget>

#include <vector>

class QLabel;
class QVBoxLayout;

namespace semhap {

/**
 * One page of the participant's questionnaire: a questionnaire item's question, as the
 * protocol words it, and widgets that offer only its scale (TlxPage, LikertPage, RankingPage,
 * NotesPage). The QuestionnaireWindow stores what a page holds when the page is left.
 */
class QuestionPage : public QWidget
{
    Q_OBJECT

public:
    /**
     * A page for `question` of `protocol`, asked about `condition` (-1: at the end); null
     * for none (every kind has a page).
     */
    static QuestionPage *create(const StudyProtocol &protocol,
                                const StudyProtocol::Question &question, int condition,
                                QWidget *parent = nullptr);

    const StudyProtocol::Question &question() const { return m_question; }
    /** Whether every measure of the page has an answer the participant gave. */
    virtual bool isComplete() const = 0;
    /** The page's answers, one per measure (participant left empty); none while incomplete. */
    virtual std::vector<StudyDatabase::Answer> answers() const = 0;
    /** Shows answers given before (the study's newest), those of this page's measures. */
    virtual void showAnswers(const std::vector<StudyDatabase::Answer> &given) = 0;

signals:
    /** What the page holds changed (isComplete() may have too). */
    void edited();
    /** The participant asked to go on from a field that keeps Return for itself (notes). */
    void submitted();

protected:
    QuestionPage(const StudyProtocol::Question &question, int condition, QWidget *parent);
    /** An answer of this page's condition to `measure`. */
    StudyDatabase::Answer answer(const QString &measure) const;
    /** The given answer to `measure` of `condition`, or null. */
    static const StudyDatabase::Answer *find(const std::vector<StudyDatabase::Answer> &given,
                                             int condition, const QString &measure);
    int condition() const { return m_condition; }
    /** The page's layout, the question's text on top when it has one (`fallback` else). */
    QVBoxLayout *layoutWithText(const QString &fallback);

private:
    StudyProtocol::Question m_question;
    int m_condition;
};

} // namespace semhap
