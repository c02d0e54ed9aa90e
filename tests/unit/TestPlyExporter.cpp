// PLY particle export: the file is read back by an independent little parser (header lines, then
// the binary body by the declared properties) and compared value for value.
#include "core/Error.h"
#include "io/PlyExporter.h"
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
T valueAt(const PlyFile& ply, std::size_t vertex, std::size_t property) {
    T value;
    std::memcpy(&value, ply.body.data() + vertex * PlyExporter::kVertexBytes + property * 4,
                sizeof value);
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

QTEST_APPLESS_MAIN(TestPlyExporter)
#include "TestPlyExporter.moc"
