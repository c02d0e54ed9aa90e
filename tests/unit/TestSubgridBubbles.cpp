// Sub-grid bubbles (paper §4.2): a new bubble sheds more of them the less of it lies in water,
// on three spheres around it and outside it, the same ones for the same seed; later generations
// are smaller; carried by the water they rise at their capped Stokes speed (the midpoint rule is
// exact in a uniform flow), and pop where the water ends. The post pass keeps them per frame:
// files round-trip exactly and refuse damage by name, frames are current only while every cache
// frame up to theirs is unchanged, and a pass continued from a stored frame makes the same
// bubbles as one run straight through.
#include "core/Error.h"
#include "post/SubgridAdvector.h"
#include "post/SubgridFile.h"
#include "post/SubgridPass.h"
#include "post/SubgridSpawner.h"
#include "scene/SceneJson.h"
#include "sim/FrameStats.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace airtrap;

namespace {

BubbleState newBubble(std::uint32_t id, double areaFraction) {
    BubbleState bubble;
    bubble.id = id;
    bubble.radius = 0.02;
    bubble.body.position = Vec3d(0.5, 0.3, 0.5);
    bubble.body.linearVelocity = Vec3d(0.0, 0.1, 0.0);
    bubble.areaFractionInWater = areaFraction;
    return bubble;
}

//! Water filling [0,1] × [0,height] × [0,1] on the lattice, all moving at `velocity`.
ParticleSet uniformWater(double spacing, double height, const Vec3f& velocity) {
    ParticleSet water;
    std::uint32_t id = 0;
    const int columns = int(std::lround(1.0 / spacing));
    const int rows = int(std::lround(height / spacing));
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < rows; ++j)
            for (int k = 0; k < columns; ++k)
                water.push((spacing * Vec3d(i + 0.5, j + 0.5, k + 0.5)).cast<float>(), velocity,
                           1000.0f, id++);
    return water;
}

Scene sceneWithSpacing(double spacing) {
    Scene scene;
    scene.solver.particleSpacing = spacing;
    scene.bubbles.maxRiseSpeed = 0.25;
    return scene;
}

SubgridFrame someFrame() {
    SubgridFrame frame;
    frame.trappedIdsBelow = 5;
    frame.nextId = 40;
    std::uint32_t nextId = 0;
    frame.bubbles = SubgridSpawner({}, 7).shed(newBubble(3, 0.0), nextId);
    frame.bubbles[4].age = 0.125;
    return frame;
}

void expectCorrupt(const std::vector<std::uint8_t>& bytes, const char* what) {
    try {
        SubgridFile::decode(bytes, "/c/post/subgrid_0007.atb");
        QFAIL(what);
    } catch (const Error& error) {
        QCOMPARE(int(error.kind()), int(ErrorKind::CacheCorrupt));
        QVERIFY2(std::string(error.what()).starts_with("/c/post/subgrid_0007.atb: "), error.what());
    }
}

//! Frame `frame` of a cache of still water 0.4 m deep, in which trapped bubble 0 (entirely in
//! air at its birth, so it sheds the most) appears from frame 2 on.
SimulationState stillWaterFrame(int frame, const Scene& scene) {
    SimulationState state;
    state.frame = frame;
    state.time = scene.frameTime(frame);
    state.fluid = uniformWater(scene.solver.particleSpacing, 0.4, Vec3f::Zero());
    if (frame >= 2) {
        state.bubbles.push_back(newBubble(0, 0.0));
        state.nextBubbleId = 1;
    }
    return state;
}

FrameCache stillWaterCache(const std::string& dir, const Scene& scene, int frames) {
    FrameCache cache =
        FrameCache::create(dir, sceneToJson(scene), parameterHash(scene), scene.frames.fps);
    for (int frame = 1; frame <= frames; ++frame)
        cache.writeFrame(stillWaterFrame(frame, scene), FrameStats());
    return cache;
}

} // namespace

