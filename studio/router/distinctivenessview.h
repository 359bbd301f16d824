// SPDX-License-Identifier: MIT
#pragma once

#include "distinctiveness.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;
class QTableWidget;

namespace semhap {

class Router;

/**
 * How far apart the messages of the open router feel on each band, as a heat map: a band at
 * a time, a cell per pair of messages with its distance in JND (Distinctiveness::bands),
 * confusable pairs (under 1 JND) marked and named beneath. The router editor shows the
 * router it compiled last.
 */
class DistinctivenessView : public QWidget
{
    Q_OBJECT

public:
    explicit DistinctivenessView(QWidget *parent = nullptr);

    /** Compares the messages of `router` (null: a router that does not compile). */
    void setRouter(const Router *router);
    /** The bands shown, as the model measured them. */
    const std::vector<BandDistinctiveness> &bands() const { return m_bands; }
    /** The intensity the patterns are compared at. */
    static constexpr double Intensity = 0.5;

private:
    void showBand(int index);

    QComboBox *m_band = nullptr;
    QTableWidget *m_matrix = nullptr;
    QLabel *m_summary = nullptr;
    std::vector<BandDistinctiveness> m_bands;
};

} // namespace semhap
