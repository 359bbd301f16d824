// SPDX-License-Identifier: MIT
// The scene renderer in a real OpenGL context (run under Xvfb): it draws the scene, the
// overlay tints the gripper in its colour, and grabs are opaque. The images are saved
// beside the test binary to be looked at.
#include "imagechecks.h"
#include "scenefeed.h"
#include "scenerenderer.h"
#include "world.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QTest>

using namespace semhap;

namespace {

/** Pixels close to `colour` (the overlay's tint, lit or in shade). */
int pixelsNear(const QImage &image, QColor colour)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.hueF() - colour.hueF()) < 0.04 && c.saturationF() > 0.6 &&
                c.valueF() > 0.25)
                ++count;
        }
    }
    return count;
}

} // namespace

class TestSimView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void feedHandsOverTheNewestPicture();
    void feedKnowsWhatHidesAHand_data();
    void feedKnowsWhatHidesAHand();
    void rendersTheScene();
    void overlayTintsTheGripper_data();
    void overlayTintsTheGripper();

private:
    QImage render(const SceneOverlay &overlay, const QString &name);

    QOffscreenSurface m_surface;
    QOpenGLContext m_context;
    std::unique_ptr<World> m_world;
    std::unique_ptr<SceneFeed> m_feed;
    std::unique_ptr<SceneRenderer> m_renderer;
};

void TestSimView::initTestCase()
{
    QSurfaceFormat format;
    format.setProfile(QSurfaceFormat::CompatibilityProfile); // MuJoCo needs it
    format.setDepthBufferSize(24);
    m_surface.setFormat(format);
    m_surface.create();
    m_context.setFormat(format);
    QVERIFY(m_context.create());
    QVERIFY(m_context.makeCurrent(&m_surface));
    QString error;
    m_world = World::load("box_and_block", SceneOptions(), &error);
    QVERIFY2(m_world, qPrintable(error));
    for (int k = 0; k < 50; ++k)
        m_world->step();
    m_feed = std::make_unique<SceneFeed>(*m_world);
    m_renderer = std::make_unique<SceneRenderer>(*m_world);
    m_renderer->initialize();
    QVERIFY(m_renderer->isInitialized());
    m_renderer->camera().lookAt = {-0.1, 0.0, 0.12};
    m_renderer->camera().distance = 0.75;
}

QImage TestSimView::render(const SceneOverlay &overlay, const QString &name)
{
    QOpenGLFramebufferObject fbo(800, 600, QOpenGLFramebufferObject::CombinedDepthStencil);
    m_feed->capture(*m_world, overlay);
    if (!m_renderer->render(*m_feed, fbo.handle(), fbo.width(), fbo.height()))
        return QImage();
    const QImage image = fbo.toImage();
    image.save(QString("%1/simview-%2.png").arg(QCoreApplication::applicationDirPath(), name));
    return image;
}

void TestSimView::feedHandsOverTheNewestPicture()
{
    SceneFeed feed(*m_world);
    QVERIFY(feed.wantsCapture()); // a new viewport wants its first picture
    QVERIFY(!feed.takeLatest());
    QVERIFY(!feed.hasPicture());
    QOpenGLFramebufferObject fbo(64, 48);
    QVERIFY(!m_renderer->render(feed, fbo.handle(), fbo.width(), fbo.height()));

    feed.capture(*m_world, {});
    QVERIFY(!feed.wantsCapture());
    feed.capture(*m_world, {}); // the renderer was slow: only the newest counts
    QVERIFY(feed.takeLatest());
    QVERIFY(!feed.takeLatest());
    QVERIFY(feed.hasPicture());
    feed.request();
    QVERIFY(feed.wantsCapture());
}

