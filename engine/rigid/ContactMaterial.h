#pragma once
// How a body's contacts respond (paper eq. 4): the coefficient of restitution ε of the normal
// impulse and the Coulomb coefficient μ that bounds the tangential one.
#include <algorithm>

namespace airtrap {

struct ContactMaterial {
    double restitution = 0.0; //!< ε, share of the approach speed kept
    double friction = 0.0;    //!< μ, tangential impulse ≤ μ × normal impulse

    //! The pair's material: the bouncier restitution and the slipperier friction, so that a
    //! ball with ε = 0.5 bounces on any floor and an ice block with μ = 0 slides on any floor.
    static ContactMaterial combine(const ContactMaterial& a, const ContactMaterial& b) {
        return {std::max(a.restitution, b.restitution), std::min(a.friction, b.friction)};
    }
};

} // namespace airtrap
