#pragma once
// Contacts between rigid bodies (docs/METHOD.md "Contacts between bodies": the impulse of the
// water's contacts, with both bodies' terms): body–container, body–obstacle and body–body. Once per
// sub-step, after the bodies' velocities have taken the step's forces and before their poses move.
//
// Contact points: the surface under each boundary particle of a dynamic body, tested against
// the other body's signed distance (and the other way round when both are dynamic); a sphere
// adds its exact deepest point. Each point whose distance is below a small margin is a contact
// with the other body's outward normal.
//
// Solver: sequential impulses (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005;
// Mirtich 1996 for the impulse itself): every contact's normal impulse
// j = −(1 + ε) uₙ / (K_A + K_B) is accumulated over a few sweeps and clamped to stay pushing,
// with Coulomb friction bounded by μ j. Penetration is removed by separate "split" impulses that
// change only the positions of this step (Catto 2006), so resolving overlap adds no bounce: a
// stack of boxes comes to rest.
#include "rigid/RigidBody.h"

#include <vector>

namespace airtrap {

class RigidContactSolver {
public:
    struct Settings {
        int iterations = 12;
        //! m: points nearer than this count as touching, so a resting contact stays known.
        double margin = 0.0;
        //! m of overlap left alone, so resting bodies do not jitter.
        double allowedPenetration = 0.0;
        //! Share of the remaining overlap removed per step.
        double correction = 0.2;
    };

    explicit RigidContactSolver(const Settings& settings) : settings_(settings) {}

    //! Bodies from `index` on are bubbles: they touch the other bodies as usual, but not each
    //! other, since bubble pairs take their own impulse with non-positive restitution.
    void setBubblesFrom(std::size_t index) { bubblesFrom_ = index; }

    //! Resolves the contacts of `bodies` (world states) over a step of `dt` seconds: changes
    //! the velocities of dynamic bodies, and returns each body's extra "position velocity" to
    //! add to its velocity when its pose moves this step (zero for bodies without overlap).
    std::vector<RigidVelocity> solve(std::vector<RigidBody>& bodies, double dt);

private:
    struct Contact {
        std::size_t a = 0; //!< the body the normal points towards
        std::size_t b = 0; //!< the body the normal points out of
        Vec3d point = Vec3d::Zero();
        Vec3d normal = Vec3d::Zero();
        double depth = 0.0;            //!< m, > 0 when overlapping
        double restitutionSpeed = 0.0; //!< m/s, the target separation speed from ε
        double friction = 0.0;
        double normalMass = 0.0;              //!< 1 / (K_A + K_B) along the normal
        double normalImpulse = 0.0;           //!< accumulated
        double pushImpulse = 0.0;             //!< accumulated split impulse
        Vec3d tangentImpulse = Vec3d::Zero(); //!< accumulated
    };

    void findContacts(const std::vector<RigidBody>& bodies);
    //! Points of `a`'s surface inside or near `b`.
    void collide(const std::vector<RigidBody>& bodies, std::size_t a, std::size_t b);
    void addContact(const std::vector<RigidBody>& bodies, std::size_t a, std::size_t b,
                    const Vec3d& point);
    void prepare(const std::vector<RigidBody>& bodies, double dt);
    void solveVelocities(std::vector<RigidBody>& bodies);
    void solveFriction(Contact& contact, std::vector<RigidBody>& bodies);
    //! Velocity of body a's material point at the contact relative to body b's.
    static Vec3d relativeVelocity(const std::vector<RigidBody>& bodies, const Contact& contact);
    static void applyImpulse(std::vector<RigidBody>& bodies, const Contact& contact,
                             const Vec3d& impulse);
    std::vector<RigidVelocity> solvePositions(const std::vector<RigidBody>& bodies, double dt);

    Settings settings_;
    std::size_t bubblesFrom_ = static_cast<std::size_t>(-1);
    std::vector<Contact> contacts_;
};

} // namespace airtrap
