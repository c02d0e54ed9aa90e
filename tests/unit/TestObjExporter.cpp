// OBJ export (docs/CLI.md "export") read back the way renderers' importers read it, with assimp:
// one object per named mesh with its vertex and triangle counts, positions to float precision,
// normals that face out, the z-up switch as a proper quarter turn, and sequence names padded to
// four digits.
#include "core/Error.h"
#include "io/ObjExporter.h"
#include "post/SequenceName.h"
#include "post/ShapeTessellation.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

using namespace airtrap;

namespace {

std::vector<NamedMesh> twoObjects() {
    return {{"Water surface", tessellateBox(Vec3d(1.0, 0.5, 0.25))},
            {"Ball", tessellateSphere(0.1).transformed(1.0, Quatd::Identity(), Vec3d(2, 3, 4))}};
}

Vec3d toVec3d(const aiVector3D& v) {
    return {v.x, v.y, v.z};
}

} // namespace

class TestObjExporter : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void assimpReadsBackEveryObjectWithItsCounts() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("bodies_0001.obj").toStdString();
        const std::vector<NamedMesh> objects = twoObjects();
        ObjExporter::write(path, objects, UpAxis::Y, {"frame 1", "second\nline"});

        Assimp::Importer importer;
        const aiScene* scene = importer.ReadFile(path, 0);
        QVERIFY2(scene != nullptr, importer.GetErrorString());
        QCOMPARE(scene->mNumMeshes, 2u);
        for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
            const aiMesh* mesh = scene->mMeshes[m];
            const TriangleMesh& written = objects[m].mesh;
            QCOMPARE(std::size_t(mesh->mNumFaces), written.triangleCount());
            QVERIFY(mesh->HasNormals());
            // assimp's OBJ reader gives every face corner its own vertex.
            QCOMPARE(std::size_t(mesh->mNumVertices), 3 * written.triangleCount());
            for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
                const aiFace& face = mesh->mFaces[f];
                QCOMPARE(face.mNumIndices, 3u);
                for (unsigned corner = 0; corner < 3; ++corner) {
                    const Vec3d read = toVec3d(mesh->mVertices[face.mIndices[corner]]);
                    const Vec3d& expected = written.vertices[written.triangles[f][corner]];
                    QVERIFY((read - expected).norm() < 1e-6 * (1.0 + expected.norm()));
                }
            }
        }
        QCOMPARE(QString(scene->mRootNode->mChildren[0]->mName.C_Str()), QString("Water_surface"));
        QCOMPARE(QString(scene->mRootNode->mChildren[1]->mName.C_Str()), QString("Ball"));
    }

    void normalsFaceOutOfTheirSolid() {
        const TriangleMesh sphere = tessellateSphere(0.5);
        const std::vector<Vec3d> normals = sphere.vertexNormals();
        for (std::size_t v = 0; v < sphere.vertices.size(); ++v)
            QVERIFY(normals[v].dot(sphere.vertices[v].normalized()) > 0.999);
        // A box's faces keep their own vertices, so its normals stay flat.
        const TriangleMesh box = tessellateBox(Vec3d::Ones());
        for (const Vec3d& n : box.vertexNormals())
            QVERIFY(std::abs(n.cwiseAbs().maxCoeff() - 1.0) < 1e-12);
    }

    void zUpTurnsTheSceneAQuarterAboutX() {
        TriangleMesh triangle;
        triangle.vertices = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 2, 3)};
        triangle.triangles = {{0, 1, 2}};
        const std::string text = ObjExporter::encode({{"t", triangle}}, UpAxis::Z);
        QVERIFY(text.find("v 0 -3 2\n") != std::string::npos);
        QVERIFY(text.find("f 1//1 2//2 3//3\n") != std::string::npos);
        QCOMPARE(toExportAxes(Vec3d::UnitY(), UpAxis::Z), Vec3d(Vec3d::UnitZ()));
        QCOMPARE(toExportAxes(Vec3d::UnitZ(), UpAxis::Z), Vec3d(-Vec3d::UnitY()));
        QCOMPARE(toExportAxes(Vec3d(1, 2, 3), UpAxis::Y), Vec3d(1, 2, 3));
    }

    void anEmptyFrameIsAValidFileWithNoObjects() {
        const std::string text = ObjExporter::encode({}, UpAxis::Y, {"nothing to show"});
        QCOMPARE(text, std::string("# nothing to show\n# end: 0 vertices, 0 triangles\n"));
    }

    void theLastLineCountsWhatTheFileHolds() {
        // A file cut short loses this line, which is how a reader tells it from a whole one.
        const std::vector<NamedMesh> objects = twoObjects();
        const std::string text = ObjExporter::encode(objects, UpAxis::Y);
        const std::size_t vertices =
            objects[0].mesh.vertices.size() + objects[1].mesh.vertices.size();
        const std::size_t triangles =
            objects[0].mesh.triangleCount() + objects[1].mesh.triangleCount();
        const std::string last = "# end: " + std::to_string(vertices) + " vertices, " +
                                 std::to_string(triangles) + " triangles\n";
        QVERIFY(text.size() > last.size());
        QCOMPARE(text.substr(text.size() - last.size()), last);
    }

    void sequenceNamesArePaddedToFourDigits() {
        QCOMPARE(sequenceFileName("water", 1, "obj"), std::string("water_0001.obj"));
        QCOMPARE(sequenceFileName("fluid", 250, "vdb"), std::string("fluid_0250.vdb"));
        QCOMPARE(sequenceFileName("bubbles", 12345, "ply"), std::string("bubbles_12345.ply"));
    }

    void anUnwritableFolderIsNamed() {
        try {
            ObjExporter::write("/proc/airtrap/none/water_0001.obj", twoObjects(), UpAxis::Y);
            QFAIL("expected an error");
        } catch (const Error& error) {
            QCOMPARE(int(error.kind()), int(ErrorKind::Io));
            QVERIFY(std::string(error.what()).find("/proc/airtrap/none/water_0001.obj") !=
                    std::string::npos);
        }
    }
};

AIRTRAP_TEST_APPLESS(TestObjExporter)
#include "TestObjExporter.moc"
