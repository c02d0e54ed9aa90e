#include "timeline/TimelineWidget.h"

#include "timeline/FrameRuler.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

//! At EveryFrame, a frame the viewport never reports shown (a failed load) holds playback this
//! long at most.
constexpr int kDisplayWaitMs = 500;
//! The achieved rate is measured over the frames shown in this last stretch of time.
constexpr qint64 kRateWindowMs = 1000;

} // namespace

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent) {
    playTimer_ = new QTimer(this);
    playTimer_->setTimerType(Qt::PreciseTimer);
    connect(playTimer_, &QTimer::timeout, this, &TimelineWidget::advancePlayback);
    clock_.start();
    createControls();
    setFps(fps_);
}

QToolButton* TimelineWidget::makeButton(const char* objectName, const QString& toolTip) {
    auto* button = new QToolButton(this);
    button->setObjectName(QString::fromLatin1(objectName));
    button->setToolTip(toolTip);
    button->setAutoRaise(true);
    // Space and the arrow keys are the main window's shortcuts; a focused button would take them.
    button->setFocusPolicy(Qt::NoFocus);
    return button;
}

void TimelineWidget::createControls() {
    QToolButton* first = makeButton("firstButton", tr("First frame (Home)"));
    first->setIcon(style()->standardIcon(QStyle::SP_MediaSkipBackward));
    connect(first, &QToolButton::clicked, this, &TimelineWidget::goToFirst);
    QToolButton* back = makeButton("stepBackButton", tr("Previous frame (Left)"));
    back->setIcon(style()->standardIcon(QStyle::SP_MediaSeekBackward));
    connect(back, &QToolButton::clicked, this, &TimelineWidget::stepBackward);
    playButton_ = makeButton("playButton", tr("Play or pause (Space)"));
    connect(playButton_, &QToolButton::clicked, this, &TimelineWidget::togglePlayback);
    QToolButton* forward = makeButton("stepForwardButton", tr("Next frame (Right)"));
    forward->setIcon(style()->standardIcon(QStyle::SP_MediaSeekForward));
    connect(forward, &QToolButton::clicked, this, &TimelineWidget::stepForward);
    QToolButton* last = makeButton("lastButton", tr("Newest cached frame (End)"));
    last->setIcon(style()->standardIcon(QStyle::SP_MediaSkipForward));
    connect(last, &QToolButton::clicked, this, &TimelineWidget::goToLast);
    loopButton_ = makeButton("loopButton", QString());
    loopButton_->setText(tr("Loop"));
    loopButton_->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
    loopButton_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    loopButton_->setCheckable(true);
    // Raised, and filled with the highlight colour while on: a flat checked tool button looks the
    // same as an unchecked one in several styles.
    loopButton_->setAutoRaise(false);
    loopButton_->setStyleSheet(QStringLiteral(
        "QToolButton:checked { background-color: palette(highlight); "
        "color: palette(highlighted-text); border: 1px solid palette(dark); border-radius: 3px; "
        "padding: 2px 4px; }"));
    connect(loopButton_, &QToolButton::toggled, this, &TimelineWidget::setLoop);
    showLoop();
    createRateChoice();

    ruler_ = new FrameRuler(this);
    ruler_->setObjectName(QStringLiteral("frameRuler"));
    connect(ruler_, &FrameRuler::frameScrubbed, this, &TimelineWidget::setCurrentFrame);

    frameSpinBox_ = new QSpinBox(this);
    frameSpinBox_->setObjectName(QStringLiteral("frameSpinBox"));
    frameSpinBox_->setToolTip(tr("Current frame"));
    frameSpinBox_->setKeyboardTracking(false);
    frameSpinBox_->setRange(first_, last_);
    connect(frameSpinBox_, &QSpinBox::valueChanged, this, &TimelineWidget::setCurrentFrame);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    for (QToolButton* button : {first, back, playButton_, forward, last, loopButton_})
        layout->addWidget(button);
    layout->addWidget(rateChoice_);
    layout->addWidget(ruler_, 1);
    layout->addWidget(fpsLabel_);
    layout->addWidget(frameSpinBox_);
    showPlaying();
}

