// SPDX-License-Identifier: MIT
// The waveform designer driven like a user: editing a ramp in the inspector with the
// keyboard changes the preview, undo and redo restore the exact JSON, a duplicated built-in
// saves and opens again, the preview shows the pneumatic band smearing fast pulses, an
// audition reaches an emulated band over UDP, and an AHAP file imports and exports.
#include "ahapformat.h"
#include "devicemanager.h"
#include "emulatedband.h"
#include "emulator.h"
#include "hjifdocument.h"
#include "jsonreader.h"
#include "nodeinspector.h"
#include "numberedit.h"
#include "patternauditioner.h"
#include "patterndocument.h"
#include "patternpreview.h"
#include "waveformdesigner.h"
#include "waveformtype.h"
#include "widgetchecks.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QTreeWidget>

#include <qcustomplot.h>

#include <algorithm>
#include <atomic>
#include <thread>

using namespace semhap;

namespace {

const QString Data = QStringLiteral(SEMHAP_TEST_DATA);

/** A designer on a fresh user folder, shown. */
struct Fixture
{
    QTemporaryDir folder;
    WaveformDesigner designer;

    explicit Fixture(DeviceManager *devices = nullptr) : designer(devices)
    {
        designer.setUserFolder(folder.path());
        designer.resize(900, 760);
        designer.show();
    }
    template<typename T> T *child(const QString &name) const
    {
        return designer.findChild<T *>(name);
    }
    void trigger(const QString &action) const
    {
        auto *bar = child<QToolBar>(QStringLiteral("designerToolBar"));
        QWidget *button = bar->widgetForAction(child<QAction>(action));
        QVERIFY(button && button->isEnabled());
        QTest::mouseClick(button, Qt::LeftButton);
    }
    void clickTreeNode(const QString &pointer) const
    {
        QTreeWidget *tree = designer.tree();
        for (QTreeWidgetItemIterator it(tree); *it; ++it) {
            if ((*it)->data(0, Qt::UserRole).toString() == pointer) {
                tree->scrollToItem(*it);
                // On the row's text, as a person clicks: a row wider than the pane has its
                // centre out of sight.
                const QRect row = tree->visualItemRect(*it);
                QTest::mouseClick(tree->viewport(), Qt::LeftButton, {},
                                  QPoint(std::max(row.left(), 0) + 24, row.center().y()));
                return;
            }
        }
        QFAIL(qPrintable(QStringLiteral("no tree node %1").arg(pointer)));
    }
    /** Clicks a library entry, as a user picks a pattern. */
    void clickLibraryItem(const QString &text) const
    {
        auto *library = child<QListWidget>(QStringLiteral("library"));
        const QList<QListWidgetItem *> items = library->findItems(text, Qt::MatchExactly);
        QCOMPARE(items.size(), 1);
        library->scrollToItem(items.first());
        QTest::mouseClick(library->viewport(), Qt::LeftButton, {},
                          library->visualItemRect(items.first()).center());
    }
    /** The library's entries, as shown. */
    QStringList libraryTexts() const
    {
        QStringList texts;
        auto *library = child<QListWidget>(QStringLiteral("library"));
        for (int i = 0; i < library->count(); ++i)
            texts.append(library->item(i)->text());
        return texts;
    }
    /** Saves a copy of the built-in `builtin` as a user pattern; its file. */
    QString saveCopyOf(const QString &builtin) const
    {
        clickLibraryItem(builtin);
        trigger(QStringLiteral("duplicatePattern"));
        trigger(QStringLiteral("savePattern"));
        return designer.document()->path();
    }
    /** Types a new name into the pattern's Name field, as a user renames it. */
    void typeName(const QString &name) const
    {
        clickTreeNode(QString());
        QCoreApplication::processEvents(); // the inspector rebuilds queued
        auto *field = child<QLineEdit>(QStringLiteral("param:name"));
        QVERIFY(field);
        QTest::mouseClick(field, Qt::LeftButton);
        field->selectAll();
        QTest::keyClicks(field, name);
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(designer.document()->json().value(QLatin1String("name")).toString(), name);
    }
    /** Types `text` into a number field of the inspector and presses Enter. */
    void typeNumber(const QString &field, const QString &text) const
    {
        QCoreApplication::processEvents(); // the inspector rebuilds queued
        auto *edit = child<NumberEdit>(QStringLiteral("param:") + field);
        QVERIFY(edit);
        auto *spin = edit->findChild<QDoubleSpinBox *>(QStringLiteral("value"));
        QTest::mouseClick(spin, Qt::LeftButton);
        QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(spin, text);
        QTest::keyClick(spin, Qt::Key_Return);
        QCoreApplication::processEvents();
    }
    std::vector<double> graphValues(int graph) const
    {
        std::vector<double> values;
        QCPGraph *g = designer.preview()->plot()->graph(graph);
        for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
            values.push_back(it->value);
        return values;
    }
};

double peakToPeak(const std::vector<double> &values, const std::vector<double> &t, double from)
{
    double low = 1e9;
    double high = -1e9;
    for (size_t i = 0; i < values.size(); ++i) {
        if (t[i] >= from) {
            low = std::min(low, values[i]);
            high = std::max(high, values[i]);
        }
    }
    return high - low;
}

} // namespace

