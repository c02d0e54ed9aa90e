// `airtrap --screenshot`: the real editor binary renders a cached dam-break frame to a PNG and
// exits; the picture shows water where the water is, and bad requests fail with a reason.
#include "BakeTestScenes.h"
#include "support/TestMain.h"

#include <QImage>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

namespace airtrap {

namespace {

struct Run {
    int exitCode = -1;
    QString err;
};

Run runEditor(const QStringList& arguments,
              const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment()) {
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(AIRTRAP_BINARY_DIR "/bin/airtrap"), arguments);
    Run run;
    if (!process.waitForStarted(10000) || !process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        run.err = QStringLiteral("did not finish: ") + process.errorString();
        return run;
    }
    run.err = QString::fromUtf8(process.readAllStandardError());
    if (process.exitStatus() == QProcess::NormalExit)
        run.exitCode = process.exitCode();
    return run;
}

//! Water is drawn blue to white by speed over a dark grey background.
bool isWaterColoured(const QColor& colour) {
    return colour.blue() > 150 && colour.blue() > colour.red() + 40;
}

int waterPixels(const QImage& image) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            count += isWaterColoured(image.pixelColor(x, y)) ? 1 : 0;
    return count;
}

} // namespace

class TestScreenshot : public QObject {
    Q_OBJECT

    QTemporaryDir folder_;
    QString scenePath_;
    QString cacheDir_;

