// The viewport draws the scene and cached water for real: these tests render into the widget's
// framebuffer and check pixels where the camera says things are. Runs under a real (virtual) X
// server: QOpenGLWidget crashes on the offscreen platform.
#include "PixelCounts.h"
#include "scene/SceneJson.h"
#include "sim/Simulation.h"
#include "support/WidgetTestMain.h"
#include "viewport/BodyDrawable.h"
#include "viewport/BoxGizmoDrawable.h"
#include "viewport/BubbleDrawable.h"
#include "viewport/SpeedColormap.h"
#include "viewport/SpeedLegend.h"
#include "viewport/ViewportWidget.h"

#include <QLineF>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>
#include <cmath>

namespace airtrap {

namespace {

const QSize kViewportSize(640, 480);

Scene damBreak() {
    return readSceneFile(AIRTRAP_SOURCE_DIR "/samples/dam_break.json");
}

//! The dam break with an obstacle standing in the empty part of the tank.
Scene damBreakWithObstacle() {
    Scene scene = damBreak();
    BoxObstacle obstacle;
    obstacle.center = Vec3d(1.6, 0.3, 0.2);
    obstacle.size = Vec3d(0.3, 0.6, 0.3);
    scene.obstacles.push_back(obstacle);
    return scene;
}

//! Frame 1 of `scene`: the water at rest where the fluid blocks put it.
std::shared_ptr<const FrameData> initialFrame(const Scene& scene) {
    Simulation simulation(scene);
    return std::make_shared<const FrameData>(
        FrameData{simulation.state(), simulation.lastFrameStats()});
}

//! Water at rest is deep blue: blue well above red and green, unlike the grey background.
bool isWater(const QColor& colour) {
    return colour.blue() >= colour.red() + 40 && colour.blue() >= colour.green() + 20;
}

bool isHighlight(const QColor& colour) {
    const QColor highlight = BoxGizmoDrawable::highlightColour();
    return std::abs(colour.red() - highlight.red()) < 40 &&
           std::abs(colour.green() - highlight.green()) < 50 &&
           std::abs(colour.blue() - highlight.blue()) < 50;
}

//! The dam break with a dynamic box body in the empty part of the tank.
Scene damBreakWithBody() {
    Scene scene = damBreak();
    RigidBodySettings body;
    body.name = "Crate";
    body.motion = "dynamic";
    body.position = Vec3d(1.6, 0.3, 0.2);
    body.size = Vec3d(0.3, 0.3, 0.3);
    scene.bodies.push_back(body);
    return scene;
}

//! `base` at any shading: the bodies' shading scales all three channels alike, so green and blue
//! keep their share of red.
bool isShadedAs(const QColor& colour, const QColor& base) {
    if (colour.red() < 40)
        return false;
    const auto share = [](int channel, int red) { return double(channel) / double(red); };
    return std::abs(share(colour.green(), colour.red()) - share(base.green(), base.red())) < 0.08 &&
           std::abs(share(colour.blue(), colour.red()) - share(base.blue(), base.red())) < 0.08;
}

bool isDynamicBody(const QColor& colour) {
    return isShadedAs(colour, BodyDrawable::colourOf("dynamic"));
}

bool isSelectedBody(const QColor& colour) {
    return isShadedAs(colour, BoxGizmoDrawable::highlightColour());
}

//! Bubbles are light at any shading (their darkest side keeps 60 % of the colour): a dark pixel
//! of similar hue, where water and grid lines blend, is not one.
bool isBubble(const QColor& colour) {
    return colour.red() >= 100 && isShadedAs(colour, BubbleDrawable::colour());
}

// A 0.3 m body low in the dam break's water column and a bubble higher up, both wholly inside it.
const Vec3d kSunkenBody(0.25, 0.3, 0.2);
const Vec3d kSunkenBubble(0.25, 0.75, 0.2);
constexpr double kSunkenBubbleRadius = 0.12;

//! The dam break with its body standing in the water column.
Scene damBreakWithSunkenBody() {
    Scene scene = damBreakWithBody();
    scene.bodies[0].position = kSunkenBody;
    return scene;
}

//! Frame 1 of the dam break with the sunken body, and a bubble centred at `bubbleCentre`. The
//! water is simulated without the body, which would overlap it.
std::shared_ptr<const FrameData> frameWithSunkenBubble(const Vec3d& bubbleCentre) {
    FrameData frame = *initialFrame(damBreak());
    RigidBodyState body;
    body.position = kSunkenBody;
    frame.state.bodies = {body};
    BubbleState bubble;
    bubble.radius = kSunkenBubbleRadius;
    bubble.body.position = bubbleCentre;
    frame.state.bubbles = {bubble};
    return std::make_shared<const FrameData>(frame);
}

QVector3D toQt(const Vec3d& v) {
    return QVector3D(float(v.x()), float(v.y()), float(v.z()));
}

int countWater(const QImage& image) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            count += isWater(image.pixelColor(x, y)) ? 1 : 0;
        }
    }
    return count;
}

