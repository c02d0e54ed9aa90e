#pragma once
// The weights of Chebyshev semi-iterative acceleration (Golub & Varga 1961; used on an SPH-like
// Jacobi solve by Wang 2015, "A Chebyshev semi-iterative approach for accelerating projective and
// position-based dynamics"): xₖ₊₁ = ωₖ₊₁ (x̂ₖ₊₁ − xₖ₋₁) + xₖ₋₁, with x̂ the plain Jacobi iterate.
// Jacobi removes an error component by the factor its eigenvalue leaves; the smooth components of
// a deep pool's pressure (a column's weight spread over fifty layers) have eigenvalues near 1 and
// take hundreds of iterations. Chebyshev's weights damp every component with |λ| ≤ ρ by the
// Chebyshev polynomial's bound, about ρ' = (1 − √(1 − ρ²)) / ρ per iteration: for ρ = 0.99 that is
// 0.87, where Jacobi's own is 0.99. docs/METHOD.md "Water: divergence-free SPH".

namespace airtrap {

class ChebyshevWeights {
public:
    //! `spectralRadius` bounds the moduli of the Jacobi iteration's eigenvalues that are to be
    //! accelerated; components beyond it grow, so it must not be overestimated.
    explicit ChebyshevWeights(float spectralRadius) : radius2_(spectralRadius * spectralRadius) {}

    //! The weight of the next iterate: 1 for the first after a (re)start, then the recurrence.
    float next() {
        if (iteration_ == 0)
            weight_ = 1.0f;
        else if (iteration_ == 1)
            weight_ = 2.0f / (2.0f - radius2_);
        else
            weight_ = 4.0f / (4.0f - radius2_ * weight_);
        ++iteration_;
        return weight_;
    }

    //! The next iterate is a plain Jacobi one again (after a rise of the residual).
    void restart() { iteration_ = 0; }

private:
    float radius2_;
    float weight_ = 1.0f;
    int iteration_ = 0;
};

} // namespace airtrap