void TestSimView::feedKnowsWhatHidesAHand_data()
{
    // box_and_block: the partition stands at x = 0, 15 cm high; the right hand's wrist is
    // at (-0.15, 0, 0.3) after the first steps, its palm around it.
    QTest::addColumn<QVector<double>>("eye");
    QTest::addColumn<QVector<double>>("point");
    QTest::addColumn<bool>("clear");
    QTest::newRow("through the partition")
        << QVector<double>{-0.4, 0.0, 0.1} << QVector<double>{0.15, 0.0, 0.05} << false;
    QTest::newRow("grazing the partition's top")
        << QVector<double>{-0.4, 0.0, 0.4} << QVector<double>{0.15, 0.0, 0.05} << false;
    QTest::newRow("from box B's side")
        << QVector<double>{0.55, 0.0, 0.2} << QVector<double>{0.15, 0.0, 0.05} << true;
    QTest::newRow("high over the partition")
        << QVector<double>{-0.4, 0.0, 0.6} << QVector<double>{0.15, 0.0, 0.1} << true;
    QTest::newRow("a cube on the way does not count")
        << QVector<double>{-0.27, -0.06, 0.03} << QVector<double>{-0.1, -0.06, 0.03} << true;
    QTest::newRow("what the point touches does not count")
        << QVector<double>{0.15, 0.0, 0.4} << QVector<double>{0.15, 0.0, 0.002} << true;
}

void TestSimView::feedKnowsWhatHidesAHand()
{
    QFETCH(QVector<double>, eye);
    QFETCH(QVector<double>, point);
    QFETCH(bool, clear);
    SceneFeed feed(*m_world);
    QVERIFY(!feed.handPose(Gripper::Right)); // no picture yet
    feed.capture(*m_world, {});
    QVERIFY(feed.takeLatest());
    const std::optional<Pose> wrist = feed.handPose(Gripper::Right);
    QVERIFY(wrist);
    QCOMPARE(wrist->pos, m_world->gripperPose(Gripper::Right).pos);
    QVERIFY(!feed.handPose(Gripper::Left)); // the scene has one hand

    const std::array<double, 3> from{eye[0], eye[1], eye[2]};
    const std::array<double, 3> to{point[0], point[1], point[2]};
    QCOMPARE(feed.inSight(from, to, Gripper::Right), clear);
    // A hand hides nothing from itself, but from the other hand's view it is in the way.
    const std::array<double, 3> above{wrist->pos[0], wrist->pos[1], wrist->pos[2] + 0.2};
    const std::array<double, 3> below{wrist->pos[0], wrist->pos[1], wrist->pos[2] - 0.1};
    QVERIFY(feed.inSight(above, below, Gripper::Right));
    QVERIFY(!feed.inSight(above, below, Gripper::Left));
}

void TestSimView::rendersTheScene()
{
    const QImage image = render({}, "plain");
    QString why;
    QVERIFY2(looksDrawn(image, &why), qPrintable(why));
}

void TestSimView::overlayTintsTheGripper_data()
{
    QTest::addColumn<double>("confirm");
    QTest::addColumn<double>("warn");
    QTest::addColumn<QColor>("colour");
    QTest::newRow("confirmation: blue") << 1.0 << 0.0 << QColor::fromRgbF(0.0f, 0.447f, 0.698f);
    QTest::newRow("warning: orange") << 0.0 << 1.0 << QColor::fromRgbF(0.902f, 0.624f, 0.0f);
    QTest::newRow("warning over confirmation")
        << 1.0 << 1.0 << QColor::fromRgbF(0.902f, 0.624f, 0.0f);
}

void TestSimView::overlayTintsTheGripper()
{
    QFETCH(double, confirm);
    QFETCH(double, warn);
    QFETCH(QColor, colour);
    const QImage plain = render({}, "plain");
    SceneOverlay overlay;
    overlay.rightConfirm = confirm;
    overlay.rightWarn = warn;
    const QImage tinted = render(overlay, QTest::currentDataTag());
    const int before = pixelsNear(plain, colour);
    const int after = pixelsNear(tinted, colour);
    QVERIFY2(after > before + 500, qPrintable(QString("%1 -> %2 pixels").arg(before).arg(after)));
}

QTEST_MAIN(TestSimView)
#include "tst_simview.moc"
