// SPDX-License-Identifier: MIT
#include "simviewport.h"

#include "colors.h"
#include "handdrive.h"
#include "scenefeed.h"
#include "world.h"

#include <QAction>
#include <QActionGroup>
#include <QKeyEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QPainter>
#include <QPainterPath>
#include <QScreen>
#include <QWindow>

#include <algorithm>
#include <cmath>
#include <optional>
#include <time.h>

namespace semhap {

namespace {

constexpr double Pi = 3.14159265358979323846;
constexpr int FrameMs = 16;
// Degrees of orbit per pixel dragged, and the zoom per wheel notch.
constexpr double OrbitPerPixel = 0.4;
constexpr double ZoomPerNotch = 0.9;
// Limits: close enough to see the pads, far enough for any scene; never under the table.
constexpr double Nearest = 0.2;
constexpr double Farthest = 4.0;
constexpr double Lowest = -89.0;
constexpr double Highest = 0.0;
constexpr double PanRange = 1.5;
// MuJoCo's default vertical field of view (degrees): a pan moves with the mouse.
constexpr double FieldOfView = 45.0;
// The wrist is this far above the pads' centre (m): Follow looks halfway.
constexpr double FingerReach = 0.06;
// How much higher (degrees) Follow looks from when neither side of the jaws sees the hand.
constexpr double FollowRaises[] = {0.0, 20.0, 40.0};

const QColor &Background = colors::SceneGround;

double clampAngle(double degrees)
{
    return std::remainder(degrees, 360.0);
}

/** Where `camera` looks from, as MuJoCo's free camera places it. */
std::array<double, 3> eyeOf(const OrbitCamera &camera)
{
    const double az = camera.azimuth * Pi / 180;
    const double el = camera.elevation * Pi / 180;
    const std::array<double, 3> forward{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                                        std::sin(el)};
    std::array<double, 3> eye{};
    for (size_t axis = 0; axis < 3; ++axis)
        eye[axis] = camera.lookAt[axis] - camera.distance * forward[axis];
    return eye;
}

/**
 * A bold heading over lines of text in a rounded dark box, readable over the floor and over
 * the black sky alike; lines wider than the width it is given wrap. Laid out first (its
 * size), so the caller can place it, then drawn.
 */
class TextBox
{
public:
    TextBox(const QFont &font, const QString &title, const QStringList &lines, qreal widest,
            Qt::Alignment horizontal)
        : m_font(font), m_bold(font), m_title(title), m_lines(lines),
          m_flags(int(horizontal & Qt::AlignHorizontal_Mask) | Qt::TextWordWrap)
    {
        m_bold.setBold(true);
        const QFontMetrics metrics(m_font);
        m_pad = metrics.height() / 2;
        const QRect room(0, 0, std::max(1, int(widest) - 2 * m_pad), 1 << 20);
        m_titleRect = QFontMetrics(m_bold).boundingRect(room, m_flags, title);
        m_textWidth = m_titleRect.width();
        m_textHeight = m_titleRect.height();
        for (const QString &line : lines) {
            m_lineRects.push_back(metrics.boundingRect(room, m_flags, line));
            m_textWidth = std::max(m_textWidth, m_lineRects.back().width());
            m_textHeight += m_lineRects.back().height();
        }
    }

    QSizeF size() const { return {qreal(m_textWidth + 2 * m_pad), m_textHeight + m_pad * 1.5}; }

