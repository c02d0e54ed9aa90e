// Mesh loading: OBJ, PLY and STL read to the same indexed solid; every way a mesh can fail to bound
// a solid is refused with the file's path and the reason (docs/SCENE_FORMAT.md "Validation").
#include "MeshTestSupport.h"
#include "core/Error.h"
#include "rigid/MeshLoader.h"
#include "rigid/ObjText.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <sys/stat.h>

using namespace airtrap;
using namespace airtrap::test;

class TestMeshLoader : public QObject {
    Q_OBJECT

    QTemporaryDir folder_;

    std::string pathOf(const char* name) const { return folder_.filePath(name).toStdString(); }

    //! The InvalidInput message loading `path` gives, or "" if it loads.
    static std::string loadError(const std::string& path) {
        try {
            MeshLoader::load(path);
        } catch (const Error& error) {
            return error.kind() == ErrorKind::InvalidInput ? error.what() : "wrong error kind";
        }
        return {};
    }

    static bool contains(const std::string& text, const std::string& part) {
        return text.find(part) != std::string::npos;
    }

    static std::string dataFile(const char* name) {
        return std::string(AIRTRAP_SOURCE_DIR) + "/tests/data/" + name;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(folder_.isValid()); }

    void readsAnIndexedObj() {
        const TriangleMesh sphere = icosphere(0.1, 3);
        writeObj(folder_.filePath("sphere.obj"), sphere);
        const TriangleMesh loaded = MeshLoader::load(pathOf("sphere.obj"));
        QCOMPARE(loaded.triangleCount(), std::size_t(1280));
        QCOMPARE(loaded.vertices.size(), sphere.vertices.size()); // 642: nothing lost or split
        // assimp keeps positions in single precision: seven digits survive.
        QVERIFY(relativeError(loaded.signedVolume(), sphere.signedVolume()) < 1e-6);
    }

    void stlSoupAndPlyGiveTheSameSolid() {
        const TriangleMesh box = cube(0.3);
        writeStl(folder_.filePath("cube.stl"), box);
        writePly(folder_.filePath("cube.ply"), box);
        const TriangleMesh fromStl = MeshLoader::load(pathOf("cube.stl"));
        const TriangleMesh fromPly = MeshLoader::load(pathOf("cube.ply"));
        // The STL stores each triangle's three corners on their own: welding joins the 36
        // corners into the cube's 8 vertices, or the cube would not be closed.
        QCOMPARE(fromStl.vertices.size(), std::size_t(8));
        QCOMPARE(fromPly.vertices.size(), std::size_t(8));
        QVERIFY(relativeError(fromStl.signedVolume(), 0.027) < 1e-6); // written with 9 digits
        QVERIFY(relativeError(fromPly.signedVolume(), fromStl.signedVolume()) < 1e-12);
    }

