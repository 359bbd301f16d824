// SPDX-License-Identifier: MIT
#include "waveformdesigner.h"

#include "colors.h"
#include "devicemanager.h"
#include "filedialogs.h"
#include "hapticconverter.h"
#include "hjifconverter.h"
#include "jsonreader.h"
#include "nodeinspector.h"
#include "patternauditioner.h"
#include "patterndocument.h"
#include "patternlibrary.h"
#include "patternpreview.h"
#include "transportfactory.h"
#include "undoactions.h"
#include "userpatterns.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QPainter>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

namespace semhap {

namespace {

constexpr int PointerRole = Qt::UserRole;
constexpr int PathRole = Qt::UserRole + 1; ///< library: a user file's path; empty: built-in
/** The preview shows at most this long a stretch, whatever the end time. */
constexpr double MaxPreview = 30.0;

/** A small padlock, drawn so it matches any style: built-ins are read-only. */
QIcon lockIcon()
{
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(colors::MutedText, 1.6));
    painter.drawArc(QRectF(4.5, 1.5, 7, 8), 0, 180 * 16);
    painter.drawLine(QPointF(4.5, 5.5), QPointF(4.5, 7.5));
    painter.drawLine(QPointF(11.5, 5.5), QPointF(11.5, 7.5));
    painter.setPen(Qt::NoPen);
    painter.setBrush(colors::MutedText);
    painter.drawRoundedRect(QRectF(2.5, 7, 11, 8), 1.5, 1.5);
    return QIcon(pixmap);
}

/** A number or a bound parameter, compactly: `0.5`, `intensity`, `18·intensity+2`. */
QString numberText(const QJsonValue &value)
{
    if (value.isDouble())
        return QLocale().toString(value.toDouble(), 'g', 4);
    if (value.isString())
        return value.toString();
    const NumberJson number = NumberJson::read(value);
    QString text = number.param;
    if (!number.curve.isUndefined())
        return text + QStringLiteral("→curve");
    if (number.gain != 1.0)
        text = QLocale().toString(number.gain, 'g', 4) + QStringLiteral("·") + text;
    if (number.offset != 0.0)
        text += QStringLiteral("+") + QLocale().toString(number.offset, 'g', 4);
    return text;
}

/** `ramp  to 1, time 0.5`: a waveform's type and its own values, for the tree. */
QString waveformSummary(const QJsonObject &node)
{
    QStringList values;
    for (auto it = node.begin(); it != node.end(); ++it) {
        const QString &key = it.key();
        if (key == QLatin1String("type") || key == QLatin1String("of") ||
            key == QLatin1String("in"))
            continue;
        if (key == QLatin1String("points"))
            values.append(
                WaveformDesigner::tr("%n point(s)", nullptr, int(it.value().toArray().size())));
        else
            values.append(QStringLiteral("%1 %2").arg(key, numberText(it.value())));
    }
    const QString type = node.value(QLatin1String("type")).toString();
    return values.isEmpty()
               ? type
               : QStringLiteral("%1  %2").arg(type, values.join(QStringLiteral(", ")));
}

} // namespace

WaveformDesigner::WaveformDesigner(DeviceManager *devices, PatternDocument *document,
                                   QWidget *parent)
    : QWidget(parent), m_devices(devices), m_userFolder(StudioFolders::patterns()),
      m_document(document ? document : new PatternDocument(this))
{
    setObjectName(QStringLiteral("waveformDesigner"));
    m_auditioner = new PatternAuditioner(this);
    m_preview = new PatternPreview(this);
    m_inspector = new NodeInspector(*m_document, this);
    m_inspector->setObjectName(QStringLiteral("inspector"));

    createActions();
    // The rarer file commands in a menu, as in the router editor: Save, Duplicate, Undo and
    // Redo stay in sight in the dock of a 1280 px window, in German too.
    auto *fileMenu = new QMenu(this);
    fileMenu->setObjectName(QStringLiteral("patternMenu"));
    for (const char *name :
         {"newPattern", "openPattern", "saveAsPattern", "", "importPattern", "exportPattern"}) {
        if (*name)
            fileMenu->addAction(findChild<QAction *>(QLatin1String(name)));
        else
            fileMenu->addSeparator();
    }
    auto *fileAction = new QAction(tr("Pattern"), this);
    fileAction->setObjectName(QStringLiteral("patternMenuAction"));
    fileAction->setToolTip(tr("New, open, save as, import and export"));
    fileAction->setMenu(fileMenu);
    auto *toolBar = new QToolBar(this);
    toolBar->setObjectName(QStringLiteral("designerToolBar"));
    toolBar->setIconSize(QSize(16, 16));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    toolBar->addAction(fileAction);
    if (auto *button = qobject_cast<QToolButton *>(toolBar->widgetForAction(fileAction)))
        button->setPopupMode(QToolButton::InstantPopup);
    toolBar->addSeparator();
    toolBar->addActions({m_saveAction, m_duplicateAction});
    toolBar->addSeparator();
    toolBar->addActions({m_undoAction, m_redoAction});

    m_banner = new QLabel(this);
    m_banner->setObjectName(QStringLiteral("banner"));
    m_banner->setWordWrap(true);
    m_banner->setStyleSheet(
        QStringLiteral("QLabel { background: %1; border: 1px solid %2; padding: 4px; }")
            .arg(colors::css(colors::ConfirmationWash), colors::css(colors::Confirmation)));

    auto *top = new QSplitter(Qt::Horizontal, this);
    top->addWidget(createLibrary());
    top->addWidget(createEditor());
    top->setStretchFactor(0, 0);
    top->setStretchFactor(1, 1);
    top->setSizes({130, 520});

    auto *bottom = new QWidget(this);
    auto *bottomLayout = new QVBoxLayout(bottom);
    bottomLayout->setContentsMargins(0, 0, 0, 0);
    bottomLayout->addWidget(createControls());
    bottomLayout->addWidget(m_preview, 1);

    auto *split = new QSplitter(Qt::Vertical, this);
    split->setObjectName(QStringLiteral("designerSplit"));
    split->addWidget(top);
    split->addWidget(bottom);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    split->setChildrenCollapsible(false);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addWidget(toolBar);
    layout->addWidget(m_banner);
    layout->addWidget(split, 1);

    connect(m_document, &PatternDocument::changed, this, &WaveformDesigner::onDocumentChanged);
    connect(m_document, &PatternDocument::stateChanged, this, &WaveformDesigner::onStateChanged);
    connect(m_auditioner, &PatternAuditioner::playingChanged, this, [this](bool playing) {
        m_endButton->setEnabled(playing);
        m_stopButton->setEnabled(playing);
        if (!playing)
            m_auditionStatus->setText(tr("Stopped"));
    });
    auto *statusTimer = new QTimer(this);
    connect(statusTimer, &QTimer::timeout, this, [this] {
        if (!m_auditioner->isPlaying())
            return;
        Transport *transport = auditionTransport();
        const QString where = m_devicePicker->currentText();
        QString text = m_auditioner->isActive() ? tr("Playing on %1").arg(where)
                                                : tr("Releasing on %1").arg(where);
        if (transport && !transport->isArmed())
            text += tr(" — disarmed: arm it in the Devices panel to feel it");
        m_auditionStatus->setText(text);
    });
    statusTimer->start(250);

    refreshLibrary();
    refreshDevices();
    if (m_document->json().isEmpty()) {
        openBuiltin(QStringLiteral("air.squeeze")); // the canonical confirmation
    } else {
        onDocumentChanged();
        onStateChanged();
    }
}