    //! Frame 3 of the test scene at 480×320 with `extra` flags, saved as `name` in the scratch
    //! folder; a null image when the editor failed.
    QImage frameThreeShot(const QString& name, const QStringList& extra) {
        const QString png = folder_.filePath(name);
        const Run run =
            runEditor(QStringList{QStringLiteral("--scene"), scenePath_, QStringLiteral("--frame"),
                                  QStringLiteral("3"), QStringLiteral("--screenshot"), png,
                                  QStringLiteral("--size"), QStringLiteral("480x320")} +
                      extra);
        return run.exitCode == 0 ? QImage(png) : QImage();
    }

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(folder_.isValid());
        scenePath_ = folder_.filePath(QStringLiteral("tiny.json"));
        cacheDir_ = folder_.filePath(QStringLiteral("tiny.cache"));
        const Scene scene = test::tinyDamBreak();
        writeSceneFile(scene, scenePath_.toStdString());
        test::bakeNow(scene, cacheDir_);
    }

    void rendersACachedFrame() {
        const QString png = folder_.filePath(QStringLiteral("frame3.png"));
        const Run run = runEditor({QStringLiteral("--scene"), scenePath_, QStringLiteral("--frame"),
                                   QStringLiteral("3"), QStringLiteral("--screenshot"), png,
                                   QStringLiteral("--size"), QStringLiteral("480x320")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QImage image(png);
        QCOMPARE(image.size(), QSize(480, 320));
        // The water column fills a visible share of the picture, and most of it is background.
        const int water = waterPixels(image);
        QVERIFY2(water > image.width() * image.height() / 100, qPrintable(QString::number(water)));
        QVERIFY2(water < image.width() * image.height() / 2, qPrintable(QString::number(water)));
    }

    void editModeHasNoParticles() {
        // A scene with no cache beside it opens in edit mode.
        const QString uncached = folder_.filePath(QStringLiteral("uncached.json"));
        QVERIFY(QFile::copy(scenePath_, uncached));
        const QString png = folder_.filePath(QStringLiteral("edit.png"));
        const Run run = runEditor({uncached, QStringLiteral("--screenshot"), png,
                                   QStringLiteral("--size"), QStringLiteral("480x320")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QImage image(png);
        QVERIFY(!image.isNull());
        // Only the fluid block's blue outline: a thin line, not a filled column.
        QVERIFY(waterPixels(image) < image.width() * image.height() / 100);
    }

    void wholeWindowOnRequest() {
        const QString png = folder_.filePath(QStringLiteral("window.png"));
        const Run run = runEditor({QStringLiteral("--cache"), cacheDir_, QStringLiteral("--frame"),
                                   QStringLiteral("2"), QStringLiteral("--screenshot"), png,
                                   QStringLiteral("--size"), QStringLiteral("1200x800"),
                                   QStringLiteral("--window")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QCOMPARE(QImage(png).size(), QSize(1200, 800));
    }

    void layersAndCameraComeFromTheFlags() {
        const QImage particles =
            frameThreeShot(QStringLiteral("particles.png"),
                           {QStringLiteral("--show"), QStringLiteral("particles")});
        const QImage bubblesOnly = frameThreeShot(
            QStringLiteral("bubbles.png"), {QStringLiteral("--show"), QStringLiteral("bubbles")});
        QVERIFY(!particles.isNull() && !bubblesOnly.isNull());
        QVERIFY(waterPixels(particles) > particles.width() * particles.height() / 100);
        QVERIFY(waterPixels(bubblesOnly) < bubblesOnly.width() * bubblesOnly.height() / 500);
        // The water column seen from the front and from the top covers different pixels.
        const QImage front = frameThreeShot(QStringLiteral("front.png"),
                                            {QStringLiteral("--camera"), QStringLiteral("front")});
        const QImage top = frameThreeShot(
            QStringLiteral("top.png"),
            {QStringLiteral("--camera"), QStringLiteral("top"), QStringLiteral("--no-selection")});
        QVERIFY(!front.isNull() && !top.isNull());
        QVERIFY(front != top);

        Run run = runEditor({scenePath_, QStringLiteral("--screenshot"),
                             folder_.filePath(QStringLiteral("x.png")), QStringLiteral("--show"),
                             QStringLiteral("mesh,foam")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("\"foam\"")), qPrintable(run.err));
        run = runEditor({scenePath_, QStringLiteral("--screenshot"),
                         folder_.filePath(QStringLiteral("x.png")), QStringLiteral("--camera"),
                         QStringLiteral("under")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--camera under")), qPrintable(run.err));
    }

    void particleSizeAndSurfaceShadingComeFromTheFlags() {
        const auto shot = [&](const QString& name, const QStringList& extra) {
            return frameThreeShot(
                name, QStringList{QStringLiteral("--show"), QStringLiteral("particles")} + extra);
        };
        const QImage standard = shot(QStringLiteral("standard.png"), {});
        const QImage points = shot(QStringLiteral("points.png"),
                                   {QStringLiteral("--particle-size"), QStringLiteral("0.2")});
        QVERIFY(!standard.isNull() && !points.isNull());
        // Points a fifth of the size leave gaps between them: fewer water pixels.
        QVERIFY2(
            waterPixels(points) < waterPixels(standard) * 9 / 10,
            qPrintable(
                QStringLiteral("%1 of %2").arg(waterPixels(points)).arg(waterPixels(standard))));
        QVERIFY(!shot(QStringLiteral("wire.png"),
                      {QStringLiteral("--surface"), QStringLiteral("wireframe")})
                     .isNull());

        Run run = runEditor({scenePath_, QStringLiteral("--screenshot"),
                             folder_.filePath(QStringLiteral("x.png")), QStringLiteral("--surface"),
                             QStringLiteral("glass")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--surface glass")), qPrintable(run.err));
        run = runEditor({scenePath_, QStringLiteral("--screenshot"),
                         folder_.filePath(QStringLiteral("x.png")),
                         QStringLiteral("--particle-size"), QStringLiteral("9")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("0.1 to 3")), qPrintable(run.err));
    }

    void neitherReadsNorWritesTheUsersSettings() {
        // A user who hid the water, with a settings file of their own.
        QTemporaryDir config;
        QVERIFY(config.isValid());
        const QString file = config.filePath(QStringLiteral("Airtrap/Airtrap.conf"));
        {
            QSettings user(file, QSettings::IniFormat);
            user.setValue(QStringLiteral("view/showWater"), false);
            user.setValue(QStringLiteral("recentFiles"), QStringList{QStringLiteral("/a.json")});
        }
        QFile before(file);
        QVERIFY(before.open(QIODevice::ReadOnly));
        const QByteArray saved = before.readAll();
        before.close();
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
        const QString png = folder_.filePath(QStringLiteral("settings.png"));
        const Run run = runEditor({QStringLiteral("--scene"), scenePath_, QStringLiteral("--frame"),
                                   QStringLiteral("3"), QStringLiteral("--screenshot"), png,
                                   QStringLiteral("--size"), QStringLiteral("480x320")},
                                  environment);
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        // The water is drawn, and the file is as the user left it (no scene added to the list).
        const QImage image(png);
        QVERIFY(waterPixels(image) > image.width() * image.height() / 100);
        QFile after(file);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), saved);
    }

    void refusesBadRequests() {
        const QString png = folder_.filePath(QStringLiteral("bad.png"));
        Run run = runEditor({QStringLiteral("--scene"), scenePath_, QStringLiteral("--frame"),
                             QStringLiteral("99"), QStringLiteral("--screenshot"), png});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("frame 99")), qPrintable(run.err));
        QVERIFY(!QFile::exists(png));

        run = runEditor({QStringLiteral("--scene"), scenePath_, QStringLiteral("--screenshot"), png,
                         QStringLiteral("--size"), QStringLiteral("big")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--size big")), qPrintable(run.err));

        run = runEditor({QStringLiteral("--scene"), folder_.filePath(QStringLiteral("none.json")),
                         QStringLiteral("--screenshot"), png});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("none.json")), qPrintable(run.err));
    }
};

} // namespace airtrap

AIRTRAP_TEST_GUILESS(airtrap::TestScreenshot)
#include "TestScreenshot.moc"
