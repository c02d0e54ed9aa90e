// PLY particle export: the file is read back by an independent little parser (header lines, then
// the binary body by the declared properties) and compared value for value.
#include "core/Error.h"
#include "io/BubblePoints.h"
#include "io/PlyExporter.h"
#include "support/TestMain.h"
#include "unit/CacheTestData.h"

#include <QTemporaryDir>
#include <QtTest/QtTest>
#include <cstring>
#include <fstream>
#include <sstream>

using namespace airtrap;
using namespace airtrap::testing;

namespace {

//! What the parser found in a PLY file.
struct PlyFile {
    std::string format;
    std::vector<std::string> comments;
    std::size_t vertexCount = 0;
    std::vector<std::pair<std::string, std::string>> properties; //!< (type, name)
    std::vector<std::uint8_t> body;
};

std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

//! Parses the ASCII header line by line; everything after "end_header\n" is the body.
PlyFile parsePly(const std::vector<std::uint8_t>& bytes) {
    const std::string text(bytes.begin(), bytes.end());
    const std::string marker = "end_header\n";
    const std::size_t end = text.find(marker);
    if (end == std::string::npos)
        throw std::runtime_error("no end_header");
    PlyFile ply;
    std::istringstream header(text.substr(0, end));
    std::string line;
    std::getline(header, line);
    if (line != "ply")
        throw std::runtime_error("no magic");
    while (std::getline(header, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "format")
            ply.format = line.substr(7);
        else if (keyword == "comment")
            ply.comments.push_back(line.substr(8));
        else if (keyword == "element") {
            std::string name;
            words >> name >> ply.vertexCount;
            if (name != "vertex")
                throw std::runtime_error("unexpected element " + name);
        } else if (keyword == "property") {
            std::string type, name;
            words >> type >> name;
            ply.properties.emplace_back(type, name);
        } else
            throw std::runtime_error("unexpected header line: " + line);
    }
    ply.body.assign(bytes.begin() + std::ptrdiff_t(end + marker.size()), bytes.end());
    return ply;
}

template <typename T>
T valueAt(const PlyFile& ply, std::size_t vertex, std::size_t property,
          std::size_t stride = PlyExporter::kVertexBytes) {
    T value;
    std::memcpy(&value, ply.body.data() + vertex * stride + property * 4, sizeof value);
    return value;
}

} // namespace

class TestPlyExporter : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void writesHeaderAndEveryValue() {
        QTemporaryDir temp;
        QVERIFY(temp.isValid());
        const std::string path = temp.path().toStdString() + "/" + PlyExporter::fileName(3);
        const ParticleSet particles = randomState(3, 57, 11).fluid;
        PlyExporter::write(path, particles, {"Airtrap frame 3"});

