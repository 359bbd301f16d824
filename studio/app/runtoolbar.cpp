// SPDX-License-Identifier: MIT
#include "runtoolbar.h"

#include "colors.h"
#include "drawnicon.h"
#include "engine.h"
#include "filedialogs.h"
#include "gripperlibrary.h"
#include "routergraph.h"
#include "workspace.h"
#include "world.h"

#include <QActionGroup>
#include <QComboBox>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenu>
#include <QPainter>
#include <QStandardItemModel>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace semhap {

namespace {

/** The speeds the toolbar offers, slowest first; real time is the default. */
constexpr double Speeds[] = {0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0};
constexpr int RealTimeIndex = 3;
constexpr int SpeedCount = int(sizeof(Speeds) / sizeof(Speeds[0]));

/** The scene picker's entry for a live rig (not a scene file or name). */
const QString LiveRigEntry = QStringLiteral("semhap:live-rig");
/** The Gripper menu's entry that asks for an adapter file (not an adapter's name). */
const QString OtherGripperEntry = QStringLiteral("semhap:other-gripper");

/** Marks a router picker entry that names what a replay shows, not a router to load. */
constexpr int ShownByReplayRole = Qt::UserRole + 1;

/**
 * The router picker's widest name, in average characters ("mine-v2.json" fits): what the
 * top toolbar has room for at 1280 px in German with every button and field whole.
 */
constexpr int RouterNameChars = 14;

/**
 * The Gripper menu's button: a parallel gripper holding a cube, its jaws blue when a gripper
 * adapter's model takes the place of the scene's own.
 */
QIcon gripperIcon(bool adapter)
{
    return drawnIcon([adapter](QPainter &painter) {
        painter.setBrush(colors::Text);
        painter.drawRect(QRectF(13, 2, 6, 5)); // the wrist
        painter.setBrush(adapter ? colors::Confirmation : colors::Text);
        painter.drawRect(QRectF(4, 7, 24, 5));  // the palm
        painter.drawRect(QRectF(4, 12, 5, 17)); // the jaws
        painter.drawRect(QRectF(23, 12, 5, 17));
        painter.setBrush(colors::Border);
        painter.drawRect(QRectF(11, 17, 10, 10)); // the cube
    });
}

} // namespace

