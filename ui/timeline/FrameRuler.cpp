#include "timeline/FrameRuler.h"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

//! Free space left and right of the range, so the end frames' handle and labels fit.
constexpr double kMargin = 12.0;
constexpr int kStripHeight = 5;
constexpr int kOutputStripHeight = 3;
const QColor kCachedColor(76, 175, 80);
const QColor kOutputColor(33, 150, 243);
constexpr double kMinorTickSpacing = 6.0;
constexpr double kLabelSpacing = 48.0;

} // namespace

FrameRuler::FrameRuler(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setCursor(Qt::PointingHandCursor);
    setToolTip(tr("Click or drag to go to a frame; the green strip marks cached frames, the blue "
                  "one above it frames with render outputs"));
}

void FrameRuler::setFrameRange(int first, int last) {
    first_ = first;
    last_ = std::max(first, last);
    update();
}

void FrameRuler::setCachedFrames(std::vector<int> frames) {
    cached_ = std::move(frames);
    update();
}

void FrameRuler::setOutputFrames(std::vector<int> frames) {
    outputs_ = std::move(frames);
    update();
}

void FrameRuler::setCurrentFrame(int frame) {
    current_ = frame;
    update();
}

double FrameRuler::pixelsPerFrame() const {
    const double span = std::max(1, last_ - first_);
    return std::max(1.0, width() - 2.0 * kMargin) / span;
}

int FrameRuler::frameAt(double x) const {
    const int frame = first_ + int(std::lround((x - kMargin) / pixelsPerFrame()));
    return std::clamp(frame, first_, last_);
}

double FrameRuler::xOf(int frame) const {
    if (last_ == first_)
        return width() / 2.0;
    return kMargin + (frame - first_) * pixelsPerFrame();
}

QSize FrameRuler::sizeHint() const {
    return {400, minimumSizeHint().height()};
}

QSize FrameRuler::minimumSizeHint() const {
    return {120, fontMetrics().height() + 16 + kStripHeight + kOutputStripHeight};
}

int FrameRuler::tickStep(double spacing) const {
    const double perFrame = pixelsPerFrame();
    for (int magnitude = 1;; magnitude *= 10)
        for (int factor : {1, 2, 5})
            if (factor * magnitude * perFrame >= spacing || factor * magnitude > last_ - first_)
                return factor * magnitude;
}

void FrameRuler::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().color(QPalette::Base));
    const double cachedTop = height() - kStripHeight;
    paintStrip(painter, cached_, cachedTop, kStripHeight, kCachedColor);
    paintStrip(painter, outputs_, cachedTop - kOutputStripHeight, kOutputStripHeight, kOutputColor);
    paintTicks(painter);
    paintHandle(painter);
}

void FrameRuler::paintTicks(QPainter& painter) const {
    const int minor = tickStep(kMinorTickSpacing);
    const int labelled = std::max(minor, tickStep(kLabelSpacing));
    const int baseline = height() - kStripHeight - kOutputStripHeight - 1;
    const int labelHeight = fontMetrics().height();
    painter.setPen(palette().color(QPalette::Text));
    // Ticks sit on multiples of the step (frame 10, 20, …) plus the first frame itself.
    for (int frame = first_; frame <= last_; frame = (frame / minor + 1) * minor) {
        const double x = xOf(frame);
        const bool labelledTick = frame % labelled == 0 || frame == first_;
        painter.drawLine(QPointF(x, baseline), QPointF(x, baseline - (labelledTick ? 8 : 4)));
        if (labelledTick)
            painter.drawText(QRectF(x - kLabelSpacing / 2, 2, kLabelSpacing, labelHeight),
                             Qt::AlignCenter, QString::number(frame));
    }
}

void FrameRuler::paintStrip(QPainter& painter, const std::vector<int>& frames, double top,
                            double height, const QColor& color) const {
    const double halfFrame = std::max(1.0, pixelsPerFrame() / 2.0);
    // One rectangle per run of consecutive frames, so a long cache is a few rectangles.
    for (std::size_t runStart = 0; runStart < frames.size();) {
        std::size_t runEnd = runStart;
        while (runEnd + 1 < frames.size() && frames[runEnd + 1] == frames[runEnd] + 1)
            ++runEnd;
        const int from = std::max(frames[runStart], first_);
        const int to = std::min(frames[runEnd], last_);
        if (from <= to)
            painter.fillRect(
                QRectF(xOf(from) - halfFrame, top, xOf(to) - xOf(from) + 2 * halfFrame, height),
                color);
        runStart = runEnd + 1;
    }
}

void FrameRuler::paintHandle(QPainter& painter) const {
    const double x = xOf(current_);
    const QColor color = palette().color(QPalette::Highlight);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(color, 2.0));
    painter.drawLine(QPointF(x, 0), QPointF(x, height()));
    const QPointF marker[] = {{x - 5, 0}, {x + 5, 0}, {x, 7}};
    painter.setBrush(color);
    painter.drawPolygon(marker, 3);
}

void FrameRuler::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    Q_EMIT frameScrubbed(frameAt(event->position().x()));
}

void FrameRuler::mouseMoveEvent(QMouseEvent* event) {
    if (!(event->buttons() & Qt::LeftButton)) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    Q_EMIT frameScrubbed(frameAt(event->position().x()));
}

} // namespace airtrap
