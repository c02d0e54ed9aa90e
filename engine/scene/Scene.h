#pragma once
// The scene as plain data. Every field here is declared once, with its JSON key, label, unit,
// range, default and help, in SceneSchema; the JSON reader, `--set`, docs/SCENE_FORMAT.md and the
// editor's parameter panel all read that declaration. The defaults below mirror it so that a
// default-constructed Scene is valid.
#include "core/Math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

//! The water's solver (docs/SCENE_FORMAT.md `solver`): the paper's weakly compressible SPH
//! (§3.1) or divergence-free SPH (docs/METHOD.md "Water: divergence-free SPH").
struct SolverSettings {
    std::string method = "wcsph";  //!< "wcsph" or "dfsph"
    double particleSpacing = 0.02; //!< m, initial distance between water particles
    double supportFactor = 2.0;    //!< kernel support radius = supportFactor × spacing
    double restDensity = 1000.0;   //!< kg/m³, ρ₀
    double maxSpeed = 10.0;        //!< m/s, u_max; speed of sound c = 10 u_max (paper §3.1)
    double viscosityAlpha = 0.1;   //!< Monaghan artificial viscosity α
    double wallViscosity = 0.05;   //!< artificial viscosity coefficient at solid walls (friction)
    double wallRestitution = 0.0;  //!< ε of the contact impulse against solid walls (eq. 4)
    double cflFactor = 0.3;        //!< λ in Δt = λ h / (c + |v|max)
    int shepardInterval = 30;      //!< steps between Shepard density re-initialisations (0 = off)
    double maxDensityError = 0.2; //!< stop the bake when |ρ/ρ₀ − 1| exceeds this (blow-up guard)
    Vec3d gravity = Vec3d(0.0, -9.81, 0.0); //!< m/s²
    // Divergence-free SPH only.
    double densityErrorTarget = 0.0001; //!< average |ρ/ρ₀ − 1| the density solve stops at
    double divergenceErrorTarget = 0.001; //!< average Δt·(Dρ/Dt)/ρ₀ the divergence solve stops at
    int minIterations = 2;                //!< per solve
    int maxIterations = 100;              //!< per solve
    double flowCflFactor = 0.4;           //!< λ in Δt = λ Δx / |v|max
    double xsphFactor = 0.3;              //!< XSPH viscosity between water particles
    double wallXsphFactor = 0.04;         //!< XSPH toward the walls' velocity (friction)
    double minTimeStep = 0.0001;          //!< s
    double maxTimeStep = 0.005;           //!< s

    bool divergenceFree() const { return method == "dfsph"; }
};

//! Frame range and rate of the bake. Frame 1 is the initial state at t = 0; frame n is at
//! t = (n − 1) / fps.
struct FrameSettings {
    double fps = 30.0;
    int endFrame = 60;
};

//! The static open-top tank. Its inside is the water's world; the domain extends `headroom`
//! metres above its rim for splashes.
struct ContainerSettings {
    Vec3d min = Vec3d(0.0, 0.0, 0.0);
    Vec3d max = Vec3d(1.0, 1.0, 1.0);
    double headroom = 0.5; //!< m above the rim still inside the simulation domain
};

//! A box of water at rest (or moving) at t = 0, filled on the particle lattice.
struct FluidBlock {
    std::string name = "Water";
    Vec3d min = Vec3d(0.0, 0.0, 0.0);
    Vec3d max = Vec3d(0.5, 0.5, 0.5);
    Vec3d initialVelocity = Vec3d::Zero();

    //! Particle layers that fill the block along `axis` at `spacing`: its extent in whole
    //! spacings, rounded to the nearest, at least one, but no more than fit below `wall` (m along
    //! `axis`, the simulation domain's far side): a layer rounded up past a tank wall would sit
    //! in the wall's boundary layer, squeezed to a density the pressure solve cannot bring back
    //! in one step. The validator warns when they do not make up the extent exactly.
    int layers(int axis, double spacing, double wall) const {
        const int nearest = static_cast<int>(std::lround((max - min)[axis] / spacing));
        // A micrometre's slack: 0.3 m of 0.02 m layers is 15, not 14.999999999999998.
        const int room = static_cast<int>(std::floor((wall - min[axis]) / spacing + 1e-6));
        return std::max(1, std::min(nearest, room));
    }
};