    void draw(QPainter &painter, const QRectF &box, const QColor &rim, qreal rimWidth) const
    {
        QPainterPath path;
        path.addRoundedRect(box, m_pad / 2.0, m_pad / 2.0);
        painter.fillPath(path, colors::OverlayGround);
        painter.setPen(QPen(rim, rimWidth));
        painter.drawPath(path);
        qreal y = box.top() + m_pad * 3 / 4;
        const auto line = [&](const QFont &f, const QColor &colour, qreal h, const QString &t) {
            painter.setFont(f);
            painter.setPen(colour);
            painter.drawText(QRectF(box.left() + m_pad, y, m_textWidth, h), m_flags, t);
            y += h;
        };
        line(m_bold, Qt::white, m_titleRect.height(), m_title);
        for (int i = 0; i < int(m_lines.size()); ++i)
            line(m_font, colors::OverlayText, m_lineRects[size_t(i)].height(), m_lines[i]);
        painter.setFont(m_font);
    }

private:
    QFont m_font;
    QFont m_bold;
    QString m_title;
    QStringList m_lines;
    int m_flags;
    int m_pad = 0;
    QRect m_titleRect;
    std::vector<QRect> m_lineRects;
    int m_textWidth = 0;
    int m_textHeight = 0;
};

/**
 * The lines with those of hints ("Q E turn · Space grip") broken between their hints to fit
 * `room` pixels: a break inside a hint ("+/-" and "force" apart) reads as two hints.
 */
QStringList packHints(const QStringList &lines, const QFontMetrics &metrics, int room)
{
    const QString between = QStringLiteral(" · ");
    QStringList packed;
    for (const QString &line : lines) {
        QString current;
        for (const QString &hint : line.split(between)) {
            const QString longer = current.isEmpty() ? hint : current + between + hint;
            if (!current.isEmpty() && metrics.horizontalAdvance(longer) > room) {
                packed.append(current);
                current = hint;
            } else {
                current = longer;
            }
        }
        packed.append(current);
    }
    return packed;
}

} // namespace

SimViewport::SimViewport(QWidget *parent)
    : QWidget(parent), m_resetCamera(new QAction(tr("Reset camera"), this)),
      m_showForcesAction(new QAction(tr("Contact forces"), this))
{
    // Every pixel is the picture's: nothing of the parent to paint under it.
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(320, 240);

    // The window's View menu and tool bar show these; their shortcuts work anywhere in the
    // window (Home alone only here: keyPressEvent).
    m_resetCamera->setObjectName(QStringLiteral("resetCameraAction"));
    m_resetCamera->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Home));
    m_resetCamera->setToolTip(
        tr("Back to the default view (%1; Home in the viewport)")
            .arg(m_resetCamera->shortcut().toString(QKeySequence::NativeText)));
    connect(m_resetCamera, &QAction::triggered, this, &SimViewport::resetCamera);
    addAction(m_resetCamera);
    m_showForcesAction->setObjectName(QStringLiteral("forcesAction"));
    m_showForcesAction->setCheckable(true);
    m_showForcesAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F));
    m_showForcesAction->setToolTip(
        tr("Show contact forces as arrows in the viewport (%1)")
            .arg(m_showForcesAction->shortcut().toString(QKeySequence::NativeText)));
    connect(m_showForcesAction, &QAction::toggled, this, &SimViewport::setShowForces);
    addAction(m_showForcesAction);

    const QString presetNames[CameraPresetCount] = {tr("Across the jaws"), tr("From the top"),
                                                    tr("From the side"), tr("Follow the hand")};
    const char *const presetIds[CameraPresetCount] = {"cameraAcrossJaws", "cameraTop",
                                                      "cameraSide", "cameraFollow"};
    auto *presets = new QActionGroup(this);
    for (int p = 0; p < CameraPresetCount; ++p) {
        auto *preset = new QAction(presetNames[p], presets);
        preset->setObjectName(QLatin1String(presetIds[p]));
        preset->setCheckable(true);
        preset->setShortcut(QKeySequence(Qt::Key_1 + p));
        preset->setShortcutContext(Qt::WidgetShortcut);
        connect(preset, &QAction::triggered, this,
                [this, p] { setCameraPreset(CameraPreset(p)); });
        addAction(preset);
        m_presetActions[size_t(p)] = preset;
    }
    m_presetActions[0]->setChecked(true);

    m_frameTimer.setInterval(FrameMs);
    connect(&m_frameTimer, &QTimer::timeout, this, &SimViewport::frame);
    m_paceClock.start();
}

SimViewport::~SimViewport()
{
    releaseRenderer();
}

void SimViewport::setScene(const World *world, SceneFeed *feed)
{
    m_world = world;
    m_feed = world ? feed : nullptr;
    if (m_feed)
        m_feed->setShowForces(m_showForces);
    if (isValid() && makeCurrent()) {
        createRenderer();
        doneCurrent();
    }
    if (m_handDrive)
        m_handDrive->setWorld(world);
    m_home = world ? defaultCamera(*world) : OrbitCamera();
    setCameraPreset(m_preset);
}

void SimViewport::setPlaceholder(const QString &text)
{
    m_placeholder = text;
    update();
}

void SimViewport::setCaption(const QString &text)
{
    m_caption = text;
    update();
}

