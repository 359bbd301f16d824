// SPDX-License-Identifier: MIT
#include "numberedit.h"

#include "waveform.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QJsonObject>
#include <QLabel>

namespace semhap {

namespace {

QDoubleSpinBox *makeSpin(const QString &name, const QString &prefix, QWidget *parent)
{
    auto *spin = new QDoubleSpinBox(parent);
    spin->setObjectName(name);
    spin->setDecimals(4);
    spin->setSingleStep(0.05);
    spin->setRange(-1e6, 1e6);
    spin->setPrefix(prefix);
    // valueChanged only on Enter, an arrow step or leaving: one undo step per edit.
    spin->setKeyboardTracking(false);
    spin->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    // The range's widest number would make the form too wide for a dock.
    spin->setMinimumWidth(
        spin->fontMetrics().horizontalAdvance(prefix + QStringLiteral("-000.0000")) + 24);
    return spin;
}

} // namespace

NumberEdit::NumberEdit(QWidget *parent) : QWidget(parent)
{
    // A constant on one row: the source and the value. A bound number puts its gain and
    // offset on a second row, so that three fields fit an inspector's width.
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_source = new QComboBox(this);
    m_source->setObjectName(QStringLiteral("source"));
    m_source->setToolTip(tr("A fixed value, or a live parameter of the pattern"));
    m_source->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_source->setMinimumContentsLength(6);
    m_value = makeSpin(QStringLiteral("value"), QString(), this);
    m_gain = makeSpin(QStringLiteral("gain"), tr("× "), this);
    m_gain->setToolTip(tr("Gain: the value is gain × parameter + offset"));
    m_offset = makeSpin(QStringLiteral("offset"), tr("+ "), this);
    m_offset->setToolTip(tr("Offset: the value is gain × parameter + offset"));
    m_curve = new QLabel(tr("through a curve (edit it in the JSON tab)"), this);
    m_curve->setWordWrap(true);
    layout->addWidget(m_source, 0, 0);
    layout->addWidget(m_value, 0, 1);
    layout->addWidget(m_gain, 1, 0);
    layout->addWidget(m_offset, 1, 1);
    layout->addWidget(m_curve, 1, 0, 1, 2);
    layout->setColumnStretch(1, 1);
    connect(m_source, &QComboBox::activated, this, [this] {
        updateVisibility();
        commit();
    });
    for (QDoubleSpinBox *spin : {m_value, m_gain, m_offset})
        connect(spin, &QDoubleSpinBox::valueChanged, this, &NumberEdit::commit);
}

void NumberEdit::setNumber(const QJsonValue &json, const QStringList &params, double minimum,
                           double maximum)
{
    m_updating = true;
    m_source->clear();
    m_source->addItem(tr("value"), QString());
    for (const QString &param : params)
        m_source->addItem(param, param);
    m_value->setRange(minimum, maximum);
    const NumberJson number = NumberJson::read(json);
    m_curveJson = number.curve;
    if (number.isBound() && m_source->findData(number.param) < 0)
        m_source->addItem(number.param, number.param);
    m_source->setCurrentIndex(number.isBound() ? m_source->findData(number.param) : 0);
    m_value->setValue(number.constant);
    m_gain->setValue(number.gain);
    m_offset->setValue(number.offset);
    updateVisibility();
    m_updating = false;
}

QJsonValue NumberEdit::number() const
{
    NumberJson number;
    number.constant = m_value->value();
    number.param = m_source->currentData().toString();
    number.gain = m_gain->value();
    number.offset = m_offset->value();
    number.curve = m_curveJson;
    return number.toJson();
}

void NumberEdit::updateVisibility()
{
    const bool bound = !m_source->currentData().toString().isEmpty();
    const bool curve = bound && !m_curveJson.isUndefined();
    m_value->setVisible(!bound);
    m_gain->setVisible(bound && !curve);
    m_offset->setVisible(bound && !curve);
    m_curve->setVisible(curve);
}

void NumberEdit::commit()
{
    if (!m_updating)
        emit edited(number());
}

} // namespace semhap