RunToolBar::RunToolBar(const Actions &actions, Workspace &workspace, QWidget *parent)
    : QToolBar(tr("Simulation"), parent), m_actions(actions), m_gripperMenu(new QMenu(this))
{

    setObjectName(QStringLiteral("runToolBar"));
    setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    addAction(actions.run);
    addAction(actions.step);
    addAction(actions.reset);
    // Step and Reset go by their players' icons (their tooltips name them): the room is the
    // session name's and notes', in German too.
    for (QAction *action : {actions.step, actions.reset}) {
        if (auto *button = qobject_cast<QToolButton *>(widgetForAction(action)))
            button->setToolButtonStyle(Qt::ToolButtonIconOnly);
    }
    // Run and Pause take the same room: the toolbar stands still as the run starts and stops.
    if (auto *button = qobject_cast<QToolButton *>(widgetForAction(actions.run))) {
        int widest = 0;
        for (const QString &text : {tr("Run"), tr("Pause")}) {
            actions.run->setText(text);
            widest = std::max(widest, button->sizeHint().width());
        }
        button->setMinimumWidth(widest);
    }
    addSeparator();

    m_speed = new QComboBox(this);
    m_speed->setObjectName(QStringLiteral("speedPicker"));
    m_speed->setToolTip(tr("Simulated seconds per real second (Ctrl+- / Ctrl++)"));
    for (double speed : Speeds) {
        m_speed->addItem(speed == 1.0 ? tr("Real time")
                                      : tr("%1× speed").arg(QLocale().toString(speed)),
                         speed);
    }
    m_speed->setCurrentIndex(RealTimeIndex);
    connect(m_speed, &QComboBox::activated, this, &RunToolBar::pickSpeed);
    addWidget(m_speed);
    addSeparator();

    addWidget(new QLabel(tr("Scene:"), this));
    m_scene = new QComboBox(this);
    m_scene->setObjectName(QStringLiteral("scenePicker"));
    m_scene->setToolTip(tr("The task to simulate, or a live rig's frames"));
    for (const QString &name : World::builtinScenes())
        m_scene->addItem(name, name);
    m_scene->addItem(tr("Live rig…"), LiveRigEntry);
    connect(m_scene, &QComboBox::activated, this, [this](int index) {
        const QString scene = m_scene->itemData(index).toString();
        if (scene == LiveRigEntry)
            emit liveRigPicked();
        else
            emit scenePicked(scene);
    });
    addWidget(m_scene);
    // Beside the scene, as its icon: a field naming the choice has no room at 1280 px in
    // German; the button's tooltip and the window's title name it. Its menu is filled as it
    // opens: an adapter copied into the gripper folder shows without a restart.
    m_gripperMenu->setObjectName(QStringLiteral("gripperMenu"));
    connect(m_gripperMenu, &QMenu::aboutToShow, this, &RunToolBar::fillGripperMenu);
    actions.gripper->setMenu(m_gripperMenu);
    actions.gripper->setIcon(gripperIcon(false));
    addAction(actions.gripper);
    if (auto *button = qobject_cast<QToolButton *>(widgetForAction(actions.gripper))) {
        button->setObjectName(QStringLiteral("gripperButton"));
        button->setToolButtonStyle(Qt::ToolButtonIconOnly);
        button->setPopupMode(QToolButton::InstantPopup);
    }

    addWidget(new QLabel(tr("Router:"), this));
    m_router = new QComboBox(this);
    m_router->setObjectName(QStringLiteral("routerPicker"));
    // It grows with a name added later (a file opened, what a replay shows) up to a limit,
    // beyond which the name gives up its middle (syncPickers).
    m_router->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_router->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    for (const QString &name : RouterPresets::names())
        m_router->addItem(name, name);
    connect(m_router, &QComboBox::activated, this,
            [this](int index) { emit routerPicked(m_router->itemData(index).toString()); });
    addWidget(m_router);
    addSeparator();
    addAction(actions.drive);
    addAction(actions.forces);
    addSeparator();
    addAction(actions.record);
    m_sessionName = new QLineEdit(this);
    m_sessionName->setObjectName(QStringLiteral("sessionName"));
    m_sessionName->setPlaceholderText(tr("Session name"));
    m_sessionName->setToolTip(tr("Names the next recording's file (empty: scene, router and "
                                 "time); File → Preferences says where it goes"));
    m_sessionName->setMaximumWidth(140);
    m_sessionName->setText(workspace.sessionName());
    connect(m_sessionName, &QLineEdit::textChanged, &workspace, &Workspace::setSessionName);
    addWidget(m_sessionName);
    m_notes = new QLineEdit(this);
    m_notes->setObjectName(QStringLiteral("sessionNotes"));
    m_notes->setPlaceholderText(tr("Session notes"));
    m_notes->setToolTip(tr("Kept with the next recording (participant, condition, …)"));
    m_notes->setMaximumWidth(180);
    m_notes->setText(workspace.sessionNotes());
    connect(m_notes, &QLineEdit::textChanged, &workspace, &Workspace::setSessionNotes);
    addWidget(m_notes);

    // Kept apart and in a colour of its own, so it is found without looking.
    auto *spacer = new QWidget(this);
    spacer->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    addWidget(spacer);
    addAction(actions.stopAll);
    if (QWidget *button = widgetForAction(actions.stopAll)) {
        button->setObjectName(QStringLiteral("stopAllButton"));
        button->setStyleSheet(
            QStringLiteral("QToolButton { background: %1; color: white; font-weight: bold;"
                           " border-radius: 4px; padding: 4px 14px; }"
                           "QToolButton:pressed { background: %2; }")
                .arg(colors::css(colors::Error), colors::css(colors::ErrorDark)));
    }
}

void RunToolBar::stepSpeed(int steps)
{
    pickSpeed(m_speed->currentIndex() + steps);
}

void RunToolBar::pickRealTime()
{
    pickSpeed(RealTimeIndex);
}

void RunToolBar::pickSpeed(int index)
{
    index = std::clamp(index, 0, SpeedCount - 1);
    m_speed->setCurrentIndex(index);
    emit speedPicked(Speeds[index]);
}