class TestWaveformDesigner : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void editRampChangesPreview();
    void undoRedoRestoresJson();
    void documentStructureEdits();
    void duplicateSaveOpen();
    void renamingMovesTheFile();
    void takenNamesAreRefused_data();
    void takenNamesAreRefused();
    void builtinIsReadOnly();
    void pneumaticSmearsPulses();
    void jsonTabShowsErrors();
    void auditionReachesEmulator();
    void auditionEndsWhereThePreviewDoes();
    void auditionKeepsTheDevicesRate();
    void auditionIsStampedFromTheRun();
    void importAhap();
    void exportImportHjif();
    void screenshot();
};

void TestWaveformDesigner::initTestCase()
{
    QLocale::setDefault(QLocale::c());
}

void TestWaveformDesigner::editRampChangesPreview()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.openBuiltin(QStringLiteral("air.squeeze"));
    f.trigger(QStringLiteral("duplicatePattern"));
    QVERIFY(!f.designer.document()->isReadOnly());
    f.clickTreeNode(QStringLiteral("/tracks/0/attack"));
    QCOMPARE(f.designer.inspector()->target(), QStringLiteral("/tracks/0/attack"));

    const std::vector<double> before = f.graphValues(0);
    f.typeNumber(QStringLiteral("time"), QStringLiteral("0.2"));
    QCOMPARE(f.designer.document()->value(QStringLiteral("/tracks/0/attack/time")).toDouble(),
             0.2);
    const std::vector<double> after = f.graphValues(0);
    QCOMPARE(after.size(), before.size());
    QVERIFY(after != before);
    // pneumatic6 at 100 Hz: sample 10 is t = 0.1 s, halfway up the faster ramp.
    QVERIFY(std::abs(before[10] - 0.2) < 1e-9);
    QVERIFY(std::abs(after[10] - 0.5) < 1e-9);
    // The keyboard stays in the field after the rebuild.
    QCoreApplication::processEvents();
    QVERIFY(f.child<NumberEdit>(QStringLiteral("param:time"))
                ->isAncestorOf(QApplication::focusWidget()));
}