WaveformDesigner::~WaveformDesigner()
{
    m_auditioner->stop();
}

void WaveformDesigner::createActions()
{
    const auto action = [this](const QString &text, const QString &name,
                               const QKeySequence &shortcut, void (WaveformDesigner::*slot)()) {
        auto *a = new QAction(text, this);
        a->setObjectName(name);
        if (!shortcut.isEmpty()) {
            a->setShortcut(shortcut);
            a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
            a->setToolTip(
                QStringLiteral("%1 (%2)").arg(text.chopped(text.endsWith(QChar(0x2026))),
                                              shortcut.toString(QKeySequence::NativeText)));
        }
        if (slot)
            connect(a, &QAction::triggered, this, slot);
        addAction(a);
        return a;
    };
    action(tr("New"), QStringLiteral("newPattern"), QKeySequence::New,
           &WaveformDesigner::newPattern);
    // No Ctrl+O: the main window opens scenes with it, and a shared shortcut fires neither.
    action(tr("Open…"), QStringLiteral("openPattern"), {}, nullptr)
        ->setToolTip(tr("Open a pattern, an AHAP, a .haptic or an HJIF file"));
    connect(findChild<QAction *>(QStringLiteral("openPattern")), &QAction::triggered, this,
            [this] {
                const QString path = FileDialogs::openFile(
                    this, FileKind::Pattern, tr("Open pattern"),
                    tr("Patterns and haptic files (*.json *.ahap *.haptic *.hjif)"));
                QString error;
                if (!path.isEmpty() && !openFile(path, &error))
                    reportError(tr("Could not open %1").arg(path), error);
            });
    m_saveAction = action(tr("Save"), QStringLiteral("savePattern"), QKeySequence::Save,
                          &WaveformDesigner::save);
    action(tr("Save as…"), QStringLiteral("saveAsPattern"), QKeySequence::SaveAs,
           &WaveformDesigner::saveAs);
    m_duplicateAction = action(tr("Duplicate"), QStringLiteral("duplicatePattern"), {},
                               &WaveformDesigner::duplicate);
    m_duplicateAction->setToolTip(tr("Make an editable copy of this pattern"));
    action(tr("Import…"), QStringLiteral("importPattern"), {}, &WaveformDesigner::importFile)
        ->setToolTip(tr("Import an Apple AHAP or a Meta .haptic file as a new pattern"));
    action(tr("Export…"), QStringLiteral("exportPattern"), {}, &WaveformDesigner::exportFile)
        ->setToolTip(tr("Export the pattern as AHAP or .haptic (docs/convert.md)"));
    m_undoAction = UndoActions::undo(m_document->undoStack(), this);
    m_undoAction->setObjectName(QStringLiteral("undo"));
    m_redoAction = UndoActions::redo(m_document->undoStack(), this);
    m_redoAction->setObjectName(QStringLiteral("redo"));
}

QWidget *WaveformDesigner::createLibrary()
{
    auto *box = new QWidget(this);
    auto *layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(tr("Library"), box));
    m_library = new QListWidget(box);
    m_library->setObjectName(QStringLiteral("library"));
    // A long name keeps both ends (the copies of one pattern differ at the end).
    m_library->setTextElideMode(Qt::ElideMiddle);
    m_library->setToolTip(
        tr("Built-in patterns (locked) and your own, from %1").arg(m_userFolder));
    connect(m_library, &QListWidget::itemActivated, this, &WaveformDesigner::openLibraryItem);
    connect(m_library, &QListWidget::itemClicked, this, &WaveformDesigner::openLibraryItem);
    layout->addWidget(m_library, 1);
    return box;
}

