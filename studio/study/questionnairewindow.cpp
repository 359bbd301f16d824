// SPDX-License-Identifier: MIT
#include "questionnairewindow.h"

#include "colors.h"
#include "questionpage.h"
#include "studydocument.h"

#include <QGuiApplication>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace semhap {

namespace {

using Kind = StudyProtocol::Question::Kind;

/** What the keys do on a page of `kind`, as its hint line says. */
QString keysOf(Kind kind, int points)
{
    switch (kind) {
    case Kind::NasaTlx:
        return QuestionnaireWindow::tr(
            "Tab: next scale · ← →: set it · Enter: next page · Backspace: back");
    case Kind::Likert:
        return QuestionnaireWindow::tr(
                   "1–%1: choose · ← →: move · Enter: next page · Backspace: back")
            .arg(std::min(points, 9));
    case Kind::Ranking:
        return QuestionnaireWindow::tr(
            "↑ ↓: choose · Ctrl+↑ ↓: move it · Enter: next page · Backspace: back");
    case Kind::Notes:
        break;
    }
    // The field keeps Return and Backspace for the text.
    return QuestionnaireWindow::tr("Ctrl+Enter: next page · Alt+←: back");
}

} // namespace

QuestionnaireWindow::QuestionnaireWindow(StudyDocument &study, const StudyProtocol::Step &step,
                                         QWidget *parent)
    : QWidget(parent, Qt::Window), m_study(study), m_participant(study.participant()), m_step(step)
{
    setObjectName(QStringLiteral("questionnaireWindow"));
    setWindowTitle(tr("Questionnaire"));
    setAttribute(Qt::WA_DeleteOnClose);
    // Read from further away than the experimenter's panels.
    QFont bigger = font();
    bigger.setPointSizeF(bigger.pointSizeF() * 1.5);
    setFont(bigger);

    const StudyProtocol &protocol = study.protocol();
    const bool final = step.kind == StudyProtocol::Step::Kind::Final;
    const int condition = final ? -1 : step.condition;
    const std::vector<StudyProtocol::Question> items =
        final ? protocol.atTheEnd : protocol.questionsAfter(condition);

    m_heading =
        new QLabel(final ? tr("At the end of the study")
                         : tr("After: %1").arg(protocol.conditions[size_t(condition)].label),
                   this);
    m_heading->setObjectName(QStringLiteral("questionnaireHeading"));
    m_heading->setTextFormat(Qt::PlainText); // the protocol's label, as written
    m_position = new QLabel(this);
    m_position->setObjectName(QStringLiteral("questionnairePosition"));
    m_progress = new QProgressBar(this);
    m_progress->setTextVisible(false);
    m_progress->setRange(0, int(items.size()));
    m_progress->setMaximumHeight(8);
    auto *top = new QHBoxLayout;
    top->addWidget(m_heading, 1);
    top->addWidget(m_position);

    m_stack = new QStackedWidget(this);
    const std::vector<StudyDatabase::Answer> given = study.database()->answers(m_participant);
    int first = -1;
    for (const StudyProtocol::Question &item : items) {
        QuestionPage *page = QuestionPage::create(protocol, item, condition, m_stack);
        page->showAnswers(given);
        // A page counts as given when the study has an answer to each of its measures.
        bool stored = page->isComplete();
        for (const StudyDatabase::Answer &a : page->answers()) {
            stored = stored && std::any_of(given.begin(), given.end(), [&](const auto &g) {
                         return g.condition == a.condition && g.measure == a.measure;
                     });
        }
        if (!stored && first < 0)
            first = int(m_pages.size());
        connect(page, &QuestionPage::edited, this, [this, index = m_pages.size()] {
            m_stored[index] = false;
            m_problem->clear();
        });
        connect(page, &QuestionPage::submitted, this, &QuestionnaireWindow::next);
        m_stack->addWidget(page);
        m_pages.push_back(page);
        m_stored.push_back(stored);
    }
    m_thanks =
        new QLabel(tr("Thank you!\n\nPlease tell the experimenter that you are done."), m_stack);
    m_thanks->setObjectName(QStringLiteral("thanks"));
    m_thanks->setAlignment(Qt::AlignCenter);
    m_stack->addWidget(m_thanks);

    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("questionnaireProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: %1;").arg(colors::css(colors::Error)));
    m_keys = new QLabel(this);
    m_keys->setObjectName(QStringLiteral("questionnaireKeys"));
    m_keys->setEnabled(false); // greyed: a hint, not content
    m_back = new QPushButton(tr("Back"), this);
    m_back->setObjectName(QStringLiteral("backButton"));
    m_next = new QPushButton(this);
    m_next->setObjectName(QStringLiteral("nextButton"));
    // The keys stay with the page (numbers, arrows, Return); the buttons take the mouse.
    for (QPushButton *button : {m_back, m_next}) {
        button->setFocusPolicy(Qt::NoFocus);
        button->setMinimumWidth(button->fontMetrics().averageCharWidth() * 14);
    }
    connect(m_back, &QPushButton::clicked, this, &QuestionnaireWindow::back);
    connect(m_next, &QPushButton::clicked, this, [this] {
        if (currentPage() >= pageCount())
            close();
        else
            next();
    });
    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_back);
    bottom->addWidget(m_keys, 1, Qt::AlignCenter);
    bottom->addWidget(m_next);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(48, 32, 48, 32);
    layout->setSpacing(16);
    layout->addLayout(top);
    layout->addWidget(m_progress);
    layout->addWidget(m_stack, 1);
    layout->addWidget(m_problem);
    layout->addLayout(bottom);
    resize(1024, 720);
    showPage(first < 0 ? 0 : first);
}