void TestWaveformDesigner::documentStructureEdits()
{
    // The document makes the structure edits, each one undo step, and every result loads.
    PatternDocument document;
    document.reset(PatternDocument::newPattern("mine", "lra4"), QString(), false);
    QVERIFY2(document.pattern(), qPrintable(document.error().toString()));
    QCOMPARE(document.addTrack(), QString("/tracks/1"));
    QCOMPARE(document.addPart("/tracks/1/sustain", "release"), QString("/tracks/1/release"));
    QCOMPARE(document.value("/tracks/1/release/to").toDouble(), 0.0);
    QVERIFY(document.addPart("/params", "attack").isEmpty());
    document.setValue("/tracks/1/sustain",
                      newWaveform("sum", document.value("/tracks/1/sustain")));
    QCOMPARE(document.addInput("/tracks/1/sustain"), QString("/tracks/1/sustain/of/2"));
    QVERIFY2(document.pattern(), qPrintable(document.error().toString()));
    QCOMPARE(document.remove("/tracks/1/sustain/of/2"), QString("/tracks/1/sustain"));
    QCOMPARE(document.remove("/tracks/1/release"), QString("/tracks/1"));
    QVERIFY2(document.pattern(), qPrintable(document.error().toString()));
    QCOMPARE(document.undoStack()->count(), 6);
    while (document.undoStack()->canUndo())
        document.undoStack()->undo();
    QCOMPARE(document.json(), PatternDocument::newPattern("mine", "lra4"));
}

void TestWaveformDesigner::undoRedoRestoresJson()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.openBuiltin(QStringLiteral("vib.rampup"));
    f.trigger(QStringLiteral("duplicatePattern"));
    const QJsonObject original = f.designer.document()->json();
    f.clickTreeNode(QStringLiteral("/tracks/0/release"));
    f.typeNumber(QStringLiteral("time"), QStringLiteral("1.25"));
    f.clickTreeNode(QStringLiteral("/tracks/0/attack"));
    f.typeNumber(QStringLiteral("to"), QStringLiteral("0.75"));
    const QJsonObject edited = f.designer.document()->json();
    QCOMPARE(f.designer.document()->undoStack()->count(), 2);

    f.trigger(QStringLiteral("undo"));
    f.trigger(QStringLiteral("undo"));
    QCOMPARE(f.designer.document()->json(), original);
    QCOMPARE(QJsonDocument(f.designer.document()->json()).toJson(),
             QJsonDocument(original).toJson());
    f.trigger(QStringLiteral("redo"));
    f.trigger(QStringLiteral("redo"));
    QCOMPARE(f.designer.document()->json(), edited);
    QCOMPARE(f.designer.document()->value(QStringLiteral("/tracks/0/release/time")).toDouble(),
             1.25);
}

void TestWaveformDesigner::duplicateSaveOpen()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    auto *library = f.child<QListWidget>(QStringLiteral("library"));
    const auto clickItem = [&](const QString &text) {
        const QList<QListWidgetItem *> items = library->findItems(text, Qt::MatchExactly);
        QCOMPARE(items.size(), 1);
        library->scrollToItem(items.first());
        QTest::mouseClick(library->viewport(), Qt::LeftButton, {},
                          library->visualItemRect(items.first()).center());
    };
    clickItem(QStringLiteral("vib.geiger"));
    QCOMPARE(f.designer.document()->json().value(QLatin1String("name")).toString(),
             QStringLiteral("vib.geiger"));
    f.trigger(QStringLiteral("duplicatePattern"));
    const QString path = f.folder.filePath(QStringLiteral("vib.geiger.copy.json"));
    QCOMPARE(f.designer.document()->path(), path);
    QVERIFY(!QFileInfo::exists(path)); // created on first save
    // The library reads the duplicate's row whole: marked unsaved, not "(not saved yet)",
    // which the 130 px library cut after "(noch" in German.
    const QList<QListWidgetItem *> unsaved =
        library->findItems(QStringLiteral("vib.geiger.copy *"), Qt::MatchExactly);
    QCOMPARE(unsaved.size(), 1);
    QVERIFY(unsaved.first()->toolTip().contains(path));
    QVERIFY2(library->visualItemRect(unsaved.first()).width() - library->iconSize().width() - 8 >=
                 QFontMetrics(unsaved.first()->font()).horizontalAdvance(unsaved.first()->text()),
             qPrintable(QString("%1 in %2 px")
                            .arg(unsaved.first()->text())
                            .arg(library->visualItemRect(unsaved.first()).width())));
    f.clickTreeNode(QStringLiteral("/tracks/0/sustain"));
    f.typeNumber(QStringLiteral("width"), QStringLiteral("0.04"));
    f.trigger(QStringLiteral("savePattern"));
    QVERIFY(QFileInfo::exists(path));
    QVERIFY(!f.designer.document()->isModified());
    const QJsonObject saved = f.designer.document()->json();

    clickItem(QStringLiteral("air.squeeze"));
    QCOMPARE(f.designer.document()->json().value(QLatin1String("name")).toString(),
             QStringLiteral("air.squeeze"));
    clickItem(QStringLiteral("vib.geiger.copy"));
    QCOMPARE(f.designer.document()->path(), path);
    QCOMPARE(f.designer.document()->json(), saved);
    QVERIFY(f.designer.document()->pattern());
    QVERIFY(!f.designer.document()->isReadOnly());
}

