#pragma once
// The editor's side of the render outputs (docs/ARCHITECTURE.md "Data flow": FrameCache → Post →
// Exporters): the Make Render Outputs and Export… actions, a progress bar with a Cancel button in
// the status bar while they run, and their outcome in the log. The render settings are the
// document's (an artist tunes the Surface mesh section and runs Post again without re-baking). It
// talks to the engine only through RenderOutputController.
#include "controller/RenderJob.h"

#include <QObject>
#include <QString>
#include <functional>

class QProgressBar;
class QStatusBar;
class QToolButton;
class QWidget;

namespace airtrap {

class EditorActions;
class LogPanel;
class RenderOutputController;
class SceneDocument;

class RenderSession : public QObject {
    Q_OBJECT

public:
    RenderSession(SceneDocument& document, RenderOutputController& controller, LogPanel& log,
                  EditorActions& actions, QStatusBar& statusBar, QWidget* dialogParent);

    //! Where the open scene's cache is; asked at every run.
    void setCacheDirectoryProvider(std::function<QString()> provider);
    //! The newest cached frame (0: none), for the actions and the dialog's range.
    void setLastCachedFrameProvider(std::function<int()> provider);

    QProgressBar* progressBar() const { return progressBar_; }

Q_SIGNALS:
    //! A short line for the status bar.
    void statusMessage(const QString& text);
    //! A run finished or stopped: the stored meshes of some frames may have changed.
    void outputsChanged();

public Q_SLOTS:
    //! Runs the post stage on every cached frame.
    void post();
    //! Asks what to export (ExportDialog), then runs it.
    void exportSequences();
    //! Runs `request` (cache and render settings filled in here); the dialog's path and tests'.
    void run(RenderRequest request);
    //! Enables the actions for the cache and the controller's state.
    void updateActions();

private:
    void onProgress(const QString& stage, double percent);
    void onFinished(bool completed, const QString& summary);
    void onFailed(const QString& message);

    SceneDocument& document_;
    RenderOutputController& controller_;
    LogPanel& log_;
    EditorActions& actions_;
    QWidget* dialogParent_;
    QProgressBar* progressBar_;
    QToolButton* cancelButton_;
    std::function<QString()> cacheDirectory_;
    std::function<int()> lastCachedFrame_ = [] { return 0; };
};

} // namespace airtrap
