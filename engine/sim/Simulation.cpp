#include "sim/Simulation.h"

#include "core/Error.h"
#include "core/Parallel.h"
#include "core/PeriodicEvent.h"
#include "core/RunBeside.h"
#include "scene/SceneSchema.h"
#include "sim/SceneSetup.h"
#include "sph/DfsphSolver.h"
#include "sph/WcsphSolver.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <tbb/blocked_range.h>

namespace airtrap {

namespace {

//! Steps shorter than this mean the time-step controller has given up: accelerations exploded.
constexpr double kMinTimeStep = 1e-9;
//! A frame that loses more than this share of its particles through the domain's walls is a
//! blow-up, not a splash.
constexpr double kMaxLostShare = 0.05;
//! Density solves in a row that may stop at max_iterations before the bake stops: a few are a
//! burst (an impact), this many mean the step cannot hold the water incompressible.
constexpr int kMaxUnconvergedInARow = 50;

std::unique_ptr<PressureSolver> makePressureSolver(const Scene& scene) {
    if (scene.solver.divergenceFree())
        return std::make_unique<DfsphSolver>(scene.solver, scene.domain());
    return std::make_unique<WcsphSolver>(scene.solver, scene.domain());
}

std::string formatVector(const Vec3f& x) {
    std::ostringstream out;
    out.precision(3);
    out << "(" << x.x() << ", " << x.y() << ", " << x.z() << ") m";
    return out.str();
}

FrameStats measure(const ParticleSet& fluid) {
    FrameStats stats;
    using Range = tbb::blocked_range<std::size_t>;
    struct Sums {
        double maxSpeed = 0.0;
        double density = 0.0;
    };
    // Deterministic reduce: the same split and the same order of additions on every run.
    const Sums sums = parallelDeterministicReduce(
        Range(0, fluid.size(), 4096), Sums{},
        [&](const Range& r, Sums acc) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
                acc.maxSpeed = std::max(acc.maxSpeed, double(fluid.velocities[i].norm()));
                acc.density += fluid.densities[i];
            }
            return acc;
        },
        [](Sums a, const Sums& b) {
            a.maxSpeed = std::max(a.maxSpeed, b.maxSpeed);
            a.density += b.density;
            return a;
        });
    stats.maxSpeed = sums.maxSpeed;
    stats.meanDensity = fluid.empty() ? 0.0 : sums.density / double(fluid.size());
    return stats;
}

//! Runs `work` now, timed as `phase` of `phases`.
template <class Work>
void inPhase(StepPhases& phases, StepPhases::Phase phase, Work&& work) {
    StepPhases::Scope scope(phases, phase);
    work();
}

//! `work`, timed as `phase` of `phases` whenever it is called: a part for runBeside().
template <class Work>
auto timed(StepPhases& phases, StepPhases::Phase phase, Work work) {
    return [&phases, phase, work] { inPhase(phases, phase, work); };
}

//! "0.0123 m/s": three significant digits, as a user reads a speed.
std::string speedText(double metresPerSecond) {
    std::ostringstream out;
    out.precision(3);
    out << metresPerSecond << " m/s";
    return out.str();
}

std::string percent(double fraction) {
    std::ostringstream out;
    out.precision(3);
    out << 100.0 * fraction << " %";
    return out.str();
}

} // namespace

Simulation::Simulation(Scene scene, SimulationState resumeFrom)
    : scene_(std::move(scene)), state_(std::move(resumeFrom)), water_(makePressureSolver(scene_)),
      bodies_(SceneSetup::buildBodies(scene_), SceneSetup::sceneryCount(scene_), scene_.solver,
              scene_.bubbles, water_->kernel()) {
    water_->placeBoundary(bodies_.bodies(), bodies_.firstBubbleBody());
    water_->restoreWarmStart(state_.warmStart);
    for (const InflowEmitterSettings& settings : scene_.emitters)
        emitters_.emplace_back(settings, scene_.solver.particleSpacing, scene_.solver.restDensity);
    if (scene_.bubbles.enabled) {
        bubbleDeletion_.emplace(scene_.bubbles);
        bubbleSpawner_.emplace(scene_.bubbles, scene_.solver.particleSpacing, scene_.seed);
    }
    lastFrameStats_ = measure(state_.fluid);
}

