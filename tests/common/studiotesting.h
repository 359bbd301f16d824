// SPDX-License-Identifier: MIT
#pragma once

// What the studio's whole-window tests (tst_studio, tst_studiolayout, tst_studiofiles) share:
// their own settings, sound card and home folder, and the ways a person reaches a dialog, a
// tab or a language.

#include "fifocard.h"
#include "mainwindow.h"
#include "openwindow.h"
#include "preferencesdialog.h"
#include "studio.h"
#include "waveformdesigner.h"
#include "workspace.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>

#include <functional>
#include <memory>

namespace semhap {

/**
 * The base of a studio test: settings and a sound card (FifoCard) of its own, and each test
 * function starting on the defaults.
 */
class StudioTestCase : public QObject
{
protected:
    /** For initTestCase(): the settings folder and the sound card. */
    void setUp()
    {
        QVERIFY(m_config.isValid());
        QCoreApplication::setOrganizationName("semhap");
        QCoreApplication::setApplicationName("semhap-studio-test");
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_config.path());
        m_fifo = FifoCard::install(m_config.path());
        QVERIFY(!m_fifo.isEmpty());
    }
    /** For init(): no settings and no saved workspace. */
    static void reset()
    {
        QSettings().clear();
        QFile::remove(Workspace::defaultFile());
    }
    static StudioOptions options()
    {
        StudioOptions o;
        QString message;
        bool help = false;
        // Fast, so the first grasp comes soon; no network input, so tests can run side by side.
        StudioOptions::parse({"--speed", "4", "--pose-port", "0", "--size", "1280x800"}, &o,
                             &message, &help);
        return o;
    }
    QString m_fifo; ///< the sound card's (FifoCard)

private:
    QTemporaryDir m_config;
};

/**
 * A home folder of the test's own for as long as it lives: the user pattern folder, the
 * sessions folder and the documents folder are in it.
 */
class OwnHome
{
public:
    OwnHome()
    {
        for (const char *name : {"HOME", "XDG_CONFIG_HOME", "XDG_DATA_HOME"})
            m_saved.append({name, qgetenv(name), qEnvironmentVariableIsSet(name)});
        QDir(m_home.path()).mkpath("Documents");
        qputenv("HOME", m_home.path().toUtf8());
        qputenv("XDG_CONFIG_HOME", m_home.filePath(".config").toUtf8());
        qputenv("XDG_DATA_HOME", m_home.filePath(".local/share").toUtf8());
    }
    ~OwnHome()
    {
        for (const Saved &saved : m_saved) {
            if (saved.set)
                qputenv(saved.name, saved.value);
            else
                qunsetenv(saved.name);
        }
    }
    QString documents() const { return m_home.filePath("Documents"); }

private:
    struct Saved
    {
        const char *name;
        QByteArray value;
        bool set;
    };
    QTemporaryDir m_home;
    QList<Saved> m_saved;
};

/**
 * Does `open` (which opens a file dialog) and answers the dialog: with `answer` when given,
 * else Cancel. The folder the dialog started in.
 */
inline QString dialogFolder(const std::function<void()> &open, const QString &answer = QString())
{
    QString folder = QStringLiteral("(no file dialog)");
    QTimer::singleShot(0, [&folder, answer] {
        QTRY_VERIFY(qobject_cast<QFileDialog *>(QApplication::activeModalWidget()));
        auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        folder = dialog->directory().absolutePath();
        if (answer.isEmpty()) {
            dialog->reject();
            return;
        }
        dialog->selectFile(answer);
        QTest::keyClick(dialog->focusWidget() ? dialog->focusWidget() : dialog, Qt::Key_Return);
    });
    open();
    return folder;
}

/** Clicks the designer's action `name`: its toolbar button, or its entry in the Pattern menu. */
inline void clickDesignerAction(MainWindow &window, const QString &name)
{
    window.findChild<QDockWidget *>("patternsDock")->raise();
    WaveformDesigner *designer = window.waveformDesigner();
    auto *bar = designer->findChild<QToolBar *>("designerToolBar");
    auto *action = designer->findChild<QAction *>(name);
    QVERIFY(action);
    if (QWidget *button = bar->widgetForAction(action)) {
        QTest::mouseClick(button, Qt::LeftButton);
        return;
    }
    auto *menu = designer->findChild<QMenu *>("patternMenu");
    QVERIFY(menu && menu->actions().contains(action));
    QWidget *menuButton =
        bar->widgetForAction(designer->findChild<QAction *>("patternMenuAction"));
    // No waiting in between: a caller may have a dialog's answer queued for what it opens.
    menu->popup(menuButton->mapToGlobal(menuButton->rect().bottomLeft()));
    QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(action).center());
}

/** A studio at the test row's size and language; its window is shown and active. */
inline std::unique_ptr<Studio> startStudio(StudioOptions o)
{
    QFETCH(QSize, size);
    QFETCH(QString, language);
    o.size = size;
    auto studio = std::make_unique<Studio>(o);
    studio->start();
    if (language != "en")
        studio->setLanguage(language);
    if (!openWindow(*studio->window()))
        qWarning("the window did not become active");
    return studio;
}

/** Picks `language` in File → Preferences, as a person would, and waits for the window. */
inline void pickLanguage(Studio &studio, const QString &language)
{
    QSignalSpy rebuilt(&studio, &Studio::windowRebuilt);
    // The preferences dialog is modal: answer it once it is up.
    QTimer::singleShot(0, [language] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        auto *dialog = qobject_cast<PreferencesDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        QComboBox *picker = dialog->languagePicker();
        picker->setFocus();
        picker->setCurrentIndex(0);
        while (picker->currentData().toString() != language &&
               picker->currentIndex() < picker->count() - 1)
            QTest::keyClick(picker, Qt::Key_Down);
        QCOMPARE(picker->currentData().toString(), language);
        QTest::keyClick(dialog, Qt::Key_Return);
    });
    studio.window()->findChild<QAction *>("preferencesAction")->trigger();
    QTRY_COMPARE(rebuilt.count(), 1);
}
/** Clicks the tab named `title` among the window's dock tabs. */
inline bool raiseTab(MainWindow &window, const QString &title)
{
    for (QTabBar *bar : window.findChildren<QTabBar *>()) {
        for (int i = 0; i < bar->count(); ++i) {
            if (bar->tabText(i) == title) {
                QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(i).center());
                return true;
            }
        }
    }
    return false;
}

/** Starts `studio` in `language`, switched to as a user does it (the window is rebuilt). */
inline MainWindow &startIn(Studio &studio, const QString &language)
{
    studio.start();
    if (language != "en")
        studio.setLanguage(language);
    return *studio.window();
}

} // namespace semhap
