// airtrap: the editor. `airtrap [scene.json]` opens the window; with --screenshot it renders one
// frame to a PNG and exits (for the docs and for pixel tests).
#include "viewport/ViewportWidget.h"
#include "window/ContactSheet.h"
#include "window/EditorSettings.h"
#include "window/MainWindow.h"
#include "window/ScreenshotJob.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QRegularExpression>
#include <QSurfaceFormat>
#include <QTimer>
#include <csignal>
#include <cstdio>
#include <cstdlib>

namespace {

struct EditorOptions {
    QString scenePath;
    airtrap::ScreenshotRequest screenshot;
    bool takeScreenshot = false;
    QString contactSheetPath; //!< --contact-sheet: tile the renders of --tiles into this PNG
    QString tilesPath;
    int sheetColumns = 0; //!< --columns: tiles per row (0: about √n)
};

//! Bad command-line input: the reason on stderr and exit code 2, like airtrap-cli.
[[noreturn]] void refuse(const QString& reason) {
    std::fprintf(stderr, "airtrap: %s\n", qPrintable(reason));
    std::exit(2);
}

QSize parseSize(const QString& text, bool& ok) {
    const QRegularExpressionMatch match =
        QRegularExpression(QStringLiteral("^(\\d{2,5})x(\\d{2,5})$")).match(text);
    ok = match.hasMatch();
    return ok ? QSize(match.captured(1).toInt(), match.captured(2).toInt()) : QSize();
}

//! `--show particles,mesh,bubbles,subgrid`: the layers listed, in any order.
airtrap::ScreenshotRequest::Layers parseLayers(const QString& text) {
    airtrap::ScreenshotRequest::Layers layers;
    for (const QString& name : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString layer = name.trimmed();
        if (layer == QLatin1String("particles"))
            layers.particles = true;
        else if (layer == QLatin1String("mesh"))
            layers.mesh = true;
        else if (layer == QLatin1String("bubbles"))
            layers.bubbles = true;
        else if (layer == QLatin1String("subgrid"))
            layers.subgrid = true;
        else
            refuse(QStringLiteral("--show %1: unknown layer \"%2\"; expected a comma-separated "
                                  "list of particles, mesh, bubbles, subgrid")
                       .arg(text, layer));
    }
    return layers;
}

airtrap::ViewportWidget::CameraView parseCamera(const QString& text) {
    using View = airtrap::ViewportWidget::CameraView;
    if (text == QLatin1String("front"))
        return View::Front;
    if (text == QLatin1String("side"))
        return View::Side;
    if (text == QLatin1String("top"))
        return View::Top;
    if (text == QLatin1String("persp"))
        return View::Perspective;
    refuse(QStringLiteral("--camera %1: expected front, side, top or persp").arg(text));
}

airtrap::SurfaceShading parseSurface(const QString& text) {
    if (const auto shading = airtrap::surfaceShadingNamed(text.toStdString()))
        return *shading;
    refuse(QStringLiteral("--surface %1: expected translucent, opaque or wireframe").arg(text));
}

float parseParticleSize(const QString& text) {
    bool ok = false;
    const float factor = text.toFloat(&ok);
    using Viewport = airtrap::ViewportWidget;
    if (!ok || factor < Viewport::kMinParticleSize || factor > Viewport::kMaxParticleSize)
        refuse(QStringLiteral("--particle-size %1: expected a factor from %2 to %3 of the default "
                              "radius (half the particle spacing)")
                   .arg(text)
                   .arg(double(Viewport::kMinParticleSize))
                   .arg(double(Viewport::kMaxParticleSize)));
    return factor;
}

//! Parses the command line; exits with a message on bad input (QCommandLineParser's way).
EditorOptions parseOptions(const QApplication& app) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Airtrap editor: SPH water with trapped air"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("scene"), QStringLiteral("Scene file to open."),
                                 QStringLiteral("[scene.json]"));
    const QCommandLineOption scene(QStringLiteral("scene"), QStringLiteral("Scene file to open."),
                                   QStringLiteral("file"));
    const QCommandLineOption cache(QStringLiteral("cache"),
                                   QStringLiteral("Cache folder to show (default: next to the "
                                                  "scene; alone: view the cache)."),
                                   QStringLiteral("dir"));
    const QCommandLineOption frame(QStringLiteral("frame"), QStringLiteral("Cached frame to show."),
                                   QStringLiteral("n"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                        QStringLiteral("Render to this PNG and exit."),
                                        QStringLiteral("out.png"));
    const QCommandLineOption size(QStringLiteral("size"),
                                  QStringLiteral("Screenshot size (default 1280x720)."),
                                  QStringLiteral("WxH"));
    const QCommandLineOption window(QStringLiteral("window"),
                                    QStringLiteral("Screenshot the whole editor window, not "
                                                   "just the viewport."));
    const QCommandLineOption show(
        QStringLiteral("show"),
        QStringLiteral("Screenshot layers, comma-separated: particles, mesh, bubbles, subgrid "
                       "(default: the mesh once post has made it, else the particles; and the "
                       "bubbles)."),
        QStringLiteral("layers"));
    const QCommandLineOption camera(
        QStringLiteral("camera"),
        QStringLiteral("Screenshot camera: front, side, top or persp (default persp)."),
        QStringLiteral("view"));
    const QCommandLineOption surface(
        QStringLiteral("surface"),
        QStringLiteral("Screenshot water surface shading: translucent, opaque or wireframe "
                       "(default translucent)."),
        QStringLiteral("shading"));
    const QCommandLineOption particleSize(
        QStringLiteral("particle-size"),
        QStringLiteral("Screenshot particle size, times the default radius of half the "
                       "particle spacing (0.1 to 3; default 1)."),
        QStringLiteral("factor"));
    const QCommandLineOption noSelection(
        QStringLiteral("no-selection"),
        QStringLiteral("Draw no selection (screenshots never draw one; accepted for scripts)."));
    const QCommandLineOption contactSheet(
        QStringLiteral("contact-sheet"),
        QStringLiteral("Tile the renders listed by --tiles, labelled, into this PNG and exit "
                       "(farm wedges, docs/FARM.md)."),
        QStringLiteral("out.png"));
    const QCommandLineOption tiles(
        QStringLiteral("tiles"),
        QStringLiteral("For --contact-sheet: a file with one render per line, its path, a tab "
                       "and its label."),
        QStringLiteral("list.tsv"));
    const QCommandLineOption columns(
        QStringLiteral("columns"),
        QStringLiteral("For --contact-sheet: tiles per row (default about the square root of "
                       "their number)."),
        QStringLiteral("n"));
    parser.addOptions({scene, cache, frame, screenshot, size, window, show, camera, surface,
                       particleSize, noSelection, contactSheet, tiles, columns});
    parser.process(app);
    EditorOptions options;
    options.contactSheetPath = parser.value(contactSheet);
    options.tilesPath = parser.value(tiles);
    if (parser.isSet(contactSheet) != parser.isSet(tiles))
        refuse(QStringLiteral("--contact-sheet and --tiles go together"));
    if (parser.isSet(columns)) {
        bool ok = false;
        options.sheetColumns = parser.value(columns).toInt(&ok);
        if (!ok || options.sheetColumns < 1 || options.sheetColumns > 100)
            refuse(QStringLiteral("--columns %1: expected a number from 1 to 100")
                       .arg(parser.value(columns)));
    }

    options.scenePath =
        parser.isSet(scene) ? parser.value(scene) : parser.positionalArguments().value(0);
    options.takeScreenshot = parser.isSet(screenshot);
    airtrap::ScreenshotRequest& request = options.screenshot;
    request.scenePath = options.scenePath;
    request.cacheDir = parser.value(cache);
    request.outputPath = parser.value(screenshot);
    request.wholeWindow = parser.isSet(window);
    if (parser.isSet(show))
        request.layers = parseLayers(parser.value(show));
    if (parser.isSet(camera))
        request.camera = parseCamera(parser.value(camera));
    if (parser.isSet(surface))
        request.surface = parseSurface(parser.value(surface));
    if (parser.isSet(particleSize))
        request.particleSize = parseParticleSize(parser.value(particleSize));
    if (parser.isSet(frame)) {
        bool ok = false;
        request.frame = parser.value(frame).toInt(&ok);
        if (!ok || request.frame < 1)
            refuse(
                QStringLiteral("--frame %1: expected a frame number ≥ 1").arg(parser.value(frame)));
    }
    if (parser.isSet(size)) {
        bool ok = false;
        request.size = parseSize(parser.value(size), ok);
        if (!ok)
            refuse(
                QStringLiteral("--size %1: expected WxH, e.g. 1280x720").arg(parser.value(size)));
    }
    return options;
}

