#include "window/MainWindow.h"

#include "controller/BakeSession.h"
#include "controller/CacheReader.h"
#include "controller/FrameLoader.h"
#include "controller/PostResultLoader.h"
#include "controller/RenderOutputController.h"
#include "controller/SimulationController.h"
#include "core/Error.h"
#include "document/ElementMover.h"
#include "document/SceneDocument.h"
#include "panels/BodyAddMenu.h"
#include "panels/ParameterPanel.h"
#include "panels/SceneTreePanel.h"
#include "scene/SceneSchema.h"
#include "timeline/TimelineWidget.h"
#include "viewport/ViewportWidget.h"
#include "window/CacheFolderQuestion.h"
#include "window/CacheLocation.h"
#include "window/EditorActions.h"
#include "window/EditorSettings.h"
#include "window/GuideDialog.h"
#include "window/LogPanel.h"
#include "window/RecentFiles.h"
#include "window/RenderSession.h"
#include "window/ShortcutSheet.h"
#include "window/StatusBarFields.h"
#include "window/ViewPreferences.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QShowEvent>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>
#include <QUndoView>

namespace airtrap {

namespace {
constexpr auto kGeometryKey = "mainWindow/geometry";
constexpr auto kStateKey = "mainWindow/state";
constexpr auto kSceneFilter = "Airtrap scenes (*.json);;All files (*)";
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), document_(std::make_unique<SceneDocument>()),
      mover_(std::make_unique<ElementMover>(*document_)) {
    setObjectName(QStringLiteral("mainWindow"));
    setDockNestingEnabled(true);
    createParts();
    createDocks();
    createMenus();
    createToolbar();
    connectDocument();
    connectSelection();
    connectPlayback();
    connectActions();
    restoreSettings();
    onDocumentChanged();
    updateTitle();
    statusBar()->showMessage(tr("Ready"));
}

MainWindow::~MainWindow() {
    controller_->stop();
    controller_->waitForIdle(10000);
}

void MainWindow::createParts() {
    actions_ = new EditorActions(this);
    viewport_ = new ViewportWidget(this);
    viewport_->setObjectName(QStringLiteral("viewport"));
    setCentralWidget(viewport_);
    sceneTree_ = new SceneTreePanel(*document_, this);
    parameterPanel_ = new ParameterPanel(*document_, this);
    timeline_ = new TimelineWidget(this);
    timeline_->setObjectName(QStringLiteral("timeline"));
    log_ = new LogPanel(this);
    controller_ = new SimulationController(this);
    loader_ = new FrameLoader(this);
    statusFields_ = new StatusBarFields(statusBar());
    bakeSession_ = new BakeSession(*document_, *controller_, *timeline_, *loader_, *log_,
                                   *statusFields_, *actions_, this);
    bakeSession_->setCacheDirectoryProvider([this] { return cacheDirectory(); });
    bakeSession_->setBakeDirectoryProvider([this] { return bakeDirectory(); });
    renderController_ = new RenderOutputController(this);
    renderSession_ =
        new RenderSession(*document_, *renderController_, *log_, *actions_, *statusBar(), this);
    renderSession_->setCacheDirectoryProvider([this] { return cacheDirectory(); });
    renderSession_->setLastCachedFrameProvider([this] { return bakeSession_->lastCachedFrame(); });
    postResultLoader_ = new PostResultLoader(this);
    connect(postResultLoader_, &PostResultLoader::resultsLoaded, this,
            [this](int frame, const PostFrameResults& results) {
                if (frame != timeline_->currentFrame())
                    return;
                viewport_->setWaterSurface(results.surface);
                viewport_->setSubgridBubbles(results.subgridBubbles);
                Q_EMIT frameShown(frame);
            });
    // New meshes for the frame on screen: show them, and mark their frames on the timeline.
    connect(renderSession_, &RenderSession::outputsChanged, this, [this] {
        onTimelineFrameChanged(timeline_->currentFrame());
        loader_->refresh();
    });
    connect(this, &MainWindow::frameShown, timeline_, &TimelineWidget::frameDisplayed);
}

QDockWidget* MainWindow::addDock(QWidget* content, const QString& title, const char* objectName,
                                 Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    // saveState() finds docks by object name.
    dock->setObjectName(QLatin1String(objectName));
    dock->setWidget(content);
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::createDocks() {
    addDock(sceneTree_, tr("Scene"), "sceneDock", Qt::LeftDockWidgetArea);
    addDock(parameterPanel_, tr("Parameters"), "parametersDock", Qt::RightDockWidgetArea);
    auto* history = new QUndoView(document_->undoStack(), this);
    history->setObjectName(QStringLiteral("historyView"));
    history->setEmptyLabel(tr("<opened>"));
    QDockWidget* historyDock =
        addDock(history, tr("History"), "historyDock", Qt::LeftDockWidgetArea);
    tabifyDockWidget(findChild<QDockWidget*>(QStringLiteral("sceneDock")), historyDock);
    findChild<QDockWidget*>(QStringLiteral("sceneDock"))->raise();
    addDock(timeline_, tr("Timeline"), "timelineDock", Qt::BottomDockWidgetArea);
    QDockWidget* logDock = addDock(log_, tr("Log"), "logDock", Qt::BottomDockWidgetArea);
    splitDockWidget(findChild<QDockWidget*>(QStringLiteral("timelineDock")), logDock, Qt::Vertical);
}

void MainWindow::applyDefaultDockSizes() {
    // Sizes only take once the window has its own: called on the first show.
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("timelineDock")),
                 findChild<QDockWidget*>(QStringLiteral("logDock"))},
                {80, 110}, Qt::Vertical);
    resizeDocks({findChild<QDockWidget*>(QStringLiteral("sceneDock")),
                 findChild<QDockWidget*>(QStringLiteral("parametersDock"))},
                {250, 460}, Qt::Horizontal);
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (useDefaultDockSizes_) {
        useDefaultDockSizes_ = false;
        applyDefaultDockSizes();
    }
}