Simulation::Simulation(Scene scene) : Simulation(std::move(scene), SimulationState{}) {
    state_.bodies = SceneSetup::initialBodyStates(scene_, bodies_.bodies());
    SceneSetup::fillFluid(scene_, bodies_.bodies(), state_);
    lastFrameStats_ = measure(state_.fluid);
}

Simulation::~Simulation() = default;

Simulation::Advance Simulation::advanceFrame(Interrupter& interrupter, const StepObserver& onStep) {
    const int nextFrame = state_.frame + 1;
    const double target = scene_.frameTime(nextFrame);
    const double start = state_.time;
    const std::size_t particlesAtStart = state_.fluid.size();
    std::size_t lost = 0;
    std::uint64_t steps = 0;
    phases_.reset();
    frameBubbles_ = {};
    PressureSolveStats solve;
    double fastestInFrame = 0.0;
    const auto wallStart = std::chrono::steady_clock::now();

    while (state_.time < target) {
        const double remaining = target - state_.time;
        const StepReport report = takeStep(remaining, target);
        // Growth is not loss: `lost` counts only the particles the solver removed at the
        // domain's walls.
        lost += report.removedParticles;
        ++steps;
        fastestInFrame = std::max(fastestInFrame, report.maxSpeed);
        checkHealth(report, remaining, nextFrame, lost, particlesAtStart);
        if (scene_.solver.divergenceFree())
            tallySolve(report, nextFrame, solve);
        const double fraction = (state_.time - start) / (target - start);
        if (onStep)
            onStep(fraction);
        if (state_.time < target && interrupter.wasInterrupted(100.0 * fraction))
            return Advance::Interrupted;
    }

    state_.frame = nextFrame;
    state_.warmStart = water_->warmStart();
    noteFrame(nextFrame, lost, fastestInFrame, solve);
    lastFrameStats_ = measure(state_.fluid);
    lastFrameStats_.pressureSolve = solve;
    lastFrameStats_.bubbles = frameBubbles_;
    lastFrameStats_.stepsInFrame = steps;
    lastFrameStats_.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    for (int phase = 0; phase < StepPhases::Count; ++phase)
        lastFrameStats_.phaseSeconds[std::string(StepPhases::kNames[phase])] =
            phases_.seconds(static_cast<StepPhases::Phase>(phase));
    return Advance::FrameDone;
}

StepReport Simulation::step(double maxTimeStep) {
    // No frames are completed here, but the bubbles' per-frame creation limit still renews each
    // time a frame's worth of time has passed.
    const int frameUnderWay = static_cast<int>(std::floor(state_.time * scene_.frames.fps));
    if (frameUnderWay != steppedFrame_) {
        steppedFrame_ = frameUnderWay;
        frameBubbles_ = {};
    }
    return takeStep(maxTimeStep, std::numeric_limits<double>::infinity());
}

