#include "io/BubblePoints.h"

#include "core/AtomicFile.h"
#include "io/PlyHeader.h"

#include <cstring>

namespace airtrap {

namespace {

std::string bubbleHeader(std::size_t count, const std::vector<std::string>& comments) {
    return plyHeader(count, comments,
                     {{"float", "x"},
                      {"float", "y"},
                      {"float", "z"},
                      {"float", "pscale"},
                      {"float", "vx"},
                      {"float", "vy"},
                      {"float", "vz"},
                      {"float", "age"},
                      {"uint", "id"}});
}

} // namespace

std::vector<std::uint8_t> BubblePoints::encode(const std::vector<BubblePoint>& points,
                                               const std::vector<std::string>& comments,
                                               UpAxis up) {
    const std::string head = bubbleHeader(points.size(), comments);
    std::vector<std::uint8_t> bytes(head.size() + points.size() * kVertexBytes);
    std::memcpy(bytes.data(), head.data(), head.size());
    std::uint8_t* out = bytes.data() + head.size();
    for (const BubblePoint& point : points) {
        const Vec3f position = toExportAxes(point.position, up).cast<float>();
        const Vec3f velocity = toExportAxes(point.velocity, up).cast<float>();
        const float values[8] = {position.x(), position.y(), position.z(), float(point.radius),
                                 velocity.x(), velocity.y(), velocity.z(), float(point.age)};
        std::memcpy(out, values, sizeof values);
        out += sizeof values;
        std::memcpy(out, &point.id, sizeof point.id);
        out += sizeof point.id;
    }
    return bytes;
}

void BubblePoints::write(const std::string& path, const std::vector<BubblePoint>& points,
                         const std::vector<std::string>& comments, UpAxis up) {
    AtomicFile::write(path, encode(points, comments, up));
}

} // namespace airtrap