void SimViewport::setNotice(const QString &text)
{
    m_notice = text;
    update();
}

void SimViewport::setHandDrive(HandDrive *drive)
{
    if (m_handDrive)
        disconnect(m_handDrive, nullptr, this, nullptr);
    m_handDrive = drive;
    if (!drive)
        return;
    drive->setWorld(m_world);
    drive->setViewAzimuth(m_camera.azimuth);
    connect(drive, &HandDrive::changed, this, qOverload<>(&SimViewport::update));
    // Any drive input hands the grippers to the user.
    connect(drive, &HandDrive::driveStarted, this, [this] { setDriving(true); });
    connect(drive, &QObject::destroyed, this, [this] { m_handDrive = nullptr; });
}

void SimViewport::setShowForces(bool show)
{
    m_showForces = show;
    m_showForcesAction->setChecked(show);
    if (m_feed)
        m_feed->setShowForces(show);
}

void SimViewport::setDriving(bool driving)
{
    if (m_driving == driving)
        return;
    m_driving = driving;
    if (m_handDrive) {
        // Driving starts from where the script left the hands, and their ghosts show there
        // at once, before any drive input.
        if (driving)
            m_handDrive->startDrive();
        else
            m_handDrive->endDrive();
    }
    update();
}

void SimViewport::setCamera(const OrbitCamera &camera)
{
    changeCamera(camera);
}

void SimViewport::resetCamera()
{
    setCameraPreset(CameraPreset::AcrossJaws);
}

void SimViewport::setCameraPreset(CameraPreset preset)
{
    m_preset = preset;
    m_presetActions[size_t(preset)]->setChecked(true);
    OrbitCamera camera = m_world ? presetCamera(*m_world, preset) : OrbitCamera();
    if (preset == CameraPreset::Follow) {
        if (const std::optional<Pose> hand = activeHandPose()) {
            // Across this hand's jaws: its fingers close along its own y axis.
            const auto &q = hand->quat;
            const double yaw =
                std::atan2(2 * (q[0] * q[3] + q[1] * q[2]), 1 - 2 * (q[2] * q[2] + q[3] * q[3]));
            camera.azimuth = yaw * 180 / Pi;
        }
        m_followAim = camera;
        m_followFlipped = false;
    }
    changeCamera(camera);
    if (preset == CameraPreset::Follow)
        follow();
}

void SimViewport::nextCameraPreset()
{
    setCameraPreset(CameraPreset((int(m_preset) + 1) % CameraPresetCount));
}

std::optional<Pose> SimViewport::activeHandPose() const
{
    const Gripper hand = m_handDrive ? m_handDrive->activeHand() : Gripper::Right;
    if (m_feed && m_feed->handPose(hand))
        return m_feed->handPose(hand);
    if (m_handDrive && m_handDrive->command(hand))
        return m_handDrive->command(hand)->target;
    return std::nullopt;
}

void SimViewport::follow()
{
    const std::optional<Pose> hand = activeHandPose();
    if (!hand)
        return;
    // The pads: FingerReach along the hand's own -z, wherever it leans.
    const auto &q = hand->quat;
    const std::array<double, 3> down{-2 * (q[1] * q[3] + q[0] * q[2]),
                                     -2 * (q[2] * q[3] - q[0] * q[1]),
                                     -(1 - 2 * (q[1] * q[1] + q[2] * q[2]))};
    std::array<double, 3> pads{};
    OrbitCamera camera = m_camera;
    for (size_t axis = 0; axis < 3; ++axis) {
        pads[axis] = hand->pos[axis] + FingerReach * down[axis];
        // Between the wrist and the pads, so the fingers and what they hold are in the middle.
        camera.lookAt[axis] = (hand->pos[axis] + pads[axis]) / 2;
    }
    // The view asked for, else the other side of the jaws (a wall or the partition between),
    // then each from higher up; the side that saw the hand last is tried first, so the view
    // does not swap back and forth.
    const Gripper active = m_handDrive ? m_handDrive->activeHand() : Gripper::Right;
    bool found = false;
    for (double raise : FollowRaises) {
        for (bool flipped : {m_followFlipped, !m_followFlipped}) {
            camera.azimuth = clampAngle(m_followAim.azimuth + (flipped ? 180.0 : 0.0));
            camera.elevation = std::max(Lowest, m_followAim.elevation - raise);
            const std::array<double, 3> eye = eyeOf(camera);
            if (!m_feed ||
                (m_feed->inSight(eye, hand->pos, active) && m_feed->inSight(eye, pads, active))) {
                m_followFlipped = flipped;
                found = true;
                break;
            }
        }
        if (found)
            break;
    }
    if (!found) {
        // Hidden from everywhere: the view asked for.
        camera.azimuth = clampAngle(m_followAim.azimuth + (m_followFlipped ? 180.0 : 0.0));
        camera.elevation = m_followAim.elevation;
    }
    if (camera.lookAt != m_camera.lookAt || camera.azimuth != m_camera.azimuth ||
        camera.elevation != m_camera.elevation)
        changeCamera(camera);
}

