// SPDX-License-Identifier: MIT
#include "liverigdialog.h"

#include "filedialogs.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>

namespace semhap {

namespace {
const QString PortKey = QStringLiteral("liveRig/port");
const QString NetworkKey = QStringLiteral("liveRig/network");
const QString RobotKey = QStringLiteral("liveRig/robot");
const QString UrlKey = QStringLiteral("liveRig/foxglove");
const QString TopicsKey = QStringLiteral("liveRig/topics");
const QString AnyAddress = QStringLiteral("0.0.0.0");
} // namespace

LiveRigDialog::LiveRigDialog(const QString &router, QWidget *parent)
    : QDialog(parent), m_router(router)
{
    setWindowTitle(tr("Listen for a live rig"));
    const QSettings settings;
    m_port = new QSpinBox(this);
    m_port->setObjectName(QStringLiteral("livePort"));
    m_port->setRange(0, 65535);
    m_port->setSpecialValueText(tr("any free port"));
    m_port->setValue(settings.value(PortKey, LiveRigOptions().port).toInt());
    m_network = new QCheckBox(tr("Accept frames from other machines"), this);
    m_network->setObjectName(QStringLiteral("liveNetwork"));
    m_network->setToolTip(tr("Listen on every network (0.0.0.0) instead of this machine only"));
    m_network->setChecked(settings.value(NetworkKey, false).toBool());
    m_hint = new QLabel(this);
    m_hint->setObjectName(QStringLiteral("liveHint"));
    m_hint->setWordWrap(true);
    m_hint->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_udp = new QRadioButton(tr("Contact frames over UDP"), this);
    m_udp->setObjectName(QStringLiteral("liveUdp"));
    m_robot = new QRadioButton(tr("A robot's Foxglove server"), this);
    m_robot->setObjectName(QStringLiteral("liveRobot"));
    (settings.value(RobotKey, false).toBool() ? m_robot : m_udp)->setChecked(true);
    // foxglove_bridge's default port.
    m_url = new QLineEdit(settings.value(UrlKey, QStringLiteral("ws://localhost:8765")).toString(),
                          this);
    m_url->setObjectName(QStringLiteral("liveRobotUrl"));
    m_topics = new QLineEdit(settings.value(TopicsKey).toString(), this);
    m_topics->setObjectName(QStringLiteral("liveTopics"));
    m_topics->setPlaceholderText(tr("the semhap.topics/1 map of its topics"));
    m_topics->setMinimumWidth(320);
    auto *browse = new QPushButton(tr("Browse…"), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString map = FileDialogs::openFile(this, FileKind::TopicMap, tr("Topic map"),
                                                  tr("Topic maps (*.json);;All files (*)"));
        if (!map.isEmpty())
            m_topics->setText(map);
    });
    auto *topicsRow = new QHBoxLayout;
    topicsRow->addWidget(m_topics);
    topicsRow->addWidget(browse);

    auto *form = new QFormLayout;
    form->addRow(m_udp);
    form->addRow(tr("UDP port:"), m_port);
    form->addRow(QString(), m_network);
    form->addRow(m_robot);
    form->addRow(tr("Server:"), m_url);
    form->addRow(tr("Topic map:"), topicsRow);
    const auto enable = [this, browse] {
        const bool robot = m_robot->isChecked();
        m_port->setEnabled(!robot);
        m_network->setEnabled(!robot);
        m_url->setEnabled(robot);
        m_topics->setEnabled(robot);
        browse->setEnabled(robot);
        updateHint();
    };
    connect(m_robot, &QRadioButton::toggled, this, enable);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Listen"));
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        save();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_port, &QSpinBox::valueChanged, this, &LiveRigDialog::updateHint);
    connect(m_network, &QCheckBox::toggled, this, &LiveRigDialog::updateHint);
    connect(m_url, &QLineEdit::textChanged, this, &LiveRigDialog::updateHint);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_hint);
    layout->addWidget(buttons);
    enable();
}

LiveRigOptions LiveRigDialog::options() const
{
    LiveRigOptions options;
    options.port = m_port->value();
    if (m_network->isChecked())
        options.address = AnyAddress;
    options.router = m_router;
    if (m_robot->isChecked()) {
        options.foxglove = QUrl(m_url->text().trimmed());
        options.topics = m_topics->text().trimmed();
    }
    return options;
}

void LiveRigDialog::updateHint()
{
    if (m_robot->isChecked()) {
        m_hint->setText(
            tr("<p>The robot's topics become contact frames through the topic map, as a "
               "recording's do; they run through the detectors, the router <b>%1</b> and the "
               "devices like the simulation's. When the robot restarts, the studio connects "
               "again.</p><p>On the robot: <code>ros2 launch foxglove_bridge "
               "foxglove_bridge_launch.xml</code></p>")
                .arg(m_router.toHtmlEscaped()));
        return;
    }
    const QString port = m_port->value() == 0 ? tr("PORT") : QString::number(m_port->value());
    m_hint->setText(
        tr("<p>Send contact frames (one JSON object per datagram, or an array of them) to "
           "this port; they run through the detectors, the router <b>%1</b> and the devices "
           "like the simulation's.</p><p>To try it: <code>scripts/send-frames.py "
           "resources/traces/demo.jsonl --port %2</code></p>")
            .arg(m_router.toHtmlEscaped(), port));
}

void LiveRigDialog::save()
{
    QSettings settings;
    settings.setValue(PortKey, m_port->value());
    settings.setValue(NetworkKey, m_network->isChecked());
    settings.setValue(RobotKey, m_robot->isChecked());
    settings.setValue(UrlKey, m_url->text().trimmed());
    settings.setValue(TopicsKey, m_topics->text().trimmed());
}

} // namespace semhap
