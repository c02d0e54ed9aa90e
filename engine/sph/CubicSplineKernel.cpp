#include "sph/CubicSplineKernel.h"

#include <cmath>
#include <numbers>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

#if defined(__SSE2__)
namespace {
//! value(√r2) in four lanes, each operation as in value(), in the same order.
__m128 fourValues(__m128 distance2, float invRadius, float k) {
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 q = _mm_mul_ps(_mm_sqrt_ps(distance2), _mm_set1_ps(invRadius));
    const __m128 t = _mm_sub_ps(one, q);
    const __m128 inner = _mm_mul_ps(
        _mm_set1_ps(k),
        _mm_add_ps(_mm_mul_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(6.0f), q), q), _mm_sub_ps(q, one)),
                   one));
    const __m128 outer = _mm_mul_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(2.0f * k), t), t), t);
    const __m128 isInner = _mm_cmple_ps(q, _mm_set1_ps(0.5f));
    const __m128 piece = _mm_or_ps(_mm_and_ps(isInner, inner), _mm_andnot_ps(isInner, outer));
    return _mm_and_ps(_mm_cmple_ps(q, one), piece);
}
} // namespace
#endif

void CubicSplineKernel::valuesOfSquared(const float* r2, std::size_t count, float* values) const {
    std::size_t k = 0;
#if defined(__SSE2__)
    for (; k < count; k += 4)
        _mm_storeu_ps(values + k, fourValues(_mm_loadu_ps(r2 + k), invRadius_, k_));
#endif
    for (; k < count; ++k)
        values[k] = value(std::sqrt(r2[k]));
}

void CubicSplineKernel::valuesAndFactorCodes(const float* r2, std::size_t count, float* values,
                                             std::int32_t* codes) const {
    std::size_t k = 0;
#if defined(__SSE2__)
    // Each operation as in gradientFactor(), in the same order, lane by lane.
    const __m128 half = _mm_set1_ps(0.5f);
    const __m128 lastPosition = _mm_set1_ps(float(kTableSize - 1));
    for (; k < count; k += 4) {
        const __m128 distance2 = _mm_loadu_ps(r2 + k);
        _mm_storeu_ps(values + k, fourValues(distance2, invRadius_, k_));

        const __m128 position = _mm_mul_ps(distance2, _mm_set1_ps(tableScale_));
        const __m128 inTable = _mm_cmplt_ps(position, lastPosition);
        // Lanes beyond the table read its last entries and are zeroed after.
        const __m128i index =
            _mm_cvttps_epi32(_mm_min_ps(position, _mm_set1_ps(float(kTableSize - 2))));
        const __m128 fraction = _mm_sub_ps(position, _mm_cvtepi32_ps(index));
        alignas(16) std::int32_t at[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(at), index);
        const __m128 low = _mm_setr_ps(table_[at[0]], table_[at[1]], table_[at[2]], table_[at[3]]);
        const __m128 high =
            _mm_setr_ps(table_[at[0] + 1], table_[at[1] + 1], table_[at[2] + 1], table_[at[3] + 1]);
        const __m128 factor =
            _mm_and_ps(inTable, _mm_add_ps(low, _mm_mul_ps(fraction, _mm_sub_ps(high, low))));
        const __m128 scaled = _mm_add_ps(_mm_mul_ps(factor, _mm_set1_ps(inverseCodeStep_)), half);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(codes + k),
                         _mm_cvttps_epi32(_mm_min_ps(scaled, _mm_set1_ps(65535.0f))));
    }
#endif
    for (; k < count; ++k) {
        values[k] = value(std::sqrt(r2[k]));
        codes[k] = gradientFactorCode(r2[k]);
    }
}

} // namespace airtrap
