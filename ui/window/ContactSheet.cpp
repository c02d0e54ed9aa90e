#include "window/ContactSheet.h"

#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QSaveFile>
#include <QTextStream>
#include <cmath>

namespace airtrap {

namespace {

constexpr int kLabelHeight = 34;
constexpr int kGap = 6;

} // namespace

std::vector<ContactSheet::Tile> ContactSheet::readTiles(const QString& listPath, QString& error) {
    QFile file(listPath);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        error = listPath + QStringLiteral(": ") + file.errorString();
        return {};
    }
    std::vector<Tile> tiles;
    QTextStream in(&file);
    for (int line = 1; !in.atEnd(); ++line) {
        const QString text = in.readLine();
        if (text.trimmed().isEmpty())
            continue;
        const qsizetype tab = text.indexOf(QLatin1Char('\t'));
        if (tab <= 0) {
            error = QStringLiteral("%1, line %2: expected an image path, a tab and a label")
                        .arg(listPath)
                        .arg(line);
            return {};
        }
        tiles.push_back({text.left(tab), text.mid(tab + 1)});
    }
    if (tiles.empty())
        error = listPath + QStringLiteral(": lists no tile");
    return tiles;
}

void ContactSheet::drawTile(QImage& sheet, const Tile& tile, const QRect& area) {
    QPainter painter(&sheet);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    const QRect picture(area.topLeft(), QSize(area.width(), area.height() - kLabelHeight));
    const QImage render(tile.imagePath);
    if (render.isNull()) {
        painter.fillRect(picture, QColor(70, 70, 74));
        painter.setPen(QColor(200, 200, 200));
        painter.drawText(picture, Qt::AlignCenter,
                         QStringLiteral("no render: %1").arg(QFileInfo(tile.imagePath).fileName()));
    } else {
        painter.drawImage(picture, render);
    }
    const QRect label(picture.bottomLeft() + QPoint(0, 1), QSize(area.width(), kLabelHeight - 1));
    painter.fillRect(label, QColor(24, 24, 26));
    QFont font = painter.font();
    font.setPixelSize(15);
    painter.setFont(font);
    painter.setPen(Qt::white);
    painter.drawText(
        label.adjusted(8, 0, -8, 0), Qt::AlignVCenter | Qt::AlignLeft,
        painter.fontMetrics().elidedText(tile.label, Qt::ElideRight, label.width() - 16));
}

QImage ContactSheet::compose(const std::vector<Tile>& tiles, const QSize& tileSize,
                             int requestedColumns) {
    const int count = int(tiles.size());
    const int columns = requestedColumns > 0
                            ? std::min(requestedColumns, std::max(1, count))
                            : std::max(1, int(std::ceil(std::sqrt(double(count)))));
    const int rows = (count + columns - 1) / columns;
    const QSize cell(tileSize.width(), tileSize.height() + kLabelHeight);
    QImage sheet(columns * cell.width() + (columns + 1) * kGap,
                 rows * cell.height() + (rows + 1) * kGap, QImage::Format_RGB32);
    sheet.fill(QColor(40, 40, 43));
    for (int i = 0; i < count; ++i) {
        const QPoint corner(kGap + (i % columns) * (cell.width() + kGap),
                            kGap + (i / columns) * (cell.height() + kGap));
        drawTile(sheet, tiles[std::size_t(i)], QRect(corner, cell));
    }
    return sheet;
}

QString ContactSheet::save(const QImage& sheet, const QString& path) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || !sheet.save(&file, "PNG") || !file.commit())
        return path + QStringLiteral(": ") + file.errorString();
    return {};
}

} // namespace airtrap