QWidget *WaveformDesigner::createEditor()
{
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("editorTabs"));

    auto *treePage = new QSplitter(Qt::Horizontal, m_tabs);
    auto *treeBox = new QWidget(treePage);
    auto *treeLayout = new QVBoxLayout(treeBox);
    treeLayout->setContentsMargins(0, 0, 0, 0);
    m_tree = new QTreeWidget(treeBox);
    m_tree->setObjectName(QStringLiteral("signalTree"));
    m_tree->setHeaderHidden(true);
    m_tree->setColumnCount(1);
    // Rows read whole (a stage's times and levels were elided at 1280 px): the column is
    // as wide as its longest row and the tree scrolls sideways when the pane is narrower.
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem *item) {
        if (!item)
            return;
        m_inspector->setTarget(item->data(0, PointerRole).toString());
        updateStructureButtons();
    });
    treeLayout->addWidget(m_tree, 1);
    auto *buttons = new QGridLayout;
    const auto button = [treeBox](const QString &text, const QString &name, const QString &tip) {
        auto *b = new QPushButton(text, treeBox);
        b->setObjectName(name);
        b->setToolTip(tip);
        return b;
    };
    m_addTrack = button(tr("Add track"), QStringLiteral("addTrack"),
                        tr("A new track, driving every channel"));
    m_addPart = button(tr("Add part"), QStringLiteral("addPart"),
                       tr("Give the selected track an attack, a sustain or a release"));
    auto *parts = new QMenu(m_addPart);
    parts->addAction(tr("Attack"), this, [this] { addPart(QStringLiteral("attack")); });
    parts->addAction(tr("Sustain"), this, [this] { addPart(QStringLiteral("sustain")); });
    parts->addAction(tr("Release"), this, [this] { addPart(QStringLiteral("release")); });
    m_addPart->setMenu(parts);
    m_addInput = button(tr("Add input"), QStringLiteral("addInput"),
                        tr("Another input of the selected sum, product or sequence"));
    m_remove = button(tr("Remove"), QStringLiteral("removeNode"), tr("Remove the selected node"));
    connect(m_addTrack, &QPushButton::clicked, this, &WaveformDesigner::addTrack);
    connect(m_addInput, &QPushButton::clicked, this, &WaveformDesigner::addInput);
    connect(m_remove, &QPushButton::clicked, this, &WaveformDesigner::removeNode);
    buttons->addWidget(m_addTrack, 0, 0);
    buttons->addWidget(m_addPart, 0, 1);
    buttons->addWidget(m_addInput, 1, 0);
    buttons->addWidget(m_remove, 1, 1);
    treeLayout->addLayout(buttons);

    auto *scroll = new QScrollArea(treePage);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_inspector);
    treePage->addWidget(treeBox);
    treePage->addWidget(scroll);
    treePage->setStretchFactor(0, 2);
    treePage->setStretchFactor(1, 3);
    treePage->setSizes({200, 300});
    treePage->setChildrenCollapsible(false);
    scroll->setMinimumWidth(280);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // At least what its buttons need in the longest language, so none is cut.
    treeBox->setMinimumWidth(std::max(180, treeBox->minimumSizeHint().width()));
    m_tabs->addTab(treePage, tr("Waveform tree"));

    auto *jsonPage = new QWidget(m_tabs);
    auto *jsonLayout = new QVBoxLayout(jsonPage);
    jsonLayout->setContentsMargins(0, 0, 0, 0);
    m_jsonText = new QPlainTextEdit(jsonPage);
    m_jsonText->setObjectName(QStringLiteral("jsonText"));
    m_jsonText->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_jsonText->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_jsonError = new QLabel(jsonPage);
    m_jsonError->setObjectName(QStringLiteral("jsonError"));
    m_jsonError->setWordWrap(true);
    m_jsonError->setTextInteractionFlags(Qt::TextSelectableByMouse);
    jsonLayout->addWidget(m_jsonText, 1);
    jsonLayout->addWidget(m_jsonError);
    auto *debounce = new QTimer(this);
    debounce->setSingleShot(true);
    debounce->setInterval(300);
    connect(debounce, &QTimer::timeout, this, &WaveformDesigner::applyJsonText);
    connect(m_jsonText, &QPlainTextEdit::textChanged, this, [this, debounce] {
        if (!m_updatingText)
            debounce->start();
    });
    m_tabs->addTab(jsonPage, tr("JSON"));
    return m_tabs;
}