void TestWaveformDesigner::renamingMovesTheFile()
{
    // A saved pattern renamed in its Name field: Save writes it under the new name, removes
    // the old file, lists it under the new name, and says so (routers follow the signal).
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    const QString old = f.saveCopyOf(QStringLiteral("vib.geiger"));
    QCOMPARE(old, f.folder.filePath(QStringLiteral("vib.geiger.copy.json")));
    QVERIFY(QFileInfo::exists(old));
    f.typeName(QStringLiteral("my.buzz"));
    QSignalSpy renamed(&f.designer, &WaveformDesigner::patternRenamed);
    f.trigger(QStringLiteral("savePattern"));
    const QString moved = f.folder.filePath(QStringLiteral("my.buzz.json"));
    QVERIFY(QFileInfo::exists(moved));
    QVERIFY(!QFileInfo::exists(old));
    QCOMPARE(QDir(f.folder.path()).entryList(QDir::Files | QDir::Hidden),
             QStringList{QStringLiteral("my.buzz.json")});
    QCOMPARE(f.designer.document()->path(), moved);
    QVERIFY(!f.designer.document()->isModified());
    QFile file(moved);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(QJsonDocument::fromJson(file.readAll()).object().value(QLatin1String("name")),
             QStringLiteral("my.buzz"));
    QVERIFY(f.libraryTexts().contains(QStringLiteral("my.buzz")));
    QVERIFY(!f.libraryTexts().contains(QStringLiteral("vib.geiger.copy")));
    QCOMPARE(renamed.count(), 1);
    QCOMPARE(renamed.first(), (QVariantList{old, moved}));

    // Saved again under the same name: nothing moves.
    f.clickTreeNode(QStringLiteral("/tracks/0/sustain"));
    f.typeNumber(QStringLiteral("width"), QStringLiteral("0.03"));
    f.trigger(QStringLiteral("savePattern"));
    QCOMPARE(renamed.count(), 1);
    QVERIFY(QFileInfo::exists(moved));

    // Saved as another file of the folder, the pattern takes that file's name: the next Save
    // moves nothing and the first file stays.
    QString error;
    const QString other = f.folder.filePath(QStringLiteral("my.tick.json"));
    QVERIFY2(f.designer.saveFile(other, &error), qPrintable(error));
    QCOMPARE(f.designer.document()->json().value(QLatin1String("name")).toString(),
             QStringLiteral("my.tick"));
    f.trigger(QStringLiteral("savePattern"));
    QVERIFY(QFileInfo::exists(other));
    QVERIFY(QFileInfo::exists(moved));
    QCOMPARE(renamed.count(), 1);
}

void TestWaveformDesigner::takenNamesAreRefused_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("reason");
    QTest::newRow("another user pattern's") << "mine"
                                            << "Another of your patterns";
    QTest::newRow("a built-in's") << "air.squeeze"
                                  << "built-in";
    QTest::newRow("not a file name") << "a/b"
                                     << "cannot name a file";
    QTest::newRow("hidden") << ".hidden"
                            << "cannot name a file";
    // Its file could be written, not the temporary beside it: the write fails, late.
    QTest::newRow("too long to write") << QString(248, QLatin1Char('x')) << "cannot write";
}

