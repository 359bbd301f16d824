// SPDX-License-Identifier: MIT
#include "notespage.h"

#include <QKeyEvent>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace semhap {

NotesPage::NotesPage(const StudyProtocol::Question &question, int condition, QWidget *parent)
    : QuestionPage(question, condition, parent)
{
    QVBoxLayout *layout = layoutWithText(tr("Notes"));
    m_edit = new QPlainTextEdit(this);
    m_edit->setObjectName(QStringLiteral("notesEdit"));
    m_edit->installEventFilter(this);
    layout->addWidget(m_edit, 1);
    connect(m_edit, &QPlainTextEdit::textChanged, this, &QuestionPage::edited);
    setFocusProxy(m_edit);
}

bool NotesPage::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_edit && event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if ((key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) &&
            key->modifiers() & Qt::ControlModifier) {
            emit submitted();
            return true;
        }
    }
    return QuestionPage::eventFilter(watched, event);
}

std::vector<StudyDatabase::Answer> NotesPage::answers() const
{
    StudyDatabase::Answer a = answer(question().id);
    a.text = m_edit->toPlainText();
    return {a};
}

void NotesPage::showAnswers(const std::vector<StudyDatabase::Answer> &given)
{
    if (const StudyDatabase::Answer *a = find(given, condition(), question().id))
        m_edit->setPlainText(a->text);
}

} // namespace semhap
