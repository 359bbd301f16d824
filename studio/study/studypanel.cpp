// SPDX-License-Identifier: MIT
#include "studypanel.h"

#include "colors.h"
#include "engine.h"
#include "metricspanel.h"
#include "questionnairewindow.h"
#include "reasondialog.h"
#include "studydocument.h"

#include <QAction>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QStackedWidget>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

using Kind = StudyProtocol::Step::Kind;
using Status = StudyDatabase::Status;

/** The countdown's pace: a tenth of a second, so no second is skipped. */
constexpr int ClockInterval = 100;

/** A trial's data role: the id of the done attempt a row stands for. */
constexpr int TrialRole = Qt::UserRole;

/** What a trial's status is called in the step list. */
QString statusWord(Status status)
{
    switch (status) {
    case Status::Running:
        return StudyPanel::tr("running");
    case Status::Done:
        return StudyPanel::tr("done");
    case Status::Aborted:
        return StudyPanel::tr("aborted");
    case Status::Invalid:
        return StudyPanel::tr("invalid");
    case Status::Interrupted:
        break;
    }
    return StudyPanel::tr("interrupted");
}

/** A step's name within its condition's group (the final questionnaire stands alone). */
QString stepName(const StudyProtocol::Step &step)
{
    switch (step.kind) {
    case Kind::Practice:
        return StudyPanel::tr("Practice");
    case Kind::Trial:
        return StudyPanel::tr("Trial %1").arg(step.trial);
    case Kind::Questionnaire:
        return StudyPanel::tr("Questionnaire");
    case Kind::Final:
        return StudyPanel::tr("Final questionnaire");
    case Kind::Done:
        break;
    }
    return QString();
}

/** Whether `trial` is an attempt at `step`. */
bool attempts(const StudyDatabase::Trial &trial, const StudyProtocol::Step &step)
{
    return trial.condition == step.condition && trial.practice == (step.kind == Kind::Practice) &&
           trial.number == step.trial && (step.kind == Kind::Practice || step.kind == Kind::Trial);
}

QLabel *boldLabel(const QString &text, double scale, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    QFont font = label->font();
    font.setBold(true);
    font.setPointSizeF(font.pointSizeF() * scale);
    label->setFont(font);
    return label;
}

} // namespace

StudyPanel::StudyPanel(StudyDocument &study, Engine &engine, QWidget *parent)
    : QWidget(parent), m_study(study), m_engine(engine)
{
    setObjectName(QStringLiteral("studyPanel"));
    m_pages = new QStackedWidget(this);
    m_noStudy = new QWidget(m_pages);
    auto *noStudy = new QVBoxLayout(m_noStudy);
    auto *hint = new QLabel(tr("No study is open. A study runs a protocol's conditions, trials "
                               "and questionnaires with each participant and keeps everything "
                               "in one file."),
                            m_noStudy);
    hint->setObjectName(QStringLiteral("noStudyHint"));
    hint->setWordWrap(true);
    noStudy->addWidget(hint);
    noStudy->addStretch(1);
    m_pages->addWidget(m_noStudy);
    m_pages->addWidget(createStudyPage());
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_pages);

    m_clockTimer.setInterval(ClockInterval);
    connect(&m_clockTimer, &QTimer::timeout, this, &StudyPanel::refreshTrial);
    connect(&m_study, &StudyDocument::studyChanged, this, [this] {
        if (m_questionnaire)
            m_questionnaire->close(); // its answers belong to the study that went
        refresh();
    });
    connect(&m_study, &StudyDocument::changed, this, &StudyPanel::refresh);
    connect(&m_study, &StudyDocument::trialChanged, this, &StudyPanel::refreshTrial);
    connect(&m_study, &StudyDocument::breakChanged, this, &StudyPanel::refreshTrial);
    // Stop all, Run and Pause in the toolbar pause and resume a trial too.
    connect(&m_engine, &Engine::runningChanged, this, &StudyPanel::refreshTrial);
    refresh();
}

StudyPanel::~StudyPanel()
{
    delete m_questionnaire;
}

