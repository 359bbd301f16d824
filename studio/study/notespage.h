// SPDX-License-Identifier: MIT
#pragma once

#include "questionpage.h"

class QPlainTextEdit;

namespace semhap {

/**
 * A notes item's page: the protocol's text and a field of free text (an interview's notes).
 * Return starts a new line in it; Ctrl+Return goes on.
 */
class NotesPage : public QuestionPage
{
    Q_OBJECT

public:
    NotesPage(const StudyProtocol::Question &question, int condition, QWidget *parent = nullptr);

    bool isComplete() const override { return true; }
    std::vector<StudyDatabase::Answer> answers() const override;
    void showAnswers(const std::vector<StudyDatabase::Answer> &given) override;

    QPlainTextEdit *edit() const { return m_edit; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QPlainTextEdit *m_edit = nullptr;
};

} // namespace semhap
