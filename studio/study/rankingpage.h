// SPDX-License-Identifier: MIT
#pragma once

#include "questionpage.h"

class QListWidget;
class QPushButton;

namespace semhap {

/**
 * The ranking's page: the conditions it ranks, by their labels, as a list the participant
 * orders — dragging an entry, with Move up and Move down, or Ctrl+Up and Ctrl+Down — the top
 * one ranked 1. The list always holds each condition once, so every order is a ranking.
 */
class RankingPage : public QuestionPage
{
    Q_OBJECT

public:
    RankingPage(const StudyProtocol &protocol, const StudyProtocol::Question &question,
                QWidget *parent = nullptr);

    bool isComplete() const override { return true; }
    std::vector<StudyDatabase::Answer> answers() const override;
    void showAnswers(const std::vector<StudyDatabase::Answer> &given) override;

    QListWidget *list() const { return m_list; }
    /** The conditions' indices, from rank 1 down. */
    std::vector<int> ranking() const;
    /** Moves the entry at `row` by `by` places (clamped), keeping it selected. */
    void move(int row, int by);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    /** Numbers the entries by their rank and enables the buttons for the selected one. */
    void renumber();

    QListWidget *m_list = nullptr;
    QPushButton *m_up = nullptr;
    QPushButton *m_down = nullptr;
    QStringList m_labels; ///< by condition index
};

} // namespace semhap