void MainWindow::createMenus() {
    fileMenu_ = menuBar()->addMenu(tr("&File"));
    fileMenu_->setObjectName(QStringLiteral("fileMenu"));
    fileMenu_->addAction(actions_->newScene);
    fileMenu_->addAction(actions_->openScene);
    QMenu* recent = fileMenu_->addMenu(tr("Open &Recent"));
    recent->setObjectName(QStringLiteral("recentMenu"));
    recentFiles_ = new RecentFiles(recent, this);
    fileMenu_->addAction(actions_->openCache);
    fileMenu_->addSeparator();
    fileMenu_->addAction(actions_->saveScene);
    fileMenu_->addAction(actions_->saveSceneAs);
    fileMenu_->addSeparator();
    fileMenu_->addAction(actions_->exportSequences);
    fileMenu_->addSeparator();
    fileMenu_->addAction(actions_->quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setIcon(style()->standardIcon(QStyle::SP_ArrowBack));
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    // Ctrl+Shift+Z everywhere (QKeySequence::Redo is Ctrl+Y alone on some desktops), and Ctrl+Y.
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setIcon(style()->standardIcon(QStyle::SP_ArrowForward));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addMenu(sceneTree_->addMenu());
    edit->addAction(actions_->duplicate);
    edit->addAction(actions_->rename);
    edit->addAction(actions_->remove);

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    simulation->addActions({actions_->bake, actions_->pause, actions_->resume, actions_->stop});
    simulation->addSeparator();
    simulation->addAction(actions_->clearCache);
    simulation->addSeparator();
    simulation->addAction(actions_->post);

    QMenu* playback = menuBar()->addMenu(tr("&Playback"));
    playback->addActions({actions_->playPause, actions_->stepBackward, actions_->stepForward,
                          actions_->firstFrame, actions_->lastFrame, actions_->loop});

    viewMenu_ = menuBar()->addMenu(tr("&View"));
    viewMenu_->addActions({actions_->frameAll, actions_->frameSelected, actions_->showGrid,
                           actions_->showAxes, actions_->showGizmos});
    QMenu* camera = viewMenu_->addMenu(tr("&Camera"));
    camera->setObjectName(QStringLiteral("cameraMenu"));
    camera->addActions(
        {actions_->viewFront, actions_->viewSide, actions_->viewTop, actions_->viewPerspective});
    camera->addSeparator();
    camera->addAction(actions_->orthographic);
    viewMenu_->addSeparator();
    viewMenu_->addActions({actions_->showWater, actions_->showSurface,
                           actions_->particlesUnderSurface, actions_->bubblesThroughWater});
    viewMenu_->addSeparator();
    viewMenu_->addActions(actions_->surfaceShading->actions());
    viewMenu_->addSeparator();
    viewMenu_->addActions(
        {actions_->largerParticles, actions_->smallerParticles, actions_->defaultParticleSize});
    viewMenu_->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        viewMenu_->addAction(dock->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->setObjectName(QStringLiteral("helpMenu"));
    help->addActions({actions_->guide, actions_->shortcutSheet});
    help->addSeparator();
    help->addAction(actions_->about);
}

void MainWindow::createToolbar() {
    QToolBar* bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolbar"));
    bar->addActions({actions_->newScene, actions_->openScene, actions_->saveScene});
    bar->addSeparator();
    bar->addAction(findChild<QAction*>(QStringLiteral("undoAction")));
    bar->addAction(findChild<QAction*>(QStringLiteral("redoAction")));
    bar->addSeparator();
    bar->addActions({actions_->bake, actions_->pause, actions_->resume, actions_->stop});
    bar->addSeparator();
    bar->addAction(actions_->frameAll);
}

QAction* MainWindow::openSceneAction() const {
    return actions_->openScene;
}

QAction* MainWindow::quitAction() const {
    return actions_->quit;
}

// --- Wiring -------------------------------------------------------------------------------------

void MainWindow::connectDocument() {
    connect(document_.get(), &SceneDocument::changed, this, [this] {
        onDocumentChanged();
        bakeSession_->sceneEdited();
    });
    connect(document_.get(), &SceneDocument::reset, this, &MainWindow::onDocumentChanged);
    connect(bakeSession_, &BakeSession::statusMessage, this,
            [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(renderSession_, &RenderSession::statusMessage, this,
            [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(bakeSession_, &BakeSession::cachedFramesChanged, this, [this] {
        renderSession_->updateActions();
        onTimelineFrameChanged(timeline_->currentFrame());
        Q_EMIT cachedFramesChanged();
    });
    connect(document_.get(), &SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(document_.get(), &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(sceneTree_->bodyMenu(), &BodyAddMenu::meshRefused, this,
            [this](const QString& reason) { showError(tr("Cannot use this mesh"), reason); });
    connect(sceneTree_, &SceneTreePanel::editRefused, this, [this](const QString& reason) {
        statusBar()->showMessage(reason, 8000);
        log_->warning(reason);
    });
}

void MainWindow::connectSelection() {
    connect(sceneTree_, &SceneTreePanel::itemSelected, this, [this](const SceneItem& item) {
        parameterPanel_->showItem(item);
        viewport_->setSelection(item);
    });
    connect(viewport_, &ViewportWidget::itemPicked, this, [this](const SceneItem& item) {
        sceneTree_->selectItem(item);
        parameterPanel_->showItem(item);
        viewport_->setSelection(item);
    });
    connect(viewport_, &ViewportWidget::moveStarted, this,
            [this](const SceneItem& item) { mover_->begin(item); });
    connect(viewport_, &ViewportWidget::moveDragged, this,
            [this](const SceneItem&, int axis, double offset) {
                // A position out of range stops the object at the last one allowed.
                const QString refusal = mover_->moveTo(axis, offset);
                if (!refusal.isEmpty())
                    statusBar()->showMessage(refusal, 5000);
            });
    connect(viewport_, &ViewportWidget::moveFinished, this, [this] { mover_->end(); });
}

void MainWindow::connectPlayback() {
    connect(timeline_, &TimelineWidget::currentFrameChanged, this,
            &MainWindow::onTimelineFrameChanged);
    connect(loader_, &FrameLoader::frameLoaded, this, &MainWindow::onFrameLoaded);
    connect(loader_, &FrameLoader::renderOutputsListed, timeline_,
            &TimelineWidget::setRenderOutputFrames);
    connect(loader_, &FrameLoader::loadFailed, this, [this](int, const QString& message) {
        log_->error(message);
        statusBar()->showMessage(message, 10000);
    });
}

void MainWindow::connectCameraActions() {
    connect(actions_->frameSelected, &QAction::triggered, viewport_,
            &ViewportWidget::frameSelected);
    const auto view = [this](QAction* action, ViewportWidget::CameraView camera) {
        connect(action, &QAction::triggered, viewport_,
                [this, camera] { viewport_->setCameraView(camera); });
    };
    view(actions_->viewFront, ViewportWidget::CameraView::Front);
    view(actions_->viewSide, ViewportWidget::CameraView::Side);
    view(actions_->viewTop, ViewportWidget::CameraView::Top);
    view(actions_->viewPerspective, ViewportWidget::CameraView::Perspective);
    connect(actions_->orthographic, &QAction::toggled, viewport_, &ViewportWidget::setOrthographic);
    // The perspective preset leaves orthographic projection: the menu follows the viewport.
    connect(viewport_, &ViewportWidget::orthographicChanged, actions_->orthographic,
            &QAction::setChecked);
}

void MainWindow::connectActions() {
    connect(actions_->newScene, &QAction::triggered, this, &MainWindow::newScene);
    connect(actions_->openScene, &QAction::triggered, this, &MainWindow::chooseAndOpenScene);
    connect(actions_->openCache, &QAction::triggered, this, &MainWindow::chooseAndOpenCache);
    connect(actions_->saveScene, &QAction::triggered, this, &MainWindow::saveScene);
    connect(actions_->saveSceneAs, &QAction::triggered, this, &MainWindow::chooseAndSaveAs);
    connect(actions_->quit, &QAction::triggered, this, &MainWindow::close);
    connect(recentFiles_, &RecentFiles::fileChosen, this, &MainWindow::openScene);
    connect(actions_->duplicate, &QAction::triggered, sceneTree_,
            &SceneTreePanel::duplicateSelected);
    connect(actions_->remove, &QAction::triggered, sceneTree_, &SceneTreePanel::removeSelected);
    connect(actions_->rename, &QAction::triggered, sceneTree_, &SceneTreePanel::renameSelected);
    connect(actions_->frameAll, &QAction::triggered, viewport_, &ViewportWidget::frameAll);
    connectCameraActions();
    connect(actions_->showGrid, &QAction::toggled, viewport_, &ViewportWidget::setShowGrid);
    connect(actions_->showAxes, &QAction::toggled, viewport_, &ViewportWidget::setShowAxes);
    connect(actions_->showGizmos, &QAction::toggled, viewport_, &ViewportWidget::setShowGizmos);
    new ViewPreferences(*actions_, *viewport_, this);
    connect(actions_->playPause, &QAction::triggered, this,
            [this] { timeline_->isPlaying() ? timeline_->pause() : timeline_->play(); });
    connect(actions_->stepForward, &QAction::triggered, timeline_, &TimelineWidget::stepForward);
    connect(actions_->stepBackward, &QAction::triggered, timeline_, &TimelineWidget::stepBackward);
    connect(actions_->firstFrame, &QAction::triggered, timeline_, &TimelineWidget::goToFirst);
    connect(actions_->lastFrame, &QAction::triggered, timeline_, &TimelineWidget::goToLast);
    connect(actions_->loop, &QAction::toggled, timeline_, &TimelineWidget::setLoop);
    // The Loop button and Playback ▸ Loop are one switch.
    connect(timeline_, &TimelineWidget::loopChanged, actions_->loop, &QAction::setChecked);
    timeline_->setLoop(actions_->loop->isChecked());
    connect(actions_->about, &QAction::triggered, this, &MainWindow::showAbout);
    connect(actions_->guide, &QAction::triggered, this, &MainWindow::showGuide);
    connect(actions_->shortcutSheet, &QAction::triggered, this, &MainWindow::showShortcuts);
}

// --- Document -----------------------------------------------------------------------------------

void MainWindow::onDocumentChanged() {
    viewport_->setScene(document_->scene());
    timeline_->setFrameRange(1, document_->scene().frames.endFrame);
    timeline_->setFps(document_->scene().frames.fps);
}

void MainWindow::setInteractive(bool interactive) {
    interactive_ = interactive;
    bakeSession_->setInteractive(interactive);
}

void MainWindow::updateTitle() {
    setWindowFilePath(document_->filePath());
    setWindowTitle(QStringLiteral("%1[*] — Airtrap").arg(document_->displayName()));
    setWindowModified(document_->isModified());
}

QString MainWindow::cacheDirectory() const {
    if (!openedCacheDir_.isEmpty())
        return openedCacheDir_;
    return cacheLocation_.forScene(document_->filePath());
}

QString MainWindow::bakeDirectory() {
    const QString scenePath = document_->filePath();
    const QString dir = cacheDirectory();
    // Asked once per scene: when its own folder cannot be written and no folder of its own in
    // the user's cache exists yet (a later session finds and keeps that one).
    if (!openedCacheDir_.isEmpty() || scenePath.isEmpty() ||
        cacheLocation_.canBakeBeside(scenePath) || QFileInfo::exists(dir))
        return dir;
    const QString chosen = interactive_ ? CacheFolderQuestion::ask(this, scenePath, dir) : dir;
    if (chosen.isEmpty()) {
        log_->info(tr("Bake cancelled: no folder chosen for the frames"));
        return {};
    }
    log_->info(tr("%1 is in a folder that cannot be written; its frames go to %2")
                   .arg(document_->displayName(), chosen));
    if (chosen != dir)
        useCacheFolder(chosen);
    return chosen;
}

void MainWindow::selectSomethingToEdit() {
    // The first object of the scene (usually its water) is what one edits first; an empty scene
    // shows its own settings.
    for (const SchemaSection& section : SceneSchema::sections())
        if (section.isArray && section.elementCount(document_->scene()) > 0) {
            sceneTree_->selectItem(SceneItem::elementItem(section.key, 0));
            return;
        }
    sceneTree_->selectItem(SceneItem::sectionItem(""));
}

void MainWindow::pointLoaderAtCache() {
    selectSomethingToEdit();
    viewport_->setFrame(nullptr);
    bakeSession_->cacheFolderChanged();
    viewport_->frameAll();
}

bool MainWindow::maybeSave() {
    if (!document_->isModified() || !interactive_)
        return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"),
        tr("“%1” has unsaved changes. Save them?").arg(document_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return saveScene();
    return answer == QMessageBox::Discard;
}

void MainWindow::newScene() {
    if (!maybeSave() || !bakeSession_->releaseCache())
        return;
    openedCacheDir_.clear();
    document_->newScene();
    pointLoaderAtCache();
    statusBar()->showMessage(tr("New scene"), 4000);
}

bool MainWindow::openScene(const QString& path) {
    if (!maybeSave() || !bakeSession_->releaseCache())
        return false;
    try {
        document_->open(path);
    } catch (const Error& error) {
        showError(tr("Cannot open scene"), QString::fromUtf8(error.what()));
        if (!QFileInfo::exists(path))
            recentFiles_->remove(path);
        return false;
    }
    openedCacheDir_.clear();
    recentFiles_->add(path);
    pointLoaderAtCache();
    log_->info(tr("Opened %1").arg(document_->filePath()));
    statusBar()->showMessage(tr("Opened %1").arg(document_->displayName()), 4000);
    return true;
}

bool MainWindow::openCacheFolder(const QString& dir) {
    if (!maybeSave() || !bakeSession_->releaseCache())
        return false;
    try {
        document_->adoptScene(CacheReader::sceneOf(dir.toStdString()));
    } catch (const Error& error) {
        showError(tr("Cannot open cache"), QString::fromUtf8(error.what()));
        return false;
    }
    openedCacheDir_ = QFileInfo(dir).absoluteFilePath();
    pointLoaderAtCache();
    log_->info(tr("Viewing cache %1").arg(openedCacheDir_));
    return true;
}

void MainWindow::useCacheFolder(const QString& dir) {
    openedCacheDir_ = QFileInfo(dir).absoluteFilePath();
    pointLoaderAtCache();
}

bool MainWindow::saveScene() {
    if (document_->filePath().isEmpty())
        return chooseAndSaveAs();
    return saveSceneAs(document_->filePath());
}

bool MainWindow::saveSceneAs(const QString& path) {
    try {
        document_->save(path);
    } catch (const Error& error) {
        showError(tr("Cannot save scene"), QString::fromUtf8(error.what()));
        return false;
    }
    recentFiles_->add(path);
    statusBar()->showMessage(tr("Saved %1").arg(document_->filePath()), 4000);
    return true;
}

void MainWindow::chooseAndOpenScene() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Scene"), QString(), tr(kSceneFilter));
    if (!path.isEmpty())
        openScene(path);
}

void MainWindow::chooseAndOpenCache() {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open Cache Folder"));
    if (!dir.isEmpty())
        openCacheFolder(dir);
}

bool MainWindow::chooseAndSaveAs() {
    QString path = QFileDialog::getSaveFileName(this, tr("Save Scene As"), document_->filePath(),
                                                tr(kSceneFilter));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    return saveSceneAs(path);
}

void MainWindow::showError(const QString& title, const QString& message) {
    lastError_ = message;
    log_->error(message);
    statusBar()->showMessage(message.section(QLatin1Char('\n'), 0, 0), 10000);
    if (interactive_)
        QMessageBox::critical(this, title, message);
}

// --- Playback -----------------------------------------------------------------------------------

void MainWindow::showFrame(int frame) {
    timeline_->setCurrentFrame(frame);
    onTimelineFrameChanged(timeline_->currentFrame());
}

void MainWindow::onTimelineFrameChanged(int frame) {
    if (bakeSession_->isCached(frame)) {
        viewport_->setNotice(QString());
        loader_->request(frame);
        return;
    }
    // The scene's first frame with nothing baked is plain editing; any other frame says why the
    // viewport shows the setup instead of water in motion.
    const bool editing = frame == timeline_->firstFrame() && bakeSession_->lastCachedFrame() == 0;
    viewport_->setNotice(editing ? QString() : tr("Frame %1 is not baked yet").arg(frame));
    viewport_->setFrame(nullptr);
    viewport_->setWaterSurface(nullptr);
    viewport_->setSubgridBubbles({});
    statusFields_->showFrameNumber(frame, document_->scene().frames.fps);
}

void MainWindow::onFrameLoaded(int frame, std::shared_ptr<const FrameData> frameData) {
    // Scrubbing asks for many frames; only the one the timeline still points at is shown.
    if (frame != timeline_->currentFrame())
        return;
    statusFields_->showFrame(frame, *frameData);
    viewport_->setFrame(std::move(frameData));
    // frameShown() follows once the frame's post results (or their absence) are known too.
    postResultLoader_->request(cacheDirectory(), frame);
}

// --- Window -------------------------------------------------------------------------------------

void MainWindow::showGuide() {
    showHelpDialog(new GuideDialog(this));
}

void MainWindow::showShortcuts() {
    showHelpDialog(new ShortcutSheet(this));
}

void MainWindow::showHelpDialog(QDialog* dialog) {
    // Beside the window rather than in front of it: one reads the guide while using the editor.
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setModal(false);
    dialog->show();
    dialog->raise();
}

void MainWindow::showAbout() {
    QMessageBox::about(this, tr("About Airtrap"),
                       tr("<h3>Airtrap %1</h3>"
                          "<p>SPH water with trapped air bubbles, after Oh &amp; Jeong, "
                          "“Single-Phase Trapped Air Simulation in Water Flow” (WSCG 2014).</p>")
                           .arg(QStringLiteral(AIRTRAP_VERSION)));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave() || !bakeSession_->releaseCache()) {
        event->ignore();
        return;
    }
    saveSettings();
    QMainWindow::closeEvent(event);
}

void MainWindow::restoreSettings() {
    const QSettings& settings = EditorSettings::store();
    const QByteArray geometry = settings.value(kGeometryKey).toByteArray();
    if (geometry.isEmpty() || !restoreGeometry(geometry))
        resize(1440, 900);
    // First run: no saved layout, so the docks get proportions chosen for the editor.
    useDefaultDockSizes_ = !restoreState(settings.value(kStateKey).toByteArray());
}

void MainWindow::saveSettings() const {
    QSettings& settings = EditorSettings::store();
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    settings.sync();
}

} // namespace airtrap
