// SPDX-License-Identifier: MIT
#pragma once

#include "framepace.h"
#include "pose.h"
#include "scenerenderer.h"

#include <QElapsedTimer>
#include <QImage>
#include <QKeySequence>
#include <QPoint>
#include <QRectF>
#include <QTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QAction;
class QFocusEvent;
class QHideEvent;
class QKeyEvent;
class QLocale;
class QMouseEvent;
class QOffscreenSurface;
class QOpenGLContext;
class QOpenGLFramebufferObject;
class QPaintEvent;
class QPainter;
class QShowEvent;
class QWheelEvent;

namespace semhap {

class HandDrive;
struct DriveStatus;

/** The camera views a key or the View menu picks. */
enum class CameraPreset
{
    AcrossJaws, ///< the default: across the fingers' closing axis, so the gap shows
    Top,
    Side, ///< along the closing axis
    Follow,
};
constexpr int CameraPresetCount = 4;
class SceneFeed;
class World;

/**
 * The simulation as a picture: draws a SceneFeed's newest capture with MuJoCo's renderer,
 * at most at the display's rate and within a CPU budget (FramePace), lets the mouse orbit,
 * pan and zoom the camera, shows who drives the grippers in a small overlay, and forwards
 * drive keys to a HandDrive. It only asks the feed for pictures; the simulation thread
 * captures them. MuJoCo renders into an offscreen framebuffer of the viewport's own GL
 * context and the picture is painted as an image: the window stays a plain raster window,
 * which a QOpenGLWidget would make the GL driver compose whole at every repaint of any
 * widget (with software GL, most of the studio's CPU).
 */
class SimViewport : public QWidget
{
    Q_OBJECT

public:
    explicit SimViewport(QWidget *parent = nullptr);
    ~SimViewport() override;

    /**
     * The world to draw and the feed its pictures come through (both null to clear; both
     * must outlive the viewport or be cleared first). Resets the camera to the scene's view.
     */
    void setScene(const World *world, SceneFeed *feed);
    /** What the viewport says while it has no scene (a replay, a live rig); empty: default. */
    void setPlaceholder(const QString &text);
    const QString &placeholder() const { return m_placeholder; }
    /**
     * The heading of the corner box over the picture in place of who drives (a replay);
     * empty: the driver and the keys.
     */
    void setCaption(const QString &text);
    const QString &caption() const { return m_caption; }
    /**
     * A notice over the top of the picture until it is cleared (empty), such as the task's
     * end: its first line is the heading, the others say more.
     */
    void setNotice(const QString &text);
    const QString &notice() const { return m_notice; }
    /** Where drive keys go (null: nowhere); it is given the scene. Not owned. */
    void setHandDrive(HandDrive *drive);
    HandDrive *handDrive() const { return m_handDrive; }

    /** Draws contact forces as arrows. */
    void setShowForces(bool show);
    bool showForces() const { return m_showForces; }
    /** Whether the user drives the grippers (the overlay says so) or the scripted operator. */
    void setDriving(bool driving);
    bool isDriving() const { return m_driving; }

    const OrbitCamera &camera() const { return m_camera; }
    void setCamera(const OrbitCamera &camera);
    /** Back to the scene's default view (also a double-click): across the jaws. */
    void resetCamera();
    /**
     * One of the preset views (keys 1–4); Follow keeps the active hand in the middle, looking
     * across its jaws, from whichever side and height sees it past the scene's walls and the
     * other hand, until another view.
     */
    void setCameraPreset(CameraPreset preset);
    /** The next preset after the last one picked (a gamepad button). */
    void nextCameraPreset();
    CameraPreset cameraPreset() const { return m_preset; }
    /** A view that frames the scene's task, its regions and grippers, from the preset's side. */
    static OrbitCamera presetCamera(const World &world, CameraPreset preset);
    static OrbitCamera defaultCamera(const World &world)
    {
        return presetCamera(world, CameraPreset::AcrossJaws);
    }

    /**
     * The viewport's actions, which the main window's View menu and tool bar show: reset the
     * camera (Ctrl+Home in the window, Home in the viewport), a camera preset (1 to 4 in the
     * viewport), show contact forces (Ctrl+F).
     */
    QAction *resetCameraAction() const { return m_resetCamera; }
    /** The presets' actions (checkable, keys 1–4 while the viewport has the focus). */
    QAction *cameraPresetAction(CameraPreset preset) const
    {
        return m_presetActions[size_t(preset)];
    }
    QAction *showForcesAction() const { return m_showForcesAction; }
    /** Keys the viewport takes itself, not through an action, and what each does: the key map's.
     */
    std::vector<std::pair<QKeySequence, QString>> ownKeys() const;