//! A static box obstacle, axis-aligned in this version.
struct BoxObstacle {
    std::string name = "Obstacle";
    Vec3d center = Vec3d(0.5, 0.25, 0.5);
    Vec3d size = Vec3d(0.2, 0.5, 0.2);
};

//! An inflow nozzle ("pouring water"): from `start_time` to `stop_time` it emits layers of
//! particles on the spacing lattice, one layer each time the jet has moved on by one spacing, at
//! `speed` along `direction`, until `max_particles` would be exceeded.
struct InflowEmitterSettings {
    std::string name = "Inflow";
    std::string shape = "disc";              //!< "disc" (radius) or "rectangle" (width × height)
    Vec3d position = Vec3d(0.5, 0.8, 0.5);   //!< m, centre of the nozzle's exit plane
    Vec3d direction = Vec3d(0.0, -1.0, 0.0); //!< of the jet; normalised when used
    double radius = 0.05;                    //!< m, of a disc nozzle
    double width = 0.1;     //!< m, rectangle side along the horizontal perpendicular of direction
    double height = 0.1;    //!< m, rectangle side along the other perpendicular
    double speed = 1.0;     //!< m/s, of the emitted water
    double startTime = 0.0; //!< s
    double stopTime = 1.0;  //!< s; nothing is emitted from this time on
    int maxParticles = 100000; //!< budget; only whole layers are emitted
};

//! A rigid body the water moves or is moved by (paper §3.3.1): a box, sphere, cylinder or closed
//! triangle mesh; static, dynamic (moved by the water, gravity and contacts) or kinematic (moved
//! along its keyframes, or at constant velocity when it has none).
struct RigidBodySettings {
    std::string name = "Body";
    std::string shape = "box";             //!< "box", "sphere", "cylinder" or "mesh"
    std::string motion = "dynamic";        //!< "static", "dynamic" or "kinematic"
    Vec3d position = Vec3d(0.5, 0.5, 0.5); //!< m, centre of the shape (a mesh's own origin)
    Vec3d rotation = Vec3d::Zero();        //!< degrees about x, then y, then z (world axes)
    Vec3d size = Vec3d(0.1, 0.1, 0.1);     //!< m, edge lengths of a box
    double radius = 0.05;                  //!< m, of a sphere or cylinder
    double height = 0.1;                   //!< m, of a cylinder, along its local y axis
    std::string mesh;                      //!< mesh file, relative to the scene file
    double meshScale = 1.0;                //!< file units → m
    double density = 500.0;                //!< kg/m³
    Vec3d linearVelocity = Vec3d::Zero();  //!< m/s at t = 0 (dynamic) or throughout (kinematic)
    Vec3d angularVelocity = Vec3d::Zero(); //!< rad/s, world axes, likewise
    double restitution = 0.0;              //!< ε of contacts with water and other bodies
    double friction = 0.4;                 //!< Coulomb μ of contacts with water and bodies
};

//! A pose a kinematic body passes through; a body's keyframes are joined by straight lines and
//! the shortest rotation (KeyframedPath).
struct BodyKeyframe {
    std::string body = "Body"; //!< name of a kinematic body
    double time = 0.0;         //!< s
    Vec3d position = Vec3d(0.5, 0.5, 0.5);
    Vec3d rotation = Vec3d::Zero(); //!< degrees, as RigidBodySettings::rotation
};

