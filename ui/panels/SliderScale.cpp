#include "panels/SliderScale.h"

#include "panels/DecimalRounding.h"

#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

//! Wider linear ranges would move by more than a sensible step per pixel.
constexpr double kWidestLinearRange = 1e6;
//! A positive range spanning this ratio or more is dragged on a logarithmic scale.
constexpr double kLogarithmicRatio = 100.0;
constexpr double kSignificantDigits = 3.0;

} // namespace

std::optional<SliderScale> SliderScale::forDeclaration(const ParameterDeclaration& declaration) {
    const double minimum = declaration.minimum;
    const double maximum = declaration.maximum;
    if (declaration.kind != ParameterKind::Real || !std::isfinite(minimum) ||
        !std::isfinite(maximum) || maximum <= minimum)
        return std::nullopt;
    if (minimum > 0.0 && maximum / minimum >= kLogarithmicRatio)
        return SliderScale(declaration, true);
    if (maximum - minimum > kWidestLinearRange)
        return std::nullopt;
    return SliderScale(declaration, false);
}

SliderScale::SliderScale(const ParameterDeclaration& declaration, bool logarithmic)
    : minimum_(declaration.minimum), maximum_(declaration.maximum),
      minimumExclusive_(declaration.minimumExclusive),
      maximumExclusive_(declaration.maximumExclusive), logarithmic_(logarithmic) {}

double SliderScale::valueAt(int position) const {
    const double fraction = static_cast<double>(position) / kPositions;
    double value = 0.0;
    if (logarithmic_) {
        const double exact = minimum_ * std::pow(maximum_ / minimum_, fraction);
        value =
            roundedToStep(exact, powerOfTenBelow(exact) / std::pow(10.0, kSignificantDigits - 1));
    } else {
        const double exact = minimum_ + fraction * (maximum_ - minimum_);
        value = roundedToStep(exact, powerOfTenBelow((maximum_ - minimum_) / kPositions));
    }
    // Rounding must not step over a bound the slider's ends stand for.
    return std::clamp(value, minimum_, maximum_);
}

int SliderScale::positionOf(double value) const {
    const double fraction = logarithmic_
                                ? std::log(value / minimum_) / std::log(maximum_ / minimum_)
                                : (value - minimum_) / (maximum_ - minimum_);
    if (!std::isfinite(fraction))
        return firstPosition();
    const int position = static_cast<int>(std::lround(fraction * kPositions));
    return std::clamp(position, firstPosition(), lastPosition());
}

} // namespace airtrap