StepReport Simulation::takeStep(double timeToFrameEnd, double frameEnd) {
    PressureSolver& water = *water_;
    ParticleSet& fluid = state_.fluid;
    StepReport report;

    // 1. Neighbouring information: the search grid built for the current positions, the water
    //    sorted onto it; beside it, the bodies and the bubbles placed with their boundary
    //    particles. Then the water near moving bodies, and Δt (CFL, docs/METHOD.md).
    const auto sortWater =
        timed(phases_, StepPhases::Neighbours, [&] { water.sortByCell(fluid, report); });
    if (bodies_.needPlacing(state_))
        runBeside(sortWater, timed(phases_, StepPhases::Bodies, [&] {
                      bodies_.place(state_);
                      water.placeBoundary(bodies_.bodies(), bodies_.firstBubbleBody());
                  }));
    else
        sortWater();
    inPhase(phases_, StepPhases::Bodies, [&] { water.pairMovingBoundary(); });
    // DFSPH only (empty for WCSPH): densities by summation and the solves' factors, then the
    // velocity field made divergence-free and the non-pressure forces, which set Δt.
    inPhase(phases_, StepPhases::Density, [&] { water.prepareDensities(fluid, report); });
    inPhase(phases_, StepPhases::DivergenceSolve,
            [&] { water.solveDivergence(state_.lastTimeStep, report); });
    water.chooseTimeStep(state_.lastMaxAcceleration, timeToFrameEnd, report);

    // 2. Particle interactions. WCSPH: densities by continuity (eq. 2) and pressures (eq. 3),
    //    then the momentum equation (eq. 1) with the boundary force's contact impulses (eq. 4).
    //    DFSPH: the density solve, then the contact impulses. Beside the forces, which only read
    //    the water too, the water around the bubbles measured for their forces and deletion
    //    rules.
    inPhase(phases_, StepPhases::Density,
            [&] { water.computeDensities(fluid, state_.steps, report.timeStep, report); });
    const auto forces = timed(phases_, StepPhases::Forces,
                              [&] { water.computeForces(fluid, report.timeStep, report); });
    if (bodies_.bubbleSurroundingsDue(state_, report.timeStep))
        runBeside(forces, timed(phases_, StepPhases::BubbleForces, [&] {
                      bodies_.measureBubbleSurroundings(state_, report.timeStep, water.grid(),
                                                        water.sortedPositions());
                  }));
    else
        forces();

    // 3. Rigid-body and bubble interactions, and the move: the water's reaction on the dynamic
    //    bodies (eq. 4), which move under it with the bubbles' steered rise (eq. 5), drag
    //    (eq. 6) and pair impulses, beside the water's own integration.
    report.nonFinite = !moveBodiesAndWater(report.timeStep);
    state_.lastMaxAcceleration = report.maxAcceleration;
    state_.lastTimeStep = report.timeStep;
    ++state_.steps;
    const double stepStart = state_.time;
    // The last step of a frame lands on the frame time exactly, not on an accumulated sum.
    state_.time = report.timeStep == frameEnd - stepStart ? frameEnd : stepStart + report.timeStep;
    bodies_.followPaths(state_);
    // After the move, so that the cached frame holds the particles due by its time and a
    // resumed bake starts from the same set.
    emitInflow(stepStart, state_.time);

    // 4. Bubble deletion (age, time floating, overlap, impact, surfaced: docs/METHOD.md).
    if (bubbleDeletion_ && !state_.bubbles.empty())
        inPhase(phases_, StepPhases::BubbleDeletion, [&] { deleteBubbles(report.timeStep); });

    // 5. Air pockets on this step's grid become bubbles, every bubbles.pocket_interval of
    //    simulated time (every step when the steps are longer).
    //    Table 1 reads them off the grid before the interactions; here they are read off the
    //    same grid after the move, so a new bubble first meets the water at the next step's
    //    placing, with its boundary particles, like every other body.
    if (bubbleSpawner_ && periodDue(stepStart, state_.time, scene_.bubbles.pocketInterval))
        createBubbles(state_.frame + 1);
    return report;
}

bool Simulation::moveBodiesAndWater(double dt) {
    PressureSolver& water = *water_;
    if (!water.boundary().hasDynamicBodies()) {
        bool finite = true;
        inPhase(phases_, StepPhases::Integrate,
                [&] { finite = !water.integrate(state_.fluid, dt); });
        return finite;
    }
    inPhase(phases_, StepPhases::Bodies, [&] { water.computeBodyReactions(state_.fluid, dt); });
    bool bodiesFinite = true;
    bool waterFinite = true;
    // The bodies move on their reactions alone and the water on its accelerations alone.
    runBeside(timed(phases_, StepPhases::Bodies,
                    [&] {
                        bodiesFinite =
                            bodies_.move(state_, water.boundary(), water.bodyReactions(), dt);
                    }),
              timed(phases_, StepPhases::Integrate,
                    [&] { waterFinite = !water.integrate(state_.fluid, dt); }));
    return bodiesFinite && waterFinite;
}

void Simulation::deleteBubbles(double dt) {
    BubbleTally deleted;
    bubbleDeletion_->afterStep(state_.bubbles, dt, deleted);
    frameBubbles_ += deleted;
    state_.bubblesDeleted += deleted;
}