//! Trapped air bubbles (paper §3.2–3.4): light sphere bodies created in air pockets the water
//! encloses, steered toward their Stokes rise speed, and deleted by the rules of §3.4.
struct BubbleSettings {
    bool enabled = false;
    double densityRatio = 0.1;          //!< bubble density / water density (paper: 0.1)
    double minRadius = 1.0;             //!< particle spacings; smaller pockets make no bubble
    int maxNewPerFrame = 5;             //!< bubbles created per frame at most
    double minWaterShare = 0.5;         //!< share of a new bubble's 26 probes that must be wet
    double pocketInterval = 0.0005;     //!< s of simulated time between air-pocket searches
    double kinematicViscosity = 1.0e-6; //!< m²/s, ν of water in the Stokes speed (eq. 5)
    double maxRiseSpeed = 0.25;         //!< m/s, cap of the Stokes speed
    double riseTime = 0.02;             //!< s, time constant of the steering toward it
    double drag = 10.0;                 //!< 1/s, rate of the drag toward the water's velocity
    double approachRestitution = -0.6;  //!< ε₁ between approaching bubbles
    double overlapRestitution = -0.2;   //!< ε₂ between overlapping bubbles
    double maxAge = 10.0;               //!< s; older bubbles are deleted
    double maxFloatingTime = 0.5;       //!< s at the free surface before deletion
    double maxOverlap = 0.5;            //!< overlap depth / smaller diameter that deletes
    double impactSpeed = 2.0;           //!< m/s of water hitting a floating bubble that pops it
};

//! The water mesh (paper §4.1, docs/SCENE_FORMAT.md `surface_mesh`). Lengths in particle spacings,
//! so a scene keeps its look when its resolution changes.
struct SurfaceMeshSettings {
    //! "free_surface" (the paper's: no polygons along bodies and bubbles) or "closed" (the whole
    //! watertight level-set mesh, for refraction renders).
    std::string mode = "free_surface";
    double voxelSize = 0.5;      //!< spacings per voxel of the level set (finer: more detail)
    double particleRadius = 1.0; //!< spacings; radius of the sphere each particle contributes
    int smoothing = 4;           //!< mean-curvature passes that flatten the spheres' bumps
    double margin = 1.0;         //!< spacings; polygons lying this close along a solid are dropped
};

//! The oscillating bubble mesh (paper §4.1, eq. 10).
struct BubbleMeshSettings {
    int subdivisions = 2;   //!< of the icosphere: 20·4^n triangles (2: 320)
    double magnitude = 0.1; //!< k: the largest change of the cross radius, as a share of r (≪ 1)
    double duration = 0.5;  //!< T, s: how long a bubble wobbles after its birth
    double cycles = 3.0;    //!< n: oscillations within T
};

//! The sub-grid bubbles (paper §4.2): how many a new trapped air bubble sheds, how big, how many
//! generations, and how long they live. Their rise is the trapped bubbles' own (Stokes speed from
//! `bubbles.kinematic_viscosity`, capped by `bubbles.max_rise_speed`).
struct SubgridBubbleSettings {
    int maxPerBubble = 24;     //!< shed by a new bubble entirely in air (area fraction 0); 0: none
    double minSize = 0.15;     //!< smallest radius, as a share of the parent's
    double maxSize = 0.35;     //!< largest radius, as a share of the parent's
    int generations = 1;       //!< 1: from trapped bubbles only; each more sheds from the last
    int childrenPerBubble = 3; //!< shed by a sub-grid bubble of a generation before the last
    double lifetime = 3.0;     //!< s; older ones are deleted
    int substeps = 4;          //!< RK2 steps per frame
};

struct Scene {
    static constexpr int kFormatVersion = 1;

    std::string name = "Untitled";
    std::uint64_t seed = 1;
    SolverSettings solver;
    FrameSettings frames;
    ContainerSettings container;
    std::vector<FluidBlock> fluidBlocks;
    std::vector<BoxObstacle> obstacles;
    std::vector<InflowEmitterSettings> emitters;
    std::vector<RigidBodySettings> bodies;
    std::vector<BodyKeyframe> keyframes;
    BubbleSettings bubbles;
    SurfaceMeshSettings surfaceMesh;
    BubbleMeshSettings bubbleMesh;
    SubgridBubbleSettings subgridBubbles;

    //! Where the scene was read from (not saved); used in messages.
    std::string sourcePath;

    //! Simulation domain: the container plus its headroom.
    Aabb domain() const {
        Aabb box{container.min, container.max};
        box.max.y() += container.headroom;
        return box;
    }
    double supportRadius() const { return solver.supportFactor * solver.particleSpacing; }
    double frameTime(int frame) const { return (frame - 1) / frames.fps; }
};

} // namespace airtrap