        const PlyFile ply = parsePly(readBytes(path));
        QCOMPARE(ply.format, std::string("binary_little_endian 1.0"));
        QCOMPARE(ply.comments, (std::vector<std::string>{"Airtrap frame 3"}));
        QCOMPARE(ply.vertexCount, std::size_t(57));
        const std::vector<std::pair<std::string, std::string>> expected = {
            {"float", "x"},  {"float", "y"},  {"float", "z"},       {"float", "vx"},
            {"float", "vy"}, {"float", "vz"}, {"float", "density"}, {"uint", "id"}};
        QCOMPARE(ply.properties, expected);
        QCOMPARE(ply.body.size(), 57 * PlyExporter::kVertexBytes);
        for (std::size_t i = 0; i < particles.size(); ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                QCOMPARE(valueAt<float>(ply, i, axis), particles.positions[i][axis]);
                QCOMPARE(valueAt<float>(ply, i, 3 + axis), particles.velocities[i][axis]);
            }
            QCOMPARE(valueAt<float>(ply, i, 6), particles.densities[i]);
            QCOMPARE(valueAt<std::uint32_t>(ply, i, 7), particles.ids[i]);
        }
    }

    void emptySetIsAValidFile() {
        const PlyFile ply = parsePly(PlyExporter::encode(ParticleSet{}));
        QCOMPARE(ply.vertexCount, std::size_t(0));
        QCOMPARE(ply.properties.size(), std::size_t(8));
        QVERIFY(ply.body.empty());
    }

    void commentsCannotBreakTheHeader() {
        const PlyFile ply = parsePly(PlyExporter::encode(ParticleSet{}, {"two\nlines"}));
        QCOMPARE(ply.comments, (std::vector<std::string>{"two lines"}));
    }

    void zUpTurnsPositionsAndVelocities() {
        ParticleSet particles;
        particles.push(Vec3f(1, 2, 3), Vec3f(4, 5, 6), 1000.0f, 7);
        const PlyFile ply = parsePly(PlyExporter::encode(particles, {}, UpAxis::Z));
        const std::vector<float> expected = {1, -3, 2, 4, -6, 5};
        for (std::size_t property = 0; property < expected.size(); ++property)
            QCOMPARE(valueAt<float>(ply, 0, property), expected[property]);
    }

    void bubblesArePointsWithScaleVelocityAgeAndId() {
        const std::vector<BubblePoint> bubbles = {
            {Vec3d(0.1, 0.2, 0.3), 0.015, Vec3d(0.0, 0.25, -0.1), 1.5, 42},
            {Vec3d(0.4, 0.5, 0.6), 0.02, Vec3d::Zero(), 0.0, 7}};
        const PlyFile ply = parsePly(BubblePoints::encode(bubbles, {"frame 9"}, UpAxis::Y));
        const std::vector<std::pair<std::string, std::string>> expected = {
            {"float", "x"},      {"float", "y"},   {"float", "z"},
            {"float", "pscale"}, {"float", "vx"},  {"float", "vy"},
            {"float", "vz"},     {"float", "age"}, {"uint", "id"}};
        QCOMPARE(ply.properties, expected);
        QCOMPARE(ply.vertexCount, std::size_t(2));
        QCOMPARE(ply.body.size(), 2 * BubblePoints::kVertexBytes);
        const std::size_t stride = BubblePoints::kVertexBytes;
        for (std::size_t i = 0; i < bubbles.size(); ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                QCOMPARE(valueAt<float>(ply, i, axis, stride), float(bubbles[i].position[axis]));
                QCOMPARE(valueAt<float>(ply, i, 4 + axis, stride),
                         float(bubbles[i].velocity[axis]));
            }
            QCOMPARE(valueAt<float>(ply, i, 3, stride), float(bubbles[i].radius));
            QCOMPARE(valueAt<float>(ply, i, 7, stride), float(bubbles[i].age));
            QCOMPARE(valueAt<std::uint32_t>(ply, i, 8, stride), bubbles[i].id);
        }
    }

    void fileNamesArePaddedToFourDigits() {
        QCOMPARE(PlyExporter::fileName(1), std::string("particles_0001.ply"));
        QCOMPARE(PlyExporter::fileName(60), std::string("particles_0060.ply"));
        QCOMPARE(PlyExporter::fileName(12345), std::string("particles_12345.ply"));
    }

    void unwritablePathIsAnIoErrorNamingIt() {
        QTemporaryDir temp;
        QVERIFY(temp.isValid());
        const std::string file = temp.path().toStdString() + "/plain";
        std::ofstream(file) << "not a folder";
        const std::string path = file + "/" + PlyExporter::fileName(1);
        const auto error = errorOf([&] { PlyExporter::write(path, randomState(1, 4, 1).fluid); });
        QVERIFY(error.has_value());
        QCOMPARE(int(error->kind()), int(ErrorKind::Io));
        QVERIFY2(std::string(error->what()).find(path) != std::string::npos, error->what());
    }
};

AIRTRAP_TEST_APPLESS(TestPlyExporter)
#include "TestPlyExporter.moc"
