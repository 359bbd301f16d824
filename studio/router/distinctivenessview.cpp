// SPDX-License-Identifier: MIT
#include "distinctivenessview.h"

#include "colors.h"
#include "router.h"

#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace semhap {

namespace {

/** Confusable pairs are vermillion, fading to the card's ground at 3 JND and beyond. */
QColor heat(double jnd)
{
    const double share = std::clamp(jnd / 3.0, 0.0, 1.0);
    const QColor &from = colors::ErrorPale;
    const QColor &to = colors::Card;
    return QColor::fromRgbF(float(from.redF() + (to.redF() - from.redF()) * share),
                            float(from.greenF() + (to.greenF() - from.greenF()) * share),
                            float(from.blueF() + (to.blueF() - from.blueF()) * share));
}

} // namespace

DistinctivenessView::DistinctivenessView(QWidget *parent) : QWidget(parent)
{
    m_band = new QComboBox(this);
    m_band->setObjectName(QStringLiteral("distinctBand"));
    m_band->setToolTip(tr("The band whose messages are compared"));
    m_matrix = new QTableWidget(this);
    m_matrix->setObjectName(QStringLiteral("distinctMatrix"));
    m_matrix->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_matrix->setSelectionMode(QAbstractItemView::NoSelection);
    m_matrix->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_matrix->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("distinctSummary"));
    m_summary->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_band);
    layout->addWidget(m_matrix, 1);
    layout->addWidget(m_summary);
    connect(m_band, qOverload<int>(&QComboBox::currentIndexChanged), this,
            &DistinctivenessView::showBand);
    setRouter(nullptr);
}

void DistinctivenessView::setRouter(const Router *router)
{
    const QString shown = m_band->currentData().toString();
    m_bands.clear();
    QString reason;
    const bool compared = router && Distinctiveness().bands(*router, Intensity, &m_bands, &reason);
    {
        const QSignalBlocker blocker(m_band);
        m_band->clear();
        for (const BandDistinctiveness &band : m_bands)
            m_band->addItem(tr("%1 (%2): %n message(s)", nullptr, int(band.messages.size()))
                                .arg(band.device, band.model),
                            band.device);
        // The band looked at stays, as the router is edited.
        m_band->setCurrentIndex(std::max(0, m_band->findData(shown)));
    }
    m_band->setEnabled(!m_bands.empty());
    if (!router) {
        m_matrix->clear();
        m_matrix->setRowCount(0);
        m_matrix->setColumnCount(0);
        m_summary->setText(tr("The router has problems: once it compiles, this shows how far "
                              "apart its messages feel on each band."));
        return;
    }
    if (!compared) {
        m_matrix->setRowCount(0);
        m_matrix->setColumnCount(0);
        m_summary->setText(tr("Its patterns cannot be compared: %1").arg(reason));
        return;
    }
    if (m_bands.empty()) {
        m_matrix->setRowCount(0);
        m_matrix->setColumnCount(0);
        m_summary->setText(tr("No message plays on a band."));
        return;
    }
    showBand(m_band->currentIndex());
}

void DistinctivenessView::showBand(int index)
{
    if (index < 0 || size_t(index) >= m_bands.size())
        return;
    const BandDistinctiveness &band = m_bands[size_t(index)];
    const int n = int(band.messages.size());
    m_matrix->clear();
    m_matrix->setRowCount(n);
    m_matrix->setColumnCount(n);
    m_matrix->setHorizontalHeaderLabels(band.messages);
    m_matrix->setVerticalHeaderLabels(band.messages);
    QFont bold = m_matrix->font();
    bold.setBold(true);
    for (int a = 0; a < n; ++a) {
        for (int b = 0; b < n; ++b) {
            const double d = band.distance[size_t(a)][size_t(b)];
            auto *cell = new QTableWidgetItem(QLocale().toString(d, 'f', 2));
            cell->setTextAlignment(Qt::AlignCenter);
            if (a != b) {
                cell->setBackground(heat(d));
                cell->setToolTip(tr("%1 and %2: %3 JND apart")
                                     .arg(band.messages[a], band.messages[b],
                                          QLocale().toString(d, 'f', 2)));
                if (d < 1.0)
                    cell->setFont(bold);
            } else {
                cell->setForeground(colors::MutedText);
            }
            m_matrix->setItem(a, b, cell);
        }
    }
    if (n == 1) {
        m_summary->setText(tr("Only %1 plays on this band: there is nothing here to take it for.")
                               .arg(band.messages.front()));
        return;
    }
    if (band.confusable.empty()) {
        m_summary->setText(
            tr("At intensity %1 no two of these messages are closer than 1 JND: a person "
               "tells them apart.")
                .arg(QLocale().toString(Intensity)));
        return;
    }
    QStringList pairs;
    for (const BandDistinctiveness::Pair &pair : band.confusable)
        pairs.append(tr("%1 and %2 (%3 JND)")
                         .arg(band.messages[pair.a], band.messages[pair.b],
                              QLocale().toString(pair.distance, 'f', 2)));
    m_summary->setText(tr("Confusable, under 1 JND: %1. A person will take one for the other.")
                           .arg(pairs.join(QStringLiteral("; "))));
}

} // namespace semhap
