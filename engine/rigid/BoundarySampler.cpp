#include "rigid/BoundarySampler.h"

#include <cmath>

namespace airtrap {

BoundaryParticles BoundarySampler::sampleBox(const Aabb& box, double spacing, WaterSide side,
                                             bool openTop) {
    Vec3i cells;
    Vec3d step;
    for (int axis = 0; axis < 3; ++axis) {
        cells[axis] = std::max(1, static_cast<int>(std::lround(box.size()[axis] / spacing)));
        step[axis] = box.size()[axis] / cells[axis];
    }
    const double sign = side == WaterSide::Inside ? -1.0 : 1.0;
    BoundaryParticles out;
    for (int k = 0; k <= cells.z(); ++k)
        for (int j = 0; j <= cells.y(); ++j)
            for (int i = 0; i <= cells.x(); ++i) {
                const Vec3i index(i, j, k);
                Vec3d normal = Vec3d::Zero();
                for (int axis = 0; axis < 3; ++axis) {
                    if (index[axis] == 0)
                        normal[axis] -= 1.0;
                    else if (index[axis] == cells[axis])
                        normal[axis] += 1.0;
                }
                if (normal.isZero())
                    continue; // interior lattice point
                if (openTop && j == cells.y())
                    continue;
                const Vec3d position = box.min + index.cast<double>().cwiseProduct(step);
                out.positions.push_back(position.cast<float>());
                out.normals.push_back((sign * normal.normalized()).cast<float>());
            }
    out.volumes.assign(out.positions.size(), 0.0f);
    return out;
}

} // namespace airtrap