QWidget *StudyPanel::createStudyPage()
{
    auto *page = new QWidget(m_pages);
    m_name = boldLabel(QString(), 1.2, page);
    m_name->setObjectName(QStringLiteral("studyName"));
    m_name->setTextFormat(Qt::PlainText);
    m_name->setWordWrap(true);
    m_file = new QLabel(page);
    m_file->setObjectName(QStringLiteral("studyFile"));
    m_file->setStyleSheet(QStringLiteral("color: %1;").arg(colors::css(colors::MutedText)));

    m_participants = new QListWidget(page);
    m_participants->setObjectName(QStringLiteral("participantList"));
    connect(m_participants, &QListWidget::currentTextChanged, this, [this](const QString &id) {
        if (!id.isEmpty())
            m_study.setParticipant(id);
    });
    m_participantEdit = new QLineEdit(page);
    m_participantEdit->setObjectName(QStringLiteral("participantId"));
    m_participantEdit->setPlaceholderText(tr("e.g. P01"));
    m_participantEdit->setToolTip(tr("A participant's ID: 1 to 32 letters, digits, _ . or -. "
                                     "No names needed."));
    connect(m_participantEdit, &QLineEdit::returnPressed, this, &StudyPanel::addParticipant);
    connect(m_participantEdit, &QLineEdit::textChanged, this,
            [this] { m_participantProblem->clear(); });
    m_add = new QPushButton(tr("Add"), page);
    m_add->setObjectName(QStringLiteral("addParticipant"));
    connect(m_add, &QPushButton::clicked, this, &StudyPanel::addParticipant);
    m_participantProblem = new QLabel(page);
    m_participantProblem->setObjectName(QStringLiteral("participantProblem"));
    m_participantProblem->setWordWrap(true);
    m_participantProblem->setStyleSheet(
        QStringLiteral("color: %1;").arg(colors::css(colors::Error)));
    auto *people = new QVBoxLayout;
    people->addWidget(new QLabel(tr("Participants"), page));
    people->addWidget(m_participants, 1);
    auto *add = new QHBoxLayout;
    add->addWidget(m_participantEdit, 1);
    add->addWidget(m_add);
    people->addLayout(add);
    people->addWidget(m_participantProblem);

    m_order = new QLabel(page);
    m_order->setObjectName(QStringLiteral("participantOrder"));
    m_order->setTextFormat(Qt::PlainText);
    m_order->setWordWrap(true);
    m_steps = new QTreeWidget(page);
    m_steps->setObjectName(QStringLiteral("stepTree"));
    m_steps->setColumnCount(2);
    m_steps->setHeaderLabels({tr("Step"), tr("State")});
    m_steps->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_steps->header()->setStretchLastSection(true);
    connect(m_steps, &QTreeWidget::currentItemChanged, this, &StudyPanel::refreshTrial);
    auto *steps = new QVBoxLayout;
    steps->addWidget(m_order);
    steps->addWidget(m_steps, 1);

    auto *record = new QHBoxLayout;
    record->addLayout(people, 1);
    record->addLayout(steps, 3);

    m_nextLabel = boldLabel(QString(), 1.1, page);
    m_nextLabel->setObjectName(QStringLiteral("nextStep"));
    m_nextLabel->setTextFormat(Qt::PlainText);
    m_nextLabel->setWordWrap(true);
    m_countdown = boldLabel(QString(), 2.6, page);
    m_countdown->setObjectName(QStringLiteral("countdown"));
    m_countdownCaption = new QLabel(page);
    m_countdownCaption->setObjectName(QStringLiteral("countdownCaption"));
    m_countdownCaption->setWordWrap(true);
    m_skipBreak = new QPushButton(tr("Skip break"), page);
    m_skipBreak->setObjectName(QStringLiteral("skipBreak"));
    connect(m_skipBreak, &QPushButton::clicked, &m_study, &StudyDocument::skipBreak);
    auto *caption = new QVBoxLayout;
    caption->addWidget(m_countdownCaption);
    caption->addWidget(m_skipBreak, 0, Qt::AlignLeft);
    caption->addStretch(1);

    m_start = new QPushButton(page);
    m_start->setObjectName(QStringLiteral("startStep"));
    connect(m_start, &QPushButton::clicked, this, &StudyPanel::start);
    m_pause = new QPushButton(page);
    m_pause->setObjectName(QStringLiteral("pauseTrial"));
    connect(m_pause, &QPushButton::clicked, this, [this] {
        if (m_engine.isRunning())
            m_study.pause();
        else
            m_study.resume();
    });
    m_abort = new QPushButton(tr("Abort…"), page);
    m_abort->setObjectName(QStringLiteral("abortTrial"));
    m_abort->setToolTip(tr("End the trial now; it does not count and is due again"));
    connect(m_abort, &QPushButton::clicked, this, &StudyPanel::abort);
    m_invalid = new QPushButton(tr("Mark invalid…"), page);
    m_invalid->setObjectName(QStringLiteral("markInvalid"));
    m_invalid->setToolTip(tr("The done trial chosen in the list does not count: it is due "
                             "again"));
    connect(m_invalid, &QPushButton::clicked, this, &StudyPanel::markInvalid);
    auto *buttons = new QGridLayout;
    buttons->addWidget(m_start, 0, 0);
    buttons->addWidget(m_pause, 0, 1);
    buttons->addWidget(m_abort, 1, 0);
    buttons->addWidget(m_invalid, 1, 1);

    auto *clock = new QHBoxLayout;
    clock->addWidget(m_countdown);
    clock->addSpacing(12);
    clock->addLayout(caption, 1);
    clock->addLayout(buttons);

    m_metrics = new MetricsPanel(m_engine.history(), page);
    m_metrics->setObjectName(QStringLiteral("studyMetrics"));

    auto *layout = new QVBoxLayout(page);
    layout->addWidget(m_name);
    layout->addWidget(m_file);
    layout->addLayout(record, 3);
    layout->addWidget(m_nextLabel);
    layout->addLayout(clock);
    layout->addWidget(m_metrics, 1);
    return page;
}

