// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonValue>
#include <QStringList>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace semhap {

/**
 * Edits one Number of a waveform (`1.5` or `{"param": "intensity", "gain": …, "offset": …}`):
 * a constant, or a live parameter through a linear mapping. Curves are shown but edited in
 * the JSON tab. Emits edited() when the user commits (Enter, an arrow step, leaving).
 */
class NumberEdit : public QWidget
{
    Q_OBJECT

public:
    explicit NumberEdit(QWidget *parent = nullptr);

    /** Shows `json`; `params` are the parameters it may bind to; `minimum` bounds constants. */
    void setNumber(const QJsonValue &json, const QStringList &params, double minimum,
                   double maximum);
    QJsonValue number() const;

signals:
    void edited(const QJsonValue &json);

private:
    void updateVisibility();
    void commit();

    QComboBox *m_source = nullptr;
    QDoubleSpinBox *m_value = nullptr;
    QDoubleSpinBox *m_gain = nullptr;
    QDoubleSpinBox *m_offset = nullptr;
    QLabel *m_curve = nullptr;
    QJsonValue m_curveJson;
    bool m_updating = false;
};

} // namespace semhap
