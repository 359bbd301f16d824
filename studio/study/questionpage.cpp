// SPDX-License-Identifier: MIT
#include "questionpage.h"

#include "likertpage.h"
#include "notespage.h"
#include "rankingpage.h"
#include "tlxpage.h"

#include <QLabel>
#include <QVBoxLayout>

namespace semhap {

QuestionPage *QuestionPage::create(const StudyProtocol &protocol,
                                   const StudyProtocol::Question &question, int condition,
                                   QWidget *parent)
{
    using Kind = StudyProtocol::Question::Kind;
    switch (question.kind) {
    case Kind::NasaTlx:
        return new TlxPage(question, condition, parent);
    case Kind::Likert:
        return new LikertPage(question, condition, parent);
    case Kind::Ranking:
        return new RankingPage(protocol, question, parent);
    case Kind::Notes:
        return new NotesPage(question, condition, parent);
    }
    return nullptr;
}

QuestionPage::QuestionPage(const StudyProtocol::Question &question, int condition, QWidget *parent)
    : QWidget(parent), m_question(question), m_condition(condition)
{}

StudyDatabase::Answer QuestionPage::answer(const QString &measure) const
{
    StudyDatabase::Answer a;
    a.condition = m_condition;
    a.measure = measure;
    return a;
}

const StudyDatabase::Answer *QuestionPage::find(const std::vector<StudyDatabase::Answer> &given,
                                                int condition, const QString &measure)
{
    for (const StudyDatabase::Answer &a : given) {
        if (a.condition == condition && a.measure == measure)
            return &a;
    }
    return nullptr;
}

QVBoxLayout *QuestionPage::layoutWithText(const QString &fallback)
{
    auto *layout = new QVBoxLayout(this);
    // The protocol's words as written: never read as markup.
    auto *text = new QLabel(m_question.text.isEmpty() ? fallback : m_question.text, this);
    text->setObjectName(QStringLiteral("questionText"));
    text->setTextFormat(Qt::PlainText);
    text->setWordWrap(true);
    QFont font = text->font();
    font.setPointSizeF(font.pointSizeF() * 1.3);
    font.setBold(true);
    text->setFont(font);
    if (!text->text().isEmpty())
        layout->addWidget(text);
    else
        text->hide();
    return layout;
}

} // namespace semhap
