// SPDX-License-Identifier: MIT
#include "likertpage.h"

#include <QButtonGroup>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QRadioButton>
#include <QVBoxLayout>

#include <algorithm>

namespace semhap {

namespace {

/** An anchor's words, under or beside the end of the scale it names. */
QLabel *anchorLabel(const QString &text, Qt::Alignment alignment, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setTextFormat(Qt::PlainText);
    label->setWordWrap(true);
    label->setAlignment(alignment | Qt::AlignVCenter);
    label->setMaximumWidth(label->fontMetrics().averageCharWidth() * 22);
    return label;
}

} // namespace

LikertPage::LikertPage(const StudyProtocol::Question &question, int condition, QWidget *parent)
    : QuestionPage(question, condition, parent)
{
    QVBoxLayout *layout = layoutWithText(QString());
    layout->addSpacing(24);
    auto *row = new QHBoxLayout;
    row->addStretch(1);
    row->addWidget(anchorLabel(question.anchors.value(0), Qt::AlignRight, this));
    m_points = new QButtonGroup(this);
    for (int point = 1; point <= question.points; ++point) {
        auto *button = new QRadioButton(QString::number(point), this);
        button->setObjectName(QStringLiteral("point%1").arg(point));
        // The page takes the keys (numbers, arrows); the buttons take the mouse.
        button->setFocusPolicy(Qt::NoFocus);
        // A mark the size of the text beside it, to be hit from a step away.
        const int mark = button->fontMetrics().height();
        button->setStyleSheet(
            QStringLiteral("QRadioButton::indicator { width: %1px; height: %1px; }").arg(mark));
        m_points->addButton(button, point);
        row->addSpacing(button->fontMetrics().averageCharWidth() * 3);
        row->addWidget(button);
    }
    row->addSpacing(m_points->button(1)->fontMetrics().averageCharWidth() * 3);
    row->addWidget(anchorLabel(question.anchors.value(1), Qt::AlignLeft, this));
    row->addStretch(1);
    layout->addLayout(row);
    layout->addStretch(1);
    connect(m_points, &QButtonGroup::idClicked, this, &QuestionPage::edited);
    setFocusPolicy(Qt::StrongFocus);
}

int LikertPage::value() const
{
    return std::max(0, m_points->checkedId());
}

void LikertPage::choose(int point)
{
    if (point < 1 || point > question().points || point == value())
        return;
    m_points->button(point)->setChecked(true);
    emit edited();
}

void LikertPage::keyPressEvent(QKeyEvent *event)
{
    const int key = event->key();
    if (event->modifiers() & (Qt::AltModifier | Qt::ControlModifier)) {
        QuestionPage::keyPressEvent(event); // Alt+Left goes on to the window: Back
        return;
    }
    if (key >= Qt::Key_1 && key <= Qt::Key_9) {
        choose(key - Qt::Key_0);
    } else if (key == Qt::Key_0) {
        choose(10);
    } else if (key == Qt::Key_Left || key == Qt::Key_Down) {
        choose(value() == 0 ? question().points : value() - 1);
    } else if (key == Qt::Key_Right || key == Qt::Key_Up) {
        choose(value() + 1);
    } else {
        QuestionPage::keyPressEvent(event); // Return goes on to the window: Next
        return;
    }
    event->accept();
}

std::vector<StudyDatabase::Answer> LikertPage::answers() const
{
    if (!isComplete())
        return {};
    StudyDatabase::Answer a = answer(question().id);
    a.value = value();
    return {a};
}

void LikertPage::showAnswers(const std::vector<StudyDatabase::Answer> &given)
{
    const StudyDatabase::Answer *a = find(given, condition(), question().id);
    if (a && a->value >= 1 && a->value <= question().points)
        m_points->button(int(a->value))->setChecked(true);
}

} // namespace semhap