int takeScreenshot(airtrap::MainWindow& window, const airtrap::ScreenshotRequest& request) {
    airtrap::ScreenshotJob job(window, request);
    int exitCode = 0;
    QObject::connect(&job, &airtrap::ScreenshotJob::done, [&](const QString& error) {
        if (!error.isEmpty()) {
            std::fprintf(stderr, "airtrap: screenshot failed: %s\n", qPrintable(error));
            exitCode = 1;
        }
        QApplication::exit(exitCode);
    });
    // Started from the event loop: a job that fails at once must find a loop to exit.
    QTimer::singleShot(0, &job, &airtrap::ScreenshotJob::start);
    return QApplication::exec() == 0 ? exitCode : 1;
}

//! --contact-sheet: no window, no OpenGL; the tiles at the size of --size (default 640x360).
int makeContactSheet(const EditorOptions& options) {
    QString error;
    const std::vector<airtrap::ContactSheet::Tile> tiles =
        airtrap::ContactSheet::readTiles(options.tilesPath, error);
    if (!error.isEmpty())
        refuse(error);
    const QSize tileSize =
        options.screenshot.size.isValid() ? options.screenshot.size : QSize(640, 360);
    error = airtrap::ContactSheet::save(
        airtrap::ContactSheet::compose(tiles, tileSize, options.sheetColumns),
        options.contactSheetPath);
    if (!error.isEmpty()) {
        std::fprintf(stderr, "airtrap: cannot write the contact sheet: %s\n", qPrintable(error));
        return 4;
    }
    std::printf("contact sheet of %zu render(s): %s\n", tiles.size(),
                qPrintable(options.contactSheetPath));
    return 0;
}

} // namespace

