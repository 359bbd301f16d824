// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QComboBox;
class QLineEdit;

namespace semhap {

/** The studio's settings a user changes rarely: the interface language, where sessions go. */
class PreferencesDialog : public QDialog
{
    Q_OBJECT

public:
    explicit PreferencesDialog(QWidget *parent = nullptr);

    /** The chosen language code ("en", "de"), empty for the system's. */
    QString language() const;
    bool languageChanged() const;

    QComboBox *languagePicker() const { return m_language; }
    QLineEdit *sessionsFolderEdit() const { return m_sessionsFolder; }

    /** The saved language setting (empty: follow the system). */
    static QString savedLanguage();
    /** Where recordings go: the saved folder, else `sessions` in the user's data folder. */
    static QString sessionsFolder();
    /** The folder recordings go to when the user has not chosen one. */
    static QString defaultSessionsFolder();

private:
    void save();

    QComboBox *m_language = nullptr;
    QLineEdit *m_sessionsFolder = nullptr;
    QString m_initial;
};

} // namespace semhap