OrbitCamera SimViewport::presetCamera(const World &world, CameraPreset preset)
{
    // The box around the task's regions and the grippers. The fingers close along y, so the
    // default view looks along +x (across the jaws, the pick side nearest) and a little
    // from above.
    double lowX = 1e9, highX = -1e9, lowY = 1e9, highY = -1e9;
    auto include = [&](double x, double y, double halfX, double halfY) {
        lowX = std::min(lowX, x - halfX);
        highX = std::max(highX, x + halfX);
        lowY = std::min(lowY, y - halfY);
        highY = std::max(highY, y + halfY);
    };
    for (const char *name : {"pick", "place", "home"}) {
        Region region;
        if (world.region(QLatin1String(name), &region))
            include(region.center[0], region.center[1], region.half[0], region.half[1]);
    }
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        if (world.hasGripper(hand))
            include(world.target(hand).pos[0], world.target(hand).pos[1], 0.06, 0.06);
    }
    OrbitCamera camera;
    if (lowX > highX)
        return camera;
    camera.lookAt = {(lowX + highX) / 2, (lowY + highY) / 2, 0.12};
    const double halfWidth = std::max((highX - lowX) / 2, (highY - lowY) / 2);
    camera.distance = std::clamp(0.25 + 1.6 * halfWidth, Nearest, Farthest);
    camera.azimuth = 0.0;
    camera.elevation = -30.0;
    switch (preset) {
    case CameraPreset::AcrossJaws:
        break;
    case CameraPreset::Top:
        camera.lookAt[2] = 0.0;
        camera.distance = std::clamp(0.3 + 2.0 * halfWidth, Nearest, Farthest);
        camera.elevation = Lowest;
        break;
    case CameraPreset::Side:
        camera.azimuth = 90.0;
        camera.elevation = -20.0;
        break;
    case CameraPreset::Follow:
        camera.distance = 0.45;
        camera.elevation = -20.0;
        break;
    }
    return camera;
}

void SimViewport::changeCamera(const OrbitCamera &camera)
{
    m_camera = camera;
    m_camera.distance = std::clamp(camera.distance, Nearest, Farthest);
    m_camera.elevation = std::clamp(camera.elevation, Lowest, Highest);
    m_camera.azimuth = clampAngle(camera.azimuth);
    for (size_t axis = 0; axis < 3; ++axis) {
        m_camera.lookAt[axis] = std::clamp(camera.lookAt[axis], m_home.lookAt[axis] - PanRange,
                                           m_home.lookAt[axis] + PanRange);
    }
    if (m_handDrive)
        m_handDrive->setViewAzimuth(m_camera.azimuth);
    update();
    emit cameraChanged();
}

bool SimViewport::isValid() const
{
    return m_context && m_context->isValid();
}

bool SimViewport::makeCurrent()
{
    if (!m_context) {
        QSurfaceFormat format = QSurfaceFormat::defaultFormat();
        format.setProfile(QSurfaceFormat::CompatibilityProfile); // MuJoCo's fixed-function GL
        format.setDepthBufferSize(24);
        m_surface = std::make_unique<QOffscreenSurface>();
        m_surface->setFormat(format);
        m_surface->create();
        m_context = std::make_unique<QOpenGLContext>();
        m_context->setFormat(format);
        if (!m_context->create() || !m_context->makeCurrent(m_surface.get())) {
            m_context.reset();
            return false;
        }
        createRenderer();
        return true;
    }
    return m_context->makeCurrent(m_surface.get());
}

void SimViewport::doneCurrent()
{
    if (m_context)
        m_context->doneCurrent();
}

