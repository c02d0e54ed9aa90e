#pragma once
// Maps the integer positions of a QSlider to values of a Real parameter and back. Ranges that span
// decades (particle spacing 0.001–1 m) get a logarithmic scale, so that the usual values do not
// crowd into the first pixels of the groove.
#include "scene/ParameterDeclaration.h"

#include <optional>

namespace airtrap {

class SliderScale {
public:
    //! The scale for `declaration`, or nothing when a slider would not help: not a Real, or a
    //! range that is unbounded or too wide to drag through.
    static std::optional<SliderScale> forDeclaration(const ParameterDeclaration& declaration);

    //! The slider's smallest position; above the minimum when the minimum is excluded.
    int firstPosition() const { return minimumExclusive_ ? 1 : 0; }
    //! The slider's largest position; below the maximum when the maximum is excluded.
    int lastPosition() const { return maximumExclusive_ ? kPositions - 1 : kPositions; }
    //! The value at `position`, rounded to what a user would type (3 significant digits on a
    //! logarithmic scale, a thousandth of the range on a linear one).
    double valueAt(int position) const;
    //! The position nearest to `value`, clamped to the slider.
    int positionOf(double value) const;
    //! True when equal ratios of the value take equal lengths of the groove.
    bool isLogarithmic() const { return logarithmic_; }

private:
    static constexpr int kPositions = 1000;

    SliderScale(const ParameterDeclaration& declaration, bool logarithmic);

    double minimum_;
    double maximum_;
    bool minimumExclusive_;
    bool maximumExclusive_;
    bool logarithmic_;
};

} // namespace airtrap
