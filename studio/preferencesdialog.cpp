// SPDX-License-Identifier: MIT
#include "preferencesdialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>

namespace semhap {

namespace {
const QString LanguageKey = QStringLiteral("interface/language");
}

PreferencesDialog::PreferencesDialog(QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Preferences"));
    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("languagePicker"));
    m_language->addItem(tr("System language"), QString());
    // Each language in its own name, so a user can find theirs whatever is showing.
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_initial = savedLanguage();
    m_language->setCurrentIndex(std::max(0, m_language->findData(m_initial)));

    auto *form = new QFormLayout;
    form->addRow(tr("Interface language:"), m_language);
    auto *note = new QLabel(tr("The window is rebuilt in the new language; the run starts "
                               "again from the beginning."),
                            this);
    note->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        save();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addWidget(buttons);
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

void PreferencesDialog::save()
{
    QSettings().setValue(LanguageKey, language());
}

} // namespace semhap
