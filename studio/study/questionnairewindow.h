// SPDX-License-Identifier: MIT
#pragma once

#include "studyprotocol.h"

#include <QWidget>

#include <vector>

class QLabel;
class QProgressBar;
class QPushButton;
class QStackedWidget;

namespace semhap {

class QuestionPage;
class StudyDocument;

/**
 * The participant's view (docs/studio.md, "Questionnaires"): a top-level window of its own,
 * for a second screen, with a questionnaire step's items one per page, Back and Next. Each
 * page's answers are stored in the study as the page is left (Next, Back, Finish), so a crash
 * loses nothing answered; it opens at the first page not answered yet, answered pages showing
 * their answers. Return is Next (Ctrl+Return in a notes field), Backspace and Alt+Left Back,
 * F11 full screen.
 */
class QuestionnaireWindow : public QWidget
{
    Q_OBJECT

public:
    /** The questionnaire of `step` (Questionnaire or Final) for the study's chosen participant. */
    QuestionnaireWindow(StudyDocument &study, const StudyProtocol::Step &step,
                        QWidget *parent = nullptr);

    const StudyProtocol::Step &step() const { return m_step; }
    int pageCount() const { return int(m_pages.size()); }
    /** The page shown (0-based); pageCount() once finished (the thank-you page). */
    int currentPage() const;
    QuestionPage *page(int index) const { return m_pages[size_t(index)]; }

    /** Stores the page and shows the next one, or finishes; false when it stays (why is shown). */
    bool next();
    /** Stores the page when it is complete and shows the one before. */
    void back();
    /** Shows the window for the participant: full screen on a screen `beside` is not on, else
     * maximized. */
    void showBeside(QWidget *beside);

signals:
    /** Every item was answered: the questionnaire step is done. */
    void finished();

protected:
    void keyPressEvent(QKeyEvent *event) override;

private:
    /** Stores the shown page's answers when they are new or changed; false with the reason shown.
     */
    bool store();
    void showPage(int index);

    StudyDocument &m_study;
    QString m_participant; ///< whose answers these are, whoever is chosen later
    StudyProtocol::Step m_step;
    std::vector<QuestionPage *> m_pages;
    std::vector<bool> m_stored; ///< each page's answers are in the study as shown
    QStackedWidget *m_stack = nullptr;
    QLabel *m_thanks = nullptr;
    QLabel *m_heading = nullptr;
    QLabel *m_position = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_problem = nullptr;
    QLabel *m_keys = nullptr;
    QPushButton *m_back = nullptr;
    QPushButton *m_next = nullptr;
};

} // namespace semhap
