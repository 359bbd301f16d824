// SPDX-License-Identifier: MIT
#include "rankingpage.h"

#include <QHBoxLayout>
#include <QKeyEvent>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace semhap {

RankingPage::RankingPage(const StudyProtocol &protocol, const StudyProtocol::Question &question,
                         QWidget *parent)
    : QuestionPage(question, -1, parent)
{
    QVBoxLayout *layout = layoutWithText(
        tr("Put the conditions in order: the one you liked most at the top, the one you liked "
           "least at the bottom."));
    for (const StudyProtocol::Condition &c : protocol.conditions)
        m_labels.append(c.label);
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("rankingList"));
    m_list->setDragDropMode(QAbstractItemView::InternalMove);
    m_list->setDefaultDropAction(Qt::MoveAction);
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->setSpacing(4);
    for (const QString &id : question.conditions) {
        auto *item = new QListWidgetItem(m_list);
        item->setData(Qt::UserRole, protocol.conditionIndex(id));
    }
    m_list->installEventFilter(this);
    m_up = new QPushButton(tr("Move up"), this);
    m_up->setObjectName(QStringLiteral("moveUp"));
    m_down = new QPushButton(tr("Move down"), this);
    m_down->setObjectName(QStringLiteral("moveDown"));
    connect(m_up, &QPushButton::clicked, this, [this] { move(m_list->currentRow(), -1); });
    connect(m_down, &QPushButton::clicked, this, [this] { move(m_list->currentRow(), 1); });
    auto *row = new QHBoxLayout;
    row->addWidget(m_list, 1);
    auto *buttons = new QVBoxLayout;
    buttons->addWidget(m_up);
    buttons->addWidget(m_down);
    buttons->addStretch(1);
    row->addLayout(buttons);
    layout->addLayout(row, 1);
    // A drag moves an entry within the list: it stays the same conditions, in another order.
    connect(m_list->model(), &QAbstractItemModel::rowsMoved, this, [this] {
        renumber();
        emit edited();
    });
    connect(m_list, &QListWidget::currentRowChanged, this, &RankingPage::renumber);
    m_list->setCurrentRow(0);
    renumber();
    setFocusProxy(m_list);
}

void RankingPage::renumber()
{
    for (int row = 0; row < m_list->count(); ++row) {
        QListWidgetItem *item = m_list->item(row);
        item->setText(QStringLiteral("%1.  %2").arg(row + 1).arg(
            m_labels.value(item->data(Qt::UserRole).toInt())));
    }
    const int current = m_list->currentRow();
    m_up->setEnabled(current > 0);
    m_down->setEnabled(current >= 0 && current < m_list->count() - 1);
}

void RankingPage::move(int row, int by)
{
    const int to = std::clamp(row + by, 0, m_list->count() - 1);
    if (row < 0 || row >= m_list->count() || to == row)
        return;
    QListWidgetItem *item = m_list->takeItem(row);
    m_list->insertItem(to, item);
    m_list->setCurrentRow(to);
    renumber();
    emit edited();
}

bool RankingPage::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_list && event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->modifiers() & Qt::ControlModifier &&
            (key->key() == Qt::Key_Up || key->key() == Qt::Key_Down)) {
            move(m_list->currentRow(), key->key() == Qt::Key_Up ? -1 : 1);
            return true;
        }
    }
    return QuestionPage::eventFilter(watched, event);
}

std::vector<int> RankingPage::ranking() const
{
    std::vector<int> out;
    for (int row = 0; row < m_list->count(); ++row)
        out.push_back(m_list->item(row)->data(Qt::UserRole).toInt());
    return out;
}

std::vector<StudyDatabase::Answer> RankingPage::answers() const
{
    // Each condition's rank is an answer about that condition.
    std::vector<StudyDatabase::Answer> out;
    const std::vector<int> order = ranking();
    for (size_t rank = 0; rank < order.size(); ++rank) {
        StudyDatabase::Answer a = answer(question().id);
        a.condition = order[rank];
        a.value = double(rank + 1);
        out.push_back(a);
    }
    return out;
}

void RankingPage::showAnswers(const std::vector<StudyDatabase::Answer> &given)
{
    // A ranking given before comes back in its order; one not given stays as listed.
    std::vector<std::pair<double, QListWidgetItem *>> ranked;
    while (m_list->count() > 0) {
        QListWidgetItem *item = m_list->takeItem(0);
        const StudyDatabase::Answer *a =
            find(given, item->data(Qt::UserRole).toInt(), question().id);
        ranked.emplace_back(a ? a->value : 0.0, item);
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    for (const auto &entry : ranked)
        m_list->addItem(entry.second);
    m_list->setCurrentRow(0);
    renumber();
}

} // namespace semhap