void Simulation::createBubbles(int frame) {
    const std::uint64_t limit = static_cast<std::uint64_t>(scene_.bubbles.maxNewPerFrame);
    if (frameBubbles_.created >= limit)
        return;
    StepPhases::Scope scope(phases_, StepPhases::BubblePockets);
    const BubbleSpawner::Water water{water_->grid(), water_->sortedPositions(), state_.fluid};
    const BubbleSpawner::Bubbles bubbles{state_.bubbles, state_.nextBubbleId};
    frameBubbles_.created += bubbleSpawner_->spawn(bubbles, state_.steps, water, bodies_.solids(),
                                                   frame, limit - frameBubbles_.created);
}

void Simulation::tallySolve(const StepReport& report, int frame, PressureSolveStats& solve) {
    ++solve.steps;
    solve.divergenceIterations += std::uint64_t(report.divergenceIterations);
    solve.densityIterations += std::uint64_t(report.densityIterations);
    solve.meanDensityError += (report.densityError - solve.meanDensityError) / double(solve.steps);
    solve.maxDensityError = std::max(solve.maxDensityError, report.densityError);
    if (report.stepAtMinimum && !warnedMinimumStep_) {
        warnedMinimumStep_ = true;
        notices_.push_back("frame " + std::to_string(frame) + ": the water reached " +
                           std::to_string(report.maxSpeed) + " m/s at " +
                           formatVector(report.fastestAt) + ", which asks for a step below " +
                           SceneSchema::keyOf(&SolverSettings::minTimeStep) + " = " +
                           std::to_string(scene_.solver.minTimeStep) +
                           " s; the step is held there, so the fastest water moves more than " +
                           SceneSchema::keyOf(&SolverSettings::flowCflFactor) +
                           " spacings per step (said once per bake)");
    }
    if (report.densityConverged) {
        unconvergedInARow_ = 0;
        return;
    }
    ++solve.unconvergedSteps;
    if (++unconvergedInARow_ < kMaxUnconvergedInARow)
        return;
    throw Error(ErrorKind::SimulationBlowUp,
                "frame " + std::to_string(frame) + " (t = " + std::to_string(state_.time) +
                    " s, step " + std::to_string(state_.steps) + "): the density solve has " +
                    "stopped at " + SceneSchema::keyOf(&SolverSettings::maxIterations) + " = " +
                    std::to_string(scene_.solver.maxIterations) + " for " +
                    std::to_string(kMaxUnconvergedInARow) +
                    " steps in a row, reaching an average density error of " +
                    percent(report.densityError) + " where " +
                    SceneSchema::keyOf(&SolverSettings::densityErrorTarget) + " asks for " +
                    percent(scene_.solver.densityErrorTarget) +
                    ". Likely cause: steps too long for the flow (lower " +
                    SceneSchema::keyOf(&SolverSettings::flowCflFactor) + " or " +
                    SceneSchema::keyOf(&SolverSettings::maxTimeStep) + ") or too few iterations.");
}

void Simulation::noteFrame(int frame, std::size_t lost, double fastest,
                           const PressureSolveStats& solve) {
    const std::string where = "frame " + std::to_string(frame) + ": ";
    if (lost > 0)
        notices_.push_back(where + std::to_string(lost) +
                           (lost == 1 ? " particle left the domain and was removed"
                                      : " particles left the domain and were removed"));
    if (solve.steps > 0) {
        std::ostringstream figures;
        figures.precision(3);
        figures << where << solve.steps << " steps, iterations per step "
                << solve.meanIterations(solve.divergenceIterations) << " (divergence) and "
                << solve.meanIterations(solve.densityIterations) << " (density), density error "
                << percent(solve.meanDensityError) << " on average, "
                << percent(solve.maxDensityError) << " at most";
        notices_.push_back(figures.str());
    }
    if (solve.unconvergedSteps > 0)
        notices_.push_back(where + "the density solve stopped at " +
                           SceneSchema::keyOf(&SolverSettings::maxIterations) + " in " +
                           std::to_string(solve.unconvergedSteps) + " of " +
                           std::to_string(solve.steps) + " steps (largest density error " +
                           percent(solve.maxDensityError) + ")");
    if (!scene_.solver.divergenceFree() && fastest > scene_.solver.maxSpeed && !warnedMaxSpeed_) {
        warnedMaxSpeed_ = true;
        notices_.push_back(where + "the water reached " + std::to_string(fastest) + " m/s, above " +
                           SceneSchema::keyOf(&SolverSettings::maxSpeed) + " = " +
                           std::to_string(scene_.solver.maxSpeed) +
                           " m/s on which the speed of sound is based, so the water compresses "
                           "more than the method's 1 %; raise it (said once per bake)");
    }
}

