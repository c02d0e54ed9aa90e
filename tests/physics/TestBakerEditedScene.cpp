// "Change from here": a bake stopped at frame N, continued with edited settings, keeps frames
// 1..N bit-for-bit and bakes the rest with the new settings; settings that define the particles
// themselves are refused with the reason.
#include "bake/Baker.h"
#include "cache/FrameCache.h"
#include "core/Error.h"
#include "scene/SceneJson.h"
#include "support/SceneBuilder.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

Scene smallSplash() {
    return SceneBuilder()
        .spacing(0.04)
        .maxSpeed(4.0)
        .frames(60.0, 5)
        .tank({0.6, 0.5, 0.24})
        .water({0.0, 0.0, 0.0}, {0.24, 0.32, 0.24})
        .build();
}

void bake(const Scene& scene, const std::string& dir, bool resume, int lastFrame,
          bool adoptEditedScene) {
    BakeOptions options;
    options.cacheDir = dir;
    options.resume = resume;
    options.overwrite = !resume;
    options.lastFrame = lastFrame;
    options.adoptEditedScene = adoptEditedScene;
    Interrupter interrupter;
    Baker(scene, options).run(interrupter);
}

} // namespace

class TestBakerEditedScene : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void continuesWithTheEditedScene() {
        QTemporaryDir folder;
        const std::string dir = folder.filePath("cache").toStdString();
        const Scene original = smallSplash();
        bake(original, dir, false, 3, false);
        const FrameData frame3 = FrameCache::open(dir).readFrame(3);

        Scene edited = original;
        edited.solver.viscosityAlpha = 0.3;
        // Without the editor's consent the cache of another scene is refused, as before.
        QVERIFY_THROWS_EXCEPTION(Error, bake(edited, dir, true, 0, false));

        bake(edited, dir, true, 0, true);
        const FrameCache cache = FrameCache::open(dir);
        QCOMPARE(cache.frames(), (std::vector<int>{1, 2, 3, 4, 5}));
        QVERIFY(cache.readFrame(3) == frame3);
        QCOMPARE(cache.manifest().parameterHash, parameterHash(edited));
        QCOMPARE(cache.manifest().scene["solver"]["viscosity_alpha"].get<double>(), 0.3);
        QVERIFY(cache.verify().empty());
    }

    void refusesChangedParticleSpacing() {
        QTemporaryDir folder;
        const std::string dir = folder.filePath("cache").toStdString();
        const Scene original = smallSplash();
        bake(original, dir, false, 2, false);

        Scene edited = original;
        edited.solver.particleSpacing = 0.05;
        try {
            bake(edited, dir, true, 0, true);
            QFAIL("a changed particle spacing was accepted mid-bake");
        } catch (const Error& error) {
            const QString message = QString::fromUtf8(error.what());
            QVERIFY2(message.contains("solver.particle_spacing") && message.contains("0.04") &&
                         message.contains("0.05") && message.contains("frame 1"),
                     qPrintable(message));
        }
        QCOMPARE(FrameCache::open(dir).frames(), (std::vector<int>{1, 2}));
    }

    //! The cached frames hold a state for each body the scene had; a body added later has
    //! none, so continuing is refused, while a body's edited density is taken from here on.
    void refusesAnAddedBodyButTakesAnEditedOne() {
        QTemporaryDir folder;
        const std::string dir = folder.filePath("cache").toStdString();
        Scene original = smallSplash();
        RigidBodySettings ball;
        ball.name = "Ball";
        ball.shape = "sphere";
        ball.radius = 0.06;
        ball.position = Vec3d(0.45, 0.3, 0.12);
        original.bodies.push_back(ball);
        bake(original, dir, false, 2, false);

        Scene added = original;
        ball.name = "Second";
        ball.position.x() = 0.3;
        added.bodies.push_back(ball);
        try {
            bake(added, dir, true, 0, true);
            QFAIL("a body added mid-bake was accepted");
        } catch (const Error& error) {
            const QString message = QString::fromUtf8(error.what());
            QVERIFY2(message.contains("now has 2 bodies, the cached frames 1") &&
                         message.contains("frame 1"),
                     qPrintable(message));
        }
        QCOMPARE(FrameCache::open(dir).frames(), (std::vector<int>{1, 2}));

        Scene heavier = original;
        heavier.bodies[0].density = 2000.0;
        bake(heavier, dir, true, 0, true);
        const FrameCache cache = FrameCache::open(dir);
        QCOMPARE(cache.frames(), (std::vector<int>{1, 2, 3, 4, 5}));
        QCOMPARE(cache.manifest().scene["bodies"][0]["density"].get<double>(), 2000.0);
    }
};

AIRTRAP_TEST_APPLESS(TestBakerEditedScene)
#include "TestBakerEditedScene.moc"