class TestSubgridBubbles : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void fewerInWaterShedMore() {
        const SubgridSpawner spawner({}, 7);
        QCOMPARE(spawner.countFor(1.0), 0);
        QCOMPARE(spawner.countFor(0.5), 12);
        QCOMPARE(spawner.countFor(0.0), 24);
        std::uint32_t nextId = 100;
        QCOMPARE(spawner.shed(newBubble(3, 0.25), nextId).size(), std::size_t(18));
        QCOMPARE(nextId, 118u);
    }

    void sitesLieOnThreeSpheresOutsideTheBubble() {
        const SubgridSpawner spawner({}, 7);
        const BubbleState parent = newBubble(3, 0.0);
        std::uint32_t nextId = 0;
        for (const SubgridBubble& b : spawner.shed(parent, nextId)) {
            const double shell = (b.position - parent.body.position).norm() / parent.radius;
            const bool onAShell = std::abs(shell - 1.25) < 1e-9 || std::abs(shell - 1.5) < 1e-9 ||
                                  std::abs(shell - 1.75) < 1e-9;
            QVERIFY2(onAShell, qPrintable(QString("at %1 radii").arg(shell)));
            QVERIFY(b.radius >= 0.15 * parent.radius && b.radius <= 0.35 * parent.radius);
            QCOMPARE(b.parentId, parent.id);
            QCOMPARE(b.generation, 1);
            QVERIFY(b.velocity.isApprox(parent.body.linearVelocity));
        }
    }

    void theSameSeedShedsTheSameBubbles() {
        std::uint32_t a = 0;
        std::uint32_t b = 0;
        std::uint32_t c = 0;
        const auto first = SubgridSpawner({}, 7).shed(newBubble(3, 0.0), a);
        QCOMPARE(SubgridSpawner({}, 7).shed(newBubble(3, 0.0), b), first);
        QVERIFY(SubgridSpawner({}, 8).shed(newBubble(3, 0.0), c) != first);
        std::uint32_t d = 0;
        QVERIFY2(SubgridSpawner({}, 7).shed(newBubble(4, 0.0), d) != first,
                 "another bubble, another stream");
    }

    void laterGenerationsAreSmallerAndAroundTheirParent() {
        SubgridBubbleSettings settings;
        settings.generations = 2;
        settings.childrenPerBubble = 3;
        std::uint32_t nextId = 0;
        const std::vector<SubgridBubble> all =
            SubgridSpawner(settings, 7).shed(newBubble(3, 0.0), nextId);
        QCOMPARE(all.size(), std::size_t(24 + 24 * 3));
        for (const SubgridBubble& child : all) {
            if (child.generation != 2)
                continue;
            const auto parent = std::find_if(all.begin(), all.end(), [&](const SubgridBubble& p) {
                return p.id == child.parentId;
            });
            QVERIFY(parent != all.end() && parent->generation == 1);
            QVERIFY(child.radius <= 0.35 * parent->radius);
            const double shell = (child.position - parent->position).norm() / parent->radius;
            QVERIFY(shell >= 1.25 - 1e-9 && shell <= 1.75 + 1e-9);
        }
    }

    void badSettingsAreRefused() {
        SubgridBubbleSettings tooMany;
        tooMany.maxPerBubble = 500;
        QVERIFY_THROWS_EXCEPTION(Error, SubgridSpawner(tooMany, 1));
        SubgridBubbleSettings inverted;
        inverted.minSize = 0.4;
        inverted.maxSize = 0.2;
        QVERIFY_THROWS_EXCEPTION(Error, SubgridSpawner(inverted, 1));
    }

    void theyRiseAtTheirStokesSpeedThroughStillWater() {
        const double spacing = 0.02;
        const Scene scene = sceneWithSpacing(spacing);
        const ParticleSet water = uniformWater(spacing, 0.6, Vec3f::Zero());
        const WaterVelocityField field(water, scene.supportRadius());
        const SubgridAdvector advector({}, scene);
        // 1 mm: Stokes gives 2/9 · 9.81 · 1e-6 / 1e-6 = 2.18 m/s, capped at 0.25 m/s.
        QVERIFY(std::abs(advector.riseSpeed(0.001) - 0.25) < 1e-12);
        const double small = 0.0002; // Stokes 0.0872 m/s, under the cap
        QVERIFY(std::abs(advector.riseSpeed(small) - 2.0 / 9.0 * 9.81 * small * small / 1e-6) <
                1e-12);
        std::vector<SubgridBubble> bubbles(1);
        bubbles[0].position = Vec3d(0.5, 0.2, 0.5);
        bubbles[0].radius = small;
        advector.advance(bubbles, field, {}, 1.0 / 30.0);
        QCOMPARE(bubbles.size(), std::size_t(1));
        const double risen = bubbles[0].position.y() - 0.2;
        QVERIFY2(std::abs(risen - advector.riseSpeed(small) / 30.0) < 1e-6,
                 qPrintable(QString("rose %1 m").arg(risen)));
        QVERIFY(std::abs(bubbles[0].position.x() - 0.5) < 1e-9);
        QVERIFY(std::abs(bubbles[0].age - 1.0 / 30.0) < 1e-12);
    }

    void theWaterCarriesThemAndTheyPopAtTheSurface() {
        const double spacing = 0.02;
        const Scene scene = sceneWithSpacing(spacing);
        const ParticleSet water = uniformWater(spacing, 0.4, Vec3f(0.3f, 0.0f, 0.0f));
        const WaterVelocityField field(water, scene.supportRadius());
        const SubgridAdvector advector({}, scene);
        std::vector<SubgridBubble> bubbles(2);
        bubbles[0].id = 1;
        bubbles[0].position = Vec3d(0.3, 0.2, 0.5);
        bubbles[0].radius = 0.001;
        bubbles[1].id = 2;
        bubbles[1].position = Vec3d(0.3, 0.45, 0.5); // above the water
        bubbles[1].radius = 0.001;
        advector.advance(bubbles, field, {}, 0.1);
        QCOMPARE(bubbles.size(), std::size_t(1));
        QCOMPARE(bubbles[0].id, 1u);
        QVERIFY(std::abs(bubbles[0].position.x() - 0.33) < 1e-6);
        QVERIFY(std::abs(bubbles[0].position.y() - 0.225) < 1e-6);
        // Risen to the surface, it pops there.
        for (int frame = 0; frame < 30; ++frame)
            advector.advance(bubbles, field, {}, 1.0 / 30.0);
        QVERIFY(bubbles.empty());
    }

    void theAirPocketAroundATrappedBubbleIsNotTheSurface() {
        const double spacing = 0.02;
        const Scene scene = sceneWithSpacing(spacing);
        const Vec3d centre(0.5, 0.2, 0.5);
        ParticleSet water;
        const ParticleSet full = uniformWater(spacing, 0.4, Vec3f::Zero());
        for (std::size_t i = 0; i < full.size(); ++i) // the pocket: no water within 6 cm
            if ((full.positions[i].cast<double>() - centre).norm() > 0.06)
                water.push(full.positions[i], Vec3f::Zero(), 1000.0f, std::uint32_t(i));
        const WaterVelocityField field(water, scene.supportRadius());
        BubbleState trapped = newBubble(0, 0.0);
        trapped.body.position = centre;
        trapped.radius = 0.03;
        std::vector<SubgridBubble> inGap(1);
        inGap[0].position = centre + Vec3d(0.04, 0.0, 0.0);
        inGap[0].radius = 0.005;
        const SubgridAdvector advector({}, scene);
        std::vector<SubgridBubble> kept = inGap;
        advector.removeSurfaced(kept, field, {trapped});
        QCOMPARE(kept.size(), std::size_t(1));
        advector.removeSurfaced(inGap, field, {}); // the same gap with its bubble gone: air
        QVERIFY(inGap.empty());
    }

    void aFrameFileRoundTripsExactlyAndRefusesDamage() {
        const SubgridFrame frame = someFrame();
        const std::vector<std::uint8_t> good = SubgridFile::encode(frame);
        QCOMPARE(SubgridFile::decode(good, "file"), frame);
        QCOMPARE(SubgridFile::decode(SubgridFile::encode({}), "empty"), SubgridFrame());
        expectCorrupt({good.begin(), good.end() - 5}, "truncated");
        std::vector<std::uint8_t> flipped = good;
        flipped[200] ^= 0x04;
        expectCorrupt(flipped, "one bit flipped");
        std::vector<std::uint8_t> foreign = good;
        foreign[1] = 'X';
        expectCorrupt(foreign, "not a sub-grid file");
    }

    void storedFramesAreCurrentWhileTheirChainIsUnchanged() {
        QTemporaryDir dir;
        const std::string path = dir.path().toStdString();
        CacheManifest manifest;
        manifest.frames = {{1, "frame_0001.atf", 10, 0x11u}, {2, "frame_0002.atf", 10, 0x22u}};
        const std::uint32_t chain1 = SubgridStore::chainCrc32(0, 0x11u);
        const std::uint32_t chain2 = SubgridStore::chainCrc32(chain1, 0x22u);
        QVERIFY(chain2 != SubgridStore::chainCrc32(SubgridStore::chainCrc32(0, 0x12u), 0x22u));
        {
            SubgridStore store = SubgridStore::open(path);
            store.useSettings({{"max_per_bubble", 24}});
            store.writeFrame({1, chain1, 0}, {});
            store.writeFrame({2, chain2, 24}, someFrame());
        }
        SubgridStore store = SubgridStore::open(path);
        QVERIFY(store.isCurrentIn(manifest, 1) && store.isCurrentIn(manifest, 2));
        QCOMPARE(store.readFrame(2), someFrame());
        manifest.frames[0].crc32 = 0x12u; // frame 1 was baked again: frame 2 came from the old one
        QVERIFY(!store.isCurrentIn(manifest, 1) && !store.isCurrentIn(manifest, 2));
        QVERIFY(!store.isCurrentIn(manifest, 3));
        store.useSettings({{"max_per_bubble", 12}});
        QVERIFY(SubgridStore::open(path).frames().empty());
        QVERIFY_THROWS_EXCEPTION(Error, store.readFrame(2));
    }

    void thePassShedsOnceAndGoesOnFromAStoredFrame() {
        const Scene scene = sceneWithSpacing(0.02);
        QTemporaryDir straight;
        const FrameCache cache = stillWaterCache(straight.path().toStdString(), scene, 4);
        Interrupter interrupter;
        SubgridPass pass(cache, scene);
        const SubgridReport report = pass.run(4, interrupter);
        QCOMPARE(report.made, 4);
        QCOMPARE(report.lastFrame, 4);
        QCOMPARE(report.lastFrameBubbles, 24u); // shed at its birth in frame 2, never again
        const SubgridFrame second = pass.store().readFrame(2);
        const SubgridFrame fourth = pass.store().readFrame(4);
        QVERIFY(pass.store().readFrame(1).bubbles.empty());
        QCOMPARE(second.trappedIdsBelow, 1u);
        // Two frames of still water later, each has risen at its Stokes speed.
        const SubgridAdvector advector(scene.subgridBubbles, scene);
        for (std::size_t i = 0; i < fourth.bubbles.size(); ++i) {
            const double risen = fourth.bubbles[i].position.y() - second.bubbles[i].position.y();
            QVERIFY(std::abs(risen - 2.0 / scene.frames.fps *
                                         advector.riseSpeed(fourth.bubbles[i].radius)) < 1e-9);
        }

        QTemporaryDir inSteps;
        const FrameCache same = stillWaterCache(inSteps.path().toStdString(), scene, 4);
        QCOMPARE(SubgridPass(same, scene).run(2, interrupter).made, 2);
        const SubgridReport rest = SubgridPass(same, scene).run(4, interrupter);
        QCOMPARE(rest.alreadyCurrent, 2);
        QCOMPARE(rest.made, 2);
        QCOMPARE(SubgridStore::open(same.directory()).readFrame(4), fourth);
    }

    void aRebakedFrameRemakesItAndTheFramesAfterIt() {
        const Scene scene = sceneWithSpacing(0.02);
        QTemporaryDir dir;
        FrameCache cache = stillWaterCache(dir.path().toStdString(), scene, 4);
        Interrupter interrupter;
        SubgridPass(cache, scene).run(4, interrupter);
        SimulationState rebaked = stillWaterFrame(3, scene);
        rebaked.steps = 99;
        cache.writeFrame(rebaked, FrameStats());
        const SubgridReport report = SubgridPass(cache, scene).run(4, interrupter);
        QCOMPARE(report.alreadyCurrent, 2);
        QCOMPARE(report.made, 2);
    }
};

AIRTRAP_TEST_APPLESS(TestSubgridBubbles)
#include "TestSubgridBubbles.moc"
