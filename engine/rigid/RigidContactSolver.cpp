#include "rigid/RigidContactSolver.h"

#include "rigid/RigidImpulse.h"

#include <algorithm>
#include <cmath>

namespace airtrap {
namespace {

//! Below this approach speed (m/s) a contact does not bounce: resting contacts would otherwise
//! hop on the speed gravity adds each step.
constexpr double kBounceThreshold = 0.05;

Vec3d pointVelocity(const RigidBodyState& state, const Vec3d& point) {
    return state.linearVelocity + state.angularVelocity.cross(point - state.position);
}

double inverseMassAlong(const RigidBody& body, const RigidBodyState& state, const Vec3d& point,
                        const Vec3d& direction) {
    if (!body.isDynamic())
        return 0.0;
    return RigidImpulse::inverseEffectiveMass(body.inertia(), state.orientation, direction,
                                              point - state.position);
}

//! Whether `a`, a body with a bounding sphere, may come within `margin` of `b`, a tank without
//! one: its contact points lie within the sphere grown by the surface offset.
bool mayTouchUnbounded(const RigidBody& a, const RigidBody& b, double margin) {
    const double reach = a.shape().boundingRadius() + a.surfaceOffset() + margin;
    return b.clearanceBound(a.shapePose().position) < reach;
}

//! Whether the bounding spheres of two bodies, grown by `margin`, overlap; against a tank, whether
//! the bounded body's sphere reaches its walls. Every bubble meets the tank here each step: the
//! one test saves the distance of each of its boundary particles.
bool mayTouch(const RigidBody& a, const RigidBody& b, double margin) {
    const bool boundedA = std::isfinite(a.shape().boundingRadius());
    const bool boundedB = std::isfinite(b.shape().boundingRadius());
    if (boundedA && !boundedB)
        return mayTouchUnbounded(a, b, margin);
    if (boundedB && !boundedA)
        return mayTouchUnbounded(b, a, margin);
    const double reach = a.shape().boundingRadius() + b.shape().boundingRadius() + margin;
    if (!std::isfinite(reach))
        return true;
    return (a.shapePose().position - b.shapePose().position).squaredNorm() < reach * reach;
}

} // namespace

std::vector<RigidVelocity> RigidContactSolver::solve(std::vector<RigidBody>& bodies, double dt) {
    findContacts(bodies);
    if (contacts_.empty())
        return std::vector<RigidVelocity>(bodies.size());
    prepare(bodies, dt);
    for (int sweep = 0; sweep < settings_.iterations; ++sweep)
        solveVelocities(bodies);
    return solvePositions(bodies, dt);
}

void RigidContactSolver::findContacts(const std::vector<RigidBody>& bodies) {
    contacts_.clear();
    for (std::size_t a = 0; a < bodies.size(); ++a) {
        if (!bodies[a].isDynamic())
            continue;
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            if (b == a || (bodies[b].isDynamic() && b < a))
                continue; // a dynamic pair is handled once, from its lower index, both ways
            if (a >= bubblesFrom_ && b >= bubblesFrom_)
                continue;
            if (!mayTouch(bodies[a], bodies[b], settings_.margin))
                continue;
            collide(bodies, a, b);
            if (bodies[b].isDynamic())
                collide(bodies, b, a);
        }
    }
}

void RigidContactSolver::collide(const std::vector<RigidBody>& bodies, std::size_t a,
                                 std::size_t b) {
    const RigidBody& body = bodies[a];
    for (std::size_t k = 0; k < body.boundary().size(); ++k)
        addContact(bodies, a, b, body.surfacePoint(k));
    if (body.shape().kind() == BodyShape::Kind::Sphere) {
        // The sphere's point deepest in the other body: exact where the samples are not.
        const Vec3d centre = body.position();
        addContact(bodies, a, b, centre - body.shape().radius() * bodies[b].normalAt(centre));
    }
}

void RigidContactSolver::addContact(const std::vector<RigidBody>& bodies, std::size_t a,
                                    std::size_t b, const Vec3d& point) {
    const double distance = bodies[b].signedDistance(point);
    if (distance >= settings_.margin)
        return;
    Contact contact;
    contact.a = a;
    contact.b = b;
    contact.point = point;
    contact.normal = bodies[b].normalAt(point);
    contact.depth = -distance;
    const ContactMaterial material =
        ContactMaterial::combine(bodies[a].bodyMaterial(), bodies[b].bodyMaterial());
    contact.friction = material.friction;
    contact.restitutionSpeed = material.restitution; // turned into a speed in prepare()
    if (contact.normal.squaredNorm() > 0.0)
        contacts_.push_back(contact);
}