void SimViewport::createRenderer()
{
    m_renderer.reset();
    if (!m_world)
        return;
    m_renderer = std::make_unique<SceneRenderer>(*m_world);
    m_renderer->initialize();
}

void SimViewport::releaseRenderer()
{
    if (!m_context)
        return;
    // MuJoCo's GL resources and the framebuffer go while their context is current.
    m_context->makeCurrent(m_surface.get());
    m_renderer.reset();
    m_target.reset();
    m_context->doneCurrent();
}

void SimViewport::paintEvent(QPaintEvent *)
{
    // What the frame cost the process: rendering on every thread (software GL renders on
    // several) and reading the picture back.
    const double cpu = processCpuSeconds();
    render();
    if (m_pacedFrame) {
        m_pacedFrame = false;
        m_pace.frameDrawn(m_pacedStart, processCpuSeconds() - cpu);
    }
    QPainter painter(this);
    painter.drawImage(QPointF(0, 0), m_picture);
}

QImage SimViewport::grabFramebuffer()
{
    render();
    return m_picture;
}

void SimViewport::render()
{
    const qreal ratio = devicePixelRatioF();
    const QSize pixels(int(std::lround(width() * ratio)), int(std::lround(height() * ratio)));
    bool drawn = false;
    if (m_feed && !pixels.isEmpty() && makeCurrent()) {
        if (m_renderer) {
            if (!m_target || m_target->size() != pixels)
                m_target = std::make_unique<QOpenGLFramebufferObject>(pixels);
            m_renderer->camera() = m_camera;
            m_renderer->setMarkers(markers());
            drawn =
                m_renderer->render(*m_feed, m_target->handle(), pixels.width(), pixels.height());
            if (drawn)
                m_picture = m_target->toImage().convertToFormat(QImage::Format_RGB32);
        }
        doneCurrent();
    }
    if (drawn) {
        ++m_renderedFrames;
    } else {
        m_picture = QImage(pixels, QImage::Format_RGB32);
        m_picture.fill(Background);
    }
    m_picture.setDevicePixelRatio(ratio);
    QPainter painter(&m_picture);
    const QRectF notice = m_notice.isEmpty() ? QRectF() : drawNotice(painter);
    drawOverlay(painter, drawn, notice);
}

QRectF SimViewport::drawNotice(QPainter &painter)
{
    // Centred at the bottom; the driver's box keeps clear of it.
    QStringList lines = m_notice.split(QLatin1Char('\n'));
    const QString title = lines.takeFirst();
    const int pad = painter.fontMetrics().height() / 2;
    const QRectF area = QRectF(rect()).adjusted(pad, pad, -pad, -pad);
    const TextBox box(painter.font(), title, lines, area.width(), Qt::AlignHCenter);
    QRectF placed(QPointF(), box.size());
    placed.moveCenter(area.center());
    placed.moveBottom(area.bottom());
    box.draw(painter, placed, colors::Ok, 3.0);
    return placed;
}

