// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QComboBox;

namespace semhap {

/** The studio's settings a user changes rarely: for now, the interface language. */
class PreferencesDialog : public QDialog
{
    Q_OBJECT

public:
    explicit PreferencesDialog(QWidget *parent = nullptr);

    /** The chosen language code ("en", "de"), empty for the system's. */
    QString language() const;
    bool languageChanged() const;

    QComboBox *languagePicker() const { return m_language; }

    /** The saved language setting (empty: follow the system). */
    static QString savedLanguage();

private:
    void save();

    QComboBox *m_language = nullptr;
    QString m_initial;
};

} // namespace semhap
