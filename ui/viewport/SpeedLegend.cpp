#include "viewport/SpeedLegend.h"

#include "viewport/SpeedColormap.h"

#include <QCoreApplication>
#include <QFontMetrics>
#include <QLinearGradient>
#include <QPainter>

namespace airtrap {

namespace {

constexpr int kMargin = 12;
constexpr int kPadding = 8;
constexpr int kBarWidth = 160;
constexpr int kBarHeight = 10;
constexpr int kGradientStops = 16;
const QColor kPanelColour(20, 20, 24, 170);
const QColor kTextColour(225, 225, 230);

} // namespace

QRect SpeedLegend::barRect(const QRect& area, const QFontMetrics& metrics) {
    // Room below the bar for one line of labels, above it for the title.
    const int labelHeight = metrics.height();
    const int bottom = area.bottom() - kMargin - kPadding - labelHeight;
    return QRect(area.right() - kMargin - kPadding - kBarWidth, bottom - kBarHeight, kBarWidth,
                 kBarHeight);
}

void SpeedLegend::paint(QPainter& painter, const QRect& area, float maxSpeed) const {
    const QRect bar = barRect(area, painter.fontMetrics());
    const int lineHeight = painter.fontMetrics().height();
    const QRect panel =
        bar.adjusted(-kPadding, -kPadding - lineHeight, kPadding, kPadding + lineHeight);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(kPanelColour);
    painter.drawRoundedRect(panel, 4, 4);
    paintBar(painter, bar);
    paintLabels(painter, bar, maxSpeed);
    painter.restore();
}

void SpeedLegend::paintBar(QPainter& painter, const QRect& bar) {
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    for (int i = 0; i <= kGradientStops; ++i) {
        const float t = float(i) / kGradientStops;
        gradient.setColorAt(t, SpeedColormap::colourAt(t));
    }
    painter.fillRect(bar, gradient);
}

void SpeedLegend::paintLabels(QPainter& painter, const QRect& bar, float maxSpeed) {
    painter.setPen(kTextColour);
    const int lineHeight = painter.fontMetrics().height();
    const QRect title(bar.left(), bar.top() - lineHeight - 2, bar.width(), lineHeight);
    painter.drawText(title, Qt::AlignLeft | Qt::AlignVCenter,
                     QCoreApplication::translate("SpeedLegend", "Speed (m/s)"));
    const QRect below(bar.left(), bar.bottom() + 2, bar.width(), lineHeight);
    painter.drawText(below, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0"));
    painter.drawText(below, Qt::AlignRight | Qt::AlignVCenter,
                     QString::number(double(maxSpeed), 'f', maxSpeed < 10.0f ? 2 : 1));
}

} // namespace airtrap
