#pragma once
// The editor's side of baking: the Bake / Pause / Resume / Stop / Clear Cache actions, which
// frames are cached, and what happens to them when the scene is edited. It talks to the engine
// only through SimulationController (the bake thread) and FrameLoader (the loader thread).
#include "controller/BakeProgressMeter.h"
#include "controller/SimulationController.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <functional>
#include <set>

class QWidget;

namespace airtrap {

class EditorActions;
class FrameLoader;
class LogPanel;
class SceneDocument;
class SimulationController;
class StatusBarFields;
class TimelineWidget;
struct BakeProgress;

class BakeSession : public QObject {
    Q_OBJECT

public:
    //! `dialogParent` owns the session and parents its questions.
    BakeSession(SceneDocument& document, SimulationController& controller, TimelineWidget& timeline,
                FrameLoader& loader, LogPanel& log, StatusBarFields& statusFields,
                EditorActions& actions, QWidget* dialogParent);

    //! Where the open scene's cache is; asked anew at every use.
    void setCacheDirectoryProvider(std::function<QString()> provider);
    //! Where a fresh bake goes, asked before it starts; it may ask the user (a scene in a folder
    //! that cannot be written) and returns empty when they cancel. Unset: the cache directory.
    void setBakeDirectoryProvider(std::function<QString()> provider);
    //! False: questions take the answer that loses nothing, and errors go to the log only.
    void setInteractive(bool interactive) { interactive_ = interactive; }

    //! True when `frame` is in the cache the timeline shows.
    bool isCached(int frame) const { return cached_.count(frame) > 0; }
    //! The newest cached frame (0 when none).
    int lastCachedFrame() const { return cached_.empty() ? 0 : *cached_.rbegin(); }

    //! The scene now bakes into another folder (opened, new, saved elsewhere): show its frames.
    void cacheFolderChanged();
    //! Before the document is replaced: a running bake is stopped (after asking). False when the
    //! user chose to keep it running.
    bool releaseCache();

Q_SIGNALS:
    //! The list of cached frames changed (opened, refreshed, discarded).
    void cachedFramesChanged();
    //! A short line for the status bar.
    void statusMessage(const QString& text);

public Q_SLOTS:
    void bake();
    void resumeBake();
    void clearCache();
    //! The scene was edited: when frames after the current one exist (or a bake runs), ask once
    //! whether to discard them.
    void sceneEdited();

private:
    void connectActions();
    void connectController();
    void onFrameFinished(int frame);
    void onFramesListed(const QList<int>& frames);
    void onProgress(const BakeProgress& progress);
    void onStateChanged(SimulationController::State state);
    //! The meter starts for a bake that begins now.
    void startMeter();
    double secondsNow() const;
    void onFinished(bool completed, const QString& status);
    void onFailed(const QString& message);
    void updateActions();
    void askAboutStaleFrames();
    void discardFramesAfter(int frame);
    bool confirm(const QString& title, const QString& question, bool defaultAnswer);
    //! Runs the scene validator before a fresh bake. When bodies overlap the water, the scenery
    //! or each other at t = 0 it lists the overlaps and asks "Bake anyway" or "Cancel"; false
    //! when cancelled. Errors are left to the bake, which fails with them.
    bool acceptOverlaps();
    //! Remembers (in the editor's settings, across sessions) that the editor made `dir`, so that
    //! Clear Cache may remove it again.
    static void rememberMadeFolder(const QString& dir);
    static bool madeFolder(const QString& dir);
    static void forgetMadeFolder(const QString& dir);
    //! Clear Cache of a folder the editor made: the cache and, when nothing else is in it, the
    //! folder go.
    void removeMadeCache(const QString& dir);
    SceneDocument& document_;
    SimulationController& controller_;
    TimelineWidget& timeline_;
    FrameLoader& loader_;
    LogPanel& log_;
    StatusBarFields& statusFields_;
    EditorActions& actions_;
    QWidget* dialogParent_;
    std::function<QString()> cacheDirectory_;
    std::function<QString()> bakeDirectory_;
    std::set<int> cached_;
    BakeProgressMeter meter_;
    QElapsedTimer clock_;
    SimulationController::State lastState_ = SimulationController::State::Idle;
    bool interactive_ = true;
    //! A question about stale frames is queued; edits until it is shown ask nothing more.
    bool staleQuestionPending_ = false;
    //! The user chose to keep frames that no longer match the scene; not asked again until the
    //! next bake.
    bool staleFramesAccepted_ = false;
};

} // namespace airtrap