void SimViewport::drawOverlay(QPainter &painter, bool hasPicture, const QRectF &notice)
{
    m_overlayBox = QRectF();
    m_overlayText.clear();
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    if (!hasPicture) {
        font.setPointSizeF(font.pointSizeF() * 1.3);
        painter.setFont(font);
        painter.setPen(colors::OverlayCaption);
        const QString text = m_world                   ? tr("Waiting for the simulation…")
                             : m_placeholder.isEmpty() ? tr("No scene loaded")
                                                       : m_placeholder;
        painter.drawText(rect(), Qt::AlignCenter, text);
        return;
    }

    QStringList lines;
    QString title;
    if (!m_caption.isEmpty()) {
        title = m_caption;
    } else if (m_driving) {
        const QLocale locale; // the interface language's numbers
        const Gripper hand = m_handDrive ? m_handDrive->activeHand() : Gripper::Right;
        title = hand == Gripper::Right ? tr("You are driving (right hand)")
                                       : tr("You are driving (left hand)");
        const DriveStatus status = m_handDrive ? m_handDrive->status(hand) : DriveStatus();
        if (m_handDrive && m_handDrive->command(hand))
            lines << gripLine(hand, status, locale);
        if (m_handDrive) {
            if (status.floor)
                lines << tr("Resting on what is below: the wrist stops here");
            else if (status.driven && status.surface)
                lines << tr("Wrist %1 cm above the surface below")
                             .arg(locale.toString((status.target.pos[2] - *status.surface) * 100,
                                                  'f', 1));
        }
        lines << tr("W A S D move · R F up/down · Q E turn · Space grip · +/- force");
        if (m_handDrive) {
            // Which table axes the keys follow now, so a turned camera is no surprise.
            const auto [x, y] = m_handDrive->awayDirection();
            auto axis = [](double ax, double ay) {
                return ax > 0.5    ? QStringLiteral("+x")
                       : ax < -0.5 ? QStringLiteral("−x")
                       : ay > 0.5  ? QStringLiteral("+y")
                                   : QStringLiteral("−y");
            };
            lines << tr("W goes %1, D goes %2 · 1–4 camera").arg(axis(x, y), axis(y, -x));
        }
        if (m_handDrive && m_handDrive->hasBothHands())
            lines << tr("Tab: switch hand");
    } else {
        // Scripted or reactive: the status bar names which.
        title = tr("Simulated operator");
        if (m_handDrive)
            lines << tr("Click here and press W A S D to drive");
    }

    // Narrow enough that a hand in the middle is clear of it; a line of key hints wraps
    // between its hints ("Q E turn · Space grip"), never inside one.
    const QFontMetrics metrics(font);
    const int pad = metrics.height() / 2;
    const QRectF area = QRectF(rect()).adjusted(pad, pad, -pad, -pad);
    const qreal widest =
        std::min(area.width(), std::max(0.4 * area.width(), 24.0 * metrics.averageCharWidth()));
    const TextBox box(font, title, packHints(lines, metrics, int(widest) - 2 * pad), widest,
                      Qt::AlignLeft);
    m_overlayBox = placeOverlay(box.size(), area, notice);
    box.draw(painter, m_overlayBox, colors::veil(90), 1.0);
    m_overlayText = (QStringList{title} + lines).join(QLatin1Char('\n'));
}

QString SimViewport::gripLine(Gripper hand, const DriveStatus &status, const QLocale &locale) const
{
    auto newtons = [&locale](double force) { return locale.toString(force, 'f', 0); };
    const QString setpoint = newtons(m_handDrive->gripSetpoint(hand));
    // The force the simulation applies, which the guarded close holds below the command
    // until both pads touch the cube; none before the run's first step since driving began.
    if (!status.grip)
        return m_handDrive->isClosed(hand)
                   ? tr("Grip: %1 N asked, applied at the run's next step").arg(setpoint)
                   : tr("Grip: open (closes to %1 N)").arg(setpoint);
    const QString applied = newtons(*status.grip);
    if (!m_handDrive->isClosed(hand))
        return *status.grip > 0 ? tr("Grip: opening, %1 N").arg(applied)
                                : tr("Grip: open (closes to %1 N)").arg(setpoint);
    if (applied == setpoint)
        return tr("Grip: closed, %1 N").arg(applied);
    return status.squeezing
               ? tr("Grip: %1 N of %2 N, tightening on what the pads touch").arg(applied, setpoint)
               : tr("Grip: %1 N of %2 N, closing slowly until both pads touch")
                     .arg(applied, setpoint);
}

QRectF SimViewport::placeOverlay(const QSizeF &size, const QRectF &area,
                                 const QRectF &notice) const
{
    // The first corner clear of the driven hands (their ghosts, grippers and drop lines) and
    // of the notice, from the top left; else the least covering.
    std::vector<QRectF> keepClear = handAreas();
    if (!notice.isEmpty())
        keepClear.push_back(notice);
    const auto covered = [&keepClear](const QRectF &placed) {
        qreal overlap = 0.0;
        for (const QRectF &clear : keepClear) {
            const QRectF both = placed & clear;
            overlap += both.width() * both.height();
        }
        return overlap;
    };
    QRectF best;
    for (const Qt::Corner corner :
         {Qt::TopLeftCorner, Qt::TopRightCorner, Qt::BottomLeftCorner, Qt::BottomRightCorner}) {
        QRectF placed(area.topLeft(), size);
        if (corner == Qt::TopRightCorner || corner == Qt::BottomRightCorner)
            placed.moveRight(area.right());
        if (corner == Qt::BottomLeftCorner || corner == Qt::BottomRightCorner)
            placed.moveBottom(area.bottom());
        if (best.isNull() || covered(placed) < covered(best))
            best = placed;
    }
    return best;
}

