#pragma once
// Tait's equation of state (paper eq. 3, docs/METHOD.md "Water: weakly compressible SPH"):
// p = B((ρ/ρ₀)^γ − 1) with γ = 7 and B = ρ₀c²/γ, the speed of sound c = 10·u_max, so that the
// density varies by about (u_max/c)² = 1 %.
#include "scene/Scene.h"

#include <algorithm>
#include <cmath>

namespace airtrap {

class TaitEquationOfState {
public:
    static constexpr double kGamma = 7.0;

    explicit TaitEquationOfState(const SolverSettings& settings)
        : restDensity_(settings.restDensity), speedOfSound_(10.0 * settings.maxSpeed),
          stiffness_(restDensity_ * speedOfSound_ * speedOfSound_ / kGamma) {}

    //! Pa, clamped at 0 so that the free surface does not pull particles into clumps.
    float pressure(float density) const {
        const double ratio = density / restDensity_;
        const double r2 = ratio * ratio;
        const double r7 = r2 * r2 * r2 * ratio;
        return static_cast<float>(std::max(0.0, stiffness_ * (r7 - 1.0)));
    }
    //! kg/m³, the density at which the pressure equals `pressure` Pa (the inverse of pressure()).
    float densityForPressure(double pressure) const {
        return static_cast<float>(restDensity_ *
                                  std::pow(1.0 + pressure / stiffness_, 1.0 / kGamma));
    }
    //! m/s
    double speedOfSound() const { return speedOfSound_; }

private:
    double restDensity_;
    double speedOfSound_;
    double stiffness_; //!< B = ρ₀c²/γ, Pa
};

} // namespace airtrap
