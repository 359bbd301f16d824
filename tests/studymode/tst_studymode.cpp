// SPDX-License-Identifier: MIT
// Study mode in the studio (docs/studio.md, "Running a study"), driven through the real
// widgets: a study made from the bimanual protocol (its trials shortened), a participant in
// the Latin square's order through practice, trials, breaks and questionnaires answered with
// the keys; a trial marked invalid and redone, one aborted, Stop all in a trial, a second
// studio refused, and the study taken up again after its window went, after a language
// switch and after `kill -9`.
#include "conditionorder.h"
#include "devicemanager.h"
#include "likertpage.h"
#include "mainwindow.h"
#include "openwindow.h"
#include "questionnairewindow.h"
#include "rankingpage.h"
#include "reasondialog.h"
#include "runtoolbar.h"
#include "sessionreader.h"
#include "studio.h"
#include "studydocument.h"
#include "studypanel.h"
#include "tlxpage.h"
#include "transport.h"
#include "widgetchecks.h"
#include "windowpictures.h"
#include "workspace.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyleOptionSlider>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <functional>

using namespace semhap;
using Kind = StudyProtocol::Step::Kind;
using Status = StudyDatabase::Status;

class TestStudyMode : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void aParticipantGoesThroughTheWholeStudy();
    void aTrialMarkedInvalidIsRedone();
    void aTrialIsAbortedWithAReason();
    void stopAllPausesATrial();
    void aTrialKeepsItsRun();
    void closingTheStudyAbortsItsTrial();
    void ordinaryRunsOutliveTheStudy();
    void theWidgetsOfferOnlyTheScale();
    void aSecondStudioIsRefused();
    void theStudyComesBackWhereTheWindowWent();
    void theStudyComesBackAfterAKill();
    void aTrialGoesOnThroughALanguageSwitch();
    void pictures_data();
    void pictures();

private:
    /** The bimanual protocol with 2 s practice rounds and trials and a 1 s break. */
    QString shortProtocol();
    /** The bimanual protocol with its top-level keys replaced by `changes`, as `name`. */
    QString protocolWith(const QString &name, const QJsonObject &changes);
    /** A new study of `protocol` (the short one) at `name` with `participants`, closed. */
    QString makeStudy(const QString &name, const QStringList &participants,
                      QString protocol = QString());
    /** A studio on `study` (none: the workspace's), its window shown and active. */
    std::unique_ptr<Studio> startStudio(const QString &study = QString(),
                                        const QStringList &more = {});

    QTemporaryDir m_config;
    QTemporaryDir m_dir;
};

namespace {

StudyPanel *panelOf(Studio &studio)
{
    return studio.window()->studyPanel();
}

template<typename T> T *child(QWidget *parent, const QString &name)
{
    T *found = parent->findChild<T *>(name);
    if (!found)
        qWarning("no %s", qPrintable(name));
    return found;
}

StudyDocument &studyOf(Studio &studio)
{
    return studio.workspace().study();
}

/** The state column of the step row `name` under the condition group `group` (-1: top). */
QString stepState(StudyPanel *panel, int group, const QString &name)
{
    auto *tree = child<QTreeWidget>(panel, "stepTree");
    const auto find = [&](QTreeWidgetItem *parent) -> QString {
        for (int i = 0; i < parent->childCount(); ++i) {
            if (parent->child(i)->text(0) == name)
                return parent->child(i)->text(1);
        }
        return "(no such step)";
    };
    if (group < 0)
        return find(tree->invisibleRootItem());
    return find(tree->topLevelItem(group));
}

/** Selects the step row `name` under the condition group `group`, as a click does. */
void selectStep(StudyPanel *panel, int group, const QString &name)
{
    auto *tree = child<QTreeWidget>(panel, "stepTree");
    QTreeWidgetItem *parent = tree->topLevelItem(group);
    for (int i = 0; i < parent->childCount(); ++i) {
        if (parent->child(i)->text(0) == name) {
            const QRect rect = tree->visualItemRect(parent->child(i));
            QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, rect.center());
            return;
        }
    }
    qWarning("no step %s", qPrintable(name));
}

/** Clicks Start and waits for the practice round or trial it began to end by itself. */
bool runStep(Studio &studio)
{
    StudyPanel *panel = panelOf(studio);
    auto *start = child<QPushButton>(panel, "startStep");
    if (!start->isEnabled())
        return false;
    QTest::mouseClick(start, Qt::LeftButton);
    if (!studyOf(studio).isTrialRunning())
        return false;
    return QTest::qWaitFor([&] { return !studyOf(studio).isTrialRunning(); }, 120000);
}

/** Skips the break the panel shows. */
void skipBreak(Studio &studio)
{
    auto *skip = child<QPushButton>(panelOf(studio), "skipBreak");
    QVERIFY(studyOf(studio).isOnBreak());
    QVERIFY(skip->isVisible());
    QTest::mouseClick(skip, Qt::LeftButton);
    QVERIFY(!studyOf(studio).isOnBreak());
}

/** A bound device whose last frame sent has a channel above zero; empty when none. */
QString aBandOn(Engine &engine)
{
    for (const BoundDevice &device : engine.devices().status()) {
        const DeviceFrame last = engine.devices().transport(device.name)->sent().last();
        for (int c = 0; c < last.channelCount; ++c) {
            if (last.values[size_t(c)] != 0.0)
                return QString("%1 channel %2 at %3")
                    .arg(device.name)
                    .arg(c)
                    .arg(last.values[size_t(c)]);
        }
    }
    return QString();
}

/** A key pressed where the keyboard is (the focused widget of the active window). */
void press(int key, Qt::KeyboardModifiers modifiers = {})
{
    QWidget *target =
        QApplication::focusWidget() ? QApplication::focusWidget() : QApplication::activeWindow();
    QTest::keyClick(target, Qt::Key(key), modifiers);
}

/** Opens the questionnaire of the participant's next step from the panel, active. */
QuestionnaireWindow *openQuestionnaire(Studio &studio)
{
    StudyPanel *panel = panelOf(studio);
    QTest::mouseClick(child<QPushButton>(panel, "startStep"), Qt::LeftButton);
    QuestionnaireWindow *window = panel->questionnaire();
    if (window &&
        !QTest::qWaitFor([window] { return QApplication::activeWindow() == window; }, 5000))
        qWarning("the questionnaire did not become active");
    return window;
}

