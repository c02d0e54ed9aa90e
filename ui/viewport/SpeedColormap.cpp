#include "viewport/SpeedColormap.h"

#include <algorithm>
#include <array>

namespace airtrap {

namespace {

struct Stop {
    float red, green, blue;
};

// Evenly spaced over [0, 1], so the shader finds the segment by multiplying.
constexpr std::array<Stop, 3> kStops = {{
    {0.08f, 0.27f, 0.85f}, // deep blue, at rest
    {0.15f, 0.80f, 1.00f}, // cyan, half the scale
    {1.00f, 1.00f, 1.00f}, // white, the top of the scale
}};

QString glslVector(const Stop& stop) {
    return QStringLiteral("vec3(%1, %2, %3)").arg(stop.red).arg(stop.green).arg(stop.blue);
}

} // namespace

QColor SpeedColormap::colourAt(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    const float scaled = t * float(kStops.size() - 1);
    const std::size_t index = std::min(std::size_t(scaled), kStops.size() - 2);
    const float f = scaled - float(index);
    const Stop& a = kStops[index];
    const Stop& b = kStops[index + 1];
    return QColor::fromRgbF(a.red + (b.red - a.red) * f, a.green + (b.green - a.green) * f,
                            a.blue + (b.blue - a.blue) * f);
}

QString SpeedColormap::glslFunction() {
    QString stops;
    for (const Stop& stop : kStops) {
        stops += (stops.isEmpty() ? QString() : QStringLiteral(", ")) + glslVector(stop);
    }
    return QStringLiteral("const vec3 speedStops[%1] = vec3[%1](%2);\n"
                          "vec3 speedColour(float t) {\n"
                          "    float scaled = clamp(t, 0.0, 1.0) * float(%3);\n"
                          "    int index = min(int(scaled), %4);\n"
                          "    return mix(speedStops[index], speedStops[index + 1], "
                          "scaled - float(index));\n"
                          "}\n")
        .arg(kStops.size())
        .arg(stops)
        .arg(kStops.size() - 1)
        .arg(kStops.size() - 2);
}

} // namespace airtrap
