#include "window/EditorActions.h"

#include "viewport/SurfaceShading.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QKeySequence>
#include <QStyle>
#include <QWidget>

namespace airtrap {

namespace {

QIcon standardIcon(QStyle::StandardPixmap pixmap) {
    return QApplication::style()->standardIcon(pixmap);
}

QAction* checkable(QAction* action, bool checked) {
    action->setCheckable(true);
    action->setChecked(checked);
    return action;
}

} // namespace

EditorActions::EditorActions(QWidget* window) : QObject(window), window_(window) {
    makeFileActions();
    makeEditActions();
    makeSimulationActions();
    makeViewActions();
    makePlaybackActions();
    guide = make("guideAction", tr("Editor &Guide"), tr("How to use the editor (docs/EDITOR.md)"));
    guide->setShortcut(QKeySequence::HelpContents);
    shortcutSheet = make("shortcutSheetAction", tr("&Keyboard Shortcuts"),
                         tr("Every key the editor knows, and the mouse in the viewport"));
    shortcutSheet->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F1));
    about = make("aboutAction", tr("&About Airtrap"), tr("Version and the method behind it"));
    about->setMenuRole(QAction::AboutRole);
}

QAction* EditorActions::make(const char* objectName, const QString& text,
                             const QString& statusTip) {
    auto* action = new QAction(text, window_);
    action->setObjectName(QLatin1String(objectName));
    action->setStatusTip(statusTip);
    window_->addAction(action);
    return action;
}

void EditorActions::makeFileActions() {
    newScene = make("newSceneAction", tr("&New Scene"), tr("Start a new scene"));
    newScene->setShortcut(QKeySequence::New);
    newScene->setIcon(standardIcon(QStyle::SP_FileIcon));
    openScene = make("openSceneAction", tr("&Open Scene…"), tr("Open a scene file"));
    openScene->setShortcut(QKeySequence::Open);
    openScene->setIcon(standardIcon(QStyle::SP_DialogOpenButton));
    openCache = make("openCacheAction", tr("Open &Cache Folder…"),
                     tr("View a baked cache without its scene file"));
    openCache->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    saveScene = make("saveSceneAction", tr("&Save"), tr("Save the scene"));
    saveScene->setShortcut(QKeySequence::Save);
    saveScene->setIcon(standardIcon(QStyle::SP_DialogSaveButton));
    saveSceneAs = make("saveSceneAsAction", tr("Save &As…"), tr("Save the scene to a new file"));
    // Spelled out: QKeySequence::SaveAs is empty outside KDE and GNOME (the Keyboard Shortcuts
    // sheet showed it missing), and Ctrl+Shift+S is what users expect everywhere.
    saveSceneAs->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    quit = make("quitAction", tr("&Quit"), tr("Close the editor"));
    // Spelled out: QKeySequence::Quit is empty on some desktops, Ctrl+Q is what users expect.
    quit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));
    quit->setMenuRole(QAction::QuitRole);
}

void EditorActions::makeEditActions() {
    duplicate = make("duplicateAction", tr("&Duplicate"), tr("Copy the selected object"));
    duplicate->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    remove = make("removeAction", tr("&Remove"), tr("Remove the selected object"));
    remove->setShortcut(QKeySequence::Delete);
    // Text fields claim Delete for themselves (ShortcutOverride), so typing is unaffected.
    rename = make("renameAction", tr("Re&name"), tr("Rename the selected object"));
    rename->setShortcut(QKeySequence(Qt::Key_F2));
}

void EditorActions::makeSimulationActions() {
    bake = make("bakeAction", tr("&Bake"), tr("Simulate the scene from frame 1 into its cache"));
    bake->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    bake->setIcon(standardIcon(QStyle::SP_MediaPlay));
    pause = make("pauseAction", tr("&Pause"), tr("Hold the bake after the current step"));
    pause->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    pause->setIcon(standardIcon(QStyle::SP_MediaPause));
    resume = make("resumeAction", tr("&Resume"),
                  tr("Continue a paused bake, or a stopped one from its last frame"));
    resume->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    resume->setIcon(standardIcon(QStyle::SP_MediaSeekForward));
    stop = make("stopAction", tr("&Stop"), tr("Stop the bake after the current step"));
    stop->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Period));
    stop->setIcon(standardIcon(QStyle::SP_MediaStop));
    clearCache =
        make("clearCacheAction", tr("&Clear Cache…"), tr("Delete the baked frames of this scene"));
    post = make("postAction", tr("Make Render &Outputs"),
                tr("Build the water's free-surface mesh and volume of every cached frame, with "
                   "the Surface mesh settings (kept beside the cache)"));
    post->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    exportSequences = make("exportAction", tr("&Export…"),
                           tr("Write OBJ, VDB or PLY sequences of the cached frames for a "
                              "renderer"));
    exportSequences->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    cancelRenderOutputs = make("cancelRenderOutputsAction", tr("Cancel"),
                               tr("Stop making render outputs; finished frames are kept"));
}

