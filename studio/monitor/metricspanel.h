// SPDX-License-Identifier: MIT
#pragma once

#include "paneldock.h"

#include <QJsonValue>
#include <QWidget>

class QFormLayout;
class QLabel;

namespace semhap {

class RunHistory;

/**
 * The task metrics of the running session (TaskMonitor's, docs/metrics.md) as a live form:
 * human labels for the keys the studio knows, raw keys for others, nested objects
 * flattened as `a.b`, and each value formatted for its kind (counts, rates, seconds).
 */
class MetricsPanel : public QWidget
{
    Q_OBJECT

public:
    /** Where the main window docks it by default (PanelDock). */
    static PanelDock dock();
    explicit MetricsPanel(RunHistory &history, QWidget *parent = nullptr);

    /** The label shown for a (flattened) metrics key: a translated name, or the key. */
    static QString label(const QString &key);
    /**
     * What a metric means, in one sentence, its unit and its key in exports (docs/metrics.md
     * in short); the key alone for one the studio does not know.
     */
    static QString tooltip(const QString &key);
    /** A metric's value as shown: counts as integers, rates to 2 decimals, units added. */
    static QString format(const QString &key, const QJsonValue &value);

    /** Reads the history's metrics again (connected to `metricsChanged()`). */
    void refresh();

private:
    RunHistory &m_history;
    QFormLayout *m_form = nullptr;
    QLabel *m_empty = nullptr;
    QStringList m_keys; ///< the rows shown, in order
};

} // namespace semhap
