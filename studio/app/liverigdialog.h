// SPDX-License-Identifier: MIT
#pragma once

#include "liverig.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QSpinBox;

namespace semhap {

/**
 * Asks where the live rig's frames come from: a UDP port (and whether other machines may
 * send), or a robot's Foxglove WebSocket server with the topic map of its topics.
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
    QRadioButton *udpChoice() const { return m_udp; }
    QRadioButton *robotChoice() const { return m_robot; }
    QLineEdit *robotUrlEdit() const { return m_url; }
    QLineEdit *topicsEdit() const { return m_topics; }

private:
    void updateHint();
    void save();

    QString m_router;
    QSpinBox *m_port = nullptr;
    QCheckBox *m_network = nullptr;
    QRadioButton *m_udp = nullptr;
    QRadioButton *m_robot = nullptr;
    QLineEdit *m_url = nullptr;
    QLineEdit *m_topics = nullptr;
    QLabel *m_hint = nullptr;
};

} // namespace semhap