QWidget *WaveformDesigner::createControls()
{
    auto *box = new QWidget(this);
    auto *grid = new QGridLayout(box);
    grid->setContentsMargins(2, 2, 2, 2);

    m_modelPicker = new QComboBox(box);
    m_modelPicker->setObjectName(QStringLiteral("modelPicker"));
    m_modelPicker->addItems(DeviceModelLibrary::builtinNames());
    m_modelPicker->setToolTip(tr("The device model the pattern is for; the preview predicts "
                                 "its output"));
    connect(m_modelPicker, &QComboBox::activated, this, [this] {
        m_document->setValue(QStringLiteral("/model"), m_modelPicker->currentText());
    });
    m_intensity = new QSlider(Qt::Horizontal, box);
    m_intensity->setObjectName(QStringLiteral("intensity"));
    m_intensity->setRange(0, 100);
    m_intensity->setValue(100);
    m_intensity->setToolTip(tr("The intensity the pattern begins with (preview and audition)"));
    m_intensityLabel = new QLabel(box);
    m_intensityLabel->setMinimumWidth(
        QFontMetrics(font()).horizontalAdvance(QStringLiteral("0.00 ")));
    connect(m_intensity, &QSlider::valueChanged, this, [this](int value) {
        m_auditioner->setIntensity(value / 100.0);
        updatePreview();
    });
    m_endAt = new QDoubleSpinBox(box);
    m_endAt->setObjectName(QStringLiteral("endAt"));
    m_endAt->setRange(0.0, MaxPreview);
    m_endAt->setDecimals(2);
    m_endAt->setSingleStep(0.1);
    m_endAt->setValue(1.5);
    m_endAt->setSuffix(tr(" s"));
    m_endAt->setKeyboardTracking(false);
    m_endAt->setToolTip(tr("When the preview and the audition end the pattern (its release "
                           "starts)"));
    connect(m_endAt, &QDoubleSpinBox::valueChanged, this, &WaveformDesigner::updatePreview);
    m_hold = new QCheckBox(tr("Hold"), box);
    m_hold->setObjectName(QStringLiteral("hold"));
    m_hold->setToolTip(tr("Preview and audition without an end: the sustain goes on"));
    connect(m_hold, &QCheckBox::toggled, this, [this](bool hold) {
        m_endAt->setEnabled(!hold);
        updatePreview();
    });

    grid->addWidget(new QLabel(tr("Model"), box), 0, 0);
    grid->addWidget(m_modelPicker, 0, 1);
    grid->addWidget(new QLabel(tr("Intensity"), box), 0, 2);
    grid->addWidget(m_intensity, 0, 3);
    grid->addWidget(m_intensityLabel, 0, 4);
    grid->addWidget(new QLabel(tr("End at"), box), 0, 5);
    grid->addWidget(m_endAt, 0, 6);
    grid->addWidget(m_hold, 0, 7);

    m_devicePicker = new QComboBox(box);
    m_devicePicker->setObjectName(QStringLiteral("auditionDevice"));
    m_devicePicker->setToolTip(tr("Where the audition plays: a bound device of the run (the run "
                                  "pauses), or a virtual one"));
    m_devicePicker->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_devicePicker->setMinimumContentsLength(12);
    connect(m_devicePicker, &QComboBox::activated, this,
            [this] { m_auditionDevice = m_devicePicker->currentData().toString(); });
    m_beginButton = new QPushButton(tr("Audition"), box);
    m_beginButton->setObjectName(QStringLiteral("auditionBegin"));
    m_beginButton->setToolTip(tr("Begin the pattern on the device now (again: restart it)"));
    m_beginButton->setStyleSheet(QStringLiteral("QPushButton { color: %1; font-weight: bold; }")
                                     .arg(colors::css(colors::Confirmation)));
    m_endButton = new QPushButton(tr("End"), box);
    m_endButton->setObjectName(QStringLiteral("auditionEnd"));
    m_endButton->setToolTip(tr("End the pattern: its release plays"));
    m_stopButton = new QPushButton(tr("Stop"), box);
    m_stopButton->setObjectName(QStringLiteral("auditionStop"));
    m_stopButton->setToolTip(tr("Send the device to zero now (Esc stops everything)"));
    m_stopButton->setStyleSheet(
        QStringLiteral("QPushButton { background: %1; color: white; font-weight: bold; "
                       "border-radius: 3px; padding: 3px 10px; }"
                       "QPushButton:disabled { background: %2; }")
            .arg(colors::css(colors::Error), colors::css(colors::ErrorPale)));
    m_endButton->setEnabled(false);
    m_stopButton->setEnabled(false);
    connect(m_beginButton, &QPushButton::clicked, this, &WaveformDesigner::beginAudition);
    connect(m_endButton, &QPushButton::clicked, this, &WaveformDesigner::endAudition);
    connect(m_stopButton, &QPushButton::clicked, this, &WaveformDesigner::stopAudition);
    m_auditionStatus = new QLabel(tr("Stopped"), box);
    m_auditionStatus->setObjectName(QStringLiteral("auditionStatus"));
    m_auditionStatus->setWordWrap(true);

    auto *audition = new QHBoxLayout;
    audition->addWidget(new QLabel(tr("Audition on"), box));
    audition->addWidget(m_devicePicker, 1);
    audition->addWidget(m_beginButton);
    audition->addWidget(m_endButton);
    audition->addWidget(m_stopButton);
    grid->addLayout(audition, 1, 0, 1, 8);
    grid->addWidget(m_auditionStatus, 2, 0, 1, 8);
    grid->setColumnStretch(3, 1);
    return box;
}

void WaveformDesigner::setUserFolder(const QString &folder)
{
    m_userFolder = folder;
    refreshLibrary();
}

