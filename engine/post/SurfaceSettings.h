#pragma once
// The free-surface mesh's controls (paper §4.1, DESIGN §4 "Free-surface mesh"). Lengths are in
// particle spacings, so a scene keeps its look when its resolution changes.
namespace airtrap {

struct SurfaceSettings {
    double voxelSize = 0.5;      //!< spacings per voxel of the level set (finer: more detail)
    double particleRadius = 1.0; //!< spacings; radius of the sphere each particle contributes
    int smoothing = 4;           //!< mean-curvature passes that flatten the spheres' bumps
    double margin = 1.0; //!< spacings; polygons this close to a body or a bubble are dropped
};

} // namespace airtrap
