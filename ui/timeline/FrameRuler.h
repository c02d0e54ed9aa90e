#pragma once
// The timeline's ruler: frame ticks with numbers, a green strip under the frames that are cached,
// a blue one above it under the frames that have render outputs, and the current-frame handle.
// Clicking or dragging on it scrubs.
#include <QWidget>
#include <vector>

namespace airtrap {

class FrameRuler : public QWidget {
    Q_OBJECT

public:
    explicit FrameRuler(QWidget* parent = nullptr);

    //! Frames shown from `first` to `last` (last ≥ first, the caller checks).
    void setFrameRange(int first, int last);
    //! Frames marked as cached, ascending.
    void setCachedFrames(std::vector<int> frames);
    //! Frames marked as having render outputs, ascending.
    void setOutputFrames(std::vector<int> frames);
    //! Where the handle is drawn.
    void setCurrentFrame(int frame);

    //! The frame nearest to horizontal position `x`, within the range.
    int frameAt(double x) const;
    //! Horizontal centre of `frame`.
    double xOf(int frame) const;

    //! Room for a few labelled ticks.
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

Q_SIGNALS:
    //! The user clicked or dragged to `frame`.
    void frameScrubbed(int frame);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    void paintTicks(QPainter& painter) const;
    //! One rectangle per run of consecutive `frames`, `height` px high from `top`.
    void paintStrip(QPainter& painter, const std::vector<int>& frames, double top, double height,
                    const QColor& color) const;
    void paintHandle(QPainter& painter) const;
    double pixelsPerFrame() const;
    //! The smallest of 1, 2, 5, 10, 20, 50, … frames whose ticks are at least `spacing` px apart.
    int tickStep(double spacing) const;

    int first_ = 1;
    int last_ = 1;
    int current_ = 1;
    std::vector<int> cached_;
    std::vector<int> outputs_;
};

} // namespace airtrap
