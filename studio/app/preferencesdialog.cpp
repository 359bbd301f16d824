// SPDX-License-Identifier: MIT
#include "preferencesdialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>

namespace semhap {

namespace {
const QString LanguageKey = QStringLiteral("interface/language");
const QString SessionsFolderKey = QStringLiteral("sessions/folder");
} // namespace

PreferencesDialog::PreferencesDialog(QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("languagePicker"));
    m_language->addItem(tr("System language"), QString());
    // Each language in its own name, so a user can find theirs whatever is showing.
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_initial = savedLanguage();
    m_language->setCurrentIndex(std::max(0, m_language->findData(m_initial)));

    m_sessionsFolder = new QLineEdit(QDir::toNativeSeparators(sessionsFolder()), this);
    m_sessionsFolder->setObjectName(QStringLiteral("sessionsFolder"));
    m_sessionsFolder->setPlaceholderText(QDir::toNativeSeparators(defaultSessionsFolder()));
    m_sessionsFolder->setMinimumWidth(320);
    auto *browse = new QPushButton(tr("Browse…"), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Where recordings go"),
                                                                 m_sessionsFolder->text());
        if (!folder.isEmpty())
            m_sessionsFolder->setText(QDir::toNativeSeparators(folder));
    });
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_sessionsFolder);
    folderRow->addWidget(browse);

    auto *form = new QFormLayout;
    form->addRow(tr("Interface language:"), m_language);
    form->addRow(tr("Sessions folder:"), folderRow);
    auto *note = new QLabel(tr("A new language rebuilds the window, and the run starts again "
                               "from the beginning. Recordings go to the sessions folder from "
                               "the next one on."),
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

QString PreferencesDialog::sessionsFolder()
{
    const QString saved = QSettings().value(SessionsFolderKey).toString();
    return saved.isEmpty() ? defaultSessionsFolder() : saved;
}

QString PreferencesDialog::defaultSessionsFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/sessions");
}

void PreferencesDialog::save()
{
    QSettings settings;
    settings.setValue(LanguageKey, language());
    // Left empty or at the default, it follows the default (a moved data folder too).
    const QString folder = QDir::fromNativeSeparators(m_sessionsFolder->text().trimmed());
    if (folder.isEmpty() || folder == defaultSessionsFolder())
        settings.remove(SessionsFolderKey);
    else
        settings.setValue(SessionsFolderKey, folder);
}

} // namespace semhap
