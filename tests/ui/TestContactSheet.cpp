// The contact sheet of a farm's wedges (docs/FARM.md): renders tiled in rows of about √n, each
// scaled to the tile size above its label; a missing render still gets its tile, grey; a broken
// tile list is refused naming the file and line; the PNG is written whole.
#include "support/WidgetTestMain.h"
#include "window/ContactSheet.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

namespace airtrap {

class TestContactSheet : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString path(const QString& name) const { return dir_.filePath(name); }

    void writeList(const QString& name, const QByteArray& text) {
        QFile file(path(name));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(text);
    }

private Q_SLOTS:
    void tilesAreLaidOutInRowsWithTheirLabels() {
        QImage red(320, 180, QImage::Format_RGB32);
        red.fill(Qt::red);
        QVERIFY(red.save(path("red.png")));
        writeList("tiles.tsv", (path("red.png") + "\talpha = 0.05\n" + path("missing.png") +
                                "\talpha = 0.2\n" + path("red.png") + "\talpha = 0.4\n")
                                   .toUtf8());
        QString error;
        const auto tiles = ContactSheet::readTiles(path("tiles.tsv"), error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(tiles.size(), std::size_t(3));
        QCOMPARE(tiles[1].label, QStringLiteral("alpha = 0.2"));
        const QImage sheet = ContactSheet::compose(tiles, QSize(160, 90));
        // Three tiles: two columns, two rows; 6 px gaps, 34 px labels.
        QCOMPARE(sheet.size(), QSize(2 * 160 + 3 * 6, 2 * (90 + 34) + 3 * 6));
        QCOMPARE(sheet.pixelColor(6 + 80, 6 + 45), QColor(Qt::red)); // scaled render
        QCOMPARE(sheet.pixelColor(6 + 166 + 80, 6 + 45), QColor(70, 70, 74).toRgb()); // missing
        QCOMPARE(sheet.pixelColor(6 + 80, 6 + 130 + 45), QColor(Qt::red));
        QVERIFY(ContactSheet::save(sheet, path("sheet.png")).isEmpty());
        // Asked for three columns: one row.
        QCOMPARE(ContactSheet::compose(tiles, QSize(160, 90), 3).size(),
                 QSize(3 * 160 + 4 * 6, 90 + 34 + 2 * 6));
        QCOMPARE(QImage(path("sheet.png")).size(), sheet.size());
    }

    void aBrokenListIsRefusedByFileAndLine() {
        writeList("broken.tsv", "first.png\tfine\nno tab here\n");
        QString error;
        QVERIFY(ContactSheet::readTiles(path("broken.tsv"), error).empty());
        QVERIFY2(error.contains("broken.tsv, line 2"), qPrintable(error));
        QVERIFY(ContactSheet::readTiles(path("absent.tsv"), error).empty());
        QVERIFY2(error.startsWith(path("absent.tsv")), qPrintable(error));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestContactSheet)
#include "TestContactSheet.moc"
