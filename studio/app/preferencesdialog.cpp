// SPDX-License-Identifier: MIT
#include "preferencesdialog.h"

#include "handdrive.h"
#include "studiofolders.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHash>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTabWidget>

namespace semhap {

namespace {
const QString LanguageKey = QStringLiteral("interface/language");
const QString FoxgloveKey = QStringLiteral("foxglove/publish");
const QString FoxglovePortKey = QStringLiteral("foxglove/port");
} // namespace

PreferencesDialog::PreferencesDialog(QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    auto *tabs = new QTabWidget(this);
    tabs->setObjectName(QStringLiteral("preferencesTabs"));
    tabs->addTab(createGeneralPage(), tr("General"));
    tabs->addTab(createDrivingPage(), tr("Driving"));

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        save();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(tabs);
    layout->addWidget(buttons);
}

QWidget *PreferencesDialog::createGeneralPage()
{
    auto *page = new QWidget(this);
    m_language = new QComboBox(page);
    m_language->setObjectName(QStringLiteral("languagePicker"));
    m_language->addItem(tr("System language"), QString());
    // Each language in its own name, so a user can find theirs whatever is showing.
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_initial = savedLanguage();
    m_language->setCurrentIndex(std::max(0, m_language->findData(m_initial)));

    m_sessionsFolder = new QLineEdit(QDir::toNativeSeparators(StudioFolders::sessions()), page);
    m_sessionsFolder->setObjectName(QStringLiteral("sessionsFolder"));
    m_sessionsFolder->setPlaceholderText(
        QDir::toNativeSeparators(StudioFolders::defaultSessions()));
    m_sessionsFolder->setMinimumWidth(320);
    auto *browse = new QPushButton(tr("Browse…"), page);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Where recordings go"),
                                                                 m_sessionsFolder->text());
        if (!folder.isEmpty())
            m_sessionsFolder->setText(QDir::toNativeSeparators(folder));
    });
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_sessionsFolder);
    folderRow->addWidget(browse);

    // Off by default: a server is a door into the computer, opened only when asked.
    m_foxglove = new QCheckBox(tr("Publish to Foxglove on port"), page);
    m_foxglove->setObjectName(QStringLiteral("publishToFoxglove"));
    m_foxglove->setChecked(publishesToFoxglove());
    m_foxglovePort = new QSpinBox(page);
    m_foxglovePort->setObjectName(QStringLiteral("foxglovePort"));
    m_foxglovePort->setRange(1, 65535);
    m_foxglovePort->setValue(foxglovePort());
    m_foxglovePort->setEnabled(m_foxglove->isChecked());
    connect(m_foxglove, &QCheckBox::toggled, m_foxglovePort, &QWidget::setEnabled);
    auto *foxgloveRow = new QHBoxLayout;
    foxgloveRow->addWidget(m_foxglove);
    foxgloveRow->addWidget(m_foxglovePort);
    foxgloveRow->addStretch();

    auto *form = new QFormLayout;
    form->addRow(tr("Interface language:"), m_language);
    form->addRow(tr("Sessions folder:"), folderRow);
    form->addRow(tr("Viewers:"), foxgloveRow);
    auto *note = new QLabel(tr("A new language rebuilds the window where it is, with its "
                               "layout; the run, a recording, the devices and your edits go "
                               "on. Recordings go to the sessions folder from the next one on. "
                               "Foxglove on this computer watches the run live at "
                               "ws://localhost:PORT (Open connection → Foxglove WebSocket)."),
                            page);
    note->setWordWrap(true);
    auto *layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addStretch();
    return page;
}

