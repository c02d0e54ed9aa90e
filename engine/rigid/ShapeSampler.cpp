#include "rigid/ShapeSampler.h"

#include "core/Error.h"
#include "rigid/BoundarySampler.h"
#include "rigid/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <unordered_map>

namespace airtrap {

namespace {

//! Mesh candidates are centroids of sub-triangles at most this many spacings across: dense
//! enough that thinning them behaves like thinning the continuous surface.
constexpr double kCandidateStep = 0.25;
//! Minimum distance between mesh particles, in spacings. Random sequential thinning of the
//! continuous plane to a minimum distance d saturates at 0.70/d² points per area (disc packing
//! fraction 0.547, Feder 1980, "Random sequential adsorption", J. Theor. Biol. 87), which asks
//! for d = 0.83 spacing; thinning our finite candidate set stops a little sooner, and 0.80
//! leaves 1.00–1.02 particles per spacing² on the test meshes, as the analytic samplers do.
constexpr double kMinimumDistance = 0.80;

struct Candidate {
    Vec3d position;
    std::uint32_t triangle;
};

//! Centroids of the k² congruent sub-triangles of a k-fold subdivision of each triangle, k chosen
//! so their edges are at most `step`: every candidate is strictly inside its triangle.
std::vector<Candidate> subdivisionCentroids(const TriangleMesh& mesh, double step) {
    std::vector<Candidate> candidates;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3d& a = mesh.vertices[mesh.triangles[t][0]];
        const Vec3d u = mesh.vertices[mesh.triangles[t][1]] - a;
        const Vec3d v = mesh.vertices[mesh.triangles[t][2]] - a;
        if (u.cross(v).squaredNorm() == 0.0)
            continue; // no area, no normal
        const double longest = std::max({u.norm(), v.norm(), (v - u).norm()});
        const int k = std::max(1, static_cast<int>(std::ceil(longest / step)));
        const auto at = [&](double i, double j) { return Vec3d(a + (i / k) * u + (j / k) * v); };
        const auto triangle = static_cast<std::uint32_t>(t);
        for (int i = 0; i < k; ++i)
            for (int j = 0; i + j < k; ++j) {
                candidates.push_back({at(i + 1.0 / 3.0, j + 1.0 / 3.0), triangle});
                if (i + j < k - 1) // the upside-down sub-triangle beside it
                    candidates.push_back({at(i + 2.0 / 3.0, j + 2.0 / 3.0), triangle});
            }
    }
    return candidates;
}

//! Fisher–Yates with a fixed seed, written out because std::shuffle's sequence differs between
//! standard libraries and the particles should not.
void shuffleDeterministically(std::vector<Candidate>& candidates) {
    std::mt19937_64 random(20120801); // any fixed seed
    for (std::size_t i = candidates.size(); i > 1; --i)
        std::swap(candidates[i - 1], candidates[random() % i]);
}

//! Keeps each candidate, in order, unless an already kept one lies closer than `minimum`.
std::vector<Candidate> thin(const std::vector<Candidate>& candidates, double minimum) {
    // Hash grid of cell size `minimum`: a conflict can only sit in the 27 cells around.
    const auto cellOf = [minimum](const Vec3d& x) {
        return Vec3i((x / minimum).array().floor().cast<int>());
    };
    const auto keyOf = [](const Vec3i& c) {
        const auto part = [](int value) { return std::uint64_t(value + (1 << 20)) & 0x1FFFFF; };
        return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
    std::vector<Candidate> kept;
    const double minimum2 = minimum * minimum;
    for (const Candidate& candidate : candidates) {
        const Vec3i cell = cellOf(candidate.position);
        bool free = true;
        for (int dz = -1; dz <= 1 && free; ++dz)
            for (int dy = -1; dy <= 1 && free; ++dy)
                for (int dx = -1; dx <= 1 && free; ++dx) {
                    const auto it = cells.find(keyOf(cell + Vec3i(dx, dy, dz)));
                    if (it == cells.end())
                        continue;
                    for (std::uint32_t k : it->second)
                        if ((kept[k].position - candidate.position).squaredNorm() < minimum2)
                            free = false;
                }
        if (!free)
            continue;
        cells[keyOf(cell)].push_back(static_cast<std::uint32_t>(kept.size()));
        kept.push_back(candidate);
    }
    return kept;
}

} // namespace

void ShapeSampler::requirePositive(double value, const char* what) {
    if (!std::isfinite(value) || value <= 0.0)
        throw Error(ErrorKind::InvalidInput,
                    std::string(what) + " must be a positive number, got " + std::to_string(value));
}

void ShapeSampler::append(BoundaryParticles& out, const Vec3d& position, const Vec3d& normal) {
    out.positions.push_back(position.cast<float>());
    out.normals.push_back(normal.normalized().cast<float>());
    out.volumes.push_back(0.0f);
}

BoundaryParticles ShapeSampler::sampleSphere(double radius, double spacing) {
    requirePositive(radius, "sphere radius");
    requirePositive(spacing, "spacing");
    const double area = 4.0 * std::numbers::pi * radius * radius;
    const long count = std::max(1L, std::lround(area / (spacing * spacing)));
    // Fibonacci spiral: equal-area bands in y (Archimedes: a sphere's zone area is proportional
    // to its height), successive points turned by the golden angle so no two line up
    // (González 2010, "Measurement of areas on a sphere using Fibonacci and latitude–longitude
    // lattices", Math. Geosci. 42).
    const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    BoundaryParticles out;
    for (long i = 0; i < count; ++i) {
        const double y = 1.0 - (2.0 * i + 1.0) / count;
        const double ring = std::sqrt(std::max(0.0, 1.0 - y * y));
        const double angle = goldenAngle * i;
        const Vec3d direction(ring * std::cos(angle), y, ring * std::sin(angle));
        append(out, radius * direction, direction);
    }
    return out;
}

void ShapeSampler::appendRing(BoundaryParticles& out, double ringRadius, double y, double spacing,
                              double phase, double radialWeight, const Vec3d& axialNormal) {
    if (ringRadius < 1e-9 * spacing) {
        append(out, Vec3d(0.0, y, 0.0), axialNormal);
        return;
    }
    const double circumference = 2.0 * std::numbers::pi * ringRadius;
    const long count = std::max(3L, std::lround(circumference / spacing));
    for (long j = 0; j < count; ++j) {
        const double angle = 2.0 * std::numbers::pi * (j + phase) / count;
        const Vec3d radial(std::cos(angle), 0.0, std::sin(angle));
        append(out, Vec3d(ringRadius * radial.x(), y, ringRadius * radial.z()),
               radialWeight * radial + axialNormal);
    }
}

BoundaryParticles ShapeSampler::sampleCylinder(double radius, double height, double spacing) {
    requirePositive(radius, "cylinder radius");
    requirePositive(height, "cylinder height");
    requirePositive(spacing, "spacing");
    BoundaryParticles out;
    // Side: rings from rim to rim, every other one turned half a step so the side is sampled
    // like a staggered (near-hexagonal) lattice rather than in columns.
    const long layers = std::max(1L, std::lround(height / spacing));
    for (long k = 0; k <= layers; ++k) {
        const double y = -0.5 * height + height * k / layers;
        const double rimSide = k == 0 ? -1.0 : k == layers ? 1.0 : 0.0;
        const Vec3d rim = rimSide * Vec3d::UnitY();
        appendRing(out, radius, y, spacing, 0.5 * (k % 2), 1.0, rim);
    }
    // Caps: concentric rings inward from the rim (which the side already holds) to the centre.
    const long rings = std::max(1L, std::lround(radius / spacing));
    for (const double side : {-1.0, 1.0})
        for (long j = 1; j <= rings; ++j) {
            const double ringRadius = radius * double(rings - j) / rings;
            appendRing(out, ringRadius, side * 0.5 * height, spacing, 0.5 * (j % 2), 0.0,
                       side * Vec3d::UnitY());
        }
    return out;
}

BoundaryParticles ShapeSampler::sampleSolidBox(const Vec3d& size, double spacing) {
    for (int axis = 0; axis < 3; ++axis)
        requirePositive(size[axis], "box size");
    requirePositive(spacing, "spacing");
    const Aabb box{-0.5 * size, 0.5 * size};
    return BoundarySampler::sampleBox(box, spacing, BoundarySampler::WaterSide::Outside, false);
}

BoundaryParticles ShapeSampler::sampleMesh(const TriangleMesh& mesh, double spacing) {
    requirePositive(spacing, "spacing");
    std::vector<Candidate> candidates = subdivisionCentroids(mesh, kCandidateStep * spacing);
    shuffleDeterministically(candidates);
    BoundaryParticles out;
    for (const Candidate& kept : thin(candidates, kMinimumDistance * spacing))
        append(out, kept.position, mesh.normal(kept.triangle));
    return out;
}

} // namespace airtrap
