// SPDX-License-Identifier: MIT
#include "tlxpage.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <iterator>

namespace semhap {

namespace {

/** A slider step is 5 points of the 0–100 scale: 21 marks, as on the paper form. */
constexpr int Step = 5;

/** The standard NASA-TLX rating scales (Hart & Staveland), in tlxSubscales()' order. */
struct Subscale
{
    const char *name;
    const char *question;
    const char *low;
    const char *high;
};

const Subscale Subscales[] = {
    {QT_TRANSLATE_NOOP("semhap::TlxPage", "Mental demand"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "How mentally demanding was the task?"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very low"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very high")},
    {QT_TRANSLATE_NOOP("semhap::TlxPage", "Physical demand"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "How physically demanding was the task?"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very low"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very high")},
    {QT_TRANSLATE_NOOP("semhap::TlxPage", "Temporal demand"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "How hurried or rushed was the pace of the task?"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very low"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very high")},
    {QT_TRANSLATE_NOOP("semhap::TlxPage", "Performance"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "How successful were you in accomplishing what you "
                                          "were asked to do?"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Perfect"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Failure")},
    {QT_TRANSLATE_NOOP("semhap::TlxPage", "Effort"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "How hard did you have to work to accomplish your "
                                          "level of performance?"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very low"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very high")},
    {QT_TRANSLATE_NOOP("semhap::TlxPage", "Frustration"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "How insecure, discouraged, irritated, stressed, and "
                                          "annoyed were you?"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very low"),
     QT_TRANSLATE_NOOP("semhap::TlxPage", "Very high")},
};

QString translated(const char *text)
{
    return QCoreApplication::translate("semhap::TlxPage", text);
}

} // namespace

TlxPage::TlxPage(const StudyProtocol::Question &question, int condition, QWidget *parent)
    : QuestionPage(question, condition, parent)
{
    const QStringList &measures = StudyProtocol::tlxSubscales();
    Q_ASSERT(measures.size() == int(std::size(Subscales)));
    QVBoxLayout *layout = layoutWithText(tr("How was the task you just did? Set each of the six "
                                            "scales."));
    auto *grid = new QGridLayout;
    grid->setHorizontalSpacing(12);
    grid->setVerticalSpacing(14);
    grid->setColumnStretch(0, 3);
    grid->setColumnStretch(2, 4);
    for (int i = 0; i < measures.size(); ++i) {
        const Subscale &scale = Subscales[i];
        auto *name = new QLabel(QStringLiteral("<b>%1</b><br>%2")
                                    .arg(translated(scale.name).toHtmlEscaped(),
                                         translated(scale.question).toHtmlEscaped()),
                                this);
        name->setObjectName(QStringLiteral("name:%1").arg(measures[i]));
        name->setWordWrap(true);
        auto *slider = new QSlider(Qt::Horizontal, this);
        slider->setObjectName(QStringLiteral("slider:%1").arg(measures[i]));
        slider->setRange(0, 100 / Step);
        slider->setPageStep(2);
        slider->setTickPosition(QSlider::TicksBelow);
        slider->setTickInterval(1);
        slider->setValue(50 / Step);
        slider->setAccessibleName(translated(scale.name));
        // Not set, its groove is not filled up to the handle: the middle is no answer yet.
        QPalette unset = slider->palette();
        unset.setColor(QPalette::Highlight, unset.color(QPalette::Mid));
        slider->setPalette(unset);
        auto *value = new QLabel(this);
        value->setObjectName(QStringLiteral("value:%1").arg(measures[i]));
        value->setMinimumWidth(value->fontMetrics().horizontalAdvance(QStringLiteral("100")) + 4);
        value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        auto *low = new QLabel(translated(scale.low), this);
        auto *high = new QLabel(translated(scale.high), this);
        grid->addWidget(name, i, 0);
        grid->addWidget(low, i, 1, Qt::AlignRight);
        grid->addWidget(slider, i, 2);
        grid->addWidget(high, i, 3);
        grid->addWidget(value, i, 4);
        // Any touch sets it, also one that leaves the value where it was (a press on the
        // handle in the middle, an arrow at an end).
        connect(slider, &QSlider::actionTriggered, this, [this, i] { set(i); });
        connect(slider, &QSlider::sliderPressed, this, [this, i] { set(i); });
        connect(slider, &QSlider::valueChanged, this, [this, i] {
            if (m_set[size_t(i)])
                m_values[size_t(i)]->setText(QString::number(this->value(i)));
        });
        m_sliders.push_back(slider);
        m_values.push_back(value);
        m_set.push_back(false);
    }
    layout->addLayout(grid);
    layout->addStretch(1);
    for (int i = 0; i < measures.size(); ++i)
        m_values[size_t(i)]->setText(tr("–", "a TLX scale not set yet"));
    setFocusProxy(m_sliders.front());
}

void TlxPage::set(int index)
{
    if (m_set[size_t(index)])
        return;
    showSet(index);
    emit edited();
}

void TlxPage::showSet(int index)
{
    m_set[size_t(index)] = true;
    m_sliders[size_t(index)]->setPalette(QPalette()); // filled as any slider
    // A key's action moves the value after this: the label follows valueChanged.
    m_values[size_t(index)]->setText(QString::number(value(index)));
}

int TlxPage::value(int index) const
{
    return m_set[size_t(index)] ? m_sliders[size_t(index)]->value() * Step : -1;
}

bool TlxPage::isComplete() const
{
    return std::all_of(m_set.begin(), m_set.end(), [](bool set) { return set; });
}

std::vector<StudyDatabase::Answer> TlxPage::answers() const
{
    std::vector<StudyDatabase::Answer> out;
    if (!isComplete())
        return out;
    const QStringList &measures = StudyProtocol::tlxSubscales();
    for (int i = 0; i < measures.size(); ++i) {
        StudyDatabase::Answer a = answer(measures[i]);
        a.value = value(i);
        out.push_back(a);
    }
    return out;
}

void TlxPage::showAnswers(const std::vector<StudyDatabase::Answer> &given)
{
    const QStringList &measures = StudyProtocol::tlxSubscales();
    for (int i = 0; i < measures.size(); ++i) {
        if (const StudyDatabase::Answer *a = find(given, condition(), measures[i])) {
            m_sliders[size_t(i)]->setValue(int(a->value) / Step);
            showSet(i);
        }
    }
}

} // namespace semhap
