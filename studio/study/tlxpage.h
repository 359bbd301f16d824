// SPDX-License-Identifier: MIT
#pragma once

#include "questionpage.h"

#include <vector>

class QLabel;
class QSlider;

namespace semhap {

/**
 * The NASA-TLX page: its six subscales (the measures StudyProtocol::tlxSubscales() names),
 * each with its standard name and question, as a slider from 0 to 100 in steps of 5 between
 * its two ends. A slider counts once the participant set it (moved it, or pressed on it):
 * the page is complete when all six are.
 */
class TlxPage : public QuestionPage
{
    Q_OBJECT

public:
    TlxPage(const StudyProtocol::Question &question, int condition, QWidget *parent = nullptr);

    bool isComplete() const override;
    std::vector<StudyDatabase::Answer> answers() const override;
    void showAnswers(const std::vector<StudyDatabase::Answer> &given) override;

    /** The slider of subscale `index` (0–5, tlxSubscales()' order): its steps are 5 each. */
    QSlider *slider(int index) const { return m_sliders[size_t(index)]; }
    /** What subscale `index`'s slider says now (0–100), or -1 while it is not set. */
    int value(int index) const;

private:
    /** The participant touched scale `index`: it counts from now on. */
    void set(int index);
    /** Shows scale `index` as set, with its value. */
    void showSet(int index);

    std::vector<QSlider *> m_sliders;
    std::vector<QLabel *> m_values;
    std::vector<bool> m_set;
};

} // namespace semhap