/**
 * Answers a questionnaire with the keys: each TLX scale moved `tlxSteps` to the right of
 * its middle (Tab to the next), each Likert item's point by its number key, a ranking
 * reversed with Ctrl+Up, notes typed; Return after each page.
 */
void answerWithKeys(QuestionnaireWindow *window, int tlxSteps, int likert, const QString &notes)
{
    for (int index = window->currentPage(); index < window->pageCount(); ++index) {
        QuestionPage *page = window->page(index);
        QCOMPARE(window->currentPage(), index);
        QVERIFY2(page->hasFocus() || page->isAncestorOf(QApplication::focusWidget()),
                 qPrintable(widgetPath(QApplication::focusWidget())));
        switch (page->question().kind) {
        case StudyProtocol::Question::Kind::NasaTlx:
            for (int scale = 0; scale < 6; ++scale) {
                for (int step = 0; step < tlxSteps; ++step)
                    press(Qt::Key_Right);
                if (scale < 5)
                    press(Qt::Key_Tab);
            }
            break;
        case StudyProtocol::Question::Kind::Likert:
            press(Qt::Key_0 + likert);
            break;
        case StudyProtocol::Question::Kind::Ranking: {
            // The last entry to the top, and so on: the list reversed.
            auto *ranking = static_cast<RankingPage *>(page);
            const int n = ranking->list()->count();
            for (int k = 0; k < n - 1; ++k) {
                ranking->list()->setCurrentRow(n - 1);
                for (int up = 0; up < n - 1 - k; ++up)
                    press(Qt::Key_Up, Qt::ControlModifier);
            }
            break;
        }
        case StudyProtocol::Question::Kind::Notes:
            // Return breaks the line there; Ctrl+Return goes on.
            for (int line = 0; line <= int(notes.count('\n')); ++line) {
                if (line > 0)
                    press(Qt::Key_Return);
                QTest::keyClicks(QApplication::focusWidget(), notes.section('\n', line, line));
            }
            // Backspace is the field's: it takes back a typo, the page stays.
            QTest::keyClicks(QApplication::focusWidget(), "x");
            press(Qt::Key_Backspace);
            QCOMPARE(window->currentPage(), index);
            press(Qt::Key_Return, Qt::ControlModifier);
            continue;
        }
        press(Qt::Key_Return);
    }
    QCOMPARE(window->currentPage(), window->pageCount()); // the thank-you page
}

/** The newest answer of `participant` to `measure` about `condition`; NaN when none. */
double answerOf(StudyDatabase &db, const QString &participant, int condition,
                const QString &measure, QString *text = nullptr)
{
    for (const StudyDatabase::Answer &a : db.answers(participant)) {
        if (a.condition == condition && a.measure == measure) {
            if (text)
                *text = a.text;
            return a.value;
        }
    }
    return std::nan("");
}

/**
 * Answers the reason dialog the next call opens with `reason` typed; `okWhileEmpty` says
 * whether OK was offered before.
 */
void answerReason(const QString &reason, bool *okWhileEmpty)
{
    QTimer::singleShot(0, [reason, okWhileEmpty] {
        QTRY_VERIFY(qobject_cast<ReasonDialog *>(QApplication::activeModalWidget()));
        auto *dialog = qobject_cast<ReasonDialog *>(QApplication::activeModalWidget());
        *okWhileEmpty = dialog->okButton()->isEnabled();
        QTest::keyClicks(dialog->edit(), reason);
        QTest::keyClick(dialog->edit(), Qt::Key_Return);
    });
}

/**
 * Answers the file dialogs the next call opens, one after the other, each with its entry of
 * `answers`; `folders` gets the folder each started in.
 */
void answerFileDialogs(QStringList answers, QStringList *folders)
{
    if (answers.isEmpty())
        return;
    QTimer::singleShot(0, [answers, folders]() mutable {
        QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()));
        auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        folders->append(QFileInfo(dialog->directory().absolutePath()).canonicalFilePath());
        const QString answer = answers.takeFirst();
        answerFileDialogs(answers, folders); // the next one, once this one is gone
        dialog->selectFile(answer);
        QTest::keyClick(dialog->focusWidget() ? dialog->focusWidget() : dialog, Qt::Key_Return);
    });
}

} // namespace

void TestStudyMode::initTestCase()
{
    QVERIFY(m_config.isValid());
    QVERIFY(m_dir.isValid());
    QCoreApplication::setOrganizationName("semhap");
    QCoreApplication::setApplicationName("semhap-studio-studymode-test");
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_config.path());
}

void TestStudyMode::init()
{
    QSettings().clear();
    QFile::remove(Workspace::defaultFile()); // each test starts on the defaults
}

QString TestStudyMode::shortProtocol()
{
    return protocolWith("bimanual-short",
                        {{"practice", QJsonObject{{"seconds", 2}}},
                         {"trials", QJsonObject{{"count", 2}, {"seconds", 2}, {"break", 1}}}});
}

QString TestStudyMode::protocolWith(const QString &name, const QJsonObject &changes)
{
    const QString path = m_dir.filePath(name + ".json");
    if (QFileInfo::exists(path))
        return path;
    QFile source(SEMHAP_RESOURCES "/studies/bimanual.json");
    if (!source.open(QIODevice::ReadOnly))
        qFatal("cannot read the bimanual protocol");
    QJsonObject json = QJsonDocument::fromJson(source.readAll()).object();
    for (auto change = changes.begin(); change != changes.end(); ++change)
        json[change.key()] = change.value();
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    file.write(QJsonDocument(json).toJson());
    return path;
}

QString TestStudyMode::makeStudy(const QString &name, const QStringList &participants,
                                 QString protocolFile)
{
    if (protocolFile.isEmpty())
        protocolFile = shortProtocol();
    StudyProtocol protocol;
    LoadError loadError;
    if (!StudyProtocol::read(protocolFile, &protocol, &loadError))
        qFatal("%s", qPrintable(loadError.toString()));
    const QString path = m_dir.filePath(name);
    QString error;
    auto study = StudyDatabase::create(path, protocol, &error);
    if (!study)
        qFatal("%s", qPrintable(error));
    for (const QString &id : participants) {
        if (!study->addParticipant(id, &error))
            qFatal("%s", qPrintable(error));
    }
    return path;
}