void TimelineWidget::createRateChoice() {
    rateChoice_ = new QComboBox(this);
    rateChoice_->setObjectName(QStringLiteral("playbackRateChoice"));
    rateChoice_->setToolTip(tr("Play in real time at the scene's frame rate (skipping frames that "
                               "cannot be shown in time), or show every frame as fast as the "
                               "viewport draws them"));
    rateChoice_->setFocusPolicy(Qt::NoFocus);
    rateChoice_->addItem(QString(), QVariant::fromValue(PlaybackRate::SceneFps));
    rateChoice_->addItem(tr("Every frame"), QVariant::fromValue(PlaybackRate::EveryFrame));
    connect(rateChoice_, &QComboBox::activated, this, [this](int index) {
        setPlaybackRate(rateChoice_->itemData(index).value<PlaybackRate>());
    });
    fpsLabel_ = new QLabel(this);
    fpsLabel_->setObjectName(QStringLiteral("achievedFpsLabel"));
    fpsLabel_->setToolTip(tr("Frames shown per second during the last second of playback"));
    fpsLabel_->setMinimumWidth(fpsLabel_->fontMetrics().horizontalAdvance(tr("000.0 fps")));
    fpsLabel_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
}

QList<int> TimelineWidget::cachedFrames() const {
    return QList<int>(cached_.begin(), cached_.end());
}

bool TimelineWidget::isPlaying() const {
    return playTimer_->isActive();
}

void TimelineWidget::setFrameRange(int first, int last) {
    first_ = first;
    last_ = std::max(first, last);
    ruler_->setFrameRange(first_, last_);
    {
        const QSignalBlocker blocker(frameSpinBox_);
        frameSpinBox_->setRange(first_, last_);
    }
    setCurrentFrame(current_);
}

void TimelineWidget::setCachedFrames(const QList<int>& frames) {
    cached_ = std::set<int>(frames.begin(), frames.end());
    showCachedFrames();
}

void TimelineWidget::addCachedFrame(int frame) {
    if (cached_.insert(frame).second)
        showCachedFrames();
}

void TimelineWidget::setRenderOutputFrames(const QList<int>& frames) {
    outputs_ = frames;
    ruler_->setOutputFrames(std::vector<int>(frames.begin(), frames.end()));
}

void TimelineWidget::setFps(double fps) {
    if (!(fps > 0.0))
        return;
    fps_ = fps;
    rateChoice_->setItemText(0, tr("%1 fps").arg(fps));
    applyTimerInterval();
}

void TimelineWidget::setPlaybackRate(PlaybackRate rate) {
    rate_ = rate;
    rateChoice_->setCurrentIndex(rate == PlaybackRate::SceneFps ? 0 : 1);
    awaitingDisplay_ = false;
    applyTimerInterval();
}

void TimelineWidget::applyTimerInterval() {
    // At EveryFrame the viewport's report drives playback; the timer only ends a wait for a
    // frame that never shows.
    playTimer_->setInterval(rate_ == PlaybackRate::EveryFrame
                                ? kDisplayWaitMs
                                : std::max(1, int(std::lround(1000.0 / fps_))));
}

void TimelineWidget::frameDisplayed(int frame) {
    if (!isPlaying() || frame != current_)
        return;
    const qint64 now = clock_.elapsed();
    shownAt_.push_back(now);
    while (now - shownAt_.front() > kRateWindowMs)
        shownAt_.pop_front();
    if (shownAt_.size() >= 2)
        achievedFps_ = double(shownAt_.size() - 1) * 1000.0 /
                       double(std::max<qint64>(1, shownAt_.back() - shownAt_.front()));
    showAchievedFps();
    if (rate_ == PlaybackRate::EveryFrame && awaitingDisplay_) {
        awaitingDisplay_ = false;
        // After this event: the viewport paints the frame before the next is asked for.
        QTimer::singleShot(0, this, [this] {
            if (isPlaying() && !awaitingDisplay_)
                advancePlayback();
        });
    }
}

void TimelineWidget::showAchievedFps() {
    fpsLabel_->setText(achievedFps_ > 0.0 ? tr("%1 fps").arg(achievedFps_, 0, 'f', 1) : QString());
}

void TimelineWidget::setBakeRunning(bool running) {
    bakeRunning_ = running;
}

