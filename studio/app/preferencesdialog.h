// SPDX-License-Identifier: MIT
#pragma once

#include "teleopsettings.h"

#include <QDialog>

#include <array>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace semhap {

/**
 * The studio's settings a user changes rarely: the interface language, where sessions go
 * (General), and how the grippers are driven (Driving: the wrist's speed, the gamepad's
 * mapping and dead zone, the 3D mouse).
 */
class PreferencesDialog : public QDialog
{
    Q_OBJECT

public:
    explicit PreferencesDialog(QWidget *parent = nullptr);

    /** The chosen language code ("en", "de"), empty for the system's. */
    QString language() const;
    bool languageChanged() const;

    /** The driving settings as the dialog shows them now. */
    TeleopSettings teleopSettings() const;

    QComboBox *languagePicker() const { return m_language; }
    QComboBox *gamepadControl(GamepadMapping::Motion motion) const
    {
        return m_motions[size_t(motion)];
    }
    QComboBox *gamepadButton(GamepadMapping::Action action) const
    {
        return m_actions[size_t(action)];
    }
    QLineEdit *sessionsFolderEdit() const { return m_sessionsFolder; }

    /** The saved language setting (empty: follow the system). */
    static QString savedLanguage();
    /** Foxglove's own default port, which its connection dialog offers. */
    static constexpr int DefaultFoxglovePort = 8765;
    /** Whether the run is served to Foxglove (saved; off until the user turns it on). */
    static bool publishesToFoxglove();
    /** The port it is served on (saved, else DefaultFoxglovePort). */
    static int foxglovePort();

private:
    QWidget *createGeneralPage();
    QWidget *createDrivingPage();
    void showMapping(const GamepadMapping &mapping);
    void save();

    QComboBox *m_language = nullptr;
    QLineEdit *m_sessionsFolder = nullptr;
    QCheckBox *m_foxglove = nullptr;
    QSpinBox *m_foxglovePort = nullptr;
    QDoubleSpinBox *m_speed = nullptr;
    QCheckBox *m_gamepad = nullptr;
    QDoubleSpinBox *m_gamepadDeadZone = nullptr;
    std::array<QComboBox *, GamepadMapping::MotionCount> m_motions{};
    std::array<QComboBox *, GamepadMapping::ActionCount> m_actions{};
    QCheckBox *m_spaceMouse = nullptr;
    QDoubleSpinBox *m_spaceMouseDeadZone = nullptr;
    QString m_initial;
};

} // namespace semhap
