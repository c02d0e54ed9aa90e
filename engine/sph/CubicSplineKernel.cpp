#include "sph/CubicSplineKernel.h"

#include <numbers>

namespace airtrap {

CubicSplineKernel::CubicSplineKernel(float supportRadius)
    : radius_(supportRadius), invRadius_(1.0f / supportRadius) {
    const float h3 = supportRadius * supportRadius * supportRadius;
    k_ = 8.0f / (std::numbers::pi_v<float> * h3);
    l_ = 48.0f / (std::numbers::pi_v<float> * h3);
}

} // namespace airtrap
