#pragma once
// Cubic spline kernel (Monaghan 1992) written with the support radius H = 2h:
//   q = r/H, k = 8/(πH³), W = k(6q³ − 6q² + 1) for q ≤ ½, 2k(1 − q)³ for q ≤ 1, 0 beyond.
// It equals the classic σ = 1/(πh³) form with support 2h (docs/METHOD.md "Kernel").
#include "core/Math.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace airtrap {

class CubicSplineKernel {
public:
    explicit CubicSplineKernel(float supportRadius);

    float supportRadius() const { return radius_; }
    //! The smoothing length h = H/2 that artificial viscosity and time-step criteria use.
    float smoothingLength() const { return 0.5f * radius_; }

    float value(float r) const {
        const float q = r * invRadius_;
        if (q <= 0.5f)
            return k_ * (6.0f * q * q * (q - 1.0f) + 1.0f);
        if (q <= 1.0f) {
            const float t = 1.0f - q;
            return 2.0f * k_ * t * t * t;
        }
        return 0.0f;
    }

    //! ∇ᵢW(xᵢ − xⱼ) for the offset d = xᵢ − xⱼ of length r > 0 (zero at r = 0 and beyond H).
    Vec3f gradient(const Vec3f& d, float r) const {
        const float q = r * invRadius_;
        if (r <= 1e-9f || q > 1.0f)
            return Vec3f::Zero();
        // dW/dr divided by r, so the gradient is this factor times d.
        float dWdrOverR;
        if (q <= 0.5f)
            dWdrOverR = l_ * (3.0f * q - 2.0f) * invRadius_ * invRadius_;
        else {
            const float t = 1.0f - q;
            dWdrOverR = -l_ * t * t * invRadius_ / r;
        }
        return dWdrOverR * d;
    }

    //! The same gradient from the squared distance, read from a table of dW/dr / r over r²
    //! with linear interpolation: no square root, division or branch in the neighbour loops.
    //! Relative error below 1e-4 for r > H/16 (particles never come closer than that).
    Vec3f gradientFromSquared(const Vec3f& d, float r2) const { return gradientFactor(r2) * d; }

    //! dW/dr / r at squared distance r2 from the same table: ∇ᵢW = factor · (xᵢ − xⱼ).
    float gradientFactor(float r2) const {
        const float position = r2 * tableScale_;
        if (position >= float(kTableSize - 1))
            return 0.0f;
        const int index = static_cast<int>(position);
        const float fraction = position - float(index);
        return table_[index] + fraction * (table_[index + 1] - table_[index]);
    }

    //! gradientFactor(r2) in 16 bits, for lists that keep it per pair. The factor lies between
    //! its value at r = 0 and zero, so steps of 1/65535 of that value keep every factor within
    //! 8·10⁻⁶ of the largest (the table's own error is 1e-4 of the factor).
    std::uint16_t gradientFactorCode(float r2) const {
        return static_cast<std::uint16_t>(
            std::min(gradientFactor(r2) * inverseCodeStep_ + 0.5f, 65535.0f));
    }
    //! values[k] = value(√r2[k]) for k < count, the same bits as one by one, four at a time on
    //! SSE2. Reads and writes up to three entries past count.
    void valuesOfSquared(const float* r2, std::size_t count, float* values) const;
    //! values[k] = value(√r2[k]) and codes[k] = gradientFactorCode(r2[k]) for k < count, the same
    //! bits as one by one; four at a time on SSE2, so that each pair's chain of dependent
    //! operations (root, polynomial, table, code) overlaps the next ones'. Reads and writes up to
    //! three entries past count.
    void valuesAndFactorCodes(const float* r2, std::size_t count, float* values,
                              std::int32_t* codes) const;
    //! The factor one code step stands for: a code's factor is code · gradientFactorStep().
    float gradientFactorStep() const { return codeStep_; }

private:
    static constexpr int kTableSize = 2049;

    float radius_;
    float invRadius_;
    float k_;          //!< 8/(πH³)
    float l_;          //!< 48/(πH³): derivative prefactor
    float tableScale_; //!< (kTableSize − 1) / H²
    float codeStep_;   //!< the factor at r = 0 over 65535
    float inverseCodeStep_;
    std::array<float, kTableSize> table_;
};

} // namespace airtrap