void EditorActions::makeViewActions() {
    frameAll = make("frameAllAction", tr("&Frame All"), tr("Fit the whole scene in the view"));
    frameAll->setShortcut(QKeySequence(Qt::Key_F));
    makeCameraActions();
    showGrid = checkable(make("showGridAction", tr("&Grid"), tr("Show the ground grid")), true);
    showAxes = checkable(make("showAxesAction", tr("&Axes"), tr("Show the world axes")), true);
    showGizmos = checkable(make("showGizmosAction", tr("G&izmos"),
                                tr("Show the container, fluid blocks and obstacles")),
                           true);
    showWater = checkable(make("showWaterAction", tr("Show &Water"),
                               tr("Draw the water of a cached frame; hide it to see what it "
                                  "surrounds")),
                          true);
    showWater->setShortcut(QKeySequence(Qt::Key_W));
    showSurface = checkable(make("showSurfaceAction", tr("Show Water &Surface"),
                                 tr("Draw the free-surface mesh of a cached frame, once Make "
                                    "Render Outputs has built it")),
                            true);
    showSurface->setShortcut(QKeySequence(Qt::Key_S));
    particlesUnderSurface =
        checkable(make("particlesUnderSurfaceAction", tr("&Particles Under Surface"),
                       tr("Draw the particles of a frame whose surface mesh is made; off, the "
                          "mesh stands for the water")),
                  false);
    makeSurfaceShadingActions();
    bubblesThroughWater =
        checkable(make("bubblesThroughWaterAction", tr("&Bubbles Through Water"),
                       tr("Draw air bubbles in front of the water around them; bodies still "
                          "hide them")),
                  true);
    makeParticleSizeActions();
}

void EditorActions::makeCameraActions() {
    frameSelected = make("frameSelectedAction", tr("Frame &Selected"),
                         tr("Fit the selected object in the view"));
    frameSelected->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F));
    // The number row as Blender's keypad: 1 front, 3 side, 7 top, 5 orthographic; 0 the
    // three-quarter perspective view the editor starts with.
    viewFront = make("viewFrontAction", tr("&Front View"), tr("Look along −z at the scene"));
    viewFront->setShortcut(QKeySequence(Qt::Key_1));
    viewSide = make("viewSideAction", tr("Si&de View"), tr("Look along −x at the scene"));
    viewSide->setShortcut(QKeySequence(Qt::Key_3));
    viewTop = make("viewTopAction", tr("&Top View"), tr("Look down at the scene"));
    viewTop->setShortcut(QKeySequence(Qt::Key_7));
    viewPerspective = make("viewPerspectiveAction", tr("&Perspective View"),
                           tr("The three-quarter view in perspective the editor starts with"));
    viewPerspective->setShortcut(QKeySequence(Qt::Key_0));
    orthographic = checkable(make("orthographicAction", tr("&Orthographic"),
                                  tr("Parallel projection: sizes and lengths compare across "
                                     "the view, as in a technical drawing")),
                             false);
    orthographic->setShortcut(QKeySequence(Qt::Key_5));
}

void EditorActions::makeSurfaceShadingActions() {
    surfaceShading = new QActionGroup(this);
    surfaceShading->setExclusive(true);
    const auto shadingAction = [this](const char* objectName, const QString& text,
                                      const QString& tip, SurfaceShading shading) {
        QAction* action = checkable(make(objectName, text, tip), false);
        action->setData(QString::fromUtf8(surfaceShadingName(shading).data(),
                                          qsizetype(surfaceShadingName(shading).size())));
        surfaceShading->addAction(action);
        return action;
    };
    translucentSurface =
        shadingAction("translucentSurfaceAction", tr("&Translucent Surface"),
                      tr("See the particles, bubbles and bodies through the water surface"),
                      SurfaceShading::Translucent);
    opaqueSurface = shadingAction("opaqueSurfaceAction", tr("&Opaque Surface"),
                                  tr("Show the water surface's own shape, hiding what is under it"),
                                  SurfaceShading::Opaque);
    wireframeSurface =
        shadingAction("wireframeSurfaceAction", tr("Wire&frame Surface"),
                      tr("Draw the water surface's triangle edges: its resolution and where "
                         "it is open"),
                      SurfaceShading::Wireframe);
    translucentSurface->setChecked(true);
}

void EditorActions::makeParticleSizeActions() {
    largerParticles =
        make("largerParticlesAction", tr("&Larger Particles"), tr("Draw the particles larger"));
    largerParticles->setShortcut(QKeySequence(Qt::Key_BracketRight));
    smallerParticles = make("smallerParticlesAction", tr("S&maller Particles"),
                            tr("Draw the particles smaller, down to points"));
    smallerParticles->setShortcut(QKeySequence(Qt::Key_BracketLeft));
    defaultParticleSize =
        make("defaultParticleSizeAction", tr("&Default Particle Size"),
             tr("Draw the particles with half the particle spacing as their radius"));
}

void EditorActions::makePlaybackActions() {
    playPause = make("playPauseAction", tr("&Play / Pause"), tr("Play the cached frames"));
    playPause->setShortcut(QKeySequence(Qt::Key_Space));
    stepForward = make("stepForwardAction", tr("Step &Forward"), tr("Next frame"));
    stepForward->setShortcut(QKeySequence(Qt::Key_Right));
    stepBackward = make("stepBackwardAction", tr("Step &Backward"), tr("Previous frame"));
    stepBackward->setShortcut(QKeySequence(Qt::Key_Left));
    firstFrame = make("firstFrameAction", tr("F&irst Frame"), tr("Go to frame 1"));
    firstFrame->setShortcut(QKeySequence(Qt::Key_Home));
    lastFrame = make("lastFrameAction", tr("&Last Frame"), tr("Go to the last cached frame"));
    lastFrame->setShortcut(QKeySequence(Qt::Key_End));
    loop = checkable(make("loopAction", tr("L&oop"), tr("Start again after the last frame")), true);
}

} // namespace airtrap
