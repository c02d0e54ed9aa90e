#pragma once
// Counting the pixels of a grabbed viewport frame: around a point, split at a circle, or changed
// between two frames, for the tests that check what the viewport draws where the camera says.
#include <QColor>
#include <QImage>
#include <QPointF>
#include <cmath>
#include <cstdlib>

namespace airtrap {

//! Pixels of `image` within `radius` of `centre` (widget pixels) that satisfy `test`.
template <typename Test>
inline int countAround(const QImage& image, const QPointF& centre, int radius, qreal ratio,
                       Test test) {
    int count = 0;
    const QPoint c = (centre * ratio).toPoint();
    for (int y = c.y() - radius; y <= c.y() + radius; ++y) {
        for (int x = c.x() - radius; x <= c.x() + radius; ++x) {
            count += image.valid(x, y) && test(image.pixelColor(x, y)) ? 1 : 0;
        }
    }
    return count;
}

//! Pixels (x, y) of `image` that pass `test`: how many lie within `radius` of `centre` (both in
//! image pixels), and how many outside.
struct PixelSplit {
    int inside = 0;
    int outside = 0;
};

template <typename Test>
inline PixelSplit splitAround(const QImage& image, const QPointF& centre, double radius,
                              Test test) {
    PixelSplit pixels;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (!test(x, y))
                continue;
            const QPointF offset = QPointF(x + 0.5, y + 0.5) - centre;
            const bool within = std::hypot(offset.x(), offset.y()) <= radius;
            (within ? pixels.inside : pixels.outside) += 1;
        }
    }
    return pixels;
}

//! Within a few levels in every channel: the multisampled framebuffer resolves a frame drawn
//! again after new data to within rounding of the first, not always bit for bit.
inline bool nearlySame(QRgb a, QRgb b) {
    return std::abs(qRed(a) - qRed(b)) <= 8 && std::abs(qGreen(a) - qGreen(b)) <= 8 &&
           std::abs(qBlue(a) - qBlue(b)) <= 8;
}

inline int pixelsChanged(const QImage& a, const QImage& b) {
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            count += nearlySame(a.pixel(x, y), b.pixel(x, y)) ? 0 : 1;
    return count;
}

} // namespace airtrap
