#pragma once
// Rounding that yields the double a user would type: 0.1 + 0.2 stepped or slid to 0.3 must read
// back as "0.3", not "0.30000000000000004", in the number fields and in the saved scene file.
#include <QString>
#include <algorithm>
#include <cmath>

namespace airtrap {

//! `value` rounded to a whole multiple of `step` (a power of ten), as the nearest double to the
//! decimal text, so that ParameterCodec::formatNumber prints it with the step's decimals at most.
inline double roundedToStep(double value, double step) {
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    return QString::number(std::round(value / step) * step, 'f', decimals).toDouble();
}

//! The power of ten at or below `magnitude` (> 0): 0.034 → 0.01, 250 → 100.
inline double powerOfTenBelow(double magnitude) {
    return std::pow(10.0, std::floor(std::log10(magnitude)));
}

} // namespace airtrap