void TestWaveformDesigner::takenNamesAreRefused()
{
    // A rename that cannot be done says why and moves nothing: both patterns' files stay as
    // they were and the edit stays unsaved.
    QFETCH(QString, name);
    QFETCH(QString, reason);
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.saveCopyOf(QStringLiteral("air.squeeze"));
    f.typeName(QStringLiteral("mine"));
    f.trigger(QStringLiteral("savePattern"));
    const QString other = f.saveCopyOf(QStringLiteral("vib.geiger"));
    QVERIFY(QFileInfo::exists(f.folder.filePath(QStringLiteral("mine.json"))));
    QFile file(other);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray contents = file.readAll();
    file.close();
    const QStringList files = QDir(f.folder.path()).entryList(QDir::Files | QDir::Hidden);

    f.typeName(name);
    QSignalSpy messages(&f.designer, &WaveformDesigner::message);
    QSignalSpy renamed(&f.designer, &WaveformDesigner::patternRenamed);
    f.trigger(QStringLiteral("savePattern"));
    QCOMPARE(messages.count(), 1);
    QVERIFY2(messages.first().first().toString().contains(reason),
             qPrintable(messages.first().first().toString()));
    QCOMPARE(renamed.count(), 0);
    QCOMPARE(QDir(f.folder.path()).entryList(QDir::Files | QDir::Hidden), files);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), contents);
    QCOMPARE(f.designer.document()->path(), other);
    QVERIFY(f.designer.document()->isModified());
}

void TestWaveformDesigner::builtinIsReadOnly()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.openBuiltin(QStringLiteral("air.squeeze"));
    QVERIFY(f.designer.document()->isReadOnly());
    QVERIFY(
        f.child<QLabel>(QStringLiteral("banner"))->text().contains(QStringLiteral("Duplicate")));
    QVERIFY(!f.designer.inspector()->isEnabled());
    QVERIFY(f.child<QPlainTextEdit>(QStringLiteral("jsonText"))->isReadOnly());
    const QJsonObject json = f.designer.document()->json();
    f.designer.document()->setValue(QStringLiteral("/name"), QStringLiteral("x"));
    QCOMPARE(f.designer.document()->json(), json);
}

void TestWaveformDesigner::pneumaticSmearsPulses()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    // vib.geiger at full intensity is 20 Hz pulses of 25 ms; put them on the pneumatic band.
    f.designer.openBuiltin(QStringLiteral("vib.geiger"));
    f.trigger(QStringLiteral("duplicatePattern"));
    QVERIFY(
        choose(f.child<QComboBox>(QStringLiteral("modelPicker")), QStringLiteral("pneumatic6")));
    QCOMPARE(f.designer.document()->json().value(QLatin1String("model")).toString(),
             QStringLiteral("pneumatic6"));
    QTest::mouseClick(f.child<QCheckBox>(QStringLiteral("hold")), Qt::LeftButton);
    QVERIFY(f.child<QCheckBox>(QStringLiteral("hold"))->isChecked());

    const PatternPreview *preview = f.designer.preview();
    QCOMPARE(preview->groupCount(), 1);
    QCOMPARE(preview->groupChannels(0).size(), 6);
    const double commanded = peakToPeak(preview->commanded(0), preview->times(), 0.5);
    const double predicted = peakToPeak(preview->predicted(0), preview->times(), 0.5);
    qInfo("20 Hz pulses on pneumatic6: commanded p-p %.3f, predicted p-p %.3f", commanded,
          predicted);
    QCOMPARE(commanded, 1.0);
    QVERIFY(predicted < 0.6 * commanded);

    // On the LRA band the same pulses come through almost whole.
    QVERIFY(choose(f.child<QComboBox>(QStringLiteral("modelPicker")), QStringLiteral("lra4")));
    const double lra = peakToPeak(preview->predicted(0), preview->times(), 0.5);
    qInfo("20 Hz pulses on lra4: predicted p-p %.3f", lra);
    QVERIFY(lra > 0.9);
}

