#pragma once
// The editor's main window: the viewport in the centre; docks for the scene tree, the parameter
// panel, the timeline, the undo history and the log; menus, a toolbar and a status bar. It owns
// the document and wires the parts together — the parts do not know each other.
#include "document/SceneItem.h"
#include "window/CacheLocation.h"

#include <QMainWindow>
#include <QString>
#include <memory>

class QCloseEvent;
class QShowEvent;
class QDockWidget;
class QMenu;
class QAction;
class QDialog;

namespace airtrap {

class BakeSession;
class ElementMover;
class EditorActions;
class FrameLoader;
class LogPanel;
class ParameterPanel;
class RecentFiles;
class RenderOutputController;
class RenderSession;
class PostResultLoader;
class SceneDocument;
class SceneTreePanel;
class SimulationController;
class StatusBarFields;
class TimelineWidget;
class ViewportWidget;
struct FrameData;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    //! Stops a running bake (keeping its finished frames) before the window goes.
    ~MainWindow() override;

    SceneDocument& document() const { return *document_; }
    ViewportWidget* viewport() const { return viewport_; }
    SceneTreePanel* sceneTree() const { return sceneTree_; }
    TimelineWidget* timeline() const { return timeline_; }
    SimulationController* controller() const { return controller_; }
    RenderOutputController* renderController() const { return renderController_; }
    RenderSession* renderSession() const { return renderSession_; }
    FrameLoader* frameLoader() const { return loader_; }
    LogPanel* log() const { return log_; }
    StatusBarFields* statusFields() const { return statusFields_; }
    const EditorActions& actions() const { return *actions_; }
    QMenu* fileMenu() const { return fileMenu_; }
    QMenu* viewMenu() const { return viewMenu_; }
    QAction* openSceneAction() const;
    QAction* quitAction() const;

    //! Where the open scene bakes: "<scene folder>/<scene name>.cache" for a saved scene, a
    //! folder in the user's cache location for an unsaved one or one whose folder cannot be
    //! written, or the cache opened with openCacheFolder() or chosen before a bake.
    QString cacheDirectory() const;
    //! Where the open scene's cache is looked for: tests tell it which folders are writable.
    CacheLocation& cacheLocation() { return cacheLocation_; }

    //! When false, questions (unsaved changes, discarding frames) take their default answer
    //! without a dialog and errors go to the log only: for tests and the screenshot mode.
    void setInteractive(bool interactive);
    //! The message of the last error shown (dialog or log), for callers without a dialog.
    QString lastError() const { return lastError_; }

public Q_SLOTS:
    //! Opens a scene (after offering to save unsaved changes) and its cache when one exists.
    //! Returns false, with the reason in the log and the status bar, when the file is refused.
    bool openScene(const QString& path);
    //! Views the cache in `dir` without its scene file: the scene copy in its manifest is shown
    //! (and can be saved as a new scene file).
    bool openCacheFolder(const QString& dir);
    //! Shows and bakes the cache in `dir` for the open scene (instead of the folder next to its
    //! file), e.g. a cache baked with airtrap-cli.
    void useCacheFolder(const QString& dir);
    bool saveScene();
    bool saveSceneAs(const QString& path);
    void newScene();
    //! Moves the timeline to `frame`; frameShown() follows once it is in the viewport.
    void showFrame(int frame);

Q_SIGNALS:
    //! The viewport now draws cached frame `frame`, with its water surface when post made one.
    void frameShown(int frame);
    //! The list of cached frames was read anew (after opening a scene or cache, a refresh).
    void cachedFramesChanged();

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void createParts();
    void createDocks();
    void applyDefaultDockSizes();
    QDockWidget* addDock(QWidget* content, const QString& title, const char* objectName,
                         Qt::DockWidgetArea area);
    void createMenus();
    void createToolbar();
    void connectDocument();
    void connectSelection();
    void connectPlayback();
    void connectActions();
    void connectCameraActions();
    void restoreSettings();
    void saveSettings() const;

    //! Save / Discard / Cancel for unsaved changes; true when it is fine to go on.
    bool maybeSave();
    void chooseAndOpenScene();
    void chooseAndOpenCache();
    bool chooseAndSaveAs();
    void updateTitle();
    void showError(const QString& title, const QString& message);

    void onDocumentChanged();
    void onFrameLoaded(int frame, std::shared_ptr<const FrameData> frameData);
    void onTimelineFrameChanged(int frame);
    void pointLoaderAtCache();
    //! Where a fresh bake goes: the cache directory, or for a scene whose folder cannot be
    //! written the folder the user chooses (asked once); empty when they cancel.
    QString bakeDirectory();
    void selectSomethingToEdit();
    void showAbout();
    void showGuide();
    void showShortcuts();
    void showHelpDialog(QDialog* dialog);

    std::unique_ptr<SceneDocument> document_;
    std::unique_ptr<ElementMover> mover_;
    EditorActions* actions_ = nullptr;
    ViewportWidget* viewport_ = nullptr;
    SceneTreePanel* sceneTree_ = nullptr;
    ParameterPanel* parameterPanel_ = nullptr;
    TimelineWidget* timeline_ = nullptr;
    SimulationController* controller_ = nullptr;
    RenderOutputController* renderController_ = nullptr;
    RenderSession* renderSession_ = nullptr;
    PostResultLoader* postResultLoader_ = nullptr;
    FrameLoader* loader_ = nullptr;
    BakeSession* bakeSession_ = nullptr;
    LogPanel* log_ = nullptr;
    StatusBarFields* statusFields_ = nullptr;
    RecentFiles* recentFiles_ = nullptr;
    QMenu* fileMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    //! Set by openCacheFolder(): bake and view this folder instead of the one next to the file.
    QString openedCacheDir_;
    CacheLocation cacheLocation_;
    bool interactive_ = true;
    bool useDefaultDockSizes_ = false;
    QString lastError_;
};

} // namespace airtrap
