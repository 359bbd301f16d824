// SPDX-License-Identifier: MIT
#include "liverigdialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

namespace semhap {

namespace {
const QString PortKey = QStringLiteral("liveRig/port");
const QString NetworkKey = QStringLiteral("liveRig/network");
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

    auto *form = new QFormLayout;
    form->addRow(tr("UDP port:"), m_port);
    form->addRow(QString(), m_network);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Listen"));
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        save();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_port, &QSpinBox::valueChanged, this, &LiveRigDialog::updateHint);
    connect(m_network, &QCheckBox::toggled, this, &LiveRigDialog::updateHint);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_hint);
    layout->addWidget(buttons);
    updateHint();
}

LiveRigOptions LiveRigDialog::options() const
{
    LiveRigOptions options;
    options.port = m_port->value();
    if (m_network->isChecked())
        options.address = AnyAddress;
    options.router = m_router;
    return options;
}

void LiveRigDialog::updateHint()
{
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
}

} // namespace semhap