void TestWaveformDesigner::jsonTabShowsErrors()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.openBuiltin(QStringLiteral("air.squeeze"));
    f.trigger(QStringLiteral("duplicatePattern"));
    auto *tabs = f.child<QTabWidget>(QStringLiteral("editorTabs"));
    tabs->setCurrentIndex(1);
    auto *text = f.child<QPlainTextEdit>(QStringLiteral("jsonText"));
    // Find `"time": 0.5` of the attack and make it negative.
    QTextCursor cursor = text->document()->find(QStringLiteral("\"time\": 0.5"));
    QVERIFY(!cursor.isNull());
    cursor.setPosition(cursor.selectionEnd() - 3);
    text->setTextCursor(cursor);
    QTest::keyClick(text, Qt::Key_Minus);
    auto *error = f.child<QLabel>(QStringLiteral("jsonError"));
    QTRY_VERIFY(error->text().contains(QStringLiteral("/tracks/0/attack/time")));
    QCOMPARE(f.designer.document()->value(QStringLiteral("/tracks/0/attack/time")).toDouble(),
             0.5);
    QTest::keyClick(text, Qt::Key_Backspace);
    QTRY_VERIFY(error->text().contains(QStringLiteral("Valid")));
    QTest::keyClick(text, Qt::Key_Delete);
    QTest::keyClicks(text, QStringLiteral("1"));
    QTRY_COMPARE(f.designer.document()->value(QStringLiteral("/tracks/0/attack/time")).toDouble(),
                 1.5);
}

