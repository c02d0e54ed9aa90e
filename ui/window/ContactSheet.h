#pragma once
// One picture of several renders side by side, each labelled, for comparing the wedges of a farm
// submission at a glance (docs/FARM.md, farm submit --contact-sheet): `airtrap --contact-sheet
// OUT.png
// --tiles LIST.tsv [--columns N]`. A tile whose render is missing (its wedge failed) is drawn as a
// grey panel that says so, so the sheet still shows every wedge.
#include <QImage>
#include <QString>
#include <QStringList>
#include <vector>

namespace airtrap {

class ContactSheet {
public:
    struct Tile {
        QString imagePath;
        QString label;
    };

    //! The tiles of a list file: one per line, the image's path, a tab, its label. Error text in
    //! `error` (naming the file and line) and an empty list when it cannot be read.
    static std::vector<Tile> readTiles(const QString& listPath, QString& error);

    //! The sheet: tiles in rows of `columns` (about √n when 0), each `tileSize` (renders are
    //! scaled to it) above its label.
    static QImage compose(const std::vector<Tile>& tiles, const QSize& tileSize, int columns = 0);

    //! Writes `sheet` to `path` as PNG through a temporary file renamed over it, so a reader never
    //! sees half a picture. Empty on success, else the reason.
    static QString save(const QImage& sheet, const QString& path);

private:
    static void drawTile(QImage& sheet, const Tile& tile, const QRect& area);
};

} // namespace airtrap
