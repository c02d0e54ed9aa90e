#pragma once
// A turntable camera, as in most 3D editors: it circles a target point at some distance, with
// yaw about the world's up axis (y) and pitch above the horizon. It projects in perspective or
// orthographically; the orthographic view shows at the target what the perspective view shows
// there, so switching keeps the picture's scale. Plain math, no OpenGL, so that navigation and
// picking can be tested without a window. Pixels are widget pixels, y down.
#include "core/Math.h"
#include "viewport/Ray.h"

#include <QMatrix4x4>
#include <QPointF>
#include <QSize>
#include <QVector3D>

namespace airtrap {

class OrbitCamera {
public:
    //! The point the camera looks at and orbits around.
    QVector3D target() const { return target_; }
    //! Moves the point looked at; the direction of view does not change.
    void setTarget(const QVector3D& target) { target_ = target; }

    //! Metres from the eye to the target.
    float distance() const { return distance_; }
    //! Sets the eye's distance from the target, kept within a range that stays renderable.
    void setDistance(float metres);

    //! Degrees about the y axis; 0 looks along −z (the eye is on the +z side of the target).
    float yaw() const { return yaw_; }
    //! Degrees above the horizon the eye sits at; within ±89 so that "up" stays defined.
    float pitch() const { return pitch_; }
    //! Sets both angles; the pitch is clamped, the yaw wrapped to [0, 360).
    void setAngles(float yawDegrees, float pitchDegrees);

    //! Vertical field of view in degrees.
    float fieldOfView() const { return fieldOfView_; }
    //! Sets the vertical field of view, clamped to [5, 120] degrees.
    void setFieldOfView(float degrees);

    //! True when the view is orthographic: parallel rays, sizes independent of depth.
    bool isOrthographic() const { return orthographic_; }
    void setOrthographic(bool orthographic) { orthographic_ = orthographic; }

    //! Where the camera is.
    QVector3D eye() const { return target_ - forward() * distance_; }
    //! Unit vector from the eye towards the target.
    QVector3D forward() const;
    //! Unit vector pointing right on screen.
    QVector3D right() const;
    //! Unit vector pointing up on screen.
    QVector3D up() const;

    //! World to eye space.
    QMatrix4x4 viewMatrix() const;
    //! Eye to clip space for a viewport of this width / height.
    QMatrix4x4 projectionMatrix(float aspectRatio) const;
    //! Distance of the near clipping plane; scales with the distance so zooming in never clips.
    float nearPlane() const;
    //! Distance of the far clipping plane; reaches past everything fit() was given.
    float farPlane() const;

    //! The ray from the eye through the centre of `pixel` of a viewport of `size` pixels.
    Ray ray(const QPointF& pixel, const QSize& size) const;
    //! Where `point` appears in a viewport of `size` pixels (meaningless behind the eye).
    QPointF project(const QVector3D& point, const QSize& size) const;
    //! Metres covered by one pixel at `depth` metres in front of the eye.
    float metresPerPixel(float depth, const QSize& size) const;

    //! Aims at the centre of `box` and backs off until all of it is in view, with a small border;
    //! keeps the angles.
    void fit(const Aabb& box, float aspectRatio);
    //! Turns the eye around the target by these angles (degrees).
    void orbit(float yawDegrees, float pitchDegrees);
    //! Slides the target (and eye) so that the scene follows the cursor by `pixelDelta`.
    void pan(const QPointF& pixelDelta, const QSize& size);
    //! Multiplies the distance by `factor` (< 1 moves closer), keeping the target.
    void zoom(float factor);
    //! Zooms by `factor` while the point under `pixel` (at the target's depth) stays put.
    void zoomToward(const QPointF& pixel, const QSize& size, float factor);

private:
    static float aspectOf(const QSize& size);
    float tanHalfFieldOfView() const;
    //! Half the height of the orthographic view: the perspective view's at the target.
    float orthographicHalfHeight() const { return distance_ * tanHalfFieldOfView(); }
    //! The point of the plane through the target, facing the eye, under `pixel`.
    QVector3D targetPlanePoint(const QPointF& pixel, const QSize& size) const;

    QVector3D target_{0.0f, 0.0f, 0.0f};
    float distance_ = 5.0f;
    float yaw_ = 25.0f;
    float pitch_ = 20.0f;
    float fieldOfView_ = 40.0f;
    bool orthographic_ = false;
    //! Radius of the last fitted box: the far plane must reach past it from any zoom.
    float sceneRadius_ = 2.0f;
};

} // namespace airtrap