std::unique_ptr<Studio> TestStudyMode::startStudio(const QString &study, const QStringList &more)
{
    // Fast, so a 2 s trial takes a fraction of that; no network input.
    QStringList args{"--speed", "8", "--pose-port", "0", "--size", "1280x800", "--paused"};
    if (!study.isEmpty())
        args << "--study" << study;
    args += more;
    StudioOptions o;
    QString message;
    bool help = false;
    if (!StudioOptions::parse(args, &o, &message, &help))
        qFatal("%s", qPrintable(message));
    auto studio = std::make_unique<Studio>(o);
    studio->start();
    if (!openWindow(*studio->window()))
        qWarning("the window did not become active");
    return studio;
}

// The "done means": the bimanual example opened as a new study (the protocol dialog
// starts among the examples), P01 added, the Latin square's first row as the order, each
// condition's practice, trials (with the break between them) and questionnaire, answered with
// the keys, then the final ranking and notes; the database holds the trials with their
// sessions, tagged, and every answer as given.
void TestStudyMode::aParticipantGoesThroughTheWholeStudy()
{
    auto studio = startStudio();
    MainWindow &window = *studio->window();
    StudyPanel *panel = panelOf(*studio);
    QVERIFY(!studyOf(*studio).isOpen());
    QVERIFY(!window.findChild<QAction *>("closeStudyAction")->isEnabled());

    // File → Study → New study…: first the protocol, then where the study goes.
    const QString path = m_dir.filePath("whole.db");
    QStringList folders;
    answerFileDialogs({shortProtocol(), path}, &folders);
    window.findChild<QAction *>("newStudyAction")->trigger();
    QCOMPARE(folders.size(), 2);
    QCOMPARE(folders.first(), QFileInfo(SEMHAP_RESOURCES "/studies").canonicalFilePath());
    // The study itself goes among the user's files, never beside the examples.
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QCOMPARE(folders.last(), QFileInfo(QFileInfo(documents).isDir() ? documents : QDir::homePath())
                                 .canonicalFilePath());
    QVERIFY(studyOf(*studio).isOpen());
    QVERIFY(QFileInfo::exists(path));
    QVERIFY(!window.findChild<QDockWidget *>("studyDock")->visibleRegion().isEmpty());
    QCOMPARE(child<QLabel>(panel, "studyName")->text(),
             QString("Bimanual sorting: visual and haptic feedback"));

    // No one chosen yet: nothing is done, and no clock shows.
    QCOMPARE(child<QLabel>(panel, "nextStep")->text(), QString("No participant chosen"));
    QVERIFY(!child<QLabel>(panel, "countdown")->isVisible());
    // P01 by the keys; the order shown is the Latin square's first row.
    auto *id = child<QLineEdit>(panel, "participantId");
    id->setFocus();
    QTest::keyClicks(id, "P01");
    QTest::keyClick(id, Qt::Key_Return);
    QCOMPARE(child<QListWidget>(panel, "participantList")->currentItem()->text(), QString("P01"));
    const StudyProtocol &protocol = studyOf(*studio).protocol();
    const std::vector<int> order = ConditionOrder(ConditionOrder::Scheme::Latin, 4).order(0);
    QStringList labels;
    for (int c : order)
        labels << protocol.conditions[size_t(c)].label;
    QCOMPARE(child<QLabel>(panel, "participantOrder")->text(),
             "Order of P01: " + labels.join(" → "));
    auto *tree = child<QTreeWidget>(panel, "stepTree");
    QCOMPARE(tree->topLevelItemCount(), 5); // four conditions and the final questionnaire
    for (int i = 0; i < 4; ++i)
        QCOMPARE(tree->topLevelItem(i)->text(0), QString("%1. %2").arg(i + 1).arg(labels[i]));
    QCOMPARE(child<QLabel>(panel, "nextStep")->text(), "Next: Practice — " + labels[0] + " (2 s)");
    QVERIFY(child<QLabel>(panel, "countdown")->isVisible());
    QCOMPARE(stepState(panel, 0, "Practice"), QString("next"));

    StudyDatabase &db = *studyOf(*studio).database();
    for (int position = 0; position < 4; ++position) {
        const int condition = order[size_t(position)];
        // The practice round and the two trials end by themselves.
        QVERIFY(runStep(*studio));
        QCOMPARE(stepState(panel, position, "Practice"), QString("done"));
        QVERIFY(runStep(*studio));
        QCOMPARE(child<QLabel>(panel, "countdownCaption")->text(),
                 QString("Break before the next trial"));
        QVERIFY(!child<QPushButton>(panel, "startStep")->isEnabled());
        skipBreak(*studio);
        QVERIFY(runStep(*studio));
        QCOMPARE(stepState(panel, position, "Trial 2"), QString("done"));
        QVERIFY(!window.engine().isRecording());

        // The questionnaire, with the keys: TLX scales 50 + 5 * position, Likert points.
        QCOMPARE(child<QLabel>(panel, "nextStep")->text(),
                 "Next: Questionnaire after " + labels[position]);
        QVERIFY(!child<QLabel>(panel, "countdown")->isVisible()); // no clock runs for it
        QuestionnaireWindow *questions = openQuestionnaire(*studio);
        QVERIFY(questions);
        // Nothing about the feedback after the condition without any (issue 33, D13): the
        // TLX, awareness and dexterity only.
        const bool feedback = protocol.conditions[size_t(condition)].router != "none";
        QCOMPARE(questions->pageCount(), feedback ? 6 : 3);
        answerWithKeys(questions, position + 1, position + 2, QString());
        QCOMPARE(std::isnan(answerOf(db, "P01", condition, "realistic")), !feedback);
        QCOMPARE(answerOf(db, "P01", condition, "tlx.mental"), 50.0 + 5.0 * (position + 1));
        QCOMPARE(answerOf(db, "P01", condition, "tlx.frustration"), 50.0 + 5.0 * (position + 1));
        QCOMPARE(answerOf(db, "P01", condition, "dexterity"), double(position + 2));
        QVERIFY(db.isDone("P01", {Kind::Questionnaire, condition, 0}));
        QTest::keyClick(questions, Qt::Key_Return); // closes the thank-you page
        QTRY_VERIFY(!panel->questionnaire());
        QCOMPARE(stepState(panel, position, "Questionnaire"), QString("answered"));
    }

    // The final questionnaire: the ranking reversed, notes typed.
    QCOMPARE(child<QLabel>(panel, "nextStep")->text(), QString("Next: Final questionnaire"));
    QuestionnaireWindow *final = openQuestionnaire(*studio);
    QVERIFY(final);
    QCOMPARE(final->pageCount(), 2);
    answerWithKeys(final, 0, 0, "Liked the air pressure.\nSecond line.");
    for (int rank = 0; rank < 4; ++rank)
        QCOMPARE(answerOf(db, "P01", 3 - rank, "rank"), double(rank + 1));
    QString notes;
    answerOf(db, "P01", -1, "interview", &notes);
    QCOMPARE(notes, QString("Liked the air pressure.\nSecond line."));
    QTest::keyClick(final, Qt::Key_Return);
    QTRY_VERIFY(!panel->questionnaire());
    QCOMPARE(db.nextStep("P01").kind, Kind::Done);
    QCOMPARE(child<QLabel>(panel, "nextStep")->text(), QString("All steps done"));
    QVERIFY(!child<QPushButton>(panel, "startStep")->isEnabled());

    // Twelve runs, each done after its seconds with the run's metrics, each with its session
    // tagged with the study's keys.
    const std::vector<StudyDatabase::Trial> trials = db.trials("P01");
    QCOMPARE(int(trials.size()), 12);
    for (const StudyDatabase::Trial &trial : trials) {
        QCOMPARE(trial.status, Status::Done);
        QVERIFY2(std::abs(trial.seconds - 2.0) < 0.01, qPrintable(QString::number(trial.seconds)));
        QVERIFY(trial.metrics.contains("cubes_transferred"));
        QString error;
        auto session =
            SessionReader::open(QFileInfo(path).absoluteDir().filePath(trial.session), &error);
        QVERIFY2(session, qPrintable(error));
        const QMap<QString, QString> &tags = session->info().extra;
        QCOMPARE(tags.value("study"), protocol.name);
        QCOMPARE(tags.value("participant"), QString("P01"));
        QCOMPARE(tags.value("condition"), protocol.conditions[size_t(trial.condition)].id);
        QCOMPARE(tags.value("phase"), QString(trial.practice ? "practice" : "trial"));
        QCOMPARE(tags.value("trial"), QString::number(trial.number));
        QCOMPARE(session->info().routerSource,
                 protocol.conditions[size_t(trial.condition)].router);
    }

    // File → Study → Export results…: the CSVs and the report, as `semhap study` writes them.
    const QString exported = m_dir.filePath("whole-results");
    QVERIFY(QDir().mkpath(exported));
    folders.clear();
    answerFileDialogs({exported}, &folders);
    window.findChild<QAction *>("exportStudyAction")->trigger();
    QCOMPARE(folders.size(), 1);
    QFile measures(exported + "/measures.csv");
    QVERIFY(measures.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = measures.readAll().split('\n');
    QCOMPARE(rows.first(), QByteArray("participant,condition,trial,measure,value"));
    // P01's rows, conditions in the protocol's order: the first a trial's metric.
    QVERIFY(rows[1].startsWith(QByteArray("P01," + protocol.conditions[0].id.toUtf8() + ",1,")));
    QVERIFY(rows.contains(
        QByteArray("P01," + protocol.conditions[size_t(order[0])].id.toUtf8() + ",,tlx.raw,55")));
    for (const char *file :
         {"trials.csv", "answers.csv", "report/report.md", "report/cubes_transferred.svg"})
        QVERIFY2(QFileInfo::exists(exported + "/" + file), file);
    QFile report(exported + "/report/report.md");
    QVERIFY(report.open(QIODevice::ReadOnly));
    QVERIFY(report.readAll().startsWith("# Analysis: Bimanual sorting: visual and haptic "
                                        "feedback\n\nSource: `whole.db`."));
    QVERIFY(window.statusBar()->currentMessage().startsWith("Exported "));
}

// A done trial chosen in the list is marked invalid with a reason (OK stays off until one is
// typed): it is listed so, due again, and redone into a session of its own.
void TestStudyMode::aTrialMarkedInvalidIsRedone()
{
    const QString path = makeStudy("invalid.db", {"P01"});
    auto studio = startStudio(path, {"--participant", "P01"});
    StudyPanel *panel = panelOf(*studio);
    QVERIFY(runStep(*studio)); // the practice round
    QVERIFY(runStep(*studio)); // trial 1
    skipBreak(*studio);
    auto *invalid = child<QPushButton>(panel, "markInvalid");
    QVERIFY(!invalid->isEnabled()); // nothing chosen
    selectStep(panel, 0, "Trial 1");
    QVERIFY(invalid->isEnabled());
    bool okWhileEmpty = true;
    answerReason("the participant sneezed", &okWhileEmpty);
    QTest::mouseClick(invalid, Qt::LeftButton);
    QVERIFY(!okWhileEmpty);
    QCOMPARE(stepState(panel, 0, "Trial 1"), QString("invalid · next"));
    QVERIFY(child<QLabel>(panel, "nextStep")->text().startsWith("Next: Trial 1 of 2"));

    QVERIFY(runStep(*studio)); // trial 1 again
    QCOMPARE(stepState(panel, 0, "Trial 1"), QString("done"));
    StudyDatabase &db = *studyOf(*studio).database();
    std::vector<StudyDatabase::Trial> attempts;
    for (const StudyDatabase::Trial &t : db.trials("P01")) {
        if (!t.practice && t.number == 1)
            attempts.push_back(t);
    }
    QCOMPARE(int(attempts.size()), 2);
    QCOMPARE(attempts[0].status, Status::Invalid);
    QCOMPARE(attempts[0].reason, QString("the participant sneezed"));
    QCOMPARE(attempts[1].status, Status::Done);
    QVERIFY(attempts[1].session.endsWith("trial1-2.db"));
    QCOMPARE(db.nextStep("P01"), (StudyProtocol::Step{Kind::Trial, attempts[0].condition, 2}));
}

// Abort pauses the trial at once and asks why; no reason leaves it paused, a reason ends it
// aborted, due again.
void TestStudyMode::aTrialIsAbortedWithAReason()
{
    const QString path = makeStudy("abort.db", {"P01"});
    auto studio = startStudio(path, {"--participant", "P01", "--speed", "0.5"});
    StudyPanel *panel = panelOf(*studio);
    QTest::mouseClick(child<QPushButton>(panel, "startStep"), Qt::LeftButton);
    QVERIFY(studyOf(*studio).isTrialRunning());
    QVERIFY(studio->window()->engine().isRecording());
    QCOMPARE(stepState(panel, 0, "Practice"), QString("running"));
    // The practice round's clock counts up to its limit; a run slower than real time says so.
    QCOMPARE(child<QLabel>(panel, "countdownCaption")->text(),
             QString("Practice so far · at most 00:02 · at 0.5× real time"));
    // It has run a while when it is aborted (seconds > 0 below), however busy the machine.
    QTRY_VERIFY(studio->window()->engine().simTime() > 0.0);

    // Cancelled: still the trial, paused.
    QTimer::singleShot(0, [] {
        QTRY_VERIFY(qobject_cast<ReasonDialog *>(QApplication::activeModalWidget()));
        qobject_cast<ReasonDialog *>(QApplication::activeModalWidget())->reject();
    });
    QTest::mouseClick(child<QPushButton>(panel, "abortTrial"), Qt::LeftButton);
    QVERIFY(studyOf(*studio).isTrialRunning());
    QVERIFY(!studio->window()->engine().isRunning());
    QCOMPARE(child<QPushButton>(panel, "pauseTrial")->text(), QString("Resume"));

    bool okWhileEmpty = true;
    answerReason("the band came loose", &okWhileEmpty);
    QTest::mouseClick(child<QPushButton>(panel, "abortTrial"), Qt::LeftButton);
    QVERIFY(!okWhileEmpty);
    QVERIFY(!studyOf(*studio).isTrialRunning());
    QVERIFY(!studio->window()->engine().isRecording());
    QCOMPARE(stepState(panel, 0, "Practice"), QString("aborted · next"));
    const std::vector<StudyDatabase::Trial> trials = studyOf(*studio).database()->trials("P01");
    QCOMPARE(int(trials.size()), 1);
    QCOMPARE(trials[0].status, Status::Aborted);
    QCOMPARE(trials[0].reason, QString("the band came loose"));
    QVERIFY(trials[0].seconds > 0.0 && trials[0].seconds < 2.0);
}

// Esc (Stop all) in a trial pauses it with every band at zero, mid-pattern; Resume goes on,
// and Abort sends the bands to zero too. The practice round's clock stands while paused, and
// the round still ends at its seconds of the run's time. (The scripted operator, handed the
// grippers back with Ctrl+T, grasps: C3 plays on the bands.)
void TestStudyMode::stopAllPausesATrial()
{
    const QString protocol = protocolWith(
        "semantic-only",
        {{"conditions",
          QJsonArray{QJsonObject{
              {"id", "semantic"}, {"label", "Semantic haptic feedback"}, {"router", "C3"}}}},
         {"practice", QJsonObject{{"seconds", 60}}},
         {"trials", QJsonObject{{"count", 1}, {"seconds", 3}}},
         {"questionnaires",
          QJsonObject{{"afterCondition", QJsonArray{QJsonObject{{"type", "nasa_tlx"}}}}}}});
    const QString path = makeStudy("stop.db", {"P01"}, protocol);
    auto studio = startStudio(path, {"--participant", "P01", "--speed", "2"});
    MainWindow &window = *studio->window();
    StudyPanel *panel = panelOf(*studio);
    StudyDocument &study = studyOf(*studio);
    QTest::mouseClick(child<QPushButton>(panel, "startStep"), Qt::LeftButton);
    QVERIFY(study.isTrialRunning());
    QVERIFY(window.engine().isDriving()); // the participant's
    QTest::keyClick(&window, Qt::Key_T, Qt::ControlModifier);
    QVERIFY(!window.engine().isDriving());
    QTRY_VERIFY_WITH_TIMEOUT(!aBandOn(window.engine()).isEmpty(), 30000);
    QTest::keyClick(&window, Qt::Key_Escape);
    QVERIFY(!window.engine().isRunning());
    QCOMPARE(aBandOn(window.engine()), QString());
    QVERIFY(study.isTrialRunning());
    const QString left = child<QLabel>(panel, "countdown")->text();
    QTest::qWait(600);
    QCOMPARE(child<QLabel>(panel, "countdown")->text(), left); // paused: the clock stands
    QCOMPARE(child<QLabel>(panel, "countdownCaption")->text(),
             QString("Paused. Practice so far · at most 01:00 · at 2× real time"));
    auto *pause = child<QPushButton>(panel, "pauseTrial");
    QCOMPARE(pause->text(), QString("Resume"));
    QTest::mouseClick(pause, Qt::LeftButton);
    QVERIFY(window.engine().isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(!aBandOn(window.engine()).isEmpty(), 30000);
    bool okWhileEmpty = true;
    answerReason("the operator was not the participant", &okWhileEmpty);
    QTest::mouseClick(child<QPushButton>(panel, "abortTrial"), Qt::LeftButton);
    QVERIFY(!study.isTrialRunning());
    QCOMPARE(aBandOn(window.engine()), QString());

    // Run again, the practice round ends at its seconds by itself.
    window.engine().setSpeed(8);
    QVERIFY(runStep(*studio));
    const StudyDatabase::Trial last = study.database()->trials("P01").back();
    QCOMPARE(last.status, Status::Done);
    QVERIFY(std::abs(last.seconds - 60.0) < 0.01);
}

// While a trial runs, what would change its run is off (scene, router, gripper, reset,
// record, open); a run changed all the same (here the engine reset under it) ends the trial
// as aborted, saying why.
void TestStudyMode::aTrialKeepsItsRun()
{
    const QString path = makeStudy("keep.db", {"P01"});
    auto studio = startStudio(path, {"--participant", "P01", "--speed", "0.5"});
    MainWindow &window = *studio->window();
    const QStringList actions{"resetAction",      "recordAction",  "openSceneAction",
                              "openRouterAction", "gripperAction", "openSessionAction",
                              "listenAction"};
    for (const QString &name : actions)
        QVERIFY2(window.findChild<QAction *>(name)->isEnabled(), qPrintable(name));
    QTest::mouseClick(child<QPushButton>(panelOf(*studio), "startStep"), Qt::LeftButton);
    QVERIFY(studyOf(*studio).isTrialRunning());
    for (const QString &name : actions)
        QVERIFY2(!window.findChild<QAction *>(name)->isEnabled(), qPrintable(name));
    QVERIFY(!window.runToolBar()->scenePicker()->isEnabled());
    QVERIFY(!window.runToolBar()->routerPicker()->isEnabled());

    QString error;
    QVERIFY(window.engine().reset(&error));
    QVERIFY(!studyOf(*studio).isTrialRunning());
    const StudyDatabase::Trial trial = studyOf(*studio).database()->trials("P01").front();
    QCOMPARE(trial.status, Status::Aborted);
    QVERIFY2(trial.reason.contains("the run was changed during the trial"),
             qPrintable(trial.reason));
    QMessageBox *box = nullptr;
    QTRY_VERIFY((box = window.findChild<QMessageBox *>()) && box->isVisible());
    QCOMPARE(box->text(), QString("Practice — No feedback (2 s) was aborted"));
    for (const QString &name : actions)
        QVERIFY2(window.findChild<QAction *>(name)->isEnabled(), qPrintable(name));
    QVERIFY(window.runToolBar()->scenePicker()->isEnabled());
}

// File → Study → Close study in a trial asks first; agreed, the trial is aborted (the study
// was closed) and the panel offers New and Open again.
void TestStudyMode::closingTheStudyAbortsItsTrial()
{
    const QString path = makeStudy("close.db", {"P01"});
    auto studio = startStudio(path, {"--participant", "P01", "--speed", "0.5"});
    MainWindow &window = *studio->window();
    QTest::mouseClick(child<QPushButton>(panelOf(*studio), "startStep"), Qt::LeftButton);
    QVERIFY(studyOf(*studio).isTrialRunning());
    const auto answer = [](QMessageBox::StandardButton button) {
        QTimer::singleShot(0, [button] {
            QTRY_VERIFY(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            QVERIFY(box->text().startsWith("Practice — No feedback (2 s) runs."));
            QTest::mouseClick(box->button(button), Qt::LeftButton);
        });
    };
    answer(QMessageBox::Cancel);
    window.findChild<QAction *>("closeStudyAction")->trigger();
    QVERIFY(studyOf(*studio).isTrialRunning());
    answer(QMessageBox::Ok);
    window.findChild<QAction *>("closeStudyAction")->trigger();
    QVERIFY(!studyOf(*studio).isOpen());
    QVERIFY(!window.engine().isRecording());
    QVERIFY(child<QLabel>(panelOf(*studio), "noStudyHint")->isVisible());
    QVERIFY(!window.findChild<QAction *>("closeStudyAction")->isEnabled());
    QString error;
    auto db = StudyDatabase::open(path, StudyDatabase::Access::Read, &error);
    QCOMPARE(db->trials("P01").front().status, Status::Aborted);
    QCOMPARE(db->trials("P01").front().reason, QString("the study was closed"));
}

// A trial's seconds bound its run only: the run it leaves goes on when Run is pressed, after
// the study is closed, reset, and in another scene (each ran 60 s at most, the trial's
// limit kept, until the studio was restarted).
void TestStudyMode::ordinaryRunsOutliveTheStudy()
{
    const QString path = makeStudy("outlive.db", {"P01"});
    auto studio = startStudio(path, {"--participant", "P01"});
    MainWindow &window = *studio->window();
    Engine &engine = window.engine();
    QVERIFY(runStep(*studio)); // the 2 s practice round
    QVERIFY(std::abs(engine.simTime() - 2.0) < 0.01);
    window.findChild<QAction *>("closeStudyAction")->trigger();
    QVERIFY(!studyOf(*studio).isOpen());
    const auto runsPast = [&](double seconds) {
        press(Qt::Key_F5);
        const bool ran = QTest::qWaitFor(
            [&] { return engine.simTime() > seconds || !engine.isRunning(); }, 30000);
        const bool past = ran && engine.simTime() > seconds && engine.isRunning();
        press(Qt::Key_F5); // pause again
        return past;
    };
    QVERIFY(runsPast(3.0));
    press(Qt::Key_R, Qt::ControlModifier);
    QVERIFY(runsPast(2.5));
    auto *scenes = window.findChild<QComboBox *>("scenePicker");
    const int other = scenes->findData("bimanual_sorting") == scenes->currentIndex()
                          ? scenes->findData("box_and_block")
                          : scenes->findData("bimanual_sorting");
    QVERIFY(other >= 0);
    scenes->setCurrentIndex(other);
    QVERIFY(runsPast(2.5));
}

// What the participant can enter is the scale: TLX in steps of 5 from 0 to 100 (keys at the
// ends stay there), Likert 1..points (a number beyond it chooses nothing), a ranking always
// each condition once; Next refuses a page not fully answered.
void TestStudyMode::theWidgetsOfferOnlyTheScale()
{
    const QString path = makeStudy("scale.db", {"P01"});
    auto studio = startStudio(path, {"--participant", "P01"});
    for (int run = 0; run < 3; ++run) {
        if (studyOf(*studio).isOnBreak())
            skipBreak(*studio);
        QVERIFY(runStep(*studio));
    }
    QuestionnaireWindow *questions = openQuestionnaire(*studio);
    QVERIFY(questions);
    auto *tlx = qobject_cast<TlxPage *>(questions->page(0));
    QVERIFY(tlx);
    QCOMPARE(tlx->value(0), -1); // not set: the middle is no answer until touched
    for (int k = 0; k < 15; ++k)
        press(Qt::Key_Right);
    QCOMPARE(tlx->value(0), 100);
    press(Qt::Key_Home);
    press(Qt::Key_Left);
    QCOMPARE(tlx->value(0), 0);
    QCOMPARE(tlx->slider(0)->maximum() * 5, 100);
    press(Qt::Key_Return); // five scales not set
    QCOMPARE(questions->currentPage(), 0);
    QCOMPARE(child<QLabel>(questions, "questionnaireProblem")->text(),
             QString("Please set each of the six scales."));
    // A press on a handle sets its scale where it is.
    for (int scale = 1; scale < 6; ++scale) {
        QSlider *slider = tlx->slider(scale);
        QStyleOptionSlider option;
        option.initFrom(slider);
        option.minimum = slider->minimum();
        option.maximum = slider->maximum();
        option.sliderPosition = slider->value();
        option.orientation = Qt::Horizontal;
        const QRect handle = slider->style()->subControlRect(QStyle::CC_Slider, &option,
                                                             QStyle::SC_SliderHandle, slider);
        QTest::mouseClick(slider, Qt::LeftButton, {}, handle.center());
        QCOMPARE(tlx->value(scale), 50);
    }
    press(Qt::Key_Return);
    QCOMPARE(questions->currentPage(), 1);

    auto *likert = qobject_cast<LikertPage *>(questions->page(1));
    QVERIFY(likert);
    QCOMPARE(likert->findChildren<QRadioButton *>().size(), 7);
    press(Qt::Key_Return); // nothing chosen
    QCOMPARE(questions->currentPage(), 1);
    QCOMPARE(child<QLabel>(questions, "questionnaireProblem")->text(),
             QString("Please choose one of the points."));
    press(Qt::Key_9); // beyond the 7 points: nothing
    QCOMPARE(likert->value(), 0);
    press(Qt::Key_Right);
    QCOMPARE(likert->value(), 1);
    press(Qt::Key_7);
    press(Qt::Key_Right);
    QCOMPARE(likert->value(), 7);
    QTest::mouseClick(likert->findChild<QRadioButton *>("point3"), Qt::LeftButton);
    QCOMPARE(likert->value(), 3);
    press(Qt::Key_Return);
    QCOMPARE(questions->currentPage(), 2);

    // Back shows what was stored as it was left; Alt+Left goes back too.
    press(Qt::Key_Backspace);
    QCOMPARE(questions->currentPage(), 1);
    QCOMPARE(likert->value(), 3);
    press(Qt::Key_Left, Qt::AltModifier);
    QCOMPARE(questions->currentPage(), 0);
    QCOMPARE(tlx->value(0), 0);
    StudyDatabase &db = *studyOf(*studio).database();
    const int condition = db.order("P01").front();
    QCOMPARE(answerOf(db, "P01", condition, "tlx.mental"), 0.0);
    QCOMPARE(answerOf(db, "P01", condition, "tlx.physical"), 50.0);
    QCOMPARE(answerOf(db, "P01", condition, likert->question().id), 3.0);

    // Closed half-way and opened again: at the first page not answered.
    questions->close();
    QTRY_VERIFY(!panelOf(*studio)->questionnaire());
    questions = openQuestionnaire(*studio);
    QCOMPARE(questions->currentPage(), 2);
    QCOMPARE(qobject_cast<LikertPage *>(questions->page(1))->value(), 3);
    questions->close();
}

// A study another studio holds is refused when opened, with the study's own words in a
// message box; the study open stays.
void TestStudyMode::aSecondStudioIsRefused()
{
    const QString path = makeStudy("held.db", {"P01"});
    QString error;
    auto holder = StudyDatabase::open(path, StudyDatabase::Access::Write, &error);
    QVERIFY2(holder, qPrintable(error));
    auto studio = startStudio();
    MainWindow &window = *studio->window();
    QStringList folders;
    answerFileDialogs({path}, &folders);
    window.findChild<QAction *>("openStudyAction")->trigger();
    QVERIFY(!studyOf(*studio).isOpen());
    QMessageBox *box = nullptr;
    QTRY_VERIFY((box = window.findChild<QMessageBox *>()) && box->isVisible());
    QCOMPARE(box->text(), QString("Could not open the study held.db"));
    QVERIFY2(box->informativeText().contains("held.db: already open in"),
             qPrintable(box->informativeText()));
    QVERIFY(box->informativeText().contains("close it there first"));
    box->close();

    // Let go by the other, it opens.
    holder.reset();
    answerFileDialogs({path}, &folders);
    window.findChild<QAction *>("openStudyAction")->trigger();
    QVERIFY(studyOf(*studio).isOpen());
    QCOMPARE(studyOf(*studio).participant(), QString("P01"));

    // The study open opened again (`--study` naming the one the workspace reopens) is
    // no second writer: it stays open, nothing to say.
    studio.reset();
    studio = startStudio(path);
    QVERIFY(studyOf(*studio).isOpen());
    QVERIFY(!studio->window()->findChild<QMessageBox *>());
}

// The window goes mid-trial without finishing it (as a crash would leave it): the next
// studio opens the study again from the workspace, the trial listed interrupted and the
// participant's next step again; it runs to its end from there.
void TestStudyMode::theStudyComesBackWhereTheWindowWent()
{
    const QString path = makeStudy("window.db", {"P01", "P02"});
    auto studio = startStudio(path, {"--participant", "P02", "--speed", "0.5"});
    StudyPanel *panel = panelOf(*studio);
    QTest::mouseClick(child<QPushButton>(panel, "startStep"), Qt::LeftButton);
    QVERIFY(studyOf(*studio).isTrialRunning());
    QTRY_VERIFY(studio->window()->engine().simTime() > 0.2);
    studio.reset();

    studio = startStudio(); // no --study: the workspace's
    panel = panelOf(*studio);
    QVERIFY(studyOf(*studio).isOpen());
    QCOMPARE(studyOf(*studio).participant(), QString("P02"));
    QCOMPARE(child<QListWidget>(panel, "participantList")->currentItem()->text(), QString("P02"));
    QCOMPARE(stepState(panel, 0, "Practice"), QString("interrupted · next"));
    auto *tree = child<QTreeWidget>(panel, "stepTree");
    QTreeWidgetItem *attempt = tree->topLevelItem(0)->child(0)->child(0);
    QCOMPARE(attempt->text(1), QString("interrupted: the study closed while it ran"));
    QVERIFY(child<QLabel>(panel, "nextStep")->text().startsWith("Next: Practice"));
    QVERIFY(runStep(*studio));
    QCOMPARE(stepState(panel, 0, "Practice"), QString("done"));
    QCOMPARE(int(studyOf(*studio).database()->trials("P02").size()), 2);
}

// `kill -9` of a studio in a trial (started with --start-step): the study opens again with
// that trial interrupted and next, and runs it.
void TestStudyMode::theStudyComesBackAfterAKill()
{
    const QString path = makeStudy("kill.db", {"P01"});
    QTemporaryDir home;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "xcb");
    env.insert("XDG_CONFIG_HOME", home.path());
    QProcess process;
    process.setProcessEnvironment(env);
    process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    process.start(SEMHAP_STUDIO_BINARY, {"--study", path, "--participant", "P01", "--start-step",
                                         "--pose-port", "0", "--speed", "0.25"});
    QVERIFY(process.waitForStarted());
    // Running, with a recording begun: then killed, with no chance to say anything.
    const auto running = [&path] {
        QString error;
        auto reader = StudyDatabase::open(path, StudyDatabase::Access::Read, &error);
        const std::vector<StudyDatabase::Trial> trials =
            reader ? reader->trials("P01") : std::vector<StudyDatabase::Trial>();
        return trials.size() == 1 && trials[0].status == Status::Running &&
               QFileInfo(QFileInfo(path).absoluteDir().filePath(trials[0].session)).size() > 0;
    };
    QTRY_VERIFY_WITH_TIMEOUT(running(), 30000);
    process.kill();
    QVERIFY(process.waitForFinished());
    QCOMPARE(process.exitStatus(), QProcess::CrashExit);

    auto studio = startStudio(path, {"--participant", "P01"});
    StudyPanel *panel = panelOf(*studio);
    QVERIFY(studyOf(*studio).isOpen()); // the dead studio's lock is taken over
    QCOMPARE(stepState(panel, 0, "Practice"), QString("interrupted · next"));
    const std::vector<StudyDatabase::Trial> trials = studyOf(*studio).database()->trials("P01");
    QCOMPARE(trials[0].status, Status::Interrupted);
    QVERIFY(runStep(*studio));
    QCOMPARE(stepState(panel, 0, "Practice"), QString("done"));
}

// Another interface language builds the window again: the trial runs on and ends as it
// would have, the panel (in German) shows it, the study stays open.
void TestStudyMode::aTrialGoesOnThroughALanguageSwitch()
{
    const QString path = makeStudy("language.db", {"P01"});
    auto studio = startStudio(path, {"--participant", "P01", "--speed", "1"});
    QTest::mouseClick(child<QPushButton>(panelOf(*studio), "startStep"), Qt::LeftButton);
    QVERIFY(studyOf(*studio).isTrialRunning());
    studio->setLanguage("de");
    StudyPanel *panel = panelOf(*studio);
    QVERIFY(studyOf(*studio).isTrialRunning());
    QCOMPARE(stepState(panel, 0, "Übung"), QString("läuft"));
    QVERIFY(!child<QPushButton>(panel, "startStep")->isEnabled());
    QVERIFY(child<QPushButton>(panel, "abortTrial")->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(!studyOf(*studio).isTrialRunning(), 20000);
    QCOMPARE(stepState(panel, 0, "Übung"), QString("erledigt"));
    QCOMPARE(studyOf(*studio).database()->trials("P01").front().status, Status::Done);
}

void TestStudyMode::pictures_data()
{
    addWindowRows();
}

// The experimenter's view mid-trial, a TLX page and a Likert page, at the sizes and in the
// languages the studio is looked at in: no text cut anywhere.
void TestStudyMode::pictures()
{
    QFETCH(QSize, size);
    QFETCH(QString, language);
    const QString path =
        makeStudy(QString("pictures-%1.db").arg(QTest::currentDataTag()), {"P01", "P02", "P03"});
    auto studio = startStudio(path, {"--participant", "P01", "--size",
                                     QString("%1x%2").arg(size.width()).arg(size.height())});
    if (language != "en")
        studio->setLanguage(language);
    QVERIFY(openWindow(*studio->window()));
    MainWindow &window = *studio->window();
    StudyPanel *panel = panelOf(*studio);
    QVERIFY(runStep(*studio));
    window.engine().setSpeed(0.25); // a trial caught half-way
    QTest::mouseClick(child<QPushButton>(panel, "startStep"), Qt::LeftButton);
    QVERIFY(studyOf(*studio).isTrialRunning());
    QTRY_VERIFY(window.engine().simTime() > 0.6);
    QVERIFY2(clippedTexts(panel).isEmpty(), qPrintable(clippedTexts(panel).join('\n')));
    savePicture(&window, "study-trial");
    savePicture(panel, "study-panel");
    // File → Study, its actions as a trial runs (Export results… on, New study… off).
    auto *studyMenu = window.findChild<QMenu *>("studyMenu");
    QVERIFY(studyMenu);
    QVERIFY(window.findChild<QAction *>("exportStudyAction")->isEnabled());
    QVERIFY(!window.findChild<QAction *>("newStudyAction")->isEnabled());
    QVERIFY(!window.findChild<QAction *>("openStudyAction")->isEnabled());
    studyMenu->popup(window.mapToGlobal(QPoint(40, 40)));
    QTRY_VERIFY(studyMenu->isVisible());
    savePicture(studyMenu, "study-menu");
    studyMenu->close();
    window.engine().setSpeed(8);
    QTRY_VERIFY_WITH_TIMEOUT(!studyOf(*studio).isTrialRunning(), 30000);
    skipBreak(*studio);
    QVERIFY(runStep(*studio));

    QuestionnaireWindow *questions = openQuestionnaire(*studio);
    QVERIFY(questions);
    questions->showNormal();
    questions->resize(size);
    QTest::qWait(50);
    press(Qt::Key_Right);
    press(Qt::Key_Right);
    QVERIFY2(clippedTexts(questions).isEmpty(), qPrintable(clippedTexts(questions).join('\n')));
    savePicture(questions, "study-tlx");
    for (int scale = 0; scale < 6; ++scale) {
        press(Qt::Key_Left);
        press(Qt::Key_Tab);
    }
    press(Qt::Key_Return);
    press(Qt::Key_5);
    QCOMPARE(questions->currentPage(), 1);
    QVERIFY2(clippedTexts(questions).isEmpty(), qPrintable(clippedTexts(questions).join('\n')));
    savePicture(questions, "study-likert");
    questions->close();

    // The final questionnaire's pages, opened ahead of their turn for the pictures.
    auto *final = new QuestionnaireWindow(studyOf(*studio), {Kind::Final, -1, 0}, panel);
    final->resize(size);
    final->show();
    QVERIFY(QTest::qWaitForWindowExposed(final));
    QVERIFY2(clippedTexts(final).isEmpty(), qPrintable(clippedTexts(final).join('\n')));
    savePicture(final, "study-ranking");
    QVERIFY(final->next());
    QVERIFY2(clippedTexts(final).isEmpty(), qPrintable(clippedTexts(final).join('\n')));
    savePicture(final, "study-notes");
    final->close();
}

QTEST_MAIN(TestStudyMode)
#include "tst_studymode.moc"