std::optional<QPointF> SimViewport::project(const std::array<double, 3> &point) const
{
    // MuJoCo's free camera: it looks at lookAt from `distance` away, along the azimuth and
    // elevation, with a vertical field of view of FieldOfView.
    const double az = m_camera.azimuth * Pi / 180;
    const double el = m_camera.elevation * Pi / 180;
    const std::array<double, 3> forward{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                                        std::sin(el)};
    const std::array<double, 3> right{std::sin(az), -std::cos(az), 0.0};
    const std::array<double, 3> up{-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az),
                                   std::cos(el)};
    const std::array<double, 3> eye = eyeOf(m_camera);
    std::array<double, 3> v{};
    for (size_t axis = 0; axis < 3; ++axis)
        v[axis] = point[axis] - eye[axis];
    const auto dot = [&v](const std::array<double, 3> &w) {
        return v[0] * w[0] + v[1] * w[1] + v[2] * w[2];
    };
    const double depth = dot(forward);
    if (depth <= 1e-3)
        return std::nullopt;
    const double scale = height() / 2.0 / std::tan(FieldOfView / 2 * Pi / 180) / depth;
    return QPointF(width() / 2.0 + dot(right) * scale, height() / 2.0 - dot(up) * scale);
}

std::vector<QRectF> SimViewport::handAreas() const
{
    // Around each driven hand's target: the ghost, the fingers below it (the gripper follows
    // the target) and the drop line down to the surface.
    constexpr double Reach = 0.05; // the open fingers' half span, and the ghost's
    std::vector<QRectF> areas;
    for (const WristMarker &marker : markers()) {
        const auto &t = marker.target;
        std::vector<std::array<double, 3>> corners;
        for (const double dx : {-Reach, Reach}) {
            for (const double dy : {-Reach, Reach}) {
                for (const double z : {t[2] + Reach / 2, t[2] - 2 * FingerReach})
                    corners.push_back({t[0] + dx, t[1] + dy, z});
            }
        }
        if (marker.surface)
            corners.push_back({t[0], t[1], *marker.surface});
        QRectF area;
        for (const auto &corner : corners) {
            if (const std::optional<QPointF> point = project(corner))
                area |= QRectF(*point, QSizeF(1, 1));
        }
        if (!area.isEmpty())
            areas.push_back(area);
    }
    return areas;
}

std::vector<WristMarker> SimViewport::markers() const
{
    std::vector<WristMarker> markers;
    if (!m_driving || !m_handDrive)
        return markers;
    for (Gripper hand : {Gripper::Left, Gripper::Right}) {
        if (!m_handDrive->command(hand))
            continue;
        const DriveStatus status = m_handDrive->status(hand);
        WristMarker marker;
        marker.hand = hand;
        const Pose &target = status.driven ? status.target : m_handDrive->command(hand)->target;
        marker.target = target.pos;
        marker.quat = target.quat;
        marker.surface = status.surface;
        marker.guarded = status.floor.has_value();
        marker.active = hand == m_handDrive->activeHand();
        markers.push_back(marker);
    }
    return markers;
}

void SimViewport::frame()
{
    if (!m_feed)
        return;
    // A minimised or covered window shows nothing: nothing is drawn, nothing asked for.
    const QWindow *shown = window()->windowHandle();
    if (window()->isMinimized() || (shown && !shown->isExposed()))
        return;
    m_feed->request();
    // Redraw only when the simulation sent something new (a paused run costs nothing), and
    // at the pace the frames' cost allows.
    m_freshPicture = m_feed->takeLatest() || m_freshPicture;
    if (m_preset == CameraPreset::Follow)
        follow(); // where the hand is in the newest picture
    const double now = double(m_paceClock.nsecsElapsed()) * 1e-9;
    // A frame asked for and never shown (the window hid meanwhile) is not waited for long.
    if (m_pacedFrame && now - m_pacedStart > FramePace::LongestInterval)
        m_pacedFrame = false;
    if (!m_freshPicture || m_pacedFrame || !m_pace.due(now))
        return;
    m_freshPicture = false;
    m_pacedFrame = true;
    m_pacedStart = now;
    m_pacedCpu = processCpuSeconds();
    update();
}

