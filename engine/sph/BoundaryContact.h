#pragma once
// The impulse-based boundary force's contact term (paper eq. 4, docs/METHOD.md "Impulse-based
// boundary force"): the impulse J a water particle takes from the body it is about to run into,
// shared by both pressure solvers.
#include "sph/BoundaryModel.h"
#include "sph/ContactRecords.h"

#include <cstddef>
#include <cstdint>

namespace airtrap {

class BoundaryContact {
public:
    //! The nearest boundary particle within the contact radius, if any.
    struct Nearest {
        const BoundaryLayer* layer = nullptr;
        std::int64_t boundaryParticle = -1; //!< in `layer`
        float distance2 = 0.0f;

        //! Keeps boundary particle b of `layer` at squared distance r2 if it is nearer.
        void consider(const BoundaryLayer& candidate, std::uint32_t b, float r2) {
            if (r2 < distance2) {
                distance2 = r2;
                layer = &candidate;
                boundaryParticle = b;
            }
        }
    };

    //! `waterMass` (kg) of one particle.
    explicit BoundaryContact(float waterMass) : waterMass_(waterMass) {}

    //! The contact impulse J (N·s) for a particle that would still approach the body after this
    //! step: j = −(1 + ε) uₙ / (1/mᵢ + K_B(n, r)) along the normal, plus Coulomb friction against
    //! the tangential slip, bounded by μ j. A static body has K_B = 0.
    Vec3f impulse(const Vec3f& velocity, const Vec3f& acceleration, const Nearest& contact,
                  const BoundaryModel& boundary, float dt) const;
    //! Notes particle i's impulse when it came from a dynamic body (else −1, zero); the index is
    //! into the moving layer, which holds every dynamic body.
    static void record(std::size_t i, const Nearest& contact, const Vec3f& impulse,
                       const BoundaryModel& boundary, ContactRecords& contacts);

private:
    float waterMass_;
};

} // namespace airtrap
