// SPDX-License-Identifier: MIT
#include "devicespanel.h"

#include "colors.h"
#include "devicemanager.h"
#include "deviceuri.h"
#include "levelmeter.h"
#include "runhistory.h"
#include "transportscheme.h"

#include <QApplication>
#include <QBoxLayout>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace semhap {

namespace {

constexpr int PollMs = 1000;  // hot-plug: listing serial and HID devices is not free
constexpr int StatusMs = 250; // the rates and round-trip times change slowly

/** A state as a word on a colour; the word carries it for readers who miss the colour. */
struct StateLook
{
    QString text;
    QColor color;
};

StateLook stateLook(const BoundDevice *bound)
{
    switch (bound ? bound->status.state() : LinkState::NotBound) {
    case LinkState::NotBound:
        break;
    case LinkState::Disconnected:
        return {DevicesPanel::tr("disconnected"), colors::Error};
    case LinkState::Connecting:
        return {DevicesPanel::tr("connecting"), colors::Activity};
    case LinkState::Connected:
        return {DevicesPanel::tr("connected"), colors::Ok};
    }
    return {DevicesPanel::tr("not bound"), colors::Inactive};
}

QString statusDetails(const BoundDevice &bound)
{
    const TransportStatus &s = bound.status;
    QStringList parts;
    parts.append(
        DevicesPanel::tr("%1 frames/s").arg(QLocale().toString(s.framesPerSecond, 'f', 0)));
    if (s.roundTripMs >= 0.0)
        parts.append(DevicesPanel::tr("RTT %1 ms").arg(QLocale().toString(s.roundTripMs, 'f', 1)));
    if (s.latencyMs >= 0.0)
        parts.append(
            DevicesPanel::tr("latency %1 ms").arg(QLocale().toString(s.latencyMs, 'f', 1)));
    parts.append(DevicesPanel::tr("errors: %1").arg(s.errors));
    if (s.reconnects > 0)
        parts.append(DevicesPanel::tr("reconnects: %1").arg(s.reconnects));
    parts.append(s.armed ? DevicesPanel::tr("armed") : DevicesPanel::tr("disarmed"));
    QString text = parts.join(QStringLiteral(" · "));
    if (!s.connected && !s.lastError.isEmpty())
        text += QLatin1Char('\n') + DevicesPanel::tr("retrying: %1").arg(s.lastError);
    return text;
}

QString hexId(int id)
{
    return QStringLiteral("%1").arg(id, 4, 16, QLatin1Char('0'));
}

} // namespace

/** One router device's widgets and what they last showed. */
struct DevicesPanel::Row
{
    int device = 0; ///< the history's index of the device (rows list idle devices last)
    QString name;
    QString model;
    QComboBox *uri = nullptr;
    QPushButton *disconnect = nullptr;
    QLabel *state = nullptr;
    QLabel *details = nullptr;
    LevelMeter *meter = nullptr;
    QBoxLayout *layout = nullptr; ///< the controls and the meter: side by side when wide
    QString boundUri;             ///< as last read from the manager, so typing is not overwritten
};

namespace {

/** The rows' width from which a device's meter goes beside its controls, not under them. */
constexpr int SideBySideWidth = 440;

} // namespace