double SimViewport::processCpuSeconds()
{
    timespec cpu{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
    return double(cpu.tv_sec) + double(cpu.tv_nsec) * 1e-9;
}

void SimViewport::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (screen())
        m_pace.setDisplayRate(screen()->refreshRate());
    m_frameTimer.start();
}

void SimViewport::hideEvent(QHideEvent *event)
{
    m_frameTimer.stop();
    QWidget::hideEvent(event);
}

void SimViewport::mousePressEvent(QMouseEvent *event)
{
    m_lastMouse = event->position().toPoint();
    m_panning = event->button() == Qt::RightButton ||
                (event->button() == Qt::LeftButton && event->modifiers() & Qt::ShiftModifier);
    event->accept();
}

void SimViewport::mouseMoveEvent(QMouseEvent *event)
{
    if (!(event->buttons() & (Qt::LeftButton | Qt::RightButton)))
        return;
    const QPoint now = event->position().toPoint();
    const double dx = now.x() - m_lastMouse.x();
    const double dy = now.y() - m_lastMouse.y();
    m_lastMouse = now;
    OrbitCamera camera = m_camera;
    if (m_panning) {
        // The point under the mouse stays under it: scale pixels to metres at the target.
        const double scale =
            2 * camera.distance * std::tan(FieldOfView / 2 * Pi / 180) / std::max(1, height());
        const double az = camera.azimuth * Pi / 180;
        const double el = camera.elevation * Pi / 180;
        const std::array<double, 3> right{std::sin(az), -std::cos(az), 0.0};
        const std::array<double, 3> up{-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az),
                                       std::cos(el)};
        for (size_t axis = 0; axis < 3; ++axis)
            camera.lookAt[axis] += scale * (-dx * right[axis] + dy * up[axis]);
    } else if (m_preset == CameraPreset::Follow) {
        // Orbiting turns the view Follow keeps; it still picks the side that sees the hand.
        m_followAim.azimuth -= OrbitPerPixel * dx;
        m_followAim.elevation =
            std::clamp(m_followAim.elevation - OrbitPerPixel * dy, Lowest, Highest);
        follow();
        return;
    } else {
        camera.azimuth -= OrbitPerPixel * dx;
        camera.elevation -= OrbitPerPixel * dy;
    }
    changeCamera(camera);
}

void SimViewport::mouseReleaseEvent(QMouseEvent *event)
{
    m_panning = event->buttons() & Qt::RightButton;
}

void SimViewport::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton)
        resetCamera();
}

void SimViewport::wheelEvent(QWheelEvent *event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (event->modifiers() & Qt::ControlModifier) {
        // Ctrl + wheel: the grip force, a whole step per notch.
        if (m_handDrive)
            m_handDrive->adjustGrip(int(std::lround(notches)));
    } else {
        OrbitCamera camera = m_camera;
        camera.distance *= std::pow(ZoomPerNotch, notches);
        changeCamera(camera);
    }
    event->accept();
}

std::vector<std::pair<QKeySequence, QString>> SimViewport::ownKeys() const
{
    return {{QKeySequence(Qt::Key_Home), m_resetCamera->iconText()}};
}

void SimViewport::keyPressEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Home && event->modifiers() == Qt::NoModifier) {
        resetCamera();
        event->accept();
        return;
    }
    // Auto-repeat would make a held key stutter: the keyboard drive integrates held keys itself.
    if (m_handDrive &&
        (event->isAutoRepeat() || m_handDrive->press(event->key(), event->modifiers())))
        event->accept();
    else
        QWidget::keyPressEvent(event);
}

void SimViewport::keyReleaseEvent(QKeyEvent *event)
{
    if (m_handDrive && (event->isAutoRepeat() || m_handDrive->release(event->key())))
        event->accept();
    else
        QWidget::keyReleaseEvent(event);
}

void SimViewport::focusOutEvent(QFocusEvent *event)
{
    // A key released elsewhere never reaches us: stop, or the hand drifts on.
    if (m_handDrive)
        m_handDrive->releaseAll();
    QWidget::focusOutEvent(event);
}

bool SimViewport::focusNextPrevChild(bool next)
{
    // With two hands, Tab switches between them instead of leaving the viewport.
    if (m_handDrive && m_handDrive->hasBothHands())
        return false;
    return QWidget::focusNextPrevChild(next);
}

} // namespace semhap
