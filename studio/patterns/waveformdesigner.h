// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "paneldock.h"

#include <QWidget>

#include <functional>
#include <memory>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPlainTextEdit;
class QPushButton;
class QSlider;
class QTabWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace semhap {

class DeviceManager;
class NodeInspector;
class PatternAuditioner;
class PatternDocument;
class PatternPreview;
class Transport;

/**
 * The waveform designer: a library of patterns (built-ins read-only, the user's own in
 * the data folder), the pattern's waveform tree with an inspector and a raw JSON tab, a
 * preview of commanded and predicted output per channel, and an audition on a bound device
 * or a virtual one. Every edit is undoable; files open and save as `semhap.pattern/1` and
 * import and export as AHAP and `.haptic`.
 */
class WaveformDesigner : public QWidget
{
    Q_OBJECT

public:
    /** Where the main window docks it by default (PanelDock). */
    static PanelDock dock();
    /**
     * `devices` (may be null) offers its bound devices for audition; `document` is the
     * pattern to show (null: a document of the designer's own, opened on a built-in). Both
     * must outlive the designer.
     */
    explicit WaveformDesigner(DeviceManager *devices, PatternDocument *document = nullptr,
                              QWidget *parent = nullptr);
    ~WaveformDesigner() override;

    PatternDocument *document() const { return m_document; }
    PatternPreview *preview() const { return m_preview; }
    NodeInspector *inspector() const { return m_inspector; }
    QTreeWidget *tree() const { return m_tree; }
    PatternAuditioner *auditioner() const { return m_auditioner; }

    /** Where user patterns live: `AppDataLocation/patterns` unless set for tests. */
    QString userFolder() const { return m_userFolder; }
    void setUserFolder(const QString &folder);

    /** Opens a built-in read-only. */
    void openBuiltin(const QString &name);
    /** Opens a pattern, AHAP or `.haptic` file (the latter two as a new, unsaved pattern). */
    bool openFile(const QString &path, QString *error);
    /** Saves the pattern as `semhap.pattern/1`, or exports it as AHAP or `.haptic`. */
    bool saveFile(const QString &path, QString *error);
    /** Makes an editable copy of the pattern shown, named after it, saved on first save. */
    void duplicate();
    /** Selects the tree node of a JSON pointer ("" is the pattern). */
    void selectNode(const QString &pointer);
    /** Lists the built-ins and the user folder again. */
    void refreshLibrary();
    /** Lists the devices to audition on again (call after bindings changed). */
    void refreshDevices();
    /**
     * The bound device auditions play on, as last picked (empty: the virtual one); it is
     * selected whenever it is bound, so it survives a rebinding and a new window.
     */
    QString auditionDevice() const { return m_auditionDevice; }
    void setAuditionDevice(const QString &name);
    /** How the preview and auditions play the pattern: kept through a new window. */
    struct PlaySettings
    {
        double intensity = 1.0; ///< 0..1, what the pattern begins with
        double endAt = 1.5;     ///< s, when its release starts
        bool hold = false;      ///< no end: the sustain goes on
    };
    PlaySettings playSettings() const;
    void setPlaySettings(const PlaySettings &settings);
    /**
     * The time the run's readouts are at, read as an audition on a bound device begins: its
     * frames are stamped from there, so the plots draw it on after the run (none: from 0).
     */
    void setRunClock(std::function<double()> clock) { m_runClock = std::move(clock); }

public slots:
    /** Stops the audition, sending the device to zero. */
    void stopAudition();

signals:
    /** An audition is about to play on a bound device: the main window pauses the run. */
    void auditionStarting();
    /** A one-line message for the status bar. */
    void message(const QString &text);
    /**
     * A user pattern was renamed: saved under its new name as `to`, its file `from` removed.
     * Routers being edited that name `from` follow it (RouterEditor::followRenamedPattern).
     */
    void patternRenamed(const QString &from, const QString &to);

private:
    void createActions();
    QWidget *createLibrary();
    QWidget *createEditor();
    QWidget *createControls();
    void onDocumentChanged();
    void onStateChanged();
    void rebuildTree();
    void addTreeNode(QTreeWidgetItem *parent, const QString &label, const QString &pointer,
                     const QJsonValue &node);
    void updateStructureButtons();
    void updatePreview();
    void updateJsonText();
    void applyJsonText();
    void openLibraryItem();
    void save();
    /**
     * Saves a pattern of the user folder under its name, moving its file when the name was
     * edited; false (with the reason shown) when the name is taken or a write fails.
     */
    bool saveUserPattern();
    void saveAs();
    void importFile();
    void exportFile();
    void newPattern();
    void addTrack();
    void addPart(const QString &part);
    void addInput();
    void removeNode();
    void beginAudition();
    void endAudition();
    Transport *auditionTransport();
    DeviceModelPtr previewModel() const;
    void reportError(const QString &what, const QString &error);

    DeviceManager *m_devices;
    std::function<double()> m_runClock;
    QString m_userFolder;
    PatternDocument *m_document = nullptr;
    PatternPreview *m_preview = nullptr;
    NodeInspector *m_inspector = nullptr;
    PatternAuditioner *m_auditioner = nullptr;
    std::shared_ptr<Transport> m_virtual; ///< the audition's own virtual device
    QListWidget *m_library = nullptr;
    QTreeWidget *m_tree = nullptr;
    QTabWidget *m_tabs = nullptr;
    QPlainTextEdit *m_jsonText = nullptr;
    QLabel *m_jsonError = nullptr;
    QLabel *m_banner = nullptr;
    QComboBox *m_modelPicker = nullptr;
    QSlider *m_intensity = nullptr;
    QLabel *m_intensityLabel = nullptr;
    QDoubleSpinBox *m_endAt = nullptr;
    QCheckBox *m_hold = nullptr;
    QComboBox *m_devicePicker = nullptr;
    QString m_auditionDevice;
    QPushButton *m_beginButton = nullptr;
    QPushButton *m_endButton = nullptr;
    QPushButton *m_stopButton = nullptr;
    QLabel *m_auditionStatus = nullptr;
    QPushButton *m_addTrack = nullptr;
    QPushButton *m_addPart = nullptr;
    QPushButton *m_addInput = nullptr;
    QPushButton *m_remove = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_duplicateAction = nullptr;
    QAction *m_saveAction = nullptr;
    bool m_updatingText = false;
};

} // namespace semhap