void TestWaveformDesigner::auditionReachesEmulator()
{
    EmulatedBand band(QStringLiteral("lra4"));
    QString error;
    QVERIFY2(band.start(&error), qPrintable(error));
    DeviceManager manager;
    const QString name = QStringLiteral("right.vibro");
    QVERIFY2(manager.bind(name, band.uri(), DeviceModelLibrary::builtin(QStringLiteral("lra4")),
                          &error),
             qPrintable(error));
    manager.armAll(true);
    QTRY_VERIFY_WITH_TIMEOUT(manager.transport(name)->status().responding, 5000);

    Fixture f(&manager);
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.refreshDevices();
    f.designer.openBuiltin(QStringLiteral("air.squeeze")); // pneumatic6: not for this band
    auto *device = f.child<QComboBox>(QStringLiteral("auditionDevice"));
    QVERIFY(choose(device, name + QStringLiteral(" — lra4")));
    QSignalSpy starting(&f.designer, &WaveformDesigner::auditionStarting);
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    QVERIFY(!f.designer.auditioner()->isPlaying());
    QVERIFY(f.child<QLabel>(QStringLiteral("auditionStatus"))
                ->text()
                .contains(QStringLiteral("pneumatic6")));

    // vib.rampup: up to 1 in 0.5 s while held.
    f.designer.openBuiltin(QStringLiteral("vib.rampup"));
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    QVERIFY(f.designer.auditioner()->isPlaying());
    QCOMPARE(starting.count(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(band.state().setpoints.size() == 4 && band.state().setpoints[0] > 0.3,
                             3000);
    QVERIFY(f.designer.auditioner()->framesSent() > 10);
    // Stop sends the band to zero at once.
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionStop")), Qt::LeftButton);
    QVERIFY(!f.designer.auditioner()->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(band.state().setpoints[0] == 0.0, 3000);

    // Begin, then End: the release plays and the audition stops by itself.
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(band.state().setpoints[0] > 0.5, 3000);
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionEnd")), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!f.designer.auditioner()->isPlaying(), 3000);
    QTRY_VERIFY_WITH_TIMEOUT(band.state().setpoints[0] == 0.0, 3000);

    // The band rebound while it plays: the audition stops (it never plays on a transport
    // that is not the device's any more).
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    QVERIFY(f.designer.auditioner()->isPlaying());
    QVERIFY(manager.bind(name, QStringLiteral("virtual:other"),
                         DeviceModelLibrary::builtin(QStringLiteral("lra4")), &error));
    QTRY_VERIFY_WITH_TIMEOUT(!f.designer.auditioner()->isPlaying(), 1000);
}

void TestWaveformDesigner::auditionKeepsTheDevicesRate()
{
    // The audition renders on a thread of its own: a window busy for 0.4 s (a replot, a
    // large graph) does not thin out what the band is sent. lra4 takes 500 frames a second.
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.openBuiltin(QStringLiteral("vib.geiger"));
    f.child<QCheckBox>(QStringLiteral("hold"))->setChecked(true);
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    PatternAuditioner *auditioner = f.designer.auditioner();
    QVERIFY(auditioner->isPlaying());
    const int before = auditioner->framesSent();
    QElapsedTimer busy;
    busy.start();
    while (busy.elapsed() < 400) {
    } // the GUI thread does nothing else meanwhile
    const int frames = auditioner->framesSent() - before;
    qInfo("%d frames in 0.4 s of a busy window (500 Hz: 200)", frames);
    QVERIFY2(frames >= 100, qPrintable(QString::number(frames)));
    f.designer.stopAudition();
}

void TestWaveformDesigner::auditionEndsWhereThePreviewDoes()
{
    // On the virtual device: with End at 0.3 s the audition releases at 0.3 s and stops by
    // itself, as the preview draws it; with Hold it goes on until Stop.
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.openBuiltin(QStringLiteral("vib.rampup"));
    auto *endAt = f.child<QDoubleSpinBox>(QStringLiteral("endAt"));
    endAt->setValue(0.3);
    PatternAuditioner *auditioner = f.designer.auditioner();
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    QVERIFY(auditioner->isActive());
    QTRY_VERIFY_WITH_TIMEOUT(!auditioner->isActive(), 2000);
    QVERIFY2(clock.elapsed() >= 250, qPrintable(QString::number(clock.elapsed())));
    QTRY_VERIFY_WITH_TIMEOUT(!auditioner->isPlaying(), 3000);

    QTest::mouseClick(f.child<QCheckBox>(QStringLiteral("hold")), Qt::LeftButton);
    QVERIFY(!endAt->isEnabled());
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    QTest::qWait(800);
    QVERIFY(auditioner->isActive());
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionStop")), Qt::LeftButton);
    QVERIFY(!auditioner->isPlaying());
}

void TestWaveformDesigner::auditionIsStampedFromTheRun()
{
    // On a bound device the audition's frames carry the run's time from where its readouts
    // are (here 42 s), so the plots draw it on after the run; the transport keeps them as
    // sent, clamped and scaled by its gain.
    DeviceManager manager;
    const QString name = QStringLiteral("right.vibro");
    QString error;
    QVERIFY(manager.bind(name, QStringLiteral("virtual:") + name,
                         DeviceModelLibrary::builtin(QStringLiteral("lra4")), &error));
    manager.transport(name)->setGain(0.5);
    Fixture f(&manager);
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.setRunClock([] { return 42.0; });
    f.designer.refreshDevices();
    f.designer.openBuiltin(QStringLiteral("vib.rampup"));
    QVERIFY(choose(f.child<QComboBox>(QStringLiteral("auditionDevice")),
                   name + QStringLiteral(" — lra4")));
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionBegin")), Qt::LeftButton);
    const SentLog &sent = manager.transport(name)->sent();
    QTRY_VERIFY_WITH_TIMEOUT(sent.last().t > 42.6, 3000);
    std::uint64_t next = 0;
    std::vector<DeviceFrame> frames;
    sent.readSince(&next, &frames);
    QVERIFY(frames.front().t >= 42.0);
    double peak = 0.0;
    for (const DeviceFrame &frame : frames)
        peak = std::max(peak, frame.values[0]);
    QVERIFY2(std::abs(peak - 0.5) < 0.02, qPrintable(QString::number(peak))); // 1 at gain 0.5
    QTest::mouseClick(f.child<QPushButton>(QStringLiteral("auditionStop")), Qt::LeftButton);
    QCOMPARE(sent.last().values[0], 0.0);
}

void TestWaveformDesigner::importAhap()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    QString error;
    const QString source = Data + QStringLiteral("/../convert/heartbeat.ahap");
    QVERIFY2(f.designer.openFile(source, &error), qPrintable(error));
    PatternDocument *document = f.designer.document();
    QVERIFY(document->pattern());
    QVERIFY(!document->isReadOnly());
    QCOMPARE(document->path(), f.folder.filePath(QStringLiteral("heartbeat.json")));
    QCOMPARE(document->json().value(QLatin1String("name")).toString(),
             QStringLiteral("heartbeat"));
    QVERIFY(f.designer.preview()->groupCount() >= 1);
    QVERIFY(f.designer.preview()->message().isEmpty());

    // Export again and compare the envelopes.
    const QString exported = f.folder.filePath(QStringLiteral("again.ahap"));
    QVERIFY2(f.designer.saveFile(exported, &error), qPrintable(error));
    QJsonObject in;
    QJsonObject out;
    LoadError loadError;
    QVERIFY(readJsonObjectFile(source, &in, &loadError));
    QVERIFY(readJsonObjectFile(exported, &out, &loadError));
    HapticTimeline a;
    HapticTimeline b;
    QVERIFY(AhapFormat::read(in, source, &a, nullptr, &loadError));
    QVERIFY(AhapFormat::read(out, exported, &b, nullptr, &loadError));
    double worst = 0.0;
    for (int k = 0; k <= 1200; ++k)
        worst = std::max(worst,
                         std::abs(a.intensity.value(k / 1000.0) - b.intensity.value(k / 1000.0)));
    QVERIFY2(worst < 0.01, qPrintable(QString::number(worst)));
    QVERIFY(std::abs(a.sharpness - b.sharpness) < 1e-9);
}

void TestWaveformDesigner::exportImportHjif()
{
    Fixture f;
    QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
    f.designer.openBuiltin(QStringLiteral("air.squeeze"));
    QString error;
    const QString exported = f.folder.filePath(QStringLiteral("squeeze.hjif"));
    QVERIFY2(f.designer.saveFile(exported, &error), qPrintable(error));
    QJsonObject json;
    LoadError loadError;
    HjifDocument document;
    QVERIFY(readJsonObjectFile(exported, &json, &loadError));
    QVERIFY2(HjifDocument::fromJson(json, exported, &document, nullptr, &loadError),
             qPrintable(loadError.toString()));
    QCOMPARE(document.perceptions.front().modality, QStringLiteral("Pressure"));
    QCOMPARE(document.perceptions.front().channels.size(), size_t(6));

    // Opened again it is a new pattern on the file's own device, whatever the preview shows.
    f.designer.openBuiltin(QStringLiteral("vib.geiger"));
    QVERIFY2(f.designer.openFile(exported, &error), qPrintable(error));
    PatternDocument *opened = f.designer.document();
    QVERIFY(opened->pattern());
    QCOMPARE(opened->pattern()->model(), QStringLiteral("pneumatic6"));
    QCOMPARE(opened->path(), f.folder.filePath(QStringLiteral("squeeze.json")));
    QVERIFY(f.designer.preview()->message().isEmpty());
}

/** With SEMHAP_SCREENSHOTS=DIR: the designer with a built-in open, for docs/screenshots. */
void TestWaveformDesigner::screenshot()
{
    const QString dir = qEnvironmentVariable("SEMHAP_SCREENSHOTS");
    if (dir.isEmpty())
        QSKIP("set SEMHAP_SCREENSHOTS to a folder to write the screenshot");
    Fixture f;
    f.designer.openBuiltin(QStringLiteral("air.squeeze"));
    f.clickTreeNode(QStringLiteral("/tracks/0/attack"));
    for (const QSize size : {QSize(1280, 800), QSize(660, 740)}) {
        f.designer.resize(size);
        QVERIFY(QTest::qWaitForWindowExposed(&f.designer));
        QTest::qWait(200);
        QVERIFY(f.designer.grab().save(QStringLiteral("%1/waveformdesigner-%2x%3.png")
                                           .arg(dir)
                                           .arg(size.width())
                                           .arg(size.height())));
    }
}

QTEST_MAIN(TestWaveformDesigner)
#include "tst_waveformdesigner.moc"
