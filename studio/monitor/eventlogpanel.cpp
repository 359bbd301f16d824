// SPDX-License-Identifier: MIT
#include "eventlogpanel.h"

#include "eventlogmodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>

namespace semhap {

/** Hides events that do not match the panel's choices (-1 means any) and text. */
class EventLogFilter : public QSortFilterProxyModel
{
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    /** Keeps rows whose `role` value `v` has bit `v` set in `accepted` (-1: every row). */
    void setChoice(int role, int accepted)
    {
        m_choices[role] = accepted;
        invalidateFilter();
    }
    void setText(const QString &text)
    {
        m_text = text.trimmed();
        invalidateFilter();
    }

protected:
    bool filterAcceptsRow(int row, const QModelIndex &parent) const override
    {
        const QAbstractItemModel *model = sourceModel();
        const QModelIndex first = model->index(row, 0, parent);
        for (auto it = m_choices.cbegin(); it != m_choices.cend(); ++it) {
            if (!((it.value() >> model->data(first, it.key()).toInt()) & 1))
                return false;
        }
        if (m_text.isEmpty())
            return true;
        for (int column = 0; column < model->columnCount(parent); ++column) {
            if (model->data(model->index(row, column, parent))
                    .toString()
                    .contains(m_text, Qt::CaseInsensitive))
                return true;
        }
        return false;
    }

private:
    QHash<int, int> m_choices;
    QString m_text;
};

namespace {

/** The filter's mask for one enum value. */
int only(int value)
{
    return 1 << value;
}

/** A combo box of "all" (mask -1) and the given choices, each with its mask as data. */
QComboBox *choiceBox(const QString &all, const QList<QPair<QString, int>> &choices,
                     QWidget *parent)
{
    auto *box = new QComboBox(parent);
    box->addItem(all, -1);
    for (const auto &[text, mask] : choices)
        box->addItem(text, mask);
    return box;
}

} // namespace

EventLogPanel::EventLogPanel(RunHistory &history, QWidget *parent)
    : QWidget(parent), m_model(new EventLogModel(history, this)),
      m_filter(new EventLogFilter(this)), m_view(new QTableView(this)),
      m_text(new QLineEdit(this)), m_follow(new QCheckBox(tr("Follow"), this))
{
    m_filter->setSourceModel(m_model);

    m_text->setObjectName(QStringLiteral("filterText"));
    m_text->setPlaceholderText(tr("Filter (detector, message, …)"));
    m_text->setClearButtonEnabled(true);
    m_follow->setObjectName(QStringLiteral("follow"));
    m_follow->setToolTip(tr("Keep the newest event in view"));
    m_follow->setChecked(true);
    m_gripper = choiceBox(
        tr("All grippers"),
        {{tr("Left"), only(int(Gripper::Left))}, {tr("Right"), only(int(Gripper::Right))}}, this);
    m_gripper->setObjectName(QStringLiteral("gripperFilter"));
    m_category = choiceBox(tr("All categories"),
                           {{tr("Confirmation"), only(int(Category::Confirmation))},
                            {tr("Exception"), only(int(Category::Exception))}},
                           this);
    m_category->setObjectName(QStringLiteral("categoryFilter"));
    m_phase = choiceBox(tr("All phases"),
                        {{tr("Begin"), only(int(EventPhase::Begin))},
                         {tr("Update"), only(int(EventPhase::Update))},
                         {tr("End"), only(int(EventPhase::End))}},
                        this);
    // First and chosen at the start: a message's begin and end, without the stream of
    // intensity updates between them that would bury them.
    m_phase->insertItem(0, tr("Begin and end"),
                        only(int(EventPhase::Begin)) | only(int(EventPhase::End)));
    m_phase->setCurrentIndex(0);
    m_phase->setObjectName(QStringLiteral("phaseFilter"));

    m_view->setObjectName(QStringLiteral("eventTable"));
    m_view->setModel(m_filter);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setAlternatingRowColors(true);
    m_view->setWordWrap(false);
    m_view->verticalHeader()->hide();
    // Fixed row heights: the view then never measures rows, which keeps appends cheap.
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    QHeaderView *header = m_view->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::Fixed);
    header->setSectionResizeMode(EventLogModel::DetectorColumn, QHeaderView::Stretch);
    // Widths from the header and a widest value, not measured rows: appends stay cheap.
    const QList<QPair<int, QString>> widest = {
        {EventLogModel::TimeColumn, QStringLiteral("000.000")},
        {EventLogModel::GripperColumn, gripperName(Gripper::Right)},
        {EventLogModel::MessageColumn, QStringLiteral("WW ") + messageName(Message::Break)},
        {EventLogModel::PhaseColumn, eventPhaseName(EventPhase::Update)},
        {EventLogModel::IntensityColumn, QStringLiteral("0.00")}};
    for (const auto &[column, sample] : widest) {
        const QString title = m_model->headerData(column, Qt::Horizontal).toString();
        header->resizeSection(column, std::max(header->fontMetrics().horizontalAdvance(title),
                                               fontMetrics().horizontalAdvance(sample)) +
                                          16);
    }
    // A router's own messages (plug.collision) are longer than grasp or break: the column
    // grows to the longest one logged, measured once per row appended, and may be dragged.
    header->setSectionResizeMode(EventLogModel::MessageColumn, QHeaderView::Interactive);
    connect(m_model, &QAbstractItemModel::rowsInserted, this,
            [this](const QModelIndex &, int first, int last) {
                QHeaderView *columns = m_view->horizontalHeader();
                int wanted = columns->sectionSize(EventLogModel::MessageColumn);
                for (int row = first; row <= last; ++row) {
                    const QString text =
                        m_model->index(row, EventLogModel::MessageColumn).data().toString();
                    wanted = std::max(
                        wanted,
                        fontMetrics().horizontalAdvance(QStringLiteral("WW ") + text) + 16);
                }
                if (wanted > columns->sectionSize(EventLogModel::MessageColumn))
                    columns->resizeSection(EventLogModel::MessageColumn, wanted);
            });