void StudyPanel::setStudyActions(QAction *newStudy, QAction *openStudy)
{
    auto *row = new QHBoxLayout;
    for (QAction *action : {newStudy, openStudy}) {
        auto *button = new QToolButton(m_noStudy);
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        row->addWidget(button);
    }
    row->addStretch(1);
    static_cast<QVBoxLayout *>(m_noStudy->layout())->insertLayout(1, row);
}

QString StudyPanel::clock(double seconds)
{
    const long whole = std::lround(std::ceil(std::max(0.0, seconds) - 1e-9));
    const QLatin1Char zero('0');
    if (whole >= 3600)
        return QStringLiteral("%1:%2:%3")
            .arg(whole / 3600)
            .arg((whole / 60) % 60, 2, 10, zero)
            .arg(whole % 60, 2, 10, zero);
    return QStringLiteral("%1:%2").arg(whole / 60, 2, 10, zero).arg(whole % 60, 2, 10, zero);
}

void StudyPanel::refresh()
{
    if (!m_study.isOpen()) {
        m_pages->setCurrentWidget(m_noStudy);
        m_clockTimer.stop();
        return;
    }
    m_pages->setCurrentIndex(1);
    m_next = m_study.nextStep(); // asked once per change, not on every tick of the clock
    m_name->setText(m_study.protocol().name);
    m_file->setText(QFileInfo(m_study.database()->path()).fileName());
    m_file->setToolTip(m_study.database()->path());
    refreshParticipants();
    refreshSteps();
    refreshTrial();
}

void StudyPanel::refreshParticipants()
{
    const QStringList ids = m_study.database()->participants();
    QSignalBlocker blocker(m_participants);
    QStringList shown;
    for (int row = 0; row < m_participants->count(); ++row)
        shown.append(m_participants->item(row)->text());
    if (shown != ids) {
        m_participants->clear();
        m_participants->addItems(ids);
    }
    const int row = int(ids.indexOf(m_study.participant()));
    m_participants->setCurrentRow(row);
}