std::vector<std::string> Simulation::takeNotices() {
    std::vector<std::string> taken;
    taken.swap(notices_);
    return taken;
}

void Simulation::emitInflow(double from, double to) {
    for (const InflowEmitter& emitter : emitters_)
        emitter.emit(from, to, state_);
}

std::string Simulation::densityErrorCause(const StepReport& report) const {
    const std::string speed = "the water moves at " + speedText(report.maxSpeed);
    if (scene_.solver.divergenceFree())
        return speed + " at " + formatVector(report.fastestAt) + "; steps too long for it (lower " +
               SceneSchema::keyOf(&SolverSettings::flowCflFactor) + " or " +
               SceneSchema::keyOf(&SolverSettings::maxTimeStep) +
               "), or a body much lighter or heavier than water, which DFSPH does not yet hold "
               "at its large step.";
    const std::string maxSpeed = SceneSchema::keyOf(&SolverSettings::maxSpeed);
    const std::string declared = maxSpeed + " = " + speedText(scene_.solver.maxSpeed);
    if (report.maxSpeed > scene_.solver.maxSpeed)
        return speed + ", faster than " + declared + " (raise it), or " +
               SceneSchema::keyOf(&SolverSettings::cflFactor) + " is too large.";
    // Slower than declared: the water is not too fast, its speed of sound is too low. Carrying
    // its weight at depth H takes a compression of about g H / c² (Tait's equation); with
    // c = 10 × max_speed that is 0.5 % when max_speed is √(2 g H).
    return speed + ", within " + declared + ", but the speed of sound it sets (10 × " + maxSpeed +
           " = " + speedText(10.0 * scene_.solver.maxSpeed) +
           ") is too low to hold the water up under its own weight: raise " + maxSpeed +
           " to at least the speed water reaches falling the pool's depth, √(2 g H).";
}

void Simulation::checkHealth(const StepReport& report, double timeToFrameEnd, int frame,
                             std::size_t lost, std::size_t particlesAtStart) const {
    // Called after every step: the messages and the keys they name are made only on a failure.
    const auto where = [&] {
        return "frame " + std::to_string(frame) + " (t = " + std::to_string(state_.time) + " s): ";
    };
    const auto cflFactor = [] { return SceneSchema::keyOf(&SolverSettings::cflFactor); };
    const auto maxSpeed = [] { return SceneSchema::keyOf(&SolverSettings::maxSpeed); };
    if (report.nonFinite)
        throw Error(ErrorKind::SimulationBlowUp,
                    where() +
                        "the simulation produced NaN or infinite values. Likely cause: a time "
                        "step too large for the forces (lower " +
                        cflFactor() + ") or bodies overlapping the water at t = 0.");
    if (report.maxDensityDeviation > scene_.solver.maxDensityError)
        throw Error(ErrorKind::SimulationBlowUp,
                    where() + "density error " + percent(report.maxDensityDeviation) + " exceeds " +
                        SceneSchema::keyOf(&SolverSettings::maxDensityError) + " (" +
                        percent(scene_.solver.maxDensityError) +
                        "). Likely cause: " + densityErrorCause(report));
    if (lost > std::max<std::size_t>(10, std::size_t(kMaxLostShare * particlesAtStart)))
        throw Error(ErrorKind::SimulationBlowUp,
                    where() + std::to_string(lost) +
                        " particles left the domain in one frame. Likely cause: the water "
                        "exploded (lower " +
                        cflFactor() + ", raise " + maxSpeed() + ") or " +
                        SceneSchema::keyOf(&ContainerSettings::headroom) +
                        " is too small for the splash.");
    // A step shortened to land on the frame time may be short; one the forces made short is not.
    if (report.timeStep < kMinTimeStep && report.timeStep < 0.5 * timeToFrameEnd)
        throw Error(ErrorKind::SimulationBlowUp,
                    where() + "the time step collapsed below 1 ns: accelerations are exploding. "
                              "Likely cause: overlapping bodies or particles at t = 0.");
}

} // namespace airtrap
