// SPDX-License-Identifier: MIT
#pragma once

#include "liverig.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QSpinBox;

namespace semhap {

/**
 * Asks where to listen for a live rig: the UDP port and whether other machines may send.
 * Remembers the last answer; the router is the one the studio runs.
 */
class LiveRigDialog : public QDialog
{
    Q_OBJECT

public:
    explicit LiveRigDialog(const QString &router, QWidget *parent = nullptr);

    /** What the user chose, with the router given to the constructor. */
    LiveRigOptions options() const;

    QSpinBox *portEdit() const { return m_port; }
    QCheckBox *networkCheck() const { return m_network; }

private:
    void updateHint();
    void save();

    QString m_router;
    QSpinBox *m_port = nullptr;
    QCheckBox *m_network = nullptr;
    QLabel *m_hint = nullptr;
};

} // namespace semhap
