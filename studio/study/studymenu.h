// SPDX-License-Identifier: MIT
#pragma once

#include <QMenu>

namespace semhap {

class StudyDocument;

/**
 * File → Study, the study feature's own actions, which the window puts in its File menu:
 * New study (a protocol, then where the study is kept), Open study, Export results (the
 * CSVs and the analysis' report into a folder) and Close study (a trial that runs is aborted
 * once the user agrees). New and Open wait while a trial runs, since another study would
 * abort it without asking; Export and Close need an open study.
 */
class StudyMenu : public QMenu
{
    Q_OBJECT

public:
    /** `window` parents the dialogs. */
    StudyMenu(StudyDocument &study, QWidget *window);

    QAction *newStudyAction() const { return m_new; }
    QAction *openStudyAction() const { return m_open; }

signals:
    /** Something the user asked for failed: `what`, and why. */
    void problem(const QString &what, const QString &error);
    /** Something done, for the status bar. */
    void message(const QString &text);

private:
    void newStudy();
    void openStudy();
    void exportResults();
    void closeStudy();
    void updateActions();

    StudyDocument &m_study;
    QWidget *m_window;
    QAction *m_new;
    QAction *m_open;
    QAction *m_export;
    QAction *m_close;
};

} // namespace semhap