void WaveformDesigner::refreshLibrary()
{
    m_library->clear();
    for (const QString &name : PatternLibrary::builtinNames()) {
        auto *item = new QListWidgetItem(lockIcon(), name, m_library);
        item->setToolTip(tr("Built-in, read-only: duplicate it to edit"));
    }
    for (const UserPattern &pattern : userPatterns(m_userFolder)) {
        auto *item = new QListWidgetItem(pattern.name, m_library);
        item->setData(PathRole, pattern.path);
        item->setToolTip(pattern.path);
    }
    if (!m_document->path().isEmpty() && !QFileInfo::exists(m_document->path())) {
        // Marked as editors mark unsaved work, so the name keeps the narrow library's width
        // ("air.squeeze.copy (noch nicht gespeichert)" was cut after "(noch").
        auto *item = new QListWidgetItem(
            QStringLiteral("%1 *").arg(QFileInfo(m_document->path()).completeBaseName()),
            m_library);
        item->setToolTip(tr("Not saved yet: %1").arg(m_document->path()));
        item->setData(PathRole, m_document->path());
        QFont italic = item->font();
        italic.setItalic(true);
        item->setFont(italic);
    }
    // Mark the open pattern.
    for (int i = 0; i < m_library->count(); ++i) {
        QListWidgetItem *item = m_library->item(i);
        const QString path = item->data(PathRole).toString();
        const bool open =
            path.isEmpty()
                ? m_document->isReadOnly() &&
                      item->text() == m_document->json().value(QLatin1String("name")).toString()
                : QFileInfo(path) == QFileInfo(m_document->path());
        if (open)
            m_library->setCurrentItem(item);
    }
}

void WaveformDesigner::refreshDevices()
{
    m_devicePicker->clear();
    m_devicePicker->addItem(tr("virtual (audition only)"), QString());
    if (m_devices) {
        for (const BoundDevice &device : m_devices->status())
            m_devicePicker->addItem(QStringLiteral("%1 — %2").arg(device.name, device.model),
                                    device.name);
    }
    m_devicePicker->setCurrentIndex(std::max(0, m_devicePicker->findData(m_auditionDevice)));
}

void WaveformDesigner::setAuditionDevice(const QString &name)
{
    m_auditionDevice = name;
    m_devicePicker->setCurrentIndex(std::max(0, m_devicePicker->findData(name)));
}

WaveformDesigner::PlaySettings WaveformDesigner::playSettings() const
{
    return {m_intensity->value() / 100.0, m_endAt->value(), m_hold->isChecked()};
}

void WaveformDesigner::setPlaySettings(const PlaySettings &settings)
{
    m_intensity->setValue(int(std::lround(settings.intensity * 100.0)));
    m_endAt->setValue(settings.endAt);
    m_hold->setChecked(settings.hold);
}

void WaveformDesigner::openLibraryItem()
{
    QListWidgetItem *item = m_library->currentItem();
    if (!item)
        return;
    const QString path = item->data(PathRole).toString();
    if (path.isEmpty()) {
        if (!(m_document->isReadOnly() &&
              m_document->json().value(QLatin1String("name")).toString() == item->text()))
            openBuiltin(item->text());
        return;
    }
    if (QFileInfo(path) == QFileInfo(m_document->path()))
        return;
    QString error;
    if (!openFile(path, &error))
        reportError(tr("Could not open %1").arg(path), error);
}

void WaveformDesigner::openBuiltin(const QString &name)
{
    const PatternPtr pattern = PatternLibrary::builtin(name);
    if (!pattern)
        return;
    stopAudition();
    m_document->reset(pattern->toJson(), QString(), true);
    selectNode(QString());
    refreshLibrary();
}

bool WaveformDesigner::openFile(const QString &path, QString *error)
{
    HapticFileFormat format;
    LoadError loadError;
    QStringList warnings;
    QJsonObject json;
    ConvertOptions options;
    if (!HapticConverter::formatOf(path, &format, &loadError)) {
        *error = loadError.toString();
        return false;
    }
    // The file's envelope as it is; its sharpness is kept with the pattern. An HJIF file
    // names its own device.
    const DeviceModelPtr model = previewModel();
    if (model && format != HapticFileFormat::Hjif)
        options.model = model->name();
    const bool read =
        format == HapticFileFormat::Hjif
            ? HjifConverter::readPattern(path, options, &json, &warnings, &loadError)
            : HapticConverter::readPattern(path, options, &json, &warnings, &loadError);
    if (!read) {
        *error = loadError.toString();
        return false;
    }
    stopAudition();
    // An import is a new pattern: it is saved into the user folder, not over the source.
    const bool imported = format != HapticFileFormat::Semhap;
    m_document->reset(json, imported ? QString() : path, false);
    if (imported)
        m_document->setPath(
            QDir(m_userFolder)
                .filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".json")));
    selectNode(QString());
    refreshLibrary();
    if (!warnings.isEmpty())
        emit message(warnings.join(QStringLiteral("; ")));
    return true;
}

