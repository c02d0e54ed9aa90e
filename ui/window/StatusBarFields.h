#pragma once
// The permanent fields of the status bar: frame, simulated time, particles, bubbles, and while a
// bake runs its progress bar, step time and ETA. Transient messages still use
// QStatusBar::showMessage on the left.
#include <QObject>
#include <QString>

class QLabel;
class QProgressBar;
class QStatusBar;

namespace airtrap {

struct BakeProgress;
struct FrameData;
struct SimulationState;

class StatusBarFields : public QObject {
    Q_OBJECT

public:
    //! Adds the fields to `statusBar` (which owns them).
    explicit StatusBarFields(QStatusBar* statusBar);

    //! The frame shown in the viewport: its number, time, particle count and bubble counts (the
    //! bubble field is hidden while the frame's scene has never had a bubble).
    void showFrame(int frame, const FrameData& data);
    //! Edit mode: the frame field shows the timeline position only.
    void showFrameNumber(int frame, double fps);
    //! A running bake: the bar at `fraction` (0–1) of the frame range, "Frame 12 of 100 · 34 %";
    //! the step rate as time per step; the ETA of the whole bake (negative: not known yet).
    void showBakeProgress(const BakeProgress& progress, double fraction, double etaSeconds);
    //! A paused bake: the bar keeps its value and says "Paused", as does the ETA field.
    void showBakePaused(int frame, int lastFrame, double fraction);
    //! No bake running: the bar is hidden and the step and ETA fields are cleared.
    void clearBake();

    //! "Bubbles 12 · created 30 · deleted 18 (age 2, floating 10, overlap 5, impact 1)": alive at
    //! the frame's end, then created and deleted (per rule) since frame 1. Empty when no bubble
    //! has been created or deleted yet.
    static QString bubbleSummary(const SimulationState& state);

    QLabel* frameField() const { return frame_; }
    QLabel* timeField() const { return time_; }
    QLabel* particlesField() const { return particles_; }
    QLabel* bubblesField() const { return bubbles_; }
    QLabel* stepField() const { return step_; }
    QLabel* etaField() const { return eta_; }
    QProgressBar* bakeProgressBar() const { return progress_; }

private:
    QLabel* addField(QStatusBar* statusBar, const char* objectName, const QString& toolTip);
    void showBubbles(const QString& summary);
    void showBakeBar(const QString& text, double fraction);
    static QString duration(double seconds);

    QLabel* frame_;
    QLabel* time_;
    QLabel* particles_;
    QLabel* bubbles_;
    QProgressBar* progress_;
    QLabel* step_;
    QLabel* eta_;
};

} // namespace airtrap