int QuestionnaireWindow::currentPage() const
{
    return m_stack->currentIndex();
}

void QuestionnaireWindow::showPage(int index)
{
    m_stack->setCurrentIndex(index);
    m_problem->clear();
    const bool thanks = index >= pageCount();
    m_progress->setValue(index);
    m_position->setText(thanks ? QString()
                               : tr("Question %1 of %2").arg(index + 1).arg(pageCount()));
    m_back->setVisible(!thanks);
    m_back->setEnabled(index > 0);
    m_next->setText(thanks ? tr("Close") : index + 1 == pageCount() ? tr("Finish") : tr("Next"));
    if (thanks) {
        m_keys->setText(tr("Enter: close"));
        m_thanks->setFocus();
        return;
    }
    const StudyProtocol::Question &item = page(index)->question();
    m_keys->setText(keysOf(item.kind, item.points));
    page(index)->setFocus();
}

bool QuestionnaireWindow::store()
{
    const int index = currentPage();
    if (m_stored[size_t(index)])
        return true;
    for (StudyDatabase::Answer a : page(index)->answers()) {
        a.participant = m_participant;
        QString error;
        if (!m_study.answer(a, &error)) {
            m_problem->setText(tr("Your answer could not be stored: %1").arg(error));
            return false;
        }
    }
    m_stored[size_t(index)] = true;
    return true;
}

bool QuestionnaireWindow::next()
{
    const int index = currentPage();
    if (index >= pageCount())
        return false;
    QuestionPage *shown = page(index);
    if (!shown->isComplete()) {
        m_problem->setText(shown->question().kind == Kind::NasaTlx
                               ? tr("Please set each of the six scales.")
                               : tr("Please choose one of the points."));
        return false;
    }
    if (!store())
        return false;
    showPage(index + 1);
    if (index + 1 == pageCount())
        emit finished();
    return true;
}

void QuestionnaireWindow::back()
{
    const int index = currentPage();
    if (index == 0 || index >= pageCount())
        return;
    // What was answered is kept; a page half done is left as it is.
    if (page(index)->isComplete() && !store())
        return;
    showPage(index - 1);
}

void QuestionnaireWindow::showBeside(QWidget *beside)
{
    const QScreen *own = beside ? beside->screen() : nullptr;
    for (QScreen *screen : QGuiApplication::screens()) {
        if (screen != own) {
            setGeometry(screen->availableGeometry());
            showFullScreen();
            activateWindow();
            return;
        }
    }
    showMaximized();
    // The keyboard is the participant's: the page's keys go here, not to the experimenter's.
    raise();
    activateWindow();
}

void QuestionnaireWindow::keyPressEvent(QKeyEvent *event)
{
    const int key = event->key();
    if (key == Qt::Key_Return || key == Qt::Key_Enter) {
        if (currentPage() >= pageCount())
            close();
        else
            next();
    } else if (key == Qt::Key_Backspace ||
               (key == Qt::Key_Left && event->modifiers() & Qt::AltModifier)) {
        back();
    } else if (key == Qt::Key_F11) {
        setWindowState(windowState() ^ Qt::WindowFullScreen);
    } else {
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

} // namespace semhap