DevicesPanel::DevicesPanel(DeviceManager &manager, RunHistory &history, QWidget *parent)
    : QWidget(parent), m_manager(manager), m_history(history), m_present(new QTreeWidget(this)),
      m_address(new QLineEdit(this)), m_message(new QLabel(this)), m_armed(new QLabel(this)),
      m_pollTimer(new QTimer(this)), m_statusTimer(new QTimer(this)),
      m_splitter(new QSplitter(Qt::Vertical, this))
{
    // What is present.
    m_present->setObjectName(QStringLiteral("presentList"));
    m_present->setRootIsDecorated(false);
    m_present->setAlternatingRowColors(true);
    m_present->setHeaderLabels({tr("Kind"), tr("URI"), tr("Description"), tr("VID:PID")});
    m_present->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_present->header()->setStretchLastSection(true);
    m_address->setObjectName(QStringLiteral("address"));
    m_address->setPlaceholderText(tr("e.g. udp:127.0.0.1:9000"));
    QStringList syntaxes;
    for (const TransportScheme &scheme : TransportScheme::all())
        syntaxes.append(QString::fromUtf8(scheme.syntax).toHtmlEscaped());
    m_address->setToolTip(QStringLiteral("<p>%1<br><tt>%2</tt></p>")
                              .arg(tr("An address that cannot be discovered, such as a band on "
                                      "the network or a pseudo-terminal, in one of these forms:"),
                                   syntaxes.join(QStringLiteral("<br>"))));
    auto *add = new QPushButton(tr("Add"), this);
    add->setObjectName(QStringLiteral("addButton"));
    auto *rescanButton = new QPushButton(tr("Rescan"), this);
    rescanButton->setObjectName(QStringLiteral("rescanButton"));
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: %1;").arg(colors::css(colors::Error)));
    m_message->hide();
    // The address on a line of its own, the buttons under it: the box is narrow beside
    // the router's devices in a 1280 px window.
    auto *addRow = new QHBoxLayout;
    addRow->addWidget(add);
    addRow->addWidget(rescanButton);
    addRow->addStretch(1);
    auto *presentBox = new QGroupBox(tr("Present devices"));
    auto *presentLayout = new QVBoxLayout(presentBox);
    presentLayout->addWidget(m_present, 1);
    presentLayout->addWidget(m_address);
    presentLayout->addLayout(addRow);
    presentLayout->addWidget(m_message);

    // The router's devices, one group each.
    auto *rowsWidget = new QWidget;
    m_rowsLayout = new QVBoxLayout(rowsWidget);
    m_rowsLayout->setContentsMargins(0, 0, 0, 0);
    m_rowsLayout->addStretch();
    auto *scroll = new QScrollArea;
    scroll->setObjectName(QStringLiteral("rowsScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(rowsWidget);
    // A wheel notch moves one device's row (eventFilter): QScrollArea steps a twentieth of
    // the widget's height when it was set, before any row was there.
    rowsWidget->installEventFilter(this);
    scroll->viewport()->installEventFilter(this); // its width lays the rows out
    m_rowsScroll = scroll;
    auto *arm = new QPushButton(tr("Arm all"), this);
    arm->setObjectName(QStringLiteral("armAll"));
    auto *disarm = new QPushButton(tr("Disarm all"), this);
    disarm->setObjectName(QStringLiteral("disarmAll"));
    m_armed->setObjectName(QStringLiteral("armedSummary"));
    auto *armRow = new QHBoxLayout;
    armRow->addWidget(arm);
    armRow->addWidget(disarm);
    armRow->addWidget(m_armed, 1);
    auto *armNote =
        new QLabel(tr("Real bands start disarmed: they output nothing until armed."), this);
    armNote->setWordWrap(true);
    auto *routerBox = new QGroupBox(tr("Router devices"));
    auto *routerLayout = new QVBoxLayout(routerBox);
    routerLayout->addWidget(scroll, 1);
    routerLayout->addLayout(armRow);
    routerLayout->addWidget(armNote);

    m_splitter->addWidget(presentBox);
    m_splitter->addWidget(routerBox);
    m_splitter->setStretchFactor(0, 1);
    m_splitter->setStretchFactor(1, 3);
    m_splitter->setChildrenCollapsible(false);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_splitter);

    connect(add, &QPushButton::clicked, this, &DevicesPanel::addAddress);
    connect(m_address, &QLineEdit::returnPressed, this, &DevicesPanel::addAddress);
    connect(rescanButton, &QPushButton::clicked, this, &DevicesPanel::rescan);
    connect(arm, &QPushButton::clicked, this, [this] {
        m_manager.armAll(true);
        refresh();
    });
    connect(disarm, &QPushButton::clicked, this, [this] {
        m_manager.armAll(false);
        refresh();
    });
    connect(&m_history, &RunHistory::reset, this, &DevicesPanel::rebuildRows);
    connect(&m_history, &RunHistory::routerChanged, this, &DevicesPanel::rebuildRows);
    connect(&m_history, &RunHistory::updated, this, &DevicesPanel::showLevels);
    connect(m_pollTimer, &QTimer::timeout, this, [this] {
        QStringList added;
        QStringList removed;
        if (m_manager.poll(&added, &removed))
            rescan();
    });
    connect(m_statusTimer, &QTimer::timeout, this, &DevicesPanel::refresh);
    m_pollTimer->start(PollMs);
    m_statusTimer->start(StatusMs);

    rebuildRows();
}

DevicesPanel::~DevicesPanel() = default;

void DevicesPanel::showEvent(QShowEvent *event)
{
    // A quarter for the listing: the splitter would give it its (tall) size hint.
    if (!m_splitterPlaced) {
        m_splitterPlaced = true;
        const int height = m_splitter->height();
        m_splitter->setSizes({height / 4, height - height / 4});
    }
    QWidget::showEvent(event);
}

void DevicesPanel::layOutRows()
{
    const bool wide = m_rowsScroll->viewport()->width() >= SideBySideWidth;
    for (const auto &row : m_rows)
        row->layout->setDirection(wide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
}

bool DevicesPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_rowsScroll->viewport() && event->type() == QEvent::Resize)
        layOutRows();
    if (watched == m_rowsScroll->widget() && event->type() == QEvent::Resize &&
        m_rowsLayout->count() > 1) {
        // Laid out already (the layout hears of a resize first).
        const int row = m_rowsLayout->itemAt(0)->geometry().height() + m_rowsLayout->spacing();
        m_rowsScroll->verticalScrollBar()->setSingleStep(
            std::max(1, row / QApplication::wheelScrollLines()));
    }
    auto *box = qobject_cast<QComboBox *>(watched);
    if (event->type() == QEvent::Wheel && box && !box->hasFocus()) {
        QApplication::sendEvent(m_rowsScroll->verticalScrollBar(), event);
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void DevicesPanel::rescan()
{
    const std::vector<PortInfo> ports = m_manager.present();
    m_present->clear();
    m_presentUris.clear();
    for (const PortInfo &port : ports) {
        const QString ids = port.vendorId >= 0
                                ? hexId(port.vendorId) + QLatin1Char(':') + hexId(port.productId)
                                : QString();
        // A sound output: its channels and the rate the transport plays at.
        const QString description =
            port.outputChannels >= 0
                ? tr("%1 ch, %2 Hz (%3)")
                      .arg(port.outputChannels)
                      .arg(QLocale().toString(port.sampleRate, 'f', 0), port.description)
                : port.description;
        auto *item = new QTreeWidgetItem(m_present, {port.kind, port.uri, description, ids});
        item->setToolTip(1, port.uri);
        item->setToolTip(2, description);
        m_presentUris.append(port.uri);
    }
    for (auto &row : m_rows) {
        const QString typed = row->uri->currentText();
        QStringList choices = m_presentUris;
        const QString fallback = DeviceUri::virtualFor(row->name);
        if (!choices.contains(fallback))
            choices.append(fallback);
        const QSignalBlocker blocker(row->uri);
        row->uri->clear();
        row->uri->addItems(choices);
        row->uri->setEditText(typed);
    }
}

void DevicesPanel::resizeEvent(QResizeEvent *event)
{
    // Side by side in a wide dock (under the viewport), stacked in a tall one.
    const bool wide = width() > 3 * height() / 2;
    m_splitter->setOrientation(wide ? Qt::Horizontal : Qt::Vertical);
    m_splitter->setStretchFactor(0, wide ? 2 : 1);
    QWidget::resizeEvent(event);
}

void DevicesPanel::rebuildRows()
{
    for (auto &row : m_rows)
        delete row->uri->parentWidget(); // the row's group box
    m_rows.clear();
    // The devices that can play first; those of a hand the scene lacks after them.
    std::vector<const RunDevice *> devices;
    for (const RunDevice &device : m_history.devices())
        devices.push_back(&device);
    std::stable_partition(devices.begin(), devices.end(),
                          [](const RunDevice *d) { return !d->idle; });
    for (const RunDevice *entry : devices) {
        const RunDevice &device = *entry;
        auto row = std::make_unique<Row>();
        row->device = int(entry - m_history.devices().data());
        row->name = device.name;
        row->model = device.model;
        auto *box = new QGroupBox(tr("%1 — %2").arg(device.name, device.model));
        row->uri = new QComboBox(box);
        row->uri->setObjectName(QStringLiteral("uri:") + device.name);
        row->uri->setEditable(true);
        row->uri->setInsertPolicy(QComboBox::NoInsert);
        row->uri->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        row->uri->setMinimumContentsLength(12);
        // Scrolling the rows over it must not change a binding's address (eventFilter).
        row->uri->setFocusPolicy(Qt::StrongFocus);
        row->uri->installEventFilter(this);
        row->uri->setToolTip(
            tr("The URI to drive %1: pick a present device or type one").arg(device.name));
        auto *connectButton = new QPushButton(tr("Connect"), box);
        connectButton->setObjectName(QStringLiteral("connect:") + device.name);
        row->disconnect = new QPushButton(tr("Disconnect"), box);
        row->disconnect->setObjectName(QStringLiteral("disconnect:") + device.name);
        row->disconnect->setToolTip(
            tr("Fall back to the virtual device virtual:%1; the run goes on").arg(device.name));
        row->state = new QLabel(box);
        row->state->setObjectName(QStringLiteral("state:") + device.name);
        row->details = new QLabel(box);
        row->details->setObjectName(QStringLiteral("details:") + device.name);
        row->details->setWordWrap(true);
        row->meter = new LevelMeter(box);
        row->meter->setObjectName(QStringLiteral("levels:") + device.name);
        const DeviceModelPtr model = DeviceModelLibrary::builtin(device.model);
        std::vector<LevelMeter::Channel> channels;
        for (const QString &channel : device.channels) {
            const int index = model ? model->channelIndex(channel) : -1;
            if (index >= 0)
                channels.push_back({channel, model->channels()[size_t(index)].min,
                                    model->channels()[size_t(index)].max});
            else
                channels.push_back({channel, 0.0, 1.0});
        }
        row->meter->setChannels(channels);

        // The URI on a line of its own, then the buttons and the state, then the details:
        // a row fits the dock of a 1280 px window without scrolling sideways.
        auto *bindLine = new QHBoxLayout;
        bindLine->addWidget(connectButton);
        bindLine->addWidget(row->disconnect);
        bindLine->addWidget(row->state);
        bindLine->addStretch(1);
        auto *controls = new QVBoxLayout;
        if (device.idle) {
            // Inside the box, wrapped: a title does not wrap and would widen every row.
            auto *idle = new QLabel(tr("Its hand is not in this scene."), box);
            idle->setWordWrap(true);
            controls->addWidget(idle);
        }
        controls->addWidget(row->uri);
        controls->addLayout(bindLine);
        controls->addWidget(row->details);
        controls->addStretch(1);
        // In a wide dock the meter goes beside the controls: a row half as tall, so several
        // devices show at once (one did, even at 1920×1080).
        row->layout = new QBoxLayout(QBoxLayout::TopToBottom, box);
        row->layout->addLayout(controls, 1);
        row->layout->addWidget(row->meter, 1);
        m_rowsLayout->insertWidget(m_rowsLayout->count() - 1, box);

        Row *raw = row.get();
        connect(connectButton, &QPushButton::clicked, this,
                [this, raw] { requestBind(*raw, raw->uri->currentText().trimmed()); });
        connect(row->disconnect, &QPushButton::clicked, this,
                [this, raw] { requestBind(*raw, DeviceUri::virtualFor(raw->name)); });
        m_rows.push_back(std::move(row));
    }
    layOutRows();
    rescan();
    refresh();
    showLevels();
}

void DevicesPanel::addAddress()
{
    DeviceUri uri;
    QString error;
    if (!DeviceUri::parse(m_address->text().trimmed(), &uri, &error)) {
        showMessage(error);
        return;
    }
    showMessage(QString());
    m_manager.addConfigured(uri.toString());
    m_address->clear();
    rescan();
    emit addressAdded(uri.toString());
}

void DevicesPanel::requestBind(Row &row, const QString &uri)
{
    DeviceUri parsed;
    QString error;
    if (!DeviceUri::parse(uri, &parsed, &error)) {
        showMessage(tr("%1: %2").arg(row.name, error));
        return;
    }
    showMessage(QString());
    emit bindRequested(row.name, parsed.toString());
}

void DevicesPanel::showMessage(const QString &text)
{
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
}

void DevicesPanel::refresh()
{
    const std::vector<BoundDevice> bound = m_manager.status();
    int armed = 0;
    for (const BoundDevice &device : bound)
        armed += device.status.armed ? 1 : 0;
    for (auto &row : m_rows) {
        const BoundDevice *device = nullptr;
        for (const BoundDevice &candidate : bound) {
            if (candidate.name == row->name)
                device = &candidate;
        }
        const StateLook look = stateLook(device);
        row->state->setText(look.text);
        row->state->setStyleSheet(
            QStringLiteral("QLabel { background: %1; color: black; font-weight: bold;"
                           " border-radius: 3px; padding: 1px 6px; }")
                .arg(look.color.name()));
        row->details->setText(device ? statusDetails(*device) : tr("no transport"));
        const QString uri = device ? device->uri : QString();
        if (uri != row->boundUri) {
            row->boundUri = uri;
            row->uri->setEditText(uri);
        }
        row->disconnect->setEnabled(uri != DeviceUri::virtualFor(row->name));
    }
    m_armed->setText(tr("%1 of %2 armed").arg(armed).arg(bound.size()));
}

void DevicesPanel::showLevels()
{
    for (const auto &row : m_rows) {
        const RunSeries<DeviceFrame> &frames = m_history.deviceFrames(row->device);
        if (frames.isEmpty())
            continue;
        const DeviceFrame &frame = frames.last();
        row->meter->setValues(
            std::vector<double>(frame.values.begin(), frame.values.begin() + frame.channelCount));
    }
}

PanelDock DevicesPanel::dock()
{
    return {QStringLiteral("devicesDock"), tr("Devices"), PanelDock::Side::Bottom,
            QStringLiteral("eventsDock")};
}

} // namespace semhap
