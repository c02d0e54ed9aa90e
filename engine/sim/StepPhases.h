#pragma once
// Wall-clock seconds spent in each phase of a step, accumulated until reset. The names are the
// keys of `phase_ms` in airtrap-bench and of `timing` in `info --json`.
#include <array>
#include <chrono>
#include <string_view>

namespace airtrap {

class StepPhases {
public:
    //! Bodies: placing moving bodies' boundary particles (bubbles' too), marking the water near
    //! them, the water's reaction on dynamic bodies, their contacts and motion; the placing runs
    //! beside Neighbours and the motion beside Integrate, so those pairs overlap in time.
    //! BubbleForces: measuring the water around each bubble for its drag, steering and deletion
    //! rules, beside Forces (applying them is a few operations per bubble, inside Bodies).
    //! BubblePockets: finding air pockets and creating bubbles, every bubbles.pocket_interval
    //! of simulated time. BubbleDeletion: the deletion rules, after every step. With DFSPH, Density
    //! covers the densities by summation, the α factors and the density solve, DivergenceSolve the
    //! divergence solve and the non-pressure forces, and Forces the contact impulses.
    enum Phase {
        Neighbours,
        Density,
        Forces,
        Bodies,
        Integrate,
        BubbleForces,
        BubblePockets,
        BubbleDeletion,
        DivergenceSolve,
        Count
    };

    static constexpr std::array<std::string_view, Count> kNames = {
        "neighbours",    "density",        "forces",          "bodies",          "integrate",
        "bubble_forces", "bubble_pockets", "bubble_deletion", "divergence_solve"};

    //! Times one phase for as long as it lives.
    class Scope {
    public:
        Scope(StepPhases& phases, Phase phase)
            : phases_(phases), phase_(phase), start_(std::chrono::steady_clock::now()) {}
        ~Scope() {
            const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
            phases_.seconds_[phase_] += elapsed.count();
        }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        StepPhases& phases_;
        Phase phase_;
        std::chrono::steady_clock::time_point start_;
    };

    double seconds(Phase phase) const { return seconds_[phase]; }
    double totalSeconds() const {
        double total = 0.0;
        for (double s : seconds_)
            total += s;
        return total;
    }
    void reset() { seconds_.fill(0.0); }

private:
    std::array<double, Count> seconds_{};
};

} // namespace airtrap
