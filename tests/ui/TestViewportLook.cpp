// How the viewport draws what it draws: the water surface's three shadings, the particles' size,
// and anti-aliased edges. Pixels are read from the widget's framebuffer, as in TestViewport, with
// the camera straight at the front and a flat square of water surface facing it.
#include "scene/SceneJson.h"
#include "sim/Simulation.h"
#include "support/WidgetTestMain.h"
#include "viewport/SurfaceDrawable.h"
#include "viewport/ViewportWidget.h"

#include <QTest>
#include <cmath>

namespace airtrap {

class TestViewportLook : public QObject {
    Q_OBJECT

private:
    //! Cells along each side of the surface square: 2 triangles per cell.
    static constexpr int kCells = 8;

    struct Square {
        Vec3d centre;
        double half = 0.0;
    };

    static Scene scene() { return readSceneFile(AIRTRAP_SOURCE_DIR "/samples/dam_break.json"); }

    static FrameData firstFrame() {
        Simulation simulation(scene());
        return FrameData{simulation.state(), simulation.lastFrameStats()};
    }

    //! A viewport showing frame 1 of the dam break with nothing but what a test adds: no grid,
    //! axes or gizmos, the water's particles hidden, looking along −z.
    static std::unique_ptr<ViewportWidget> bareViewport() {
        auto viewport = std::make_unique<ViewportWidget>();
        viewport->resize(640, 480);
        viewport->show();
        if (!QTest::qWaitForWindowExposed(viewport.get()))
            return nullptr;
        viewport->setScene(scene());
        viewport->setFrame(std::make_shared<const FrameData>(firstFrame()));
        viewport->setShowGrid(false);
        viewport->setShowAxes(false);
        viewport->setShowGizmos(false);
        viewport->setShowWater(false);
        viewport->setCameraView(ViewportWidget::CameraView::Front);
        return viewport;
    }