    void triangulatesPolygons() {
        std::ofstream(pathOf("quads.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                              "v 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                                              "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\n"
                                              "f 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";
        const TriangleMesh unitCube = MeshLoader::load(pathOf("quads.obj"));
        QCOMPARE(unitCube.triangleCount(), std::size_t(12));
        QVERIFY(std::abs(unitCube.signedVolume() - 1.0) < 1e-12);
    }

    void scalesToMetres() {
        writeObj(folder_.filePath("cube_mm.obj"), cube(300.0)); // millimetres
        const TriangleMesh metres = MeshLoader::load(pathOf("cube_mm.obj"), 0.001);
        QVERIFY(relativeError(metres.signedVolume(), 0.027) < 1e-12); // 150 mm is exact in float
        try {
            MeshLoader::load(pathOf("cube_mm.obj"), -1.0);
            QFAIL("a negative scale was accepted");
        } catch (const Error& error) {
            QVERIFY(contains(error.what(), pathOf("cube_mm.obj")));
            QVERIFY(contains(error.what(), "scale"));
        }
    }

    void turnsAnInsideOutMeshOutward() {
        TriangleMesh insideOut = cube(0.5); // exact in single precision, as assimp stores it
        insideOut.flipOrientation();
        QVERIFY(insideOut.signedVolume() < 0.0);
        writeObj(folder_.filePath("inside_out.obj"), insideOut);
        const TriangleMesh loaded = MeshLoader::load(pathOf("inside_out.obj"));
        QCOMPARE(loaded.signedVolume(), 0.125);
        for (std::size_t t = 0; t < loaded.triangleCount(); ++t) {
            const auto& tri = loaded.triangles[t];
            const Vec3d centre =
                (loaded.vertices[tri[0]] + loaded.vertices[tri[1]] + loaded.vertices[tri[2]]) / 3;
            QVERIFY(loaded.normal(t).dot(centre) > 0.0); // the cube is centred at the origin
        }
    }

    void refusesAnOpenMesh() {
        TriangleMesh box = cube(0.3);
        box.triangles.resize(box.triangles.size() - 2); // the +z face's two triangles
        writeObj(folder_.filePath("open_box.obj"), box);
        const std::string message = loadError(pathOf("open_box.obj"));
        qInfo("%s", message.c_str());
        QVERIFY2(contains(message, pathOf("open_box.obj")), message.c_str());
        // The missing square's four sides; its diagonal went with both its triangles.
        QVERIFY2(contains(message, "is not closed: 4 edges belong to only one triangle"),
                 message.c_str());
    }

    void refusesAnInconsistentlyOrientedMesh() {
        TriangleMesh box = cube(0.3);
        std::swap(box.triangles[0][1], box.triangles[0][2]);
        writeObj(folder_.filePath("one_flipped.obj"), box);
        const std::string message = loadError(pathOf("one_flipped.obj"));
        qInfo("%s", message.c_str());
        QVERIFY2(contains(message, pathOf("one_flipped.obj")), message.c_str());
        QVERIFY2(contains(message, "inconsistently oriented: 3 edges"), message.c_str());
    }

    void refusesANonManifoldMesh() {
        TriangleMesh twoCubes = cube(0.3);
        const TriangleMesh second = cube(0.3).transformed(1.0, Quatd::Identity(), Vec3d(0.3, 0, 0));
        // Glued along a face: its four edges now belong to four triangles each.
        const auto offset = static_cast<std::uint32_t>(twoCubes.vertices.size());
        twoCubes.vertices.insert(twoCubes.vertices.end(), second.vertices.begin(),
                                 second.vertices.end());
        for (const auto& [a, b, c] : second.triangles)
            twoCubes.triangles.push_back({a + offset, b + offset, c + offset});
        writeObj(folder_.filePath("glued.obj"), twoCubes);
        const std::string message = loadError(pathOf("glued.obj"));
        qInfo("%s", message.c_str());
        QVERIFY2(contains(message, "is not manifold"), message.c_str());
    }

    void refusesAnEmptyFile() {
        std::ofstream(pathOf("empty.obj")).flush();
        const std::string message = loadError(pathOf("empty.obj"));
        qInfo("%s", message.c_str());
        QVERIFY2(contains(message, pathOf("empty.obj") + ": contains no triangles"),
                 message.c_str());
    }

    void refusesAFileWithoutFaces() {
        std::ofstream(pathOf("points.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        const std::string message = loadError(pathOf("points.obj"));
        qInfo("%s", message.c_str());
        QVERIFY2(contains(message, pathOf("points.obj") + ": contains no triangles"),
                 message.c_str());
    }

    void refusesAMissingFile() {
        const std::string message = loadError(pathOf("no_such_mesh.obj"));
        qInfo("%s", message.c_str());
        QVERIFY2(contains(message, pathOf("no_such_mesh.obj")), message.c_str());
    }

    void refusesAnUnreadableFile() {
        std::ofstream(pathOf("garbage.stl")) << "this is not a mesh\n";
        const std::string message = loadError(pathOf("garbage.stl"));
        qInfo("%s", message.c_str());
        QVERIFY2(contains(message, pathOf("garbage.stl")), message.c_str());
        QVERIFY2(!message.empty(), "garbage loaded");
    }

    void readsObjNumbersWithoutALeadingZero() {
        // Valid OBJ that assimp 5.2 misreads ("vertex index out of range") unless given zeros.
        std::ofstream(pathOf("bare.obj")) << "# a tetrahedron .1 across\n"
                                             "v 0 0 0\nv .1 0 0\nv 0 +.1 0\nv 0 0 .1\n"
                                             "vn -.5 .5 .5\n"
                                             "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        const TriangleMesh mesh = MeshLoader::load(pathOf("bare.obj"));
        QCOMPARE(mesh.triangleCount(), std::size_t(4));
        QVERIFY((mesh.bounds().max - Vec3d(0.1, 0.1, 0.1)).norm() < 1e-6); // read as floats
        QCOMPARE(ObjText::withLeadingZeros("v .1 -.2 +.3 1.5\nf 1 2 3\n# .4\nvt .5 .5"),
                 std::string("v 0.1 -0.2 +0.3 1.5\nf 1 2 3\n# .4\nvt 0.5 0.5"));
    }

    void refusesAMalformedObjBeforeAssimpReadsIt_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("problem");
        const QString tetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
        // The fuzzer's input: a coordinate mangled into a word. assimp 5.2 leaked the mesh it
        // was building when it then met the faces.
        QTest::newRow("word for a coordinate") << "v 0 0 0\nv -0.07 0.03 u.0033\nv 0 1 0\nf 1 2 3\n"
                                               << "line 2: v value 'u.0033' is not a number";
        QTest::newRow("two coordinates") << "v 0 0\nf 1 1 1\n"
                                         << "line 1: a vertex needs 3 coordinates, this one has 2";
        QTest::newRow("face past the vertices")
            << tetrahedron + "f 1 2 5\n"
            << "line 5: the face refers to vertex 5, but 4 are defined before it";
        QTest::newRow("face before its vertex")
            << "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n"
            << "line 2: the face refers to vertex 2, but 1 are defined before it";
        QTest::newRow("negative index too far back")
            << tetrahedron + "f -1 -2 -5\n"
            << "line 5: the face refers to vertex -5, but 4 are defined before it";
        QTest::newRow("index zero") << tetrahedron + "f 0 1 2\n"
                                    << "line 5: face corner '0' has no vertex index";
        QTest::newRow("normal not a number") << "vn 0 nan 1\n"
                                             << "line 1: vn value 'nan' is not a number";
    }

    void refusesAMalformedObjBeforeAssimpReadsIt() {
        QFETCH(QString, text);
        QFETCH(QString, problem);
        QCOMPARE(QString::fromStdString(ObjText::problemIn(text.toStdString())), problem);
        std::ofstream(pathOf("bad.obj")) << text.toStdString();
        const std::string message = loadError(pathOf("bad.obj"));
        QVERIFY2(contains(message,
                          pathOf("bad.obj") + ": not a valid OBJ file: " + problem.toStdString()),
                 message.c_str());
        // Valid forms are not refused: slashes, negative indices, colours, CRLF line ends.
        QCOMPARE(ObjText::problemIn("v 0 0 0 1 0 0\r\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                                    "f 1/1/1 2//1 -1/1\n"),
                 std::string());
    }

    void refusesAFifoAndAFolderWithoutWaiting() {
        // Opened for reading, a FIFO with no writer blocks forever: the loader must not open it.
        const std::string fifo = pathOf("pipe.obj");
        QCOMPARE(::mkfifo(fifo.c_str(), 0600), 0);
        for (const std::string& path : {fifo, folder_.path().toStdString()}) {
            const std::string message = loadError(path);
            qInfo("%s", message.c_str());
            QVERIFY2(contains(message, path + ": not a regular file"), message.c_str());
        }
    }

    void loadsTheStanfordBunnyClosed() {
        // tests/data/bunny.SOURCE.txt: watertight, 5,884 vertices, 11,764 triangles.
        const TriangleMesh bunny = MeshLoader::load(dataFile("bunny_lowres.obj"));
        QCOMPARE(bunny.vertices.size(), std::size_t(5884));
        QCOMPARE(bunny.triangleCount(), std::size_t(11764));
        const TriangleMesh::EdgeCounts edges = bunny.countEdges();
        QCOMPARE(edges.paired, std::size_t(17646));
        QCOMPARE(edges.open + edges.nonManifold + edges.misoriented, std::size_t(0));
        QVERIFY(bunny.signedVolume() > 0.0);
    }

    void loadsTheContainerWithAHoleAsAClosedShell() {
        // The "open" container is open to the water (an open top and a hole through its floor)
        // but its thick walls form one closed surface of genus 1: it is a solid and loads.
        const TriangleMesh container = MeshLoader::load(dataFile("container_box_open_hole.obj"));
        QCOMPARE(container.triangleCount(), std::size_t(48));
        QCOMPARE(container.countEdges().open, std::size_t(0));
        // Its README gives 0.3225 for the walls' volume.
        QVERIFY(relativeError(container.signedVolume(), 0.3225) < 1e-3);
    }
};

AIRTRAP_TEST_APPLESS(TestMeshLoader)
#include "TestMeshLoader.moc"