bool WaveformDesigner::saveFile(const QString &path, QString *error)
{
    HapticFileFormat format;
    LoadError loadError;
    if (!HapticConverter::formatOf(path, &format, &loadError)) {
        *error = loadError.toString();
        return false;
    }
    if (format == HapticFileFormat::Semhap) {
        if (!m_document->pattern()) {
            *error = m_document->error().toString();
            return false;
        }
        // In the user folder a pattern's file is named after it (the library and the router
        // editor list it so): saved there under another file name, the pattern takes it.
        const QFileInfo file(path);
        const QString name = m_document->json().value(QLatin1String("name")).toString();
        if (file.absoluteDir() == QDir(m_userFolder) && file.completeBaseName() != name) {
            const QString problem =
                userPatternNameProblem(m_userFolder, file.completeBaseName(), path);
            if (!problem.isEmpty()) {
                *error = problem;
                return false;
            }
            m_document->setValue(QStringLiteral("/name"), file.completeBaseName());
        }
        if (!m_document->save(path, error))
            return false;
        refreshLibrary();
        return true;
    }
    ConvertOptions options;
    if (!m_hold->isChecked())
        options.releaseAt = m_endAt->value();
    QStringList warnings;
    const bool written =
        format == HapticFileFormat::Hjif
            ? HjifConverter::writePattern(m_document->json(), path, options, &warnings, &loadError)
            : HapticConverter::writePattern(m_document->json(), path, options, &warnings,
                                            &loadError);
    if (!written) {
        *error = loadError.toString();
        return false;
    }
    emit message(warnings.isEmpty() ? tr("Exported %1").arg(path)
                                    : warnings.join(QStringLiteral("; ")));
    return true;
}

void WaveformDesigner::duplicate()
{
    QJsonObject json = m_document->json();
    const QString base = json.value(QLatin1String("name")).toString();
    QString name = base + QStringLiteral(".copy");
    for (int n = 2; QFileInfo::exists(QDir(m_userFolder).filePath(name + QStringLiteral(".json")));
         ++n)
        name = QStringLiteral("%1.copy%2").arg(base).arg(n);
    json.insert(QStringLiteral("name"), name);
    stopAudition();
    m_document->reset(json, QDir(m_userFolder).filePath(name + QStringLiteral(".json")), false);
    // Unsaved until the first save; the undo stack starts dirty so Save is offered.
    m_document->undoStack()->resetClean();
    selectNode(QString());
    refreshLibrary();
}

void WaveformDesigner::newPattern()
{
    const DeviceModelPtr model = previewModel();
    QString name = QStringLiteral("my.pattern");
    for (int n = 2; QFileInfo::exists(QDir(m_userFolder).filePath(name + QStringLiteral(".json")));
         ++n)
        name = QStringLiteral("my.pattern%1").arg(n);
    const QJsonObject json =
        PatternDocument::newPattern(name, model ? model->name() : QStringLiteral("lra4"));
    stopAudition();
    m_document->reset(json, QDir(m_userFolder).filePath(name + QStringLiteral(".json")), false);
    m_document->undoStack()->resetClean();
    selectNode(QString());
    refreshLibrary();
}

void WaveformDesigner::save()
{
    if (m_document->isReadOnly() || m_document->path().isEmpty()) {
        saveAs();
        return;
    }
    if (QFileInfo(m_document->path()).dir() == QDir(m_userFolder)) {
        saveUserPattern();
        return;
    }
    QString error;
    if (!saveFile(m_document->path(), &error))
        reportError(tr("Could not save"), error);
    else
        emit message(tr("Saved %1").arg(m_document->path()));
}

bool WaveformDesigner::saveUserPattern()
{
    // In the user folder a pattern's file is named after it, so the library and the router
    // editor list it by name: editing the name moves the file.
    const QString from = m_document->path();
    const QString name = m_document->json().value(QLatin1String("name")).toString();
    const QString to = userPatternPath(m_userFolder, name);
    const bool renamed = QDir::cleanPath(QFileInfo(from).absoluteFilePath()) != to;
    if (renamed) {
        const QString problem = userPatternNameProblem(m_userFolder, name, from);
        if (!problem.isEmpty()) {
            reportError(
                tr("Could not save %1 as %2").arg(QFileInfo(from).completeBaseName(), name),
                problem);
            return false;
        }
    }
    // The new file is written whole (through a temporary) before the old one goes.
    QString error;
    if (!saveFile(to, &error)) {
        reportError(tr("Could not save"), error);
        return false;
    }
    if (!renamed || !QFileInfo::exists(from)) {
        emit message(tr("Saved %1").arg(to));
        return true;
    }
    QFile old(from);
    if (!old.remove()) {
        reportError(tr("Saved %1, but could not remove %2").arg(to, from), old.errorString());
        refreshLibrary();
        return false;
    }
    refreshLibrary();
    emit message(tr("Renamed %1 to %2").arg(QFileInfo(from).completeBaseName(), name));
    emit patternRenamed(from, to);
    return true;
}

void WaveformDesigner::saveAs()
{
    const QString name = m_document->json().value(QLatin1String("name")).toString();
    const QString path =
        FileDialogs::saveFile(this, FileKind::Pattern, tr("Save pattern"),
                              userPatternPath(m_userFolder, name), tr("Patterns (*.json)"));
    QString error;
    if (!path.isEmpty() && !saveFile(path, &error))
        reportError(tr("Could not save %1").arg(path), error);
}

void WaveformDesigner::importFile()
{
    const QString path =
        FileDialogs::openFile(this, FileKind::HapticFile, tr("Import haptic file"),
                              tr("Haptic files (*.ahap *.haptic *.hjif)"));
    QString error;
    if (!path.isEmpty() && !openFile(path, &error))
        reportError(tr("Could not import %1").arg(path), error);
}

void WaveformDesigner::exportFile()
{
    const QString name = m_document->json().value(QLatin1String("name")).toString();
    const QString path = FileDialogs::saveFile(this, FileKind::HapticFile, tr("Export pattern"),
                                               name + QStringLiteral(".ahap"),
                                               tr("Apple AHAP (*.ahap);;Meta Haptics (*.haptic);;"
                                                  "MPEG haptics (*.hjif)"));
    QString error;
    if (!path.isEmpty() && !saveFile(path, &error))
        reportError(tr("Could not export %1").arg(path), error);
}