void StudyPanel::refreshSteps()
{
    const QString participant = m_study.participant();
    const qint64 selected = selectedDoneTrial();
    QSignalBlocker blocker(m_steps);
    m_steps->clear();
    if (participant.isEmpty()) {
        m_order->setText(tr("Add a participant, or choose one."));
        return;
    }
    const StudyDatabase &db = *m_study.database();
    const StudyProtocol &protocol = m_study.protocol();
    const std::vector<int> order = db.order(participant);
    QStringList labels;
    for (int condition : order)
        labels.append(protocol.conditions[size_t(condition)].label);
    m_order->setText(tr("Order of %1: %2").arg(participant, labels.join(QStringLiteral(" → "))));
    const std::vector<StudyDatabase::Trial> trials = db.trials(participant);
    const StudyProtocol::Step next = db.nextStep(participant);
    const bool running = m_study.isTrialRunning();

    QTreeWidgetItem *group = nullptr;
    int groupCondition = -1;
    int position = 0;
    QTreeWidgetItem *current = nullptr;
    for (const StudyProtocol::Step &step : protocol.steps(order)) {
        if (step.kind != Kind::Final && (!group || step.condition != groupCondition)) {
            group = new QTreeWidgetItem(
                m_steps, {QStringLiteral("%1. %2")
                              .arg(++position)
                              .arg(protocol.conditions[size_t(step.condition)].label)});
            group->setFirstColumnSpanned(true);
            groupCondition = step.condition;
        }
        auto *row =
            step.kind == Kind::Final ? new QTreeWidgetItem(m_steps) : new QTreeWidgetItem(group);
        row->setText(0, stepName(step));
        const bool done = db.isDone(participant, step);
        QStringList state;
        int attempt = 0;
        const StudyDatabase::Trial *latest = nullptr;
        for (const StudyDatabase::Trial &trial : trials) {
            if (!attempts(trial, step))
                continue;
            latest = &trial;
            auto *child = new QTreeWidgetItem(row, {tr("Attempt %1").arg(++attempt)});
            child->setText(1, trial.reason.isEmpty()
                                  ? statusWord(trial.status)
                                  : tr("%1: %2").arg(statusWord(trial.status), trial.reason));
            child->setToolTip(0, trial.session);
            child->setToolTip(1, child->text(1));
            if (trial.status == Status::Done) {
                child->setData(0, TrialRole, trial.id);
                row->setData(0, TrialRole, trial.id);
                if (trial.id == selected)
                    current = child;
            }
        }
        if (running && step == m_study.runningStep()) {
            state.append(tr("running"));
        } else if (done) {
            state.append(step.kind == Kind::Practice || step.kind == Kind::Trial ? tr("done")
                                                                                 : tr("answered"));
            row->setForeground(1, colors::Ok);
        } else {
            if (latest)
                state.append(statusWord(latest->status));
            if (step == next)
                state.append(tr("next"));
            if (latest)
                row->setForeground(1, colors::Exception);
        }
        row->setText(1, state.join(QStringLiteral(" · ")));
        if (step == next) {
            QFont font = row->font(0);
            font.setBold(true);
            row->setFont(0, font);
            row->setFont(1, font);
        }
        if (!current && row->data(0, TrialRole).toLongLong() == selected && selected != 0)
            current = row;
    }
    m_steps->expandAll();
    if (current)
        m_steps->setCurrentItem(current);
}

void StudyPanel::refreshTrial()
{
    if (!m_study.isOpen())
        return;
    const bool running = m_study.isTrialRunning();
    const bool onBreak = m_study.isOnBreak();
    const StudyProtocol &protocol = m_study.protocol();
    const StudyProtocol::Step &next = m_next;
    const bool questionnaire = next.kind == Kind::Questionnaire || next.kind == Kind::Final;
    const bool chosen = !m_study.participant().isEmpty();
    // A clock only where one runs: a practice round counts up, a trial and a break down.
    m_countdown->setVisible(running || onBreak ||
                            (chosen && (next.kind == Kind::Practice || next.kind == Kind::Trial)));
    if (running) {
        const StudyProtocol::Step step = m_study.runningStep();
        m_nextLabel->setText(tr("Now: %1").arg(m_study.describe(step)));
        const QString paused = m_engine.isRunning() ? QString() : tr("Paused. ");
        QStringList parts;
        if (step.kind == Kind::Trial) {
            m_countdown->setText(clock(m_study.limit() - m_study.elapsed()));
            parts.append(tr("Left of the trial"));
        } else {
            m_countdown->setText(clock(m_study.elapsed()));
            parts.append(tr("Practice so far"));
            if (protocol.practiceTransfers > 0)
                parts.append(tr("%1 of %2 transfers")
                                 .arg(StudyProtocol::transfers(m_engine.history().metrics()))
                                 .arg(protocol.practiceTransfers));
            if (protocol.practiceSeconds > 0)
                parts.append(tr("at most %1").arg(clock(protocol.practiceSeconds)));
        }
        // The clock is the run's: at another speed than real time, the participant's is not.
        if (m_engine.speed() != 1.0)
            parts.append(tr("at %1× real time").arg(QLocale().toString(m_engine.speed())));
        m_countdownCaption->setText(paused + parts.join(QStringLiteral(" · ")));
    } else {
        m_nextLabel->setText(!chosen ? tr("No participant chosen")
                             : next.kind == Kind::Done
                                 ? m_study.describe(next)
                                 : tr("Next: %1").arg(m_study.describe(next)));
        if (onBreak) {
            m_countdown->setText(clock(m_study.breakLeft()));
            m_countdownCaption->setText(tr("Break before the next trial"));
        } else {
            m_countdown->setText(next.kind == Kind::Trial ? clock(protocol.trialSeconds)
                                                          : clock(0));
            m_countdownCaption->setText(
                !chosen                   ? tr("Choose a participant.")
                : next.kind == Kind::Done ? tr("This participant has done every step.")
                : questionnaire
                    ? tr("Questionnaire opens it for the participant, in a window of its own.")
                    : tr("Start when the participant is ready."));
        }
    }
    m_skipBreak->setVisible(onBreak);
    const bool asking = !m_questionnaire.isNull();
    m_start->setText(questionnaire ? tr("Questionnaire") : tr("Start"));
    m_start->setEnabled(!running && !onBreak && next.kind != Kind::Done);
    m_pause->setText(running && !m_engine.isRunning() ? tr("Resume") : tr("Pause"));
    m_pause->setEnabled(running);
    m_abort->setEnabled(running);
    m_invalid->setEnabled(!running && !asking && selectedDoneTrial() != 0);
    // The participant a trial or a questionnaire is for stays chosen until it ends.
    m_participants->setEnabled(!running && !asking);
    m_participantEdit->setEnabled(!running && !asking);
    m_add->setEnabled(!running && !asking);
    if (running || onBreak)
        m_clockTimer.start();
    else
        m_clockTimer.stop();
}