void RunToolBar::fillGripperMenu()
{
    const QString &loaded = m_gripper;
    delete m_gripperChoices; // with its entries, which leave the menu
    m_gripperMenu->clear();
    m_gripperChoices = new QActionGroup(this);
    m_gripperMenu->addSection(tr("Gripper")); // the toolbar shows only its icon
    const auto add = [this, &loaded](const QString &text, const QString &gripper) {
        QAction *choice = m_gripperChoices->addAction(text);
        choice->setData(gripper);
        choice->setCheckable(gripper != OtherGripperEntry);
        choice->setChecked(gripper == loaded);
        connect(choice, &QAction::triggered, this, [this, gripper] { pickGripper(gripper); });
        m_gripperMenu->addAction(choice);
    };
    add(tr("Scene's own"), QString());
    const QStringList names = GripperLibrary::names();
    for (const QString &name : names)
        add(name, name);
    // A file, or a name no gripper folder has now: shown, so the menu never hides what runs.
    if (!loaded.isEmpty() && !names.contains(loaded))
        add(QFileInfo(loaded).fileName(), loaded);
    m_gripperMenu->addSeparator();
    add(tr("Other file…"), OtherGripperEntry);
}

void RunToolBar::pickGripper(const QString &choice)
{
    QString gripper = choice;
    if (gripper == OtherGripperEntry) {
        gripper =
            FileDialogs::openFile(parentWidget(), FileKind::Gripper, tr("Open gripper adapter"),
                                  tr("Gripper adapters (*.json)"));
        if (gripper.isEmpty())
            return;
    }
    emit gripperPicked(gripper);
}

void RunToolBar::sync(const Engine &engine)
{
    // A file opened from disk shows as an extra entry, so the picker never lies.
    const auto sync = [](QComboBox *picker, const QString &value) {
        int index = picker->findData(value);
        if (index < 0) {
            picker->addItem(QFileInfo(value).fileName(), value);
            index = picker->count() - 1;
        }
        picker->setCurrentIndex(index);
        return index;
    };
    sync(m_scene, engine.isLive() ? LiveRigEntry : engine.options().scene);
    m_gripper = engine.options().sceneOptions.gripper;
    const QString &gripper = m_gripper;
    m_actions.gripper->setIcon(gripperIcon(!gripper.isEmpty()));
    m_actions.gripper->setToolTip(
        tr("Gripper: %1\nThe scene's own grippers, or a gripper adapter's model in their place")
            .arg(gripper.isEmpty() ? tr("the scene's own") : QFileInfo(gripper).fileName()));
    // A router only a replay shows (an untitled re-routing graph, a recorded file) is named
    // while it shows and cannot be picked: the picker offers only what it can load.
    const QString router = engine.routerSource();
    for (int i = m_router->count(); i-- > 0;) {
        if (m_router->itemData(i, ShownByReplayRole).toBool() &&
            (!engine.isReplaying() || m_router->itemData(i).toString() != router))
            m_router->removeItem(i);
    }
    const int count = m_router->count();
    const int current = sync(m_router, router);
    if (engine.isReplaying() && m_router->count() > count) {
        m_router->setItemData(current, true, ShownByReplayRole);
        auto *entries = qobject_cast<QStandardItemModel *>(m_router->model());
        entries->item(current)->setEnabled(false);
    }
    // An edit runs (or a replay shows it) under the name it started from: say so (`C3*`).
    // A name longer than the picker's room gives up its middle, and its tooltip has it whole.
    const bool edited = engine.isRouterEdited();
    const QStringList presets = RouterPresets::names();
    const QFontMetrics metrics = m_router->fontMetrics();
    const int room = RouterNameChars * metrics.averageCharWidth();
    QString whole;
    for (int i = 0; i < m_router->count(); ++i) {
        const QString value = m_router->itemData(i).toString();
        QString name = presets.contains(value) ? value : QFileInfo(value).fileName();
        if (edited && i == m_router->currentIndex())
            name += QLatin1Char('*');
        const QString shown = metrics.elidedText(name, Qt::ElideMiddle, room);
        m_router->setItemText(i, shown);
        m_router->setItemData(i, shown == name ? QVariant() : QVariant(name), Qt::ToolTipRole);
        if (shown != name && i == m_router->currentIndex())
            whole = name;
    }
    const QString purpose = tr("Which feedback design turns events into patterns");
    m_router->setToolTip(whole.isEmpty() ? purpose : QStringLiteral("%1\n%2").arg(whole, purpose));
    int speed = RealTimeIndex;
    for (int i = 0; i < SpeedCount; ++i) {
        if (std::abs(Speeds[i] - engine.speed()) < 1e-9)
            speed = i;
    }
    m_speed->setCurrentIndex(speed);
}

} // namespace semhap