    auto *top = new QHBoxLayout;
    top->addWidget(m_text, 1);
    top->addWidget(m_follow);
    auto *choices = new QHBoxLayout;
    choices->addWidget(m_gripper);
    choices->addWidget(m_category);
    choices->addWidget(m_phase);
    choices->addStretch();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addLayout(choices);
    layout->addWidget(m_view, 1);

    connect(m_text, &QLineEdit::textChanged, m_filter, &EventLogFilter::setText);
    const QList<QPair<QComboBox *, int>> boxes = {{m_gripper, EventLogModel::GripperRole},
                                                  {m_category, EventLogModel::CategoryRole},
                                                  {m_phase, EventLogModel::PhaseRole}};
    for (const auto &[box, role] : boxes) {
        m_filter->setChoice(role, box->currentData().toInt());
        connect(box, &QComboBox::currentIndexChanged, this, [this, box = box, role = role] {
            m_filter->setChoice(role, box->currentData().toInt());
        });
    }
    connect(m_filter, &QAbstractItemModel::rowsInserted, this, &EventLogPanel::rowsAppended);
    connect(m_follow, &QCheckBox::toggled, this, &EventLogPanel::rowsAppended);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                if (!current.isValid())
                    return;
                activateRow(current);
                m_emittedRow = current.row();
            });
    // A click on the row that is already current changes nothing above, yet the user
    // asks again for its time (the cursor may have moved since).
    connect(m_view, &QAbstractItemView::clicked, this, [this](const QModelIndex &index) {
        if (index.row() != m_emittedRow)
            activateRow(index);
        m_emittedRow = -1;
    });
}

EventLogPanel::~EventLogPanel() = default;

void EventLogPanel::rowsAppended()
{
    if (m_follow->isChecked())
        m_view->scrollToBottom();
}

void EventLogPanel::activateRow(const QModelIndex &proxyIndex)
{
    emit eventActivated(proxyIndex.data(EventLogModel::TimeRole).toDouble());
}

PanelDock EventLogPanel::dock()
{
    return {QStringLiteral("eventsDock"), tr("Events"), PanelDock::Side::Bottom, QString()};
}

} // namespace semhap