QString describe(const QColor& colour) {
    return colour.name(QColor::HexRgb);
}

} // namespace

class TestViewport : public QObject {
    Q_OBJECT

private:
    //! A shown 640×480 viewport whose context exists.
    std::unique_ptr<ViewportWidget> shownViewport() {
        auto viewport = std::make_unique<ViewportWidget>();
        viewport->resize(kViewportSize);
        viewport->show();
        if (!QTest::qWaitForWindowExposed(viewport.get())) {
            return nullptr;
        }
        return viewport;
    }

    QPointF project(const ViewportWidget& viewport, const QVector3D& point) {
        return viewport.camera().project(point, viewport.size());
    }

    //! Pixels of `image` that pass `test`, split at the outline (with a margin for perspective)
    //! of the sphere of `radius` m at `centre`.
    template <typename Test>
    PixelSplit splitAtSphere(const ViewportWidget& viewport, const QImage& image,
                             const Vec3d& centre, double radius, Test test) {
        const QMatrix4x4 view = viewport.camera().viewMatrix();
        const QVector3D across(view(0, 0), view(0, 1), view(0, 2)); // the camera's right
        const QPointF centrePixel = project(viewport, toQt(centre));
        const QPointF edgePixel = project(viewport, toQt(centre) + float(radius) * across);
        const qreal ratio = viewport.devicePixelRatio();
        const double outline = 1.1 * QLineF(centrePixel, edgePixel).length() * ratio + 2.0;
        return splitAround(image, centrePixel * ratio, outline,
                           [&](int x, int y) { return test(image.pixelColor(x, y)); });
    }

private Q_SLOTS:
    void withoutSceneOnlyClears() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const QImage image = viewport->grabFramebuffer();
        QVERIFY(!image.isNull());
        const QRgb clear = ViewportWidget::clearColor().rgb();
        for (const QPoint p : {QPoint(0, 0), QPoint(image.width() / 2, image.height() / 2),
                               QPoint(image.width() - 1, image.height() - 1)}) {
            QCOMPARE(QColor(image.pixel(p)).name(), QColor(clear).name());
        }
    }

    void damBreakFrameOneShowsTheWaterColumn() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreak();
        viewport->setScene(scene);
        viewport->setFrame(initialFrame(scene));
        QVERIFY(viewport->isPlayback());
        const QImage image = viewport->grabFramebuffer();
        const qreal ratio = viewport->devicePixelRatio();
        QCOMPARE(image.size(), kViewportSize * ratio);

        const QPointF column = project(*viewport, QVector3D(0.25f, 0.5f, 0.2f));
        const QColor centre = image.pixelColor((column * ratio).toPoint());
        QVERIFY2(isWater(centre), qPrintable(describe(centre)));
        QCOMPARE(countAround(image, column, 4, ratio, isWater), 81);

        const QPointF emptyTank = project(*viewport, QVector3D(2.0f, 0.5f, 0.2f));
        const QColor empty = image.pixelColor((emptyTank * ratio).toPoint());
        QVERIFY2(!isWater(empty), qPrintable(describe(empty)));
        QCOMPARE(countAround(image, emptyTank, 4, ratio, isWater), 0);

        // The column's front face alone is 0.5 × 1 m: a few percent of this view.
        const double share = double(countWater(image)) / double(image.width() * image.height());
        QVERIFY2(share > 0.015 && share < 0.2, qPrintable(QString::number(share)));
    }

    void playbackDrawsABubbleAsASphereOfItsRadius() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreak();
        viewport->setScene(scene);
        FrameData frame = *initialFrame(scene);
        viewport->setFrame(std::make_shared<const FrameData>(frame));
        // Tens of thousands of overlapping sprites do not resolve the same bit for bit twice.
        viewport->setShowWater(false);
        QCOMPARE(viewport->bubbleCount(), 0);
        const QImage without = viewport->grabFramebuffer();

        BubbleState bubble;
        bubble.radius = 0.2;
        bubble.body.position = Vec3d(1.6, 0.6, 0.2); // in the empty part of the tank
        frame.state.bubbles.push_back(bubble);
        viewport->setFrame(std::make_shared<const FrameData>(frame));
        QCOMPARE(viewport->bubbleCount(), 1);
        const QImage image = viewport->grabFramebuffer();
        QCOMPARE(image.size(), without.size());
        const qreal ratio = viewport->devicePixelRatio();

        // The sphere's outline on screen: its radius seen across the view direction.
        const QMatrix4x4 view = viewport->camera().viewMatrix();
        const QVector3D across(view(0, 0), view(0, 1), view(0, 2)); // the camera's right
        const QVector3D centre = toQt(bubble.body.position);
        const QPointF centrePixel = project(*viewport, centre);
        const double radiusPixels =
            QLineF(centrePixel, project(*viewport, centre + float(bubble.radius) * across))
                .length() *
            ratio;
        QVERIFY2(radiusPixels > 15.0, qPrintable(QString::number(radiusPixels)));
        const QColor middle = image.pixelColor((centrePixel * ratio).toPoint());
        QVERIFY2(isBubble(middle), qPrintable(describe(middle)));
        QCOMPARE(countAround(image, centrePixel, 3, ratio, isBubble), 49);
        QCOMPARE(countAround(without, centrePixel, 3, ratio, isBubble), 0);

        // Shaded, the disc is bubble-coloured but for its whitened rim and highlight; outside it
        // the bubble changes nothing (perspective widens the outline a little: hence the margin).
        const QPointF centreInImage = centrePixel * ratio;
        const double outline = 1.1 * radiusPixels + 2.0;
        const PixelSplit coloured = splitAround(image, centreInImage, outline, [&](int x, int y) {
            return isBubble(image.pixelColor(x, y));
        });
        const double disc = 3.14159 * radiusPixels * radiusPixels;
        QVERIFY2(coloured.inside > 0.6 * disc,
                 qPrintable(QStringLiteral("%1 of %2").arg(coloured.inside).arg(disc)));
        const PixelSplit changed = splitAround(image, centreInImage, outline, [&](int x, int y) {
            return !nearlySame(image.pixel(x, y), without.pixel(x, y));
        });
        QVERIFY(changed.inside >= coloured.inside);
        QCOMPARE(changed.outside, 0);
    }

    void subgridBubblesAreDrawnAsPointsInTheBubbleColour() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreak();
        viewport->setScene(scene);
        viewport->setFrame(initialFrame(scene));
        viewport->setShowWater(false);
        const QImage without = viewport->grabFramebuffer();
        SubgridBubble small;
        small.radius = 0.1;
        small.position = Vec3d(1.6, 0.6, 0.2); // in the empty part of the tank
        SubgridBubble other = small;
        other.position = Vec3d(1.2, 0.6, 0.2);
        // A tenth of a millimetre: far under a pixel, still drawn at the minimum size.
        SubgridBubble speck = small;
        speck.radius = 1e-4;
        speck.position = Vec3d(1.4, 0.9, 0.2);
        viewport->setSubgridBubbles({small, other, speck});
        QCOMPARE(viewport->subgridBubbleCount(), 3);
        QCOMPARE(viewport->bubbleCount(), 0);
        const QImage image = viewport->grabFramebuffer();
        const qreal ratio = viewport->devicePixelRatio();
        for (const SubgridBubble& bubble : {small, other}) {
            const QPointF centre = project(*viewport, toQt(bubble.position));
            QCOMPARE(countAround(image, centre, 2, ratio, isBubble), 25);
            QCOMPARE(countAround(without, centre, 2, ratio, isBubble), 0);
        }
        const QPointF speckCentre = project(*viewport, toQt(speck.position));
        // A disc 3 pixels across: more than the single pixel of a plain GL point, at most 3 × 3.
        const int speckPixels = countAround(image, speckCentre, 3, ratio, isBubble);
        QVERIFY2(speckPixels >= 4 && speckPixels <= 9, qPrintable(QString::number(speckPixels)));
        QCOMPARE(countAround(without, speckCentre, 3, ratio, isBubble), 0);
        viewport->setSubgridBubbles({});
        QCOMPARE(viewport->subgridBubbleCount(), 0);
        QCOMPARE(pixelsChanged(viewport->grabFramebuffer(), without), 0);
    }

    void bubblesHaveAColourOfTheirOwn() {
        // At any shading no speed of the water and no body motion looks like a bubble.
        for (int step = 0; step <= 100; ++step) {
            const QColor water = SpeedColormap::colourAt(float(step) / 100.0f);
            QVERIFY2(!isBubble(water), qPrintable(describe(water)));
        }
        for (const char* motion : {"static", "dynamic", "kinematic"})
            QVERIFY2(!isBubble(BodyDrawable::colourOf(motion)), motion);
        QVERIFY(!isBubble(BoxGizmoDrawable::highlightColour()));
        QVERIFY(!isBubble(ViewportWidget::clearColor()));
    }

    void playbackShowsTheSpeedLegend() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreak();
        viewport->setScene(scene);
        viewport->setFrame(initialFrame(scene));
        QCOMPARE(viewport->speedScale(), float(scene.solver.maxSpeed));
        const QImage image = viewport->grabFramebuffer();
        const QRect bar = SpeedLegend::barRect(viewport->rect(), viewport->fontMetrics());
        const qreal ratio = viewport->devicePixelRatio();
        const QColor slow =
            image.pixelColor((QPointF(bar.left() + 3, bar.center().y()) * ratio).toPoint());
        const QColor fast =
            image.pixelColor((QPointF(bar.right() - 3, bar.center().y()) * ratio).toPoint());
        QVERIFY2(isWater(slow), qPrintable(describe(slow)));
        QVERIFY2(fast.red() > 220 && fast.green() > 220 && fast.blue() > 220,
                 qPrintable(describe(fast)));
    }

    void hidingTheWaterShowsWhatItSurrounds() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreakWithSunkenBody();
        viewport->setScene(scene);
        viewport->setShowAxes(false); // the z axis is as blue as the water
        viewport->setBubblesThroughWater(false);
        viewport->setFrame(frameWithSunkenBubble(kSunkenBubble));
        QVERIFY(viewport->showsWater());
        const qreal ratio = viewport->devicePixelRatio();
        const QPointF body = project(*viewport, toQt(kSunkenBody));
        const QPointF bubble = project(*viewport, toQt(kSunkenBubble));
        const QImage water = viewport->grabFramebuffer();
        const int waterPixels = countWater(water);
        QVERIFY(waterPixels > 0);
        QCOMPARE(countAround(water, body, 4, ratio, isDynamicBody), 0);
        QCOMPARE(countAround(water, bubble, 3, ratio, isBubble), 0);

        // Nothing water-coloured is left, neither particles nor the legend's slow end, but for
        // the bubble: its whitened rim is as blue as the water.
        viewport->setShowWater(false);
        QVERIFY(!viewport->showsWater());
        const QImage dry = viewport->grabFramebuffer();
        const PixelSplit left =
            splitAtSphere(*viewport, dry, kSunkenBubble, kSunkenBubbleRadius, isWater);
        QCOMPARE(left.outside, 0);
        QCOMPARE(countAround(dry, body, 4, ratio, isDynamicBody), 81);
        QCOMPARE(countAround(dry, bubble, 3, ratio, isBubble), 49);

        viewport->setShowWater(true);
        const int waterAgain = countWater(viewport->grabFramebuffer());
        QVERIFY2(std::abs(waterAgain - waterPixels) <= waterPixels / 50,
                 qPrintable(QStringLiteral("%1, then %2").arg(waterPixels).arg(waterAgain)));
    }

    void aFrameWithItsSurfaceShowsTheSurfaceNotTheParticles() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        viewport->setScene(damBreakWithSunkenBody());
        viewport->setShowAxes(false);
        viewport->setFrame(frameWithSunkenBubble(kSunkenBubble));
        QVERIFY(viewport->drawsParticles());
        const int particlePixels = countWater(viewport->grabFramebuffer());
        QVERIFY(particlePixels > 0);
        // A post result for the frame: a small triangle far from the water stands for its mesh.
        auto mesh = std::make_shared<TriangleMesh>();
        mesh->vertices = {Vec3d(0.0, 0.0, 0.0), Vec3d(0.01, 0.0, 0.0), Vec3d(0.0, 0.01, 0.0)};
        mesh->triangles = {{0, 1, 2}};
        viewport->setWaterSurface(mesh);
        QVERIFY(viewport->showsWater());
        QVERIFY(!viewport->drawsParticles());
        QVERIFY(countWater(viewport->grabFramebuffer()) < particlePixels / 20);
        viewport->setParticlesUnderSurface(true);
        QVERIFY(viewport->drawsParticles());
        viewport->setParticlesUnderSurface(false);
        viewport->setShowSurface(false);
        QVERIFY(viewport->drawsParticles());
    }

    void bubblesAndSelectionCanBeHidden() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        viewport->setScene(damBreakWithSunkenBody());
        viewport->setFrame(frameWithSunkenBubble(kSunkenBubble));
        const qreal ratio = viewport->devicePixelRatio();
        const QPointF bubble = project(*viewport, toQt(kSunkenBubble));
        QCOMPARE(countAround(viewport->grabFramebuffer(), bubble, 3, ratio, isBubble), 49);
        viewport->setShowBubbles(false);
        QCOMPARE(countAround(viewport->grabFramebuffer(), bubble, 3, ratio, isBubble), 0);
        viewport->setShowBubbles(true);
        // The selection is kept while hidden, and drawn again when shown.
        viewport->setFrame(nullptr);
        const QImage unselected = viewport->grabFramebuffer();
        viewport->setSelection(SceneItem::elementItem("fluid_blocks", 0));
        const QImage selected = viewport->grabFramebuffer();
        QVERIFY(selected != unselected);
        viewport->setShowSelection(false);
        QCOMPARE(viewport->grabFramebuffer(), unselected);
        viewport->setShowSelection(true);
        QCOMPARE(viewport->grabFramebuffer(), selected);
    }

    void cameraViewsLookAlongTheAxes() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        viewport->setScene(damBreak());
        using View = ViewportWidget::CameraView;
        viewport->setCameraView(View::Front);
        QVERIFY(qFuzzyCompare(viewport->camera().forward(), QVector3D(0, 0, -1)));
        viewport->setCameraView(View::Side);
        QVERIFY((viewport->camera().forward() - QVector3D(-1, 0, 0)).length() < 1e-5f);
        viewport->setCameraView(View::Top);
        QVERIFY(viewport->camera().forward().y() < -0.99f);
        viewport->setCameraView(View::Perspective);
        QCOMPARE(viewport->camera().pitch(), OrbitCamera().pitch());
    }

    void bubblesShowThroughWaterButNotThroughBodies() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreakWithSunkenBody();
        viewport->setScene(scene);
        viewport->setFrame(frameWithSunkenBubble(kSunkenBubble));
        QVERIFY(viewport->drawsBubblesThroughWater());
        const qreal ratio = viewport->devicePixelRatio();
        const QPointF body = project(*viewport, toQt(kSunkenBody));
        const QPointF bubble = project(*viewport, toQt(kSunkenBubble));
        const QImage through = viewport->grabFramebuffer();
        QCOMPARE(countAround(through, bubble, 3, ratio, isBubble), 49);
        // Only the bubble comes through: the water still hides the body.
        QCOMPARE(countAround(through, body, 4, ratio, isDynamicBody), 0);
        QVERIFY(countWater(through) > 0);

        viewport->setBubblesThroughWater(false);
        const QImage hidden = viewport->grabFramebuffer();
        QCOMPARE(
            splitAtSphere(*viewport, hidden, kSunkenBubble, kSunkenBubbleRadius, isBubble).inside,
            0);

        // A bubble inside the body stays hidden, water or not: the body is in front of it.
        viewport->setBubblesThroughWater(true);
        viewport->setFrame(frameWithSunkenBubble(kSunkenBody));
        QCOMPARE(viewport->bubbleCount(), 1);
        for (const bool water : {true, false}) {
            viewport->setShowWater(water);
            const QImage image = viewport->grabFramebuffer();
            QCOMPARE(
                splitAtSphere(*viewport, image, kSunkenBody, kSunkenBubbleRadius, isBubble).inside,
                0);
            QCOMPARE(countAround(image, body, 4, ratio, isDynamicBody), water ? 0 : 81);
        }
    }

    void nullFrameReturnsToEditMode() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreak();
        viewport->setScene(scene);
        viewport->setFrame(initialFrame(scene));
        const int playbackWater = countWater(viewport->grabFramebuffer());

        viewport->setFrame(nullptr);
        QVERIFY(!viewport->isPlayback());
        const QImage image = viewport->grabFramebuffer();
        const qreal ratio = viewport->devicePixelRatio();
        // Inside the fluid block's wireframe there is no water any more, and the blue left over
        // (the block's edges, the z axis) is a fraction of what the water covered.
        const QPointF column = project(*viewport, QVector3D(0.25f, 0.5f, 0.2f));
        QCOMPARE(countAround(image, column, 6, ratio, isWater), 0);
        const int editWater = countWater(image);
        QVERIFY2(editWater * 2 < playbackWater,
                 qPrintable(QStringLiteral("%1 vs %2").arg(editWater).arg(playbackWater)));
        // The legend belongs to playback only.
        const QRect bar = SpeedLegend::barRect(viewport->rect(), viewport->fontMetrics());
        const QColor legendSpot =
            image.pixelColor((QPointF(bar.right() - 3, bar.center().y()) * ratio).toPoint());
        QVERIFY2(legendSpot.red() < 200, qPrintable(describe(legendSpot)));
    }

    void clickPicksTheGizmoUnderTheCursor() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreakWithObstacle();
        viewport->setScene(scene);
        QSignalSpy picked(viewport.get(), &ViewportWidget::itemPicked);

        const auto clickAt = [&](const QVector3D& point) {
            QTest::mouseClick(viewport.get(), Qt::LeftButton, {},
                              project(*viewport, point).toPoint());
            return picked.isEmpty() ? SceneItem::none()
                                    : picked.takeLast().at(0).value<SceneItem>();
        };
        QCOMPARE(clickAt(toQt(scene.obstacles[0].center)), SceneItem::elementItem("obstacles", 0));
        QCOMPARE(clickAt(QVector3D(0.25f, 0.5f, 0.2f)), SceneItem::elementItem("fluid_blocks", 0));
        // The container is a wireframe: picked on its edges (here the front rim), not inside.
        QCOMPARE(clickAt(QVector3D(1.25f, 2.0f, 0.4f)), SceneItem::sectionItem("container"));
        QCOMPARE(clickAt(QVector3D(2.0f, 1.2f, 0.2f)), SceneItem::none());

        QTest::mouseClick(viewport.get(), Qt::LeftButton, {}, QPoint(5, 5));
        QCOMPARE(picked.count(), 1);
        QCOMPARE(picked.takeFirst().at(0).value<SceneItem>(), SceneItem::none());
    }

    void clickPicksAnInflowNozzle() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        Scene scene = damBreak();
        InflowEmitterSettings jet;
        jet.position = Vec3d(1.8, 1.5, 0.2);
        jet.direction = Vec3d(0.0, -1.0, 0.0);
        jet.radius = 0.1;
        scene.emitters.push_back(jet);
        viewport->setScene(scene);
        QSignalSpy picked(viewport.get(), &ViewportWidget::itemPicked);
        QTest::mouseClick(viewport.get(), Qt::LeftButton, {},
                          project(*viewport, toQt(jet.position)).toPoint());
        QCOMPARE(picked.count(), 1);
        QCOMPARE(picked.first().at(0).value<SceneItem>(), SceneItem::elementItem("emitters", 0));
    }

    void dragOrbitsWithoutPicking() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreakWithObstacle();
        viewport->setScene(scene);
        QSignalSpy picked(viewport.get(), &ViewportWidget::itemPicked);
        const QPoint start = project(*viewport, toQt(scene.obstacles[0].center)).toPoint();
        const float yaw = viewport->camera().yaw();
        const QVector3D target = viewport->camera().target();

        QTest::mousePress(viewport.get(), Qt::LeftButton, {}, start);
        QTest::mouseMove(viewport.get(), start + QPoint(15, 0));
        QTest::mouseMove(viewport.get(), start + QPoint(40, 0));
        QTest::mouseRelease(viewport.get(), Qt::LeftButton, {}, start + QPoint(40, 0));
        QCOMPARE(picked.count(), 0);
        QVERIFY(std::abs(viewport->camera().yaw() - yaw) > 5.0f);
        QCOMPARE(viewport->camera().target(), target);
    }

    void selectionIsHighlighted() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreakWithObstacle();
        viewport->setScene(scene);
        // The middle of the obstacle's top front edge.
        const BoxObstacle& obstacle = scene.obstacles[0];
        const Vec3d edge = obstacle.center + 0.5 * Vec3d(0.0, obstacle.size.y(), obstacle.size.z());
        const QPointF spot = project(*viewport, toQt(edge));
        const qreal ratio = viewport->devicePixelRatio();

        QCOMPARE(countAround(viewport->grabFramebuffer(), spot, 3, ratio, isHighlight), 0);
        viewport->setSelection(SceneItem::elementItem("obstacles", 0));
        QVERIFY(countAround(viewport->grabFramebuffer(), spot, 3, ratio, isHighlight) >= 3);
        viewport->setSelection(SceneItem::none());
        QCOMPARE(countAround(viewport->grabFramebuffer(), spot, 3, ratio, isHighlight), 0);
    }

    void aBodyIsDrawnWhereItStandsAndHighlightedWhenSelected() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreakWithBody();
        viewport->setScene(scene);
        const qreal ratio = viewport->devicePixelRatio();
        const QPointF body = project(*viewport, toQt(scene.bodies[0].position));
        const QPointF empty = project(*viewport, QVector3D(2.1f, 0.3f, 0.2f));
        QImage image = viewport->grabFramebuffer();
        QCOMPARE(countAround(image, body, 4, ratio, isDynamicBody), 81);
        QCOMPARE(countAround(image, empty, 4, ratio, isDynamicBody), 0);

        viewport->setSelection(SceneItem::elementItem("bodies", 0));
        image = viewport->grabFramebuffer();
        QCOMPARE(countAround(image, body, 4, ratio, isDynamicBody), 0);
        QCOMPARE(countAround(image, body, 4, ratio, isSelectedBody), 81);

        // Without its body the spot shows the empty tank.
        viewport->setSelection(SceneItem::none());
        viewport->setScene(damBreak());
        QCOMPARE(countAround(viewport->grabFramebuffer(), body, 4, ratio, isDynamicBody), 0);
    }

    void playbackDrawsABodyWhereTheFrameHasIt() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        const Scene scene = damBreakWithBody();
        viewport->setScene(scene);
        // The body has fallen and turned by frame N: its state holds the centre of mass.
        FrameData frame;
        RigidBodyState state;
        state.position = Vec3d(2.0, 0.7, 0.2);
        state.orientation = Quatd(Eigen::AngleAxisd(0.5, Vec3d::UnitZ()));
        frame.state.bodies.push_back(state);
        viewport->setFrame(std::make_shared<const FrameData>(frame));
        const qreal ratio = viewport->devicePixelRatio();
        const QPointF moved = project(*viewport, toQt(state.position));
        const QPointF scenePose = project(*viewport, toQt(scene.bodies[0].position));
        const QImage image = viewport->grabFramebuffer();
        QCOMPARE(countAround(image, moved, 4, ratio, isDynamicBody), 81);
        QCOMPARE(countAround(image, scenePose, 4, ratio, isDynamicBody), 0);

        // Picking follows the drawn pose.
        QCOMPARE(viewport->itemAt(moved), SceneItem::elementItem("bodies", 0));
        QCOMPARE(viewport->itemAt(scenePose), SceneItem::none());

        viewport->setFrame(nullptr);
        QCOMPARE(countAround(viewport->grabFramebuffer(), scenePose, 4, ratio, isDynamicBody), 81);
    }

    void aMeshBodyFollowsItsCentreOfMassAndAMissingMeshDrawsNothing() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        Scene scene = damBreak();
        RigidBodySettings bunny;
        bunny.shape = "mesh";
        bunny.mesh = AIRTRAP_SOURCE_DIR "/tests/data/bunny_lowres.obj";
        bunny.meshScale = 2.0;
        bunny.position = Vec3d(1.6, 0.3, 0.2);
        RigidBodySettings missing = bunny;
        missing.mesh = "/nonexistent/missing.obj";
        scene.bodies = {bunny, missing};
        viewport->setScene(scene);
        const auto& bodies = viewport->bodies().bodies();
        QVERIFY(bodies[0].solid);
        QVERIFY(!bodies[1].solid);
        QVERIFY(!viewport->grabFramebuffer().isNull());

        // A dynamic mesh's state is its centre of mass, away from the mesh's own origin.
        const Vec3d centre = bodies[0].centreOfMass;
        QVERIFY(centre.norm() > 1e-3);
        RigidBodyState state;
        state.position = Vec3d(2.0, 0.5, 0.2);
        FrameData frame;
        frame.state.bodies = {state, state};
        viewport->setFrame(std::make_shared<const FrameData>(frame));
        const QVector3D origin = viewport->bodies().bodies()[0].pose.map(QVector3D());
        QVERIFY((origin - toQt(state.position - centre)).length() < 1e-5f);
        const QImage image = viewport->grabFramebuffer();
        const qreal ratio = viewport->devicePixelRatio();
        QVERIFY(countAround(image, project(*viewport, toQt(state.position)), 2, ratio,
                            isDynamicBody) > 0);
    }

    void wheelZoomsAndFrameAllRestores() {
        const auto viewport = shownViewport();
        QVERIFY(viewport);
        viewport->setScene(damBreak());
        const float fitted = viewport->camera().distance();
        const QPointF centre(viewport->width() / 2.0, viewport->height() / 2.0);
        QWheelEvent wheel(centre, viewport->mapToGlobal(centre), QPoint(), QPoint(0, 240),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport.get(), &wheel);
        QVERIFY(viewport->camera().distance() < fitted * 0.8f);

        QTest::keyClick(viewport.get(), Qt::Key_F);
        QCOMPARE(viewport->camera().distance(), fitted);
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestViewport)
#include "TestViewport.moc"
