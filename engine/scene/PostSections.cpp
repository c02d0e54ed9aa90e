#include "scene/PostSections.h"

#include "scene/SchemaBinding.h"

namespace airtrap {
namespace {

using namespace schema;

using SurfaceAccess = ObjectAccess<&Scene::surfaceMesh>;
using BubbleMeshAccess = ObjectAccess<&Scene::bubbleMesh>;
using SubgridAccess = ObjectAccess<&Scene::subgridBubbles>;

SchemaSection renderSetting(SchemaSection section) {
    section.renderSetting = true;
    return section;
}

} // namespace

SchemaSection surfaceMeshSection() {
    return renderSetting(objectSection(
        "surface_mesh", "Surface mesh",
        "The water mesh for rendering: a level set of the particles, smoothed without losing "
        "volume, with the polygons along bodies and bubbles left out so the free surface is all "
        "that remains (paper §4.1), or closed for refraction renders.",
        {
            bind<SurfaceAccess>({.key = "mode",
                                 .label = "Mesh",
                                 .help = "free_surface: the paper's mesh, without the polygons "
                                         "along bodies and bubbles, whose own surfaces render "
                                         "there. closed: the whole watertight surface of the "
                                         "water (no open edges, normals outward), for renderers "
                                         "that refract through it.",
                                 .choices = {"free_surface", "closed"}},
                                &SurfaceMeshSettings::mode),
            bind<SurfaceAccess>({.key = "voxel_size",
                                 .label = "Voxel size",
                                 .unit = "× spacing",
                                 .minimum = 0.1,
                                 .maximum = 2.0,
                                 .help = "Edge of the level set's voxels. Halving it shows finer "
                                         "ripples for four times the polygons."},
                                &SurfaceMeshSettings::voxelSize),
            bind<SurfaceAccess>({.key = "particle_radius",
                                 .label = "Particle radius",
                                 .unit = "× spacing",
                                 .minimum = 0.5,
                                 .maximum = 4.0,
                                 .help = "Radius of the sphere each particle adds to the level "
                                         "set; at least 1.5 voxels. Larger joins more spray into "
                                         "sheets."},
                                &SurfaceMeshSettings::particleRadius),
            bind<SurfaceAccess>({.key = "smoothing",
                                 .label = "Smoothing passes",
                                 .minimum = 0,
                                 .maximum = 50,
                                 .help = "Mean-curvature passes that flatten the particles' "
                                         "bumps. The volume is restored afterwards, so more "
                                         "passes round the water off without shrinking it."},
                                &SurfaceMeshSettings::smoothing),
            bind<SurfaceAccess>({.key = "margin",
                                 .label = "Boundary margin",
                                 .unit = "× spacing",
                                 .minimum = 0.0,
                                 .maximum = 2.0,
                                 .help = "Polygons with every corner closer than this to a body, "
                                         "the tank or a bubble are left out (paper Fig. 2b): "
                                         "there the other object's own surface is rendered. "
                                         "The corners of the rest that are this close are moved "
                                         "onto it, so the water meets it with no gap."},
                                &SurfaceMeshSettings::margin),
        }));
}

SchemaSection bubbleMeshSection() {
    return renderSetting(objectSection(
        "bubble_mesh", "Bubble mesh",
        "How bubbles are rendered: ellipsoids of the bubble's volume, stretched along their "
        "velocity, that wobble and settle after their birth (paper §4.1, eqs. 7–10).",
        {
            bind<BubbleMeshAccess>({.key = "subdivisions",
                                    .label = "Subdivisions",
                                    .minimum = 0,
                                    .maximum = 6,
                                    .help = "Of the icosphere each bubble is made from: 20·4ⁿ "
                                            "triangles (2: 320)."},
                                   &BubbleMeshSettings::subdivisions),
            bind<BubbleMeshAccess>({.key = "magnitude",
                                    .label = "Wobble magnitude k",
                                    .minimum = 0.0,
                                    .maximum = 0.5,
                                    .help = "Largest change of the cross radius, as a share of "
                                            "the radius (eq. 10; k ≪ 1). 0 keeps bubbles "
                                            "spherical."},
                                   &BubbleMeshSettings::magnitude),
            bind<BubbleMeshAccess>({.key = "duration",
                                    .label = "Wobble duration T",
                                    .unit = "s",
                                    .minimum = 0.01,
                                    .maximum = 10.0,
                                    .help = "How long a bubble wobbles after its birth; the "
                                            "wobble dies away as (t/T − 1)² (eq. 10)."},
                                   &BubbleMeshSettings::duration),
            bind<BubbleMeshAccess>({.key = "cycles",
                                    .label = "Wobble cycles n",
                                    .minimum = 0.5,
                                    .maximum = 20.0,
                                    .help = "Oscillations within the duration (eq. 10)."},
                                   &BubbleMeshSettings::cycles),
        }));
}

SchemaSection subgridBubblesSection() {
    return renderSetting(objectSection(
        "subgrid_bubbles", "Sub-grid bubbles",
        "Air too fine for the grid, added after the bake (paper §4.2): each new trapped bubble "
        "sheds small bubbles around itself, more the less of it lies in water. They ride the "
        "water's velocity, rise at their Stokes speed and pop at the surface.",
        {
            bind<SubgridAccess>({.key = "max_per_bubble",
                                 .label = "Bubbles per bubble",
                                 .minimum = 0,
                                 .maximum = 126,
                                 .help = "Shed by a new bubble entirely in air; one in water "
                                         "sheds in proportion to its surface in air. 0 sheds "
                                         "none."},
                                &SubgridBubbleSettings::maxPerBubble),
            bind<SubgridAccess>({.key = "min_size",
                                 .label = "Smallest radius",
                                 .unit = "× parent radius",
                                 .minimum = 0.01,
                                 .maximum = 0.5,
                                 .help = "Radii are drawn between the smallest and the largest."},
                                &SubgridBubbleSettings::minSize),
            bind<SubgridAccess>({.key = "max_size",
                                 .label = "Largest radius",
                                 .unit = "× parent radius",
                                 .minimum = 0.01,
                                 .maximum = 0.5,
                                 .help = "At least the smallest radius."},
                                &SubgridBubbleSettings::maxSize),
            bind<SubgridAccess>({.key = "generations",
                                 .label = "Generations",
                                 .minimum = 1,
                                 .maximum = 4,
                                 .help = "1: only trapped bubbles shed. Each more lets the last "
                                         "generation shed smaller bubbles around itself."},
                                &SubgridBubbleSettings::generations),
            bind<SubgridAccess>({.key = "children_per_bubble",
                                 .label = "Children per bubble",
                                 .minimum = 0,
                                 .maximum = 126,
                                 .help = "Shed by each sub-grid bubble of a generation before "
                                         "the last."},
                                &SubgridBubbleSettings::childrenPerBubble),
            bind<SubgridAccess>({.key = "lifetime",
                                 .label = "Lifetime",
                                 .unit = "s",
                                 .minimum = 0.01,
                                 .maximum = 60.0,
                                 .help = "Older sub-grid bubbles are deleted even under water."},
                                &SubgridBubbleSettings::lifetime),
            bind<SubgridAccess>({.key = "substeps",
                                 .label = "Steps per frame",
                                 .minimum = 1,
                                 .maximum = 32,
                                 .help = "Midpoint (RK2) steps between two frames. More follow "
                                         "fast, curling water more closely."},
                                &SubgridBubbleSettings::substeps),
        }));
}

} // namespace airtrap