void StudyPanel::addParticipant()
{
    QString error;
    if (!m_study.addParticipant(m_participantEdit->text().trimmed(), &error)) {
        m_participantProblem->setText(error);
        return;
    }
    m_participantEdit->clear();
}

void StudyPanel::start()
{
    const StudyProtocol::Step next = m_study.nextStep();
    if (next.kind == Kind::Questionnaire || next.kind == Kind::Final) {
        if (m_questionnaire) {
            m_questionnaire->raise();
            m_questionnaire->activateWindow();
            return;
        }
        m_questionnaire = new QuestionnaireWindow(m_study, next, this);
        connect(m_questionnaire, &QObject::destroyed, this, &StudyPanel::refreshTrial);
        m_questionnaire->showBeside(window());
        refreshTrial();
        return;
    }
    QString error;
    if (!m_study.startTrial(&error))
        emit problem(tr("Could not start %1").arg(m_study.describe(next)), error);
}

void StudyPanel::abort()
{
    if (!m_study.isTrialRunning())
        return;
    // The participant stops at once; the reason is asked while nothing moves.
    m_study.pause();
    const QString what = m_study.describe(m_study.runningStep());
    const QString reason =
        ReasonDialog::ask(this, tr("Abort the trial"),
                          tr("Why is %1 aborted? It will not count and is due again.").arg(what));
    if (reason.isEmpty())
        return; // still running, paused: Resume goes on
    QString error;
    if (!m_study.abortTrial(reason, &error))
        emit problem(tr("Could not store %1 as aborted").arg(what), error);
}

void StudyPanel::markInvalid()
{
    const qint64 trial = selectedDoneTrial();
    if (trial == 0)
        return;
    const QString reason = ReasonDialog::ask(
        this, tr("Mark the trial invalid"),
        tr("Why does this trial not count? It is kept, marked invalid, and is due "
           "again."));
    if (reason.isEmpty())
        return;
    QString error;
    if (!m_study.invalidateTrial(trial, reason, &error))
        emit problem(tr("Could not mark the trial invalid"), error);
}

QuestionnaireWindow *StudyPanel::questionnaire() const
{
    return m_questionnaire;
}

qint64 StudyPanel::selectedDoneTrial() const
{
    const QTreeWidgetItem *item = m_steps ? m_steps->currentItem() : nullptr;
    return item ? item->data(0, TrialRole).toLongLong() : 0;
}

PanelDock StudyPanel::dock()
{
    return {QStringLiteral("studyDock"), tr("Study"), PanelDock::Side::Right,
            QStringLiteral("patternsDock")};
}

} // namespace semhap
