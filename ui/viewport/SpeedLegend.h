#pragma once
// The colour bar of playback: the speed colour map from 0 to the scale, with its limits written
// under it, in the bottom-right corner. Painted with QPainter over the finished GL image.
#include <QRect>

class QFontMetrics;
class QPainter;

namespace airtrap {

class SpeedLegend {
public:
    //! Paints the legend into the bottom-right corner of `area` (widget pixels) for colours that
    //! run from 0 to `maxSpeed` m/s.
    void paint(QPainter& painter, const QRect& area, float maxSpeed) const;

    //! Where paint() puts the colour bar itself in `area`, for text of these metrics.
    static QRect barRect(const QRect& area, const QFontMetrics& metrics);

private:
    static void paintBar(QPainter& painter, const QRect& bar);
    static void paintLabels(QPainter& painter, const QRect& bar, float maxSpeed);
};

} // namespace airtrap
