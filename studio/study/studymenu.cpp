// SPDX-License-Identifier: MIT
#include "studymenu.h"

#include "filedialogs.h"
#include "studydocument.h"
#include "studyexport.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>

namespace semhap {

StudyMenu::StudyMenu(StudyDocument &study, QWidget *window)
    : QMenu(tr("Stud&y"), window), m_study(study), m_window(window),
      m_new(addAction(tr("New study…"))), m_open(addAction(tr("Open study…"))),
      m_export(addAction(tr("Export results…"))), m_close(addAction(tr("Close study")))
{
    setObjectName(QStringLiteral("studyMenu"));
    m_new->setObjectName(QStringLiteral("newStudyAction"));
    m_new->setToolTip(tr("Start a study from a protocol: participants, their orders of "
                         "conditions, timed trials and questionnaires"));
    m_open->setObjectName(QStringLiteral("openStudyAction"));
    m_export->setObjectName(QStringLiteral("exportStudyAction"));
    m_export->setToolTip(
        tr("Write the study's results into a folder: measures.csv (tidy, for R or pandas), "
           "trials.csv, answers.csv, and the analysis' report with a box plot per measure"));
    m_close->setObjectName(QStringLiteral("closeStudyAction"));
    connect(m_new, &QAction::triggered, this, &StudyMenu::newStudy);
    connect(m_open, &QAction::triggered, this, &StudyMenu::openStudy);
    connect(m_export, &QAction::triggered, this, &StudyMenu::exportResults);
    connect(m_close, &QAction::triggered, this, &StudyMenu::closeStudy);
    connect(&m_study, &StudyDocument::studyChanged, this, &StudyMenu::updateActions);
    connect(&m_study, &StudyDocument::trialChanged, this, &StudyMenu::updateActions);
    updateActions();
}

void StudyMenu::newStudy()
{
    const QString protocol =
        FileDialogs::openFile(m_window, FileKind::Protocol, tr("New study: its protocol"),
                              tr("semhap study protocols (*.json)"));
    if (protocol.isEmpty())
        return;
    const QString path =
        FileDialogs::saveFile(m_window, FileKind::Study, tr("New study: where to keep it"),
                              QFileInfo(protocol).completeBaseName() + QStringLiteral(".db"),
                              tr("semhap studies (*.db)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!m_study.create(protocol, path, &error))
        emit problem(tr("Could not create the study"), error);
}

void StudyMenu::openStudy()
{
    const QString path = FileDialogs::openFile(m_window, FileKind::Study, tr("Open study"),
                                               tr("semhap studies (*.db);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!m_study.open(path, &error))
        emit problem(tr("Could not open the study %1").arg(QFileInfo(path).fileName()), error);
}

void StudyMenu::exportResults()
{
    const QString dir =
        FileDialogs::folder(m_window, FileKind::Study, tr("Export the study's results into"));
    if (dir.isEmpty())
        return;
    QStringList written;
    QString error;
    if (!m_study.exportResults(dir, &written, &error)) {
        emit problem(tr("Could not export the study's results"), error);
        return;
    }
    emit message(
        tr("Exported %1 files into %2: measures.csv, trials.csv, answers.csv and "
           "%3/report.md")
            .arg(written.size())
            .arg(QDir::toNativeSeparators(dir), QLatin1String(StudyExport::ReportFolder)));
}

void StudyMenu::closeStudy()
{
    if (m_study.isTrialRunning() &&
        QMessageBox::question(m_window, tr("Close study"),
                              tr("%1 runs. Closing the study aborts it: it will not count and "
                                 "is due again when the study is opened again.")
                                  .arg(m_study.describe(m_study.runningStep())),
                              QMessageBox::Ok | QMessageBox::Cancel) != QMessageBox::Ok)
        return;
    m_study.close();
}

void StudyMenu::updateActions()
{
    const bool trial = m_study.isTrialRunning();
    m_new->setEnabled(!trial);
    m_open->setEnabled(!trial);
    m_export->setEnabled(m_study.isOpen());
    m_close->setEnabled(m_study.isOpen());
}

} // namespace semhap