int main(int argc, char* argv[]) {
    // As in airtrap-cli: past a file-size limit a write fails with EFBIG, reported like a full
    // disk, instead of the kernel killing the editor mid-write.
    std::signal(SIGXFSZ, SIG_IGN);
    // Before QApplication: the default format decides how Qt sets up its shared OpenGL contexts,
    // and a core-profile viewport needs them to be core profile too.
    QSurfaceFormat::setDefaultFormat(airtrap::ViewportWidget::surfaceFormat());

    QApplication app(argc, argv);
    app.setWindowIcon(QIcon(":/icons/airtrap.png"));
    QApplication::setOrganizationName(QStringLiteral("Airtrap"));
    QApplication::setApplicationName(QStringLiteral("Airtrap"));
    QApplication::setApplicationVersion(QStringLiteral(AIRTRAP_VERSION));
    const EditorOptions options = parseOptions(app);
    // A screenshot neither reads nor writes the user's settings (view options, recent files).
    if (options.takeScreenshot || !options.contactSheetPath.isEmpty())
        airtrap::EditorSettings::useScratchStore();
    if (!options.contactSheetPath.isEmpty())
        return makeContactSheet(options);

    airtrap::MainWindow window;
    if (options.takeScreenshot)
        return takeScreenshot(window, options.screenshot);
    window.show();
    if (!options.scenePath.isEmpty())
        window.openScene(options.scenePath);
    else if (!options.screenshot.cacheDir.isEmpty())
        window.openCacheFolder(options.screenshot.cacheDir);
    return QApplication::exec();
}