    //! A kCells × kCells grid of triangles filling `square`, in the plane facing the camera.
    static std::shared_ptr<TriangleMesh> squareMesh(const Square& square) {
        auto mesh = std::make_shared<TriangleMesh>();
        const double step = 2.0 * square.half / kCells;
        for (int j = 0; j <= kCells; ++j)
            for (int i = 0; i <= kCells; ++i)
                mesh->vertices.push_back(
                    square.centre + Vec3d(-square.half + i * step, -square.half + j * step, 0));
        const auto at = [](int i, int j) { return std::uint32_t(j * (kCells + 1) + i); };
        for (int j = 0; j < kCells; ++j)
            for (int i = 0; i < kCells; ++i) {
                mesh->triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                mesh->triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        return mesh;
    }

    static Square middleOfTheDomain() {
        const Aabb domain = scene().domain();
        return Square{0.5 * (domain.min + domain.max), 0.25};
    }

    static QPoint pixelOf(const ViewportWidget& viewport, const Vec3d& point) {
        const QPointF widget = viewport.camera().project(
            QVector3D(float(point.x()), float(point.y()), float(point.z())), viewport.size());
        return (widget * viewport.devicePixelRatio()).toPoint();
    }

    static bool isBackground(const QColor& colour) {
        const QColor clear = ViewportWidget::clearColor();
        return std::abs(colour.red() - clear.red()) + std::abs(colour.green() - clear.green()) +
                   std::abs(colour.blue() - clear.blue()) <=
               6;
    }

    //! Pixels of `image` inside the square's picture, shrunk by a margin off its outline, that
    //! are background.
    static int backgroundInside(const ViewportWidget& viewport, const QImage& image,
                                const Square& square) {
        const double inset = 0.9 * square.half;
        const QPoint low = pixelOf(viewport, square.centre + Vec3d(-inset, inset, 0));
        const QPoint high = pixelOf(viewport, square.centre + Vec3d(inset, -inset, 0));
        int count = 0;
        for (int y = low.y(); y <= high.y(); ++y)
            for (int x = low.x(); x <= high.x(); ++x)
                count += isBackground(image.pixelColor(x, y)) ? 1 : 0;
        return count;
    }

private Q_SLOTS:
    void theSurfaceIsTranslucentOpaqueOrAWireframe() {
        const auto viewport = bareViewport();
        QVERIFY(viewport);
        const Square square = middleOfTheDomain();
        viewport->setWaterSurface(squareMesh(square));
        QCOMPARE(viewport->surfaceShading(), SurfaceShading::Translucent);
        const QPoint centre = pixelOf(*viewport, square.centre);
        const QColor translucent = viewport->grabFramebuffer().pixelColor(centre);
        viewport->setSurfaceShading(SurfaceShading::Opaque);
        const QImage opaqueImage = viewport->grabFramebuffer();
        const QColor opaque = opaqueImage.pixelColor(centre);
        // Translucent, the grey background shows through: bluer when opaque.
        QVERIFY2(opaque.blue() > translucent.blue() + 20,
                 qPrintable(opaque.name() + QLatin1Char(' ') + translucent.name()));
        QCOMPARE(backgroundInside(*viewport, opaqueImage, square), 0);

        viewport->setSurfaceShading(SurfaceShading::Wireframe);
        const QImage wireImage = viewport->grabFramebuffer();
        // Every edge once: kCells + 1 rows and columns of kCells edges, and a diagonal per cell.
        QCOMPARE(viewport->surfaceEdgeCount(), 2 * kCells * (kCells + 1) + kCells * kCells);
        const QPoint low = pixelOf(*viewport, square.centre + Vec3d(-0.9 * square.half, 0, 0));
        const QPoint high = pixelOf(*viewport, square.centre + Vec3d(0.9 * square.half, 0, 0));
        const int insidePixels = (high.x() - low.x() + 1) * (high.x() - low.x() + 1);
        // Between the lines the background shows; the lines themselves are drawn.
        const int open = backgroundInside(*viewport, wireImage, square);
        QVERIFY2(open > insidePixels / 2, qPrintable(QString::number(open)));
        QVERIFY2(open < insidePixels, qPrintable(QString::number(open)));
    }

    void edgesAreAntialiased() {
        const auto viewport = bareViewport();
        QVERIFY(viewport);
        const Square square = middleOfTheDomain();
        // One triangle whose hypotenuse runs across pixels at a slant.
        auto mesh = std::make_shared<TriangleMesh>();
        const Vec3d& c = square.centre;
        mesh->vertices = {c + Vec3d(-0.3, -0.2, 0), c + Vec3d(0.3, -0.2, 0),
                          c + Vec3d(-0.3, 0.2, 0)};
        mesh->triangles = {{0, 1, 2}};
        viewport->setWaterSurface(mesh);
        viewport->setSurfaceShading(SurfaceShading::Opaque);
        const QImage image = viewport->grabFramebuffer();
        const int inside = image.pixelColor(pixelOf(*viewport, c + Vec3d(-0.2, -0.1, 0))).blue();
        const int outside = ViewportWidget::clearColor().blue();
        QVERIFY(inside > outside + 60);
        // Along the hypotenuse, pixels the edge crosses mix the two colours.
        const QPoint from = pixelOf(*viewport, c + Vec3d(-0.25, 0.1667, 0));
        const QPoint to = pixelOf(*viewport, c + Vec3d(0.25, -0.1667, 0));
        int mixed = 0;
        for (int x = from.x(); x <= to.x(); ++x)
            for (int y = std::min(from.y(), to.y()); y <= std::max(from.y(), to.y()); ++y) {
                const int blue = image.pixelColor(x, y).blue();
                mixed += blue > outside + 15 && blue < inside - 15 ? 1 : 0;
            }
        QVERIFY2(mixed >= (to.x() - from.x()) / 2, qPrintable(QString::number(mixed)));
    }

    void particlesHaveASizeControl() {
        const auto viewport = bareViewport();
        QVERIFY(viewport);
        const float standard = viewport->particleRadius();
        QCOMPARE(standard, 0.5f * float(scene().solver.particleSpacing));
        viewport->setParticleSize(0.25f);
        QCOMPARE(viewport->particleRadius(), 0.25f * standard);
        viewport->setParticleSize(100.0f);
        QCOMPARE(viewport->particleSize(), ViewportWidget::kMaxParticleSize);
        viewport->setParticleSize(0.0f);
        QCOMPARE(viewport->particleSize(), ViewportWidget::kMinParticleSize);

        // Drawn at twice the size, one particle covers about four times the pixels.
        FrameData one = firstFrame();
        one.state.fluid.clear();
        one.state.fluid.push(middleOfTheDomain().centre.cast<float>(), Vec3f::Zero(), 1000.0f, 0);
        viewport->setFrame(std::make_shared<const FrameData>(one));
        viewport->setShowWater(true);
        // Around the particle: the speed legend in its corner is drawn too.
        const QPoint particle = pixelOf(*viewport, middleOfTheDomain().centre);
        const auto coveredPixels = [&] {
            const QImage image = viewport->grabFramebuffer();
            int count = 0;
            for (int y = particle.y() - 60; y <= particle.y() + 60; ++y)
                for (int x = particle.x() - 60; x <= particle.x() + 60; ++x)
                    count += isBackground(image.pixelColor(x, y)) ? 0 : 1;
            return count;
        };
        viewport->setParticleSize(1.5f);
        const int standardPixels = coveredPixels();
        viewport->setParticleSize(3.0f);
        const int doubledPixels = coveredPixels();
        QVERIFY2(standardPixels > 10 &&
                     std::abs(doubledPixels - 4 * standardPixels) < standardPixels,
                 qPrintable(QStringLiteral("%1 then %2").arg(standardPixels).arg(doubledPixels)));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestViewportLook)
#include "TestViewportLook.moc"