namespace {

/** A control's name as a person reads it on the pad ("Left stick ↑" for "-lefty"). */
QString controlLabel(const QString &name)
{
    if (name.isEmpty())
        return PreferencesDialog::tr("(none)");
    if (name.contains(QLatin1Char('+'))) {
        const QStringList pair = name.split(QLatin1Char('+'));
        return controlLabel(pair[0]) + QStringLiteral(" / ") + controlLabel(pair[1]);
    }
    static const QHash<QString, const char *> labels{
        {QStringLiteral("leftx"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left stick →")},
        {QStringLiteral("-leftx"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left stick ←")},
        {QStringLiteral("lefty"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left stick ↓")},
        {QStringLiteral("-lefty"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left stick ↑")},
        {QStringLiteral("rightx"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right stick →")},
        {QStringLiteral("-rightx"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right stick ←")},
        {QStringLiteral("righty"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right stick ↓")},
        {QStringLiteral("-righty"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right stick ↑")},
        {QStringLiteral("lefttrigger"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left trigger")},
        {QStringLiteral("-lefttrigger"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left trigger, reversed")},
        {QStringLiteral("righttrigger"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right trigger")},
        {QStringLiteral("-righttrigger"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right trigger, reversed")},
        {QStringLiteral("back"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Back")},
        {QStringLiteral("guide"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Guide")},
        {QStringLiteral("start"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Start")},
        {QStringLiteral("leftstick"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left stick press")},
        {QStringLiteral("rightstick"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right stick press")},
        {QStringLiteral("leftshoulder"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Left shoulder")},
        {QStringLiteral("rightshoulder"),
         QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "Right shoulder")},
        {QStringLiteral("dpup"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "D-pad ↑")},
        {QStringLiteral("dpdown"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "D-pad ↓")},
        {QStringLiteral("dpleft"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "D-pad ←")},
        {QStringLiteral("dpright"), QT_TRANSLATE_NOOP("semhap::PreferencesDialog", "D-pad →")},
    };
    const auto found = labels.find(name);
    // Face buttons are printed on the pad: A, B, X, Y.
    return found == labels.end() ? name.toUpper() : PreferencesDialog::tr(found.value());
}

QDoubleSpinBox *percentBox(double fraction, double maximum, QWidget *parent)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(0.0, maximum * 100);
    box->setDecimals(0);
    box->setSuffix(QStringLiteral(" %"));
    box->setValue(fraction * 100);
    return box;
}

} // namespace

QWidget *PreferencesDialog::createDrivingPage()
{
    auto *page = new QWidget(this);
    const TeleopSettings settings = TeleopSettings::load();

    m_speed = new QDoubleSpinBox(page);
    m_speed->setObjectName(QStringLiteral("driveSpeed"));
    m_speed->setRange(HandDrive::MinSpeed * 100, HandDrive::MaxSpeed * 100);
    m_speed->setDecimals(0);
    m_speed->setSuffix(tr(" cm/s"));
    m_speed->setValue(settings.speed * 100);
    m_speed->setToolTip(tr("How fast the wrist moves with a key held or a stick pushed all the "
                           "way; Shift moves at a quarter of it"));

    m_gamepad = new QCheckBox(tr("Drive with a gamepad"), page);
    m_gamepad->setObjectName(QStringLiteral("useGamepad"));
    m_gamepad->setChecked(settings.gamepad);
    m_gamepadDeadZone = percentBox(settings.gamepadMapping.deadZone, 0.9, page);
    m_gamepadDeadZone->setObjectName(QStringLiteral("gamepadDeadZone"));
    m_gamepadDeadZone->setToolTip(tr("How far a stick may rest off-centre without moving the "
                                     "wrist"));

    static const char *const motionNames[GamepadMapping::MotionCount] = {
        QT_TR_NOOP("Away / toward:"), QT_TR_NOOP("Right / left:"), QT_TR_NOOP("Up / down:"),
        QT_TR_NOOP("Turn:"),          QT_TR_NOOP("Tilt:"),         QT_TR_NOOP("Roll:"),
        QT_TR_NOOP("Grip:")};
    static const char *const actionNames[GamepadMapping::ActionCount] = {
        QT_TR_NOOP("Close / open:"),          QT_TR_NOOP("Switch hand:"),
        QT_TR_NOOP("Grip force +5 N:"),       QT_TR_NOOP("Grip force −5 N:"),
        QT_TR_NOOP("Hand back (Drive off):"), QT_TR_NOOP("Next camera view:")};
    auto *motions = new QFormLayout;
    for (int m = 0; m < GamepadMapping::MotionCount; ++m) {
        auto *combo = new QComboBox(page);
        combo->setObjectName(QStringLiteral("gamepad.") +
                             GamepadMapping::motionKey(GamepadMapping::Motion(m)));
        for (const QString &choice : GamepadMapping::motionChoices())
            combo->addItem(controlLabel(choice), choice);
        m_motions[size_t(m)] = combo;
        motions->addRow(tr(motionNames[m]), combo);
    }
    auto *actions = new QFormLayout;
    for (int a = 0; a < GamepadMapping::ActionCount; ++a) {
        auto *combo = new QComboBox(page);
        combo->setObjectName(QStringLiteral("gamepad.") +
                             GamepadMapping::actionKey(GamepadMapping::Action(a)));
        for (const QString &choice : GamepadMapping::buttonChoices())
            combo->addItem(controlLabel(choice), choice);
        m_actions[size_t(a)] = combo;
        actions->addRow(tr(actionNames[a]), combo);
    }
    actions->addRow(tr("Stick dead zone:"), m_gamepadDeadZone);
    showMapping(settings.gamepadMapping);
    auto *defaults = new QPushButton(tr("Default mapping"), page);
    defaults->setObjectName(QStringLiteral("gamepadDefaults"));
    connect(defaults, &QPushButton::clicked, this,
            [this] { showMapping(GamepadMapping::defaults()); });

    auto *gamepadBox = new QGroupBox(tr("Gamepad"), page);
    auto *columns = new QHBoxLayout;
    columns->addLayout(motions);
    columns->addSpacing(16);
    columns->addLayout(actions);
    auto *gamepadLayout = new QVBoxLayout(gamepadBox);
    gamepadLayout->addWidget(m_gamepad);
    gamepadLayout->addLayout(columns);
    gamepadLayout->addWidget(defaults, 0, Qt::AlignLeft);

    m_spaceMouse = new QCheckBox(tr("Drive with a 3D mouse (through spacenavd)"), page);
    m_spaceMouse->setObjectName(QStringLiteral("useSpaceMouse"));
    m_spaceMouse->setChecked(settings.spaceMouse);
    m_spaceMouseDeadZone = percentBox(settings.spaceMouseDeadZone, 0.5, page);
    m_spaceMouseDeadZone->setObjectName(QStringLiteral("spaceMouseDeadZone"));
    auto *spaceMouseBox = new QGroupBox(tr("3D mouse"), page);
    auto *spaceMouseLayout = new QFormLayout(spaceMouseBox);
    spaceMouseLayout->addRow(m_spaceMouse);
    spaceMouseLayout->addRow(tr("Dead zone:"), m_spaceMouseDeadZone);

    auto *speedRow = new QFormLayout;
    speedRow->addRow(tr("Wrist speed:"), m_speed);
    auto *layout = new QVBoxLayout(page);
    layout->addLayout(speedRow);
    layout->addWidget(gamepadBox);
    layout->addWidget(spaceMouseBox);
    layout->addStretch();
    return page;
}

void PreferencesDialog::showMapping(const GamepadMapping &mapping)
{
    for (size_t m = 0; m < m_motions.size(); ++m)
        m_motions[m]->setCurrentIndex(std::max(0, m_motions[m]->findData(mapping.motions[m])));
    for (size_t a = 0; a < m_actions.size(); ++a)
        m_actions[a]->setCurrentIndex(std::max(0, m_actions[a]->findData(mapping.actions[a])));
    m_gamepadDeadZone->setValue(mapping.deadZone * 100);
}

TeleopSettings PreferencesDialog::teleopSettings() const
{
    TeleopSettings settings;
    settings.speed = m_speed->value() / 100;
    settings.gamepad = m_gamepad->isChecked();
    for (size_t m = 0; m < m_motions.size(); ++m)
        settings.gamepadMapping.motions[m] = m_motions[m]->currentData().toString();
    for (size_t a = 0; a < m_actions.size(); ++a)
        settings.gamepadMapping.actions[a] = m_actions[a]->currentData().toString();
    settings.gamepadMapping.deadZone = m_gamepadDeadZone->value() / 100;
    settings.spaceMouse = m_spaceMouse->isChecked();
    settings.spaceMouseDeadZone = m_spaceMouseDeadZone->value() / 100;
    return settings;
}

QString PreferencesDialog::language() const
{
    return m_language->currentData().toString();
}

bool PreferencesDialog::languageChanged() const
{
    return language() != m_initial;
}

QString PreferencesDialog::savedLanguage()
{
    return QSettings().value(LanguageKey).toString();
}

bool PreferencesDialog::publishesToFoxglove()
{
    return QSettings().value(FoxgloveKey, false).toBool();
}

int PreferencesDialog::foxglovePort()
{
    const int port = QSettings().value(FoxglovePortKey, DefaultFoxglovePort).toInt();
    return port >= 1 && port <= 65535 ? port : DefaultFoxglovePort;
}

void PreferencesDialog::save()
{
    teleopSettings().save();
    QSettings settings;
    settings.setValue(LanguageKey, language());
    settings.setValue(FoxgloveKey, m_foxglove->isChecked());
    settings.setValue(FoxglovePortKey, m_foxglovePort->value());
    StudioFolders::setSessions(QDir::fromNativeSeparators(m_sessionsFolder->text().trimmed()));
}

} // namespace semhap
