#pragma once
// The permanent fields of the status bar: frame, simulated time, particles, step time and the
// bake's ETA. Transient messages still use QStatusBar::showMessage on the left.
#include <QObject>

class QLabel;
class QStatusBar;

namespace airtrap {

struct BakeProgress;
struct FrameData;

class StatusBarFields : public QObject {
    Q_OBJECT

public:
    //! Adds the fields to `statusBar` (which owns them).
    explicit StatusBarFields(QStatusBar* statusBar);

    //! The frame shown in the viewport: its number, time and particle count.
    void showFrame(int frame, const FrameData& data);
    //! Edit mode: the frame field shows the timeline position only.
    void showFrameNumber(int frame, double fps);
    //! A running bake: step rate as time per step, and the ETA of the whole bake.
    void showBakeProgress(const BakeProgress& progress);
    //! No bake running: the step and ETA fields are cleared.
    void clearBake();

    QLabel* frameField() const { return frame_; }
    QLabel* timeField() const { return time_; }
    QLabel* particlesField() const { return particles_; }
    QLabel* stepField() const { return step_; }
    QLabel* etaField() const { return eta_; }

private:
    QLabel* addField(QStatusBar* statusBar, const char* objectName, const QString& toolTip);
    static QString duration(double seconds);

    QLabel* frame_;
    QLabel* time_;
    QLabel* particles_;
    QLabel* step_;
    QLabel* eta_;
};

} // namespace airtrap