void TimelineWidget::setCurrentFrame(int frame) {
    frame = std::clamp(frame, first_, last_);
    if (frame == current_)
        return;
    current_ = frame;
    ruler_->setCurrentFrame(frame);
    {
        const QSignalBlocker blocker(frameSpinBox_);
        frameSpinBox_->setValue(frame);
    }
    Q_EMIT currentFrameChanged(frame);
}

void TimelineWidget::play() {
    if (isPlaying())
        return;
    const bool atEnd = !cachedFrameAfter(current_);
    if (atEnd && !bakeRunning_) {
        // Nothing ahead: start over from the first cached frame, as players do.
        const std::optional<int> firstCached = firstCachedFrame();
        if (!firstCached)
            return;
        setCurrentFrame(*firstCached);
    }
    shownAt_.clear();
    achievedFps_ = 0.0;
    showAchievedFps();
    awaitingDisplay_ = false;
    playTimer_->start();
    if (rate_ == PlaybackRate::EveryFrame)
        QTimer::singleShot(0, this, [this] {
            if (isPlaying() && !awaitingDisplay_)
                advancePlayback();
        });
    showPlaying();
    Q_EMIT playingChanged(true);
}

void TimelineWidget::pause() {
    if (!isPlaying())
        return;
    playTimer_->stop();
    showPlaying();
    Q_EMIT playingChanged(false);
}

void TimelineWidget::togglePlayback() {
    if (isPlaying())
        pause();
    else
        play();
}

void TimelineWidget::setLoop(bool loop) {
    const bool changed = loop != loop_;
    loop_ = loop;
    {
        const QSignalBlocker blocker(loopButton_);
        loopButton_->setChecked(loop);
    }
    showLoop();
    if (changed)
        Q_EMIT loopChanged(loop);
}

void TimelineWidget::showLoop() {
    loopButton_->setToolTip(loop_ ? tr("Loop playback: on (at the newest cached frame it starts "
                                       "again from the first)")
                                  : tr("Loop playback: off (it stops at the newest cached frame)"));
}

void TimelineWidget::stepForward() {
    setCurrentFrame(current_ + 1);
}

void TimelineWidget::stepBackward() {
    setCurrentFrame(current_ - 1);
}

void TimelineWidget::goToFirst() {
    setCurrentFrame(first_);
}

void TimelineWidget::goToLast() {
    setCurrentFrame(lastCachedFrame().value_or(last_));
}

void TimelineWidget::advancePlayback() {
    if (const std::optional<int> next = cachedFrameAfter(current_)) {
        playTo(*next);
        return;
    }
    const std::optional<int> firstCached = firstCachedFrame();
    if (loop_ && firstCached && *firstCached != current_)
        playTo(*firstCached);
    else if (!bakeRunning_)
        pause();
    // Otherwise the bake's next frame is on its way: keep ticking until it arrives.
}

void TimelineWidget::playTo(int frame) {
    awaitingDisplay_ = rate_ == PlaybackRate::EveryFrame;
    if (awaitingDisplay_)
        playTimer_->start(); // the wait for this frame starts now
    setCurrentFrame(frame);
}

std::optional<int> TimelineWidget::cachedFrameAfter(int frame) const {
    const auto next = cached_.upper_bound(std::max(frame, first_ - 1));
    if (next == cached_.end() || *next > last_)
        return std::nullopt;
    return *next;
}

std::optional<int> TimelineWidget::firstCachedFrame() const {
    const auto first = cached_.lower_bound(first_);
    if (first == cached_.end() || *first > last_)
        return std::nullopt;
    return *first;
}

std::optional<int> TimelineWidget::lastCachedFrame() const {
    const auto afterLast = cached_.upper_bound(last_);
    if (afterLast == cached_.begin() || *std::prev(afterLast) < first_)
        return std::nullopt;
    return *std::prev(afterLast);
}

void TimelineWidget::showCachedFrames() {
    ruler_->setCachedFrames(std::vector<int>(cached_.begin(), cached_.end()));
}

void TimelineWidget::showPlaying() {
    const bool playing = isPlaying();
    playButton_->setIcon(
        style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    playButton_->setText(playing ? tr("Pause") : tr("Play"));
}

} // namespace airtrap