    /**
     * Where the corner box saying who drives was last drawn (widget coordinates; empty:
     * none): in a corner clear of the driven hands and the notice.
     */
    QRectF overlayBox() const { return m_overlayBox; }
    /** What that box said, its heading and lines, one a line (empty: none drawn). */
    QString overlayText() const { return m_overlayText; }

    /** Renders the view now and gives the picture as shown, overlay included. */
    QImage grabFramebuffer();
    /** Whether the viewport has a GL context to render with (made when first shown). */
    bool isValid() const;

    /** Frames drawn from a picture so far (tests, a frame-rate readout). */
    quint64 renderedFrames() const { return m_renderedFrames; }
    /** When frames are drawn: at most at the display's rate, within a CPU budget. */
    const FramePace &pace() const { return m_pace; }

signals:
    void cameraChanged();

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;
    bool focusNextPrevChild(bool next) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    /** Makes the GL context and its offscreen surface current, made on first use. */
    bool makeCurrent();
    void doneCurrent();
    /** Renders the scene and the overlay into m_picture. */
    void render();
    /** Makes a renderer for the scene in the current context (MuJoCo's GL resources). */
    void createRenderer();
    /** Frees MuJoCo's GL resources while their context is still there. */
    void releaseRenderer();
    void frame();
    /** The CPU time this process has used, all its threads (s). */
    static double processCpuSeconds();
    void changeCamera(const OrbitCamera &camera);
    /** The corner box (who drives, the keys), placed clear of handAreas() and `notice`. */
    void drawOverlay(QPainter &painter, bool hasPicture, const QRectF &notice);
    /**
     * The overlay's grip line for driven `hand`: the force the simulation applies (`status`)
     * and, while the guarded close holds it lower, the force asked for.
     */
    QString gripLine(Gripper hand, const DriveStatus &status, const QLocale &locale) const;
    /** Where a box of `size` goes in `area`: a corner clear of handAreas() and `notice`. */
    QRectF placeOverlay(const QSizeF &size, const QRectF &area, const QRectF &notice) const;
    /** Draws the notice at the bottom; where it went. */
    QRectF drawNotice(QPainter &painter);
    /** Where `point` (world coordinates) shows in the widget; none behind the camera. */
    std::optional<QPointF> project(const std::array<double, 3> &point) const;
    /** Where each driven hand shows: its ghost, its fingers and its drop line. */
    std::vector<QRectF> handAreas() const;
    /** The driven hands' ghosts and drop lines, from the drive and its status. */
    std::vector<WristMarker> markers() const;
    /** Follow: the active hand in the middle, across its jaws, in plain sight. */
    void follow();
    /** Where the active hand is in the newest picture, else where it is commanded to be. */
    std::optional<Pose> activeHandPose() const;

    const World *m_world = nullptr;
    QString m_placeholder;
    QString m_caption;
    QString m_notice;
    SceneFeed *m_feed = nullptr;
    HandDrive *m_handDrive = nullptr;
    std::unique_ptr<SceneRenderer> m_renderer;
    OrbitCamera m_camera;
    OrbitCamera m_home;
    QTimer m_frameTimer;
    std::unique_ptr<QOpenGLContext> m_context;
    std::unique_ptr<QOffscreenSurface> m_surface;
    std::unique_ptr<QOpenGLFramebufferObject> m_target;
    QImage m_picture; ///< the last frame, overlay included, at the device's pixel ratio
    FramePace m_pace;
    QElapsedTimer m_paceClock;
    bool m_freshPicture = false; ///< a picture came that is not drawn yet
    bool m_pacedFrame = false;   ///< a frame asked for, not shown yet
    double m_pacedStart = 0.0;   ///< when it was asked for (m_paceClock s)
    double m_pacedCpu = 0.0;     ///< the process's CPU time then
    QAction *m_resetCamera;
    QAction *m_showForcesAction;
    std::array<QAction *, CameraPresetCount> m_presetActions{};
    CameraPreset m_preset = CameraPreset::AcrossJaws;
    /** Follow's view as picked (the preset, then orbiting): its azimuth and elevation. */
    OrbitCamera m_followAim;
    /** Follow looks from the other side of the jaws than m_followAim: that side saw the hand. */
    bool m_followFlipped = false;
    QPoint m_lastMouse;
    bool m_panning = false;
    bool m_showForces = false;
    bool m_driving = false;
    quint64 m_renderedFrames = 0;
    QRectF m_overlayBox;
    QString m_overlayText;
};

} // namespace semhap
