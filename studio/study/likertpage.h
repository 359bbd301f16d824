// SPDX-License-Identifier: MIT
#pragma once

#include "questionpage.h"

class QButtonGroup;

namespace semhap {

/**
 * A Likert item's page: the protocol's statement and a row of radio buttons 1 to its points
 * between its two anchors. Keys: a number picks its point (0 is 10), the arrows move the
 * choice one point.
 */
class LikertPage : public QuestionPage
{
    Q_OBJECT

public:
    LikertPage(const StudyProtocol::Question &question, int condition, QWidget *parent = nullptr);

    bool isComplete() const override { return value() > 0; }
    std::vector<StudyDatabase::Answer> answers() const override;
    void showAnswers(const std::vector<StudyDatabase::Answer> &given) override;

    /** The point chosen (1..points), 0 while none is. */
    int value() const;

protected:
    void keyPressEvent(QKeyEvent *event) override;

private:
    /** Chooses `point` when the scale has it. */
    void choose(int point);

    QButtonGroup *m_points = nullptr;
};

} // namespace semhap
