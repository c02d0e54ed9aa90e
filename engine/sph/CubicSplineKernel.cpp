#include "sph/CubicSplineKernel.h"

#include <cmath>
#include <numbers>

namespace airtrap {

CubicSplineKernel::CubicSplineKernel(float supportRadius)
    : radius_(supportRadius), invRadius_(1.0f / supportRadius) {
    const float h3 = supportRadius * supportRadius * supportRadius;
    k_ = 8.0f / (std::numbers::pi_v<float> * h3);
    l_ = 48.0f / (std::numbers::pi_v<float> * h3);
    tableScale_ = float(kTableSize - 1) / (supportRadius * supportRadius);
    for (int k = 0; k < kTableSize; ++k) {
        const double r = std::sqrt(double(k) / tableScale_);
        // dW/dr / r, with its limit −2l/H² at r = 0 (the first branch at q → 0).
        const double factor = k == 0 ? -2.0 * l_ * invRadius_ * invRadius_
                                     : gradient(Vec3f(float(r), 0, 0), float(r)).x() / r;
        table_[k] = k == kTableSize - 1 ? 0.0f : static_cast<float>(factor);
    }
    codeStep_ = table_[0] / 65535.0f;
    inverseCodeStep_ = 1.0f / codeStep_;
}

} // namespace airtrap
