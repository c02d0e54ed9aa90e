#pragma once
// The editor's timeline: transport buttons, the frame ruler and a frame spin box. Playback runs
// over cached frames only: it skips frames that are not baked, and at the newest cached frame it
// loops, stops, or — while a bake is running — waits for the next. It runs at the scene's frame
// rate (frames that cannot be shown in time are skipped, as a player does) or shows every frame
// as fast as the viewport draws them; the rate it achieves is shown beside the ruler. Keyboard
// shortcuts belong to the main window, which calls the slots below.
#include <QElapsedTimer>
#include <QList>
#include <QWidget>
#include <deque>
#include <optional>
#include <set>

class QComboBox;
class QLabel;
class QSpinBox;
class QTimer;
class QToolButton;

namespace airtrap {

class FrameRuler;

class TimelineWidget : public QWidget {
    Q_OBJECT

public:
    explicit TimelineWidget(QWidget* parent = nullptr);

    //! The frame shown, within the frame range.
    int currentFrame() const { return current_; }
    //! The range's first frame.
    int firstFrame() const { return first_; }
    //! The range's last frame.
    int lastFrame() const { return last_; }
    //! Frames marked as cached, ascending.
    QList<int> cachedFrames() const;
    //! True while playback runs, including while it waits for a running bake's next frame.
    bool isPlaying() const;
    //! True when playback loops.
    bool loops() const { return loop_; }
    //! The scene's frame rate, frames per second.
    double fps() const { return fps_; }

    enum class PlaybackRate {
        SceneFps,   //!< real time: a frame every 1/fps s, late frames skipped
        EveryFrame, //!< the next frame once the viewport has shown the current one
    };
    Q_ENUM(PlaybackRate)
    PlaybackRate playbackRate() const { return rate_; }
    //! Frames shown per second over the last second of playback; 0 before two were shown.
    double achievedFps() const { return achievedFps_; }
    //! Frames marked as having render outputs, ascending.
    QList<int> renderOutputFrames() const { return outputs_; }

public Q_SLOTS:
    //! The scene's frames, `first` to `last` (a `last` below `first` is raised to it); the
    //! current frame is clamped into them.
    void setFrameRange(int first, int last);
    //! Replaces the cached frames (e.g. after opening a cache or discarding frames).
    void setCachedFrames(const QList<int>& frames);
    //! Marks one more frame as cached (a bake just finished it).
    void addCachedFrame(int frame);
    //! Replaces the frames marked as having render outputs (post results).
    void setRenderOutputFrames(const QList<int>& frames);
    //! The scene's frame rate; non-positive values are ignored.
    void setFps(double fps);
    void setPlaybackRate(airtrap::TimelineWidget::PlaybackRate rate);
    //! The viewport shows `frame` now: measures the achieved rate, and lets playback at
    //! EveryFrame go on.
    void frameDisplayed(int frame);
    //! While true, playback that reaches the newest cached frame waits for the next one instead
    //! of stopping. Connect it to the bake's state.
    void setBakeRunning(bool running);

    //! Goes to `frame`, clamped into the range; emits currentFrameChanged() when it moves.
    void setCurrentFrame(int frame);
    //! Plays from the current frame (from the first cached one when at the end).
    void play();
    //! Stops playback at the current frame.
    void pause();
    //! Pauses when playing, else plays (the play button; Space in the main window).
    void togglePlayback();
    //! At the newest cached frame, playback jumps back to the first cached one.
    void setLoop(bool loop);
    //! One frame on, cached or not (clamped to the range).
    void stepForward();
    //! One frame back (clamped to the range).
    void stepBackward();
    //! The range's first frame.
    void goToFirst();
    //! Goes to the newest cached frame, or to the range's last frame when none is cached.
    void goToLast();

Q_SIGNALS:
    //! The current frame moved (by the user, by playback or by a slot).
    void currentFrameChanged(int frame);
    //! Playback started or stopped.
    void playingChanged(bool playing);
    //! Looping was switched on or off (by the Loop button or setLoop()).
    void loopChanged(bool loop);

private:
    void createControls();
    QToolButton* makeButton(const char* objectName, const QString& toolTip);
    void advancePlayback();
    //! Playback moves to `frame` and, at EveryFrame, waits for the viewport to show it.
    void playTo(int frame);
    void createRateChoice();
    void applyTimerInterval();
    void showAchievedFps();
    void showLoop();
    //! The first cached frame after `frame` within the range.
    std::optional<int> cachedFrameAfter(int frame) const;
    std::optional<int> firstCachedFrame() const;
    std::optional<int> lastCachedFrame() const;
    void showCachedFrames();
    void showPlaying();

    int first_ = 1;
    int last_ = 1;
    int current_ = 1;
    double fps_ = 30.0;
    bool loop_ = false;
    bool bakeRunning_ = false;
    std::set<int> cached_;
    QList<int> outputs_;
    PlaybackRate rate_ = PlaybackRate::SceneFps;
    //! Playback at EveryFrame asked for a frame the viewport has not shown yet.
    bool awaitingDisplay_ = false;
    QElapsedTimer clock_;
    std::deque<qint64> shownAt_; //!< ms on clock_ of the frames shown in the last second
    double achievedFps_ = 0.0;

    FrameRuler* ruler_ = nullptr;
    QSpinBox* frameSpinBox_ = nullptr;
    QToolButton* playButton_ = nullptr;
    QToolButton* loopButton_ = nullptr;
    QComboBox* rateChoice_ = nullptr;
    QLabel* fpsLabel_ = nullptr;
    QTimer* playTimer_ = nullptr;
};

} // namespace airtrap
