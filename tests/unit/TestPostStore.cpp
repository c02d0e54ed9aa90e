// The post stage's store beside a cache: meshes round-trip exactly (to float), a damaged mesh
// file is refused by name, results are current only for the cache frame they were made from,
// other settings make every result stale, a reopened store lists what was written, and runs
// over other frames at once keep part lists that the next whole run merges.
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "post/MeshFile.h"
#include "post/PostStore.h"
#include "post/ShapeTessellation.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

using namespace airtrap;

namespace {

TriangleMesh someMesh() {
    return tessellateSphere(0.25).transformed(1.0, Quatd::Identity(), Vec3d(0.5, 1.0, 0.25));
}

void expectCorrupt(const std::vector<std::uint8_t>& bytes, const char* what) {
    try {
        MeshFile::decode(bytes, "/c/post/water_0007.atm");
        QFAIL(what);
    } catch (const Error& error) {
        QCOMPARE(int(error.kind()), int(ErrorKind::CacheCorrupt));
        QVERIFY2(std::string(error.what()).starts_with("/c/post/water_0007.atm: "), error.what());
    }
}

} // namespace

class TestPostStore : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void aMeshRoundTripsToFloatPrecision() {
        const TriangleMesh mesh = someMesh();
        const TriangleMesh back = MeshFile::decode(MeshFile::encode(mesh), "mesh");
        QCOMPARE(back.triangles, mesh.triangles);
        QCOMPARE(back.vertices.size(), mesh.vertices.size());
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
            QVERIFY((back.vertices[v] - mesh.vertices[v]).norm() < 1e-7);
        QCOMPARE(MeshFile::decode(MeshFile::encode({}), "empty").triangleCount(), std::size_t(0));
    }

    void aDamagedMeshFileIsRefused() {
        const std::vector<std::uint8_t> good = MeshFile::encode(someMesh());
        std::vector<std::uint8_t> truncated(good.begin(), good.end() - 9);
        expectCorrupt(truncated, "truncated");
        std::vector<std::uint8_t> flipped = good;
        flipped[100] ^= 0x10;
        expectCorrupt(flipped, "one bit flipped");
        std::vector<std::uint8_t> foreign = good;
        foreign[0] = 'X';
        expectCorrupt(foreign, "not a mesh file");
    }

    void resultsAreCurrentForTheirSourceFrameAndSettings() {
        QTemporaryDir cache;
        const std::string dir = cache.path().toStdString();
        const nlohmann::json settings = {{"surface_mesh", {{"smoothing", 4}}}};
        const WaterVolume none = WaterVolume::build(ParticleSet(), 0.02, {});
        {
            PostStore store = PostStore::open(dir);
            QVERIFY(store.frames().empty());
            store.useSettings(settings);
            store.writeFrame({3, 0xABCDu, someMesh().triangleCount(), 0.5}, someMesh(), none);
            store.writeFrame({1, 0x1234u, 0, 0.25}, TriangleMesh(), none);
        }
        PostStore store = PostStore::open(dir);
        QCOMPARE(store.frames(), (std::vector<int>{1, 3}));
        QVERIFY(store.isCurrent(3, 0xABCDu));
        QVERIFY(!store.isCurrent(3, 0xABCEu)); // the frame was baked again since
        QVERIFY(!store.isCurrent(2, 0xABCDu));
        QCOMPARE(store.readFreeSurface(3).triangleCount(), someMesh().triangleCount());
        QVERIFY(store.readVolume(1).empty());
        QVERIFY_THROWS_EXCEPTION(Error, store.readFreeSurface(2));
        // A damaged volume is refused by its listed CRC-32 before OpenVDB reads it, and is
        // no longer current: post makes it again.
        const std::string volume = dir + "/post/fluid_0001.vdb";
        std::vector<std::uint8_t> bytes = AtomicFile::read(volume);
        bytes.at(bytes.size() / 2) ^= 0x20;
        AtomicFile::write(volume, bytes);
        try {
            store.readVolume(1);
            QFAIL("a damaged volume was read");
        } catch (const Error& error) {
            QCOMPARE(error.kind(), ErrorKind::CacheCorrupt);
            QVERIFY2(std::string(error.what()).find(volume + ": does not match") == 0,
                     error.what());
        }
        QVERIFY(!store.isCurrent(1, 0x1234u));

        store.useSettings(settings);
        QCOMPARE(store.frames().size(), std::size_t(2));
        store.useSettings({{"surface_mesh", {{"smoothing", 8}}}});
        QVERIFY(store.frames().empty());
        QVERIFY(PostStore::open(dir).frames().empty()); // and so says post.json
    }

    void partRunsListApartAndAreMergedByTheNextWholeRun() {
        QTemporaryDir cache;
        const std::string dir = cache.path().toStdString();
        const nlohmann::json settings = {{"surface_mesh", {{"smoothing", 4}}}};
        const WaterVolume none = WaterVolume::build(ParticleSet(), 0.02, {});
        {
            PostStore whole = PostStore::open(dir);
            whole.useSettings(settings);
            whole.writeFrame({1, 0x11u, 0, 0.1}, TriangleMesh(), none);
        }
        std::string damage;
        // Two part runs at once, each over its frames; neither touches post.json.
        PostStore first = PostStore::openPart(dir, "chunk-0", damage);
        PostStore second = PostStore::openPart(dir, "chunk-1", damage);
        for (PostStore* part : {&first, &second})
            part->useSettings(settings);
        first.writeFrame({2, 0x22u, 0, 0.1}, TriangleMesh(), none);
        second.writeFrame({3, 0x33u, 0, 0.1}, TriangleMesh(), none);
        second.writeFrame({4, 0x44u, 0, 0.1}, TriangleMesh(), none);
        QCOMPARE(first.frames(), (std::vector<int>{1, 2})); // post.json's, then its own
        QCOMPARE(PostStore::open(dir).frames(), (std::vector<int>{1}));
        // A part whose result file was damaged since lists nothing for it: made again.
        const std::string volume = dir + "/post/fluid_0004.vdb";
        std::vector<std::uint8_t> bytes = AtomicFile::read(volume);
        bytes.at(bytes.size() / 2) ^= 0x20;
        AtomicFile::write(volume, bytes);

        PostStore whole = PostStore::open(dir);
        whole.useSettings(settings);
        std::vector<std::string> unreadable;
        QCOMPARE(whole.mergeParts(unreadable), 2);
        QVERIFY(unreadable.empty());
        QCOMPARE(whole.frames(), (std::vector<int>{1, 2, 3}));
        QVERIFY(whole.isCurrent(3, 0x33u));
        QCOMPARE(PostStore::open(dir).frames(), (std::vector<int>{1, 2, 3}));
        QVERIFY(!std::filesystem::exists(dir + "/post/parts"));
        QCOMPARE(whole.mergeParts(unreadable), 0);
    }

    void aPartNameMustBeAPlainFileName() {
        QTemporaryDir cache;
        std::string damage;
        for (const char* bad : {"", "../x", "a b", "$(touch pwned)"})
            QVERIFY_THROWS_EXCEPTION(Error,
                                     PostStore::openPart(cache.path().toStdString(), bad, damage));
    }
};

AIRTRAP_TEST_APPLESS(TestPostStore)
#include "TestPostStore.moc"