void WaveformDesigner::reportError(const QString &what, const QString &error)
{
    m_auditionStatus->setText(QStringLiteral("%1: %2").arg(what, error));
    emit message(QStringLiteral("%1: %2").arg(what, error));
}

void WaveformDesigner::onDocumentChanged()
{
    rebuildTree();
    updateJsonText();
    updatePreview();
    const QString model = m_document->json().value(QLatin1String("model")).toString();
    if (m_modelPicker->findText(model) >= 0)
        m_modelPicker->setCurrentText(model);
}

void WaveformDesigner::onStateChanged()
{
    const bool readOnly = m_document->isReadOnly();
    m_banner->setVisible(readOnly || m_document->isModified() || !m_document->path().isEmpty());
    if (readOnly)
        m_banner->setText(tr("<b>%1</b> is built in and read-only. <b>Duplicate</b> it to edit "
                             "a copy.")
                              .arg(m_document->json().value(QLatin1String("name")).toString()));
    else
        m_banner->setText(tr("%1%2").arg(
            m_document->path().isEmpty() ? tr("New pattern")
                                         : QDir::toNativeSeparators(m_document->path()),
            m_document->isModified() ? tr(" — not saved") : QString()));
    m_jsonText->setReadOnly(readOnly);
    m_modelPicker->setEnabled(!readOnly);
    m_saveAction->setEnabled(!readOnly);
    for (QPushButton *b : {m_addTrack, m_addPart, m_addInput, m_remove})
        b->setEnabled(!readOnly);
    updateStructureButtons();
}

void WaveformDesigner::rebuildTree()
{
    const QString selected =
        m_tree->currentItem() ? m_tree->currentItem()->data(0, PointerRole).toString() : QString();
    const QSignalBlocker blocker(m_tree);
    m_tree->clear();
    const QJsonObject &json = m_document->json();
    auto *root =
        new QTreeWidgetItem(m_tree, {tr("Pattern %1 (%2)")
                                         .arg(json.value(QLatin1String("name")).toString(),
                                              json.value(QLatin1String("model")).toString())});
    root->setData(0, PointerRole, QString());
    const QJsonArray tracks = json.value(QLatin1String("tracks")).toArray();
    for (int i = 0; i < tracks.size(); ++i) {
        const QJsonObject track = tracks.at(i).toObject();
        QStringList channels;
        for (const QJsonValue &c : track.value(QLatin1String("channels")).toArray())
            channels.append(c.toString());
        const QString pointer = QStringLiteral("/tracks/%1").arg(i);
        auto *item = new QTreeWidgetItem(
            root, {tr("Track %1: %2").arg(i + 1).arg(channels.join(QStringLiteral(", ")))});
        item->setData(0, PointerRole, pointer);
        const std::pair<QString, QString> parts[] = {{QStringLiteral("attack"), tr("Attack")},
                                                     {QStringLiteral("sustain"), tr("Sustain")},
                                                     {QStringLiteral("release"), tr("Release")}};
        for (const auto &[key, label] : parts) {
            if (track.contains(key))
                addTreeNode(item, label, pointer + QLatin1Char('/') + key, track.value(key));
        }
    }
    m_tree->expandAll();
    m_tree->blockSignals(false);
    selectNode(selected);
}

void WaveformDesigner::addTreeNode(QTreeWidgetItem *parent, const QString &label,
                                   const QString &pointer, const QJsonValue &node)
{
    const QJsonObject object = node.toObject();
    auto *item = new QTreeWidgetItem(
        parent, {QStringLiteral("%1: %2").arg(label, waveformSummary(object))});
    item->setData(0, PointerRole, pointer);
    item->setToolTip(0, QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact)));
    const QJsonArray children = object.value(QLatin1String("of")).toArray();
    for (int i = 0; i < children.size(); ++i)
        addTreeNode(item, QString::number(i + 1), pointer + QStringLiteral("/of/%1").arg(i),
                    children.at(i));
    if (object.contains(QLatin1String("in")))
        addTreeNode(item, tr("in"), pointer + QStringLiteral("/in"),
                    object.value(QLatin1String("in")));
}

void WaveformDesigner::selectNode(const QString &pointer)
{
    QTreeWidgetItem *found = m_tree->topLevelItem(0);
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        if ((*it)->data(0, PointerRole).toString() == pointer)
            found = *it;
    }
    if (found) {
        m_tree->setCurrentItem(found);
        m_inspector->setTarget(found->data(0, PointerRole).toString());
    }
    updateStructureButtons();
}

/** What the selected node allows: inputs for list combinators, parts for tracks. */
void WaveformDesigner::updateStructureButtons()
{
    if (m_document->isReadOnly())
        return;
    const QString pointer = m_inspector->target();
    m_addInput->setEnabled(m_document->canAddInput(pointer));
    m_addPart->setEnabled(m_document->canAddPart(pointer));
    m_remove->setEnabled(m_document->canRemove(pointer));
}

void WaveformDesigner::addTrack()
{
    selectNode(m_document->addTrack());
}

void WaveformDesigner::addPart(const QString &part)
{
    const QString pointer = m_document->addPart(m_inspector->target(), part);
    if (!pointer.isEmpty())
        selectNode(pointer);
}