void RigidContactSolver::prepare(const std::vector<RigidBody>& bodies, double dt) {
    for (Contact& contact : contacts_) {
        const RigidBody& a = bodies[contact.a];
        const RigidBody& b = bodies[contact.b];
        const double inverse = inverseMassAlong(a, a.state(), contact.point, contact.normal) +
                               inverseMassAlong(b, b.state(), contact.point, contact.normal);
        contact.normalMass = inverse > 0.0 ? 1.0 / inverse : 0.0;
        const double approach =
            (pointVelocity(a.state(), contact.point) - pointVelocity(b.state(), contact.point))
                .dot(contact.normal);
        const double restitution = contact.restitutionSpeed;
        // A gap closes this step at most: the bodies may approach until they touch
        // (speculative contact, Catto 2013); an overlap or touch bounces with ε.
        if (contact.depth < 0.0)
            contact.restitutionSpeed = contact.depth / dt;
        else
            contact.restitutionSpeed = approach < -kBounceThreshold ? -restitution * approach : 0.0;
    }
}

void RigidContactSolver::solveVelocities(std::vector<RigidBody>& bodies) {
    for (Contact& contact : contacts_) {
        if (contact.normalMass == 0.0)
            continue;
        solveFriction(contact, bodies);
        const double approach = relativeVelocity(bodies, contact).dot(contact.normal);
        const double change = -contact.normalMass * (approach - contact.restitutionSpeed);
        const double accumulated = std::max(contact.normalImpulse + change, 0.0);
        const Vec3d impulse = (accumulated - contact.normalImpulse) * contact.normal;
        contact.normalImpulse = accumulated;
        applyImpulse(bodies, contact, impulse);
    }
}

void RigidContactSolver::solveFriction(Contact& contact, std::vector<RigidBody>& bodies) {
    const RigidBody& a = bodies[contact.a];
    const RigidBody& b = bodies[contact.b];
    const Vec3d relative = relativeVelocity(bodies, contact);
    const Vec3d slip = relative - relative.dot(contact.normal) * contact.normal;
    const double slipSpeed = slip.norm();
    if (slipSpeed == 0.0 || contact.friction == 0.0)
        return;
    const Vec3d tangent = slip / slipSpeed;
    const double inverse = inverseMassAlong(a, a.state(), contact.point, tangent) +
                           inverseMassAlong(b, b.state(), contact.point, tangent);
    Vec3d accumulated = contact.tangentImpulse - (slipSpeed / inverse) * tangent;
    const double limit = contact.friction * contact.normalImpulse;
    if (accumulated.norm() > limit)
        accumulated *= limit / accumulated.norm();
    const Vec3d impulse = accumulated - contact.tangentImpulse;
    contact.tangentImpulse = accumulated;
    applyImpulse(bodies, contact, impulse);
}

Vec3d RigidContactSolver::relativeVelocity(const std::vector<RigidBody>& bodies,
                                           const Contact& contact) {
    return pointVelocity(bodies[contact.a].state(), contact.point) -
           pointVelocity(bodies[contact.b].state(), contact.point);
}

void RigidContactSolver::applyImpulse(std::vector<RigidBody>& bodies, const Contact& contact,
                                      const Vec3d& impulse) {
    // +impulse on a, the body the normal points towards; −impulse on b. Static and kinematic
    // bodies keep their state (RigidImpulse leaves infinite masses alone anyway).
    for (const auto& [index, sign] : {std::pair{contact.a, 1.0}, std::pair{contact.b, -1.0}}) {
        RigidBody& body = bodies[index];
        if (!body.isDynamic())
            continue;
        RigidBodyState state = body.state();
        RigidImpulse::apply(state, body.inertia(), sign * impulse, contact.point);
        body.setState(state);
    }
}

std::vector<RigidVelocity> RigidContactSolver::solvePositions(const std::vector<RigidBody>& bodies,
                                                              double dt) {
    // Split impulses act on "position velocities" that move this step's poses and are then
    // forgotten, so pushing an overlap apart leaves no velocity behind.
    std::vector<RigidBodyState> push(bodies.size());
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        push[k].position = bodies[k].position();
        push[k].orientation = bodies[k].orientation();
    }
    for (int sweep = 0; sweep < settings_.iterations; ++sweep)
        for (Contact& contact : contacts_) {
            const double excess = contact.depth - settings_.allowedPenetration;
            if (contact.normalMass == 0.0 || excess <= 0.0)
                continue;
            const double target = settings_.correction * excess / dt;
            const double speed = (pointVelocity(push[contact.a], contact.point) -
                                  pointVelocity(push[contact.b], contact.point))
                                     .dot(contact.normal);
            const double accumulated =
                std::max(contact.pushImpulse + contact.normalMass * (target - speed), 0.0);
            const Vec3d impulse = (accumulated - contact.pushImpulse) * contact.normal;
            contact.pushImpulse = accumulated;
            RigidImpulse::apply(push[contact.a], bodies[contact.a].inertia(), impulse,
                                contact.point);
            RigidImpulse::apply(push[contact.b], bodies[contact.b].inertia(), -impulse,
                                contact.point);
        }
    std::vector<RigidVelocity> velocities(bodies.size());
    for (std::size_t k = 0; k < bodies.size(); ++k)
        velocities[k] = {push[k].linearVelocity, push[k].angularVelocity};
    return velocities;
}

} // namespace airtrap