void WaveformDesigner::addInput()
{
    selectNode(m_document->addInput(m_inspector->target()));
}

void WaveformDesigner::removeNode()
{
    const QString pointer = m_inspector->target();
    if (!pointer.isEmpty())
        selectNode(m_document->remove(pointer));
}

void WaveformDesigner::updateJsonText()
{
    QJsonObject shown;
    LoadError ignored;
    if (parseJsonObject(m_jsonText->toPlainText().toUtf8(), QString(), &shown, &ignored) &&
        shown == m_document->json()) {
        m_jsonError->clear();
        return; // the text already says this: keep the user's cursor and layout
    }
    m_updatingText = true;
    m_jsonText->setPlainText(
        QString::fromUtf8(QJsonDocument(m_document->json()).toJson(QJsonDocument::Indented)));
    m_updatingText = false;
    m_jsonError->setText(m_document->pattern() ? QString() : m_document->error().toString());
}

void WaveformDesigner::applyJsonText()
{
    const QString file = m_document->json().value(QLatin1String("name")).toString();
    QJsonObject json;
    LoadError error;
    if (!parseJsonObject(m_jsonText->toPlainText().toUtf8(), file, &json, &error) ||
        !Pattern::fromJson(json, file, &error)) {
        m_jsonError->setText(
            QStringLiteral("<span style='color:%1'>%2</span>")
                .arg(colors::css(colors::Error), error.toString().toHtmlEscaped()));
        return;
    }
    m_jsonError->setText(QStringLiteral("<span style='color:%1'>%2</span>")
                             .arg(colors::css(colors::Ok), tr("Valid pattern")));
    m_document->setJson(json, tr("Edit JSON"));
}

DeviceModelPtr WaveformDesigner::previewModel() const
{
    return DeviceModelLibrary::builtin(
        m_document->json().value(QLatin1String("model")).toString());
}

void WaveformDesigner::updatePreview()
{
    const double intensity = m_intensity->value() / 100.0;
    m_intensityLabel->setText(QLocale().toString(intensity, 'f', 2));
    const PatternPtr &pattern = m_document->pattern();
    if (!pattern) {
        m_preview->showMessage(m_document->error().toString());
        return;
    }
    const DeviceModelPtr model = previewModel();
    if (!model) {
        m_preview->showMessage(tr("Unknown device model '%1' (built-in: %2)")
                                   .arg(pattern->model(), DeviceModelLibrary::builtinNames().join(
                                                              QStringLiteral(", "))));
        return;
    }
    RenderOptions options;
    options.intensity = intensity;
    const double *params = pattern->params().defaults().data();
    double release = 0.0;
    for (const PatternTrack &track : pattern->tracks()) {
        if (track.release)
            release = std::max(release, track.release->duration(params));
    }
    if (m_hold->isChecked()) {
        options.duration = m_endAt->value() + 1.0;
    } else {
        options.releaseAt = m_endAt->value();
        options.duration = std::min(MaxPreview, m_endAt->value() + release + 0.5);
    }
    m_preview->showPattern(pattern, model, options);
}

Transport *WaveformDesigner::auditionTransport()
{
    const QString name = m_devicePicker->currentData().toString();
    if (!name.isEmpty())
        return m_devices ? m_devices->transport(name) : nullptr;
    return m_virtual.get();
}

void WaveformDesigner::beginAudition()
{
    const QString name = m_devicePicker->currentData().toString();
    const PatternPtr pattern = m_document->pattern();
    if (!pattern) {
        reportError(tr("Cannot audition"), m_document->error().toString());
        return;
    }
    if (name.isEmpty()) {
        // The virtual device follows the pattern's model, armed: nothing real moves.
        const DeviceModelPtr model = previewModel();
        if (!model) {
            reportError(tr("Cannot audition"),
                        tr("unknown device model %1").arg(pattern->model()));
            return;
        }
        if (!m_virtual || m_virtual->model().name() != model->name()) {
            m_auditioner->stop();
            QString error;
            m_virtual =
                TransportFactory::create(QStringLiteral("virtual:audition"), model, &error);
            if (!m_virtual || !m_virtual->open(&error)) {
                reportError(tr("Cannot audition"), error);
                return;
            }
            m_virtual->setArmed(true);
        }
    } else {
        emit auditionStarting();
    }
    // Read once the run has paused: the audition is drawn on from where the run stopped.
    const double startTime = !name.isEmpty() && m_runClock ? m_runClock() : 0.0;
    QString reason;
    const bool started = m_auditioner->begin(
        pattern,
        [this, name]() -> std::shared_ptr<Transport> {
            return name.isEmpty() ? m_virtual
                                  : (m_devices ? m_devices->sharedTransport(name) : nullptr);
        },
        m_intensity->value() / 100.0, m_hold->isChecked() ? -1.0 : m_endAt->value(), startTime,
        &reason);
    if (!started)
        reportError(tr("Cannot audition on %1").arg(m_devicePicker->currentText()), reason);
    else
        m_auditionStatus->setText(tr("Playing on %1").arg(m_devicePicker->currentText()));
}

void WaveformDesigner::endAudition()
{
    m_auditioner->end();
}

void WaveformDesigner::stopAudition()
{
    m_auditioner->stop();
}

PanelDock WaveformDesigner::dock()
{
    return {QStringLiteral("patternsDock"), tr("Patterns"), PanelDock::Side::Right,
            QStringLiteral("routerDock")};
}

} // namespace semhap
