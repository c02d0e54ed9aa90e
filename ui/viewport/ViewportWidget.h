#pragma once
// The editor's 3D view: the scene's gizmos and rigid bodies over a ground grid in edit mode, the
// water, the air bubbles and the bodies of a cached frame in playback. Navigation is a turntable
// camera (left-drag orbit, middle- or shift-drag pan, wheel zoom towards the cursor, F or a
// double-click on empty space frames everything); a click without drag picks the gizmo under the
// cursor and reports it with itemPicked(). The widget never selects by itself: whoever owns the
// selection answers with setSelection().
#include "cache/FrameFile.h"
#include "controller/BodyMeshCache.h"
#include "document/SceneItem.h"
#include "scene/Scene.h"
#include "viewport/AxesDrawable.h"
#include "viewport/BodyDrawable.h"
#include "viewport/BoxGizmoDrawable.h"
#include "viewport/BubbleDrawable.h"
#include "viewport/DragTracker.h"
#include "viewport/GridDrawable.h"
#include "viewport/MoveGizmo.h"
#include "viewport/OrbitCamera.h"
#include "viewport/ParticleDrawable.h"
#include "viewport/SceneBodies.h"
#include "viewport/SceneGizmos.h"
#include "viewport/SpeedLegend.h"
#include "viewport/SubgridBubbleDrawable.h"
#include "viewport/SurfaceDrawable.h"

#include <QColor>
#include <QOpenGLWidget>
#include <QSurfaceFormat>
#include <QTimer>
#include <array>
#include <memory>
#include <optional>

namespace airtrap {

struct RenderContext;

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    //! The surface every editor window asks for: OpenGL 3.3 core with a depth buffer. main() makes
    //! it the default so that all contexts (and Qt's own compositing) agree with the viewport's.
    static QSurfaceFormat surfaceFormat();

    //! The background the viewport clears to; a flat dark grey that keeps bright water readable.
    static QColor clearColor() { return QColor(46, 46, 50); }

    //! Room for a useful view.
    QSize sizeHint() const override { return QSize(960, 640); }

    //! The camera, read-only: to project scene points to widget pixels (tests, overlays).
    const OrbitCamera& camera() const { return camera_; }
    //! True while a frame is shown (setFrame() with a frame).
    bool isPlayback() const { return frame_ != nullptr; }
    //! The highlighted item.
    const SceneItem& selection() const { return selection_; }
    //! The arrows that move the selection, where they were last drawn (tests, overlays).
    const MoveGizmo& moveGizmo() const { return moveGizmo_; }
    //! The line shown over the view ("Frame 40 is not baked yet"); empty when none.
    const QString& notice() const { return notice_; }
    //! Radius the particles are drawn with, in metres.
    float particleRadius() const;
    //! The smallest and largest particle size factor (setParticleSize()).
    static constexpr float kMinParticleSize = 0.1f;
    static constexpr float kMaxParticleSize = 3.0f;
    //! The speed drawn white, m/s: the fixed scale, or the shown frame's fastest particle.
    float speedScale() const { return particles_.effectiveSpeedScale(); }
    //! Bubbles of the shown frame that the view draws.
    int bubbleCount() const { return bubbleDrawable_.bubbleCount(); }
    //! Sub-grid bubbles drawn now.
    int subgridBubbleCount() const { return subgridBubbles_.bubbleCount(); }
    //! Triangles of the free-surface mesh drawn now (0: none shown).
    int surfaceTriangleCount() const { return showSurface_ ? surface_.triangleCount() : 0; }
    //! The scene's bodies where the view shows them now (scene or frame poses).
    const SceneBodies& bodies() const { return bodies_; }
    //! The gizmo or body under `position` (widget pixels), as a click there would pick it.
    SceneItem itemAt(const QPointF& position) const;
    //! Whether playback draws the water particles.
    bool showsWater() const { return showWater_; }
    //! Whether the particles are drawn now: water shown, and no surface mesh on screen unless
    //! particles under the surface were asked for.
    bool drawsParticles() const;
    //! Off (the default), a frame with a surface mesh shows the mesh and not the particles.
    void setParticlesUnderSurface(bool show);
    //! Whether bubbles stay visible behind water (they are still hidden behind bodies).
    bool drawsBubblesThroughWater() const { return bubblesThroughWater_; }

    //! Where the camera looks from: the editor's default three-quarter view, or straight at the
    //! front (along −z), the side (along −x) or from the top (down y).
    enum class CameraView { Perspective, Front, Side, Top };

public Q_SLOTS:
    //! Copies what the view draws from `scene` and redraws. The first scene also frames the view.
    void setScene(const airtrap::Scene& scene);
    //! Highlights this item's gizmo (none: nothing).
    void setSelection(const airtrap::SceneItem& item);
    //! Playback: draws the frame's particles instead of the fluid blocks, its bubbles, and the
    //! bodies where the frame has them; null returns to editing.
    void setFrame(std::shared_ptr<const airtrap::FrameData> frame);
    //! A line shown at the top of the view until replaced; empty removes it.
    void setNotice(const QString& text);
    //! Aims the camera at the simulation domain (container plus headroom) and fits it in view.
    void frameAll();
    //! Turns the camera to `view` and frames the domain.
    void setCameraView(CameraView view);
    //! Parallel projection on or off; the picture keeps its scale at the camera's target.
    void setOrthographic(bool orthographic);
    bool isOrthographic() const { return camera_.isOrthographic(); }
    //! Fits the selected item (its gizmo box, or a body's bounding sphere) in the view, keeping
    //! the direction of view; frames everything when nothing is selected.
    void frameSelected();
    //! Shows or hides the ground grid.
    void setShowGrid(bool show);
    //! Shows or hides the world axes at the origin.
    void setShowAxes(bool show);
    //! Shows or hides the gizmo boxes; hidden gizmos cannot be picked either.
    void setShowGizmos(bool show);
    //! Shows or hides the water particles of the shown frame (and their speed legend), so that
    //! what the water surrounds can be seen.
    void setShowWater(bool show);
    //! Shows this free-surface mesh of the shown frame (null: none), over everything else.
    void setWaterSurface(std::shared_ptr<const airtrap::TriangleMesh> mesh);
    //! Shows these sub-grid bubbles of the shown frame with its bubbles (empty: none).
    void setSubgridBubbles(const std::vector<airtrap::SubgridBubble>& bubbles);
    //! Shows or hides the trapped bubbles of the shown frame.
    void setShowBubbles(bool show);
    //! Shows or hides the sub-grid bubbles of the shown frame.
    void setShowSubgridBubbles(bool show);
    //! Whether the selection's gizmo is highlighted; off, the selection is kept but not drawn.
    void setShowSelection(bool show);
    void setShowSurface(bool show);
    //! Translucent (the default), opaque or wireframe water surface.
    void setSurfaceShading(airtrap::SurfaceShading shading);
    SurfaceShading surfaceShading() const { return surface_.shading(); }
    float surfaceOpacity() const { return surface_.opacity(); }
    //! Edges the wireframe surface drew last (0 before it is first drawn).
    int surfaceEdgeCount() const { return surface_.edgeCount(); }
    //! On, bubbles are drawn over any water in front of them, as if the water were clear, but
    //! still hidden by bodies in front; off, water in front hides them like any solid.
    void setBubblesThroughWater(bool through);
    //! Draws particles at `factor` times the default radius (clamped to kParticleSizeRange): small
    //! points to see the flow inside the water, large ones to see it as a body.
    void setParticleSize(float factor);
    float particleSize() const { return particleSize_; }
    //! Fixes the speed drawn white (m/s); 0 follows each frame's fastest particle. By default it is
    //! the scene's design speed u_max (solver max_speed), so colours compare between frames.
    void setSpeedScale(float metresPerSecond);

Q_SIGNALS:
    //! A click without drag hit this gizmo (SceneItem::none() when it hit nothing).
    void itemPicked(const airtrap::SceneItem& item);
    //! The projection switched between perspective and orthographic.
    void orthographicChanged(bool orthographic);
    //! The move gizmo: a drag of `item` along world axis `axis` began, moved it `offset` metres
    //! from where it stood (rounded to a millimetre), and ended.
    void moveStarted(const airtrap::SceneItem& item);
    void moveDragged(const airtrap::SceneItem& item, int axis, double offset);
    void moveFinished(const airtrap::SceneItem& item);

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    //! Everything drawn in 3D: opaque bubbles, bodies and water first, lines over them.
    std::array<Drawable*, 9> drawables();
    //! Puts the move gizmo at the selected object's centre, or hides it (nothing movable
    //! selected, gizmos hidden, or a cached frame shown).
    void updateMoveGizmo();
    //! A left press on an arrow of the move gizmo starts moving the selection; true when it did.
    bool startMove(const QPointF& position);
    //! Puts the bodies where the shown frame has them (or at their scene poses) for drawing.
    void placeBodies();
    //! Frees every GL object while the context is current (before it goes away).
    void releaseGl();
    void drawScene();
    //! The bubbles, the bodies and the water, each depth-tested; see the definition for how
    //! bubbles show through the water.
    void drawSolids(const RenderContext& context);
    void paintLegend();
    void paintNotice();
    //! The box the selected item occupies; none when nothing (or nothing drawn) is selected.
    std::optional<Aabb> selectionBounds() const;
    float aspectRatio() const;
    void updateParticleLook();
    //! The user moved the camera: stop refitting it on resize.
    void cameraMovedByUser();

    OrbitCamera camera_;
    DragTracker drag_;
    GridDrawable grid_;
    AxesDrawable axes_;
    BoxGizmoDrawable boxes_;
    BodyDrawable bodyDrawable_;
    ParticleDrawable particles_;
    BubbleDrawable bubbleDrawable_;
    SubgridBubbleDrawable subgridBubbles_;
    SurfaceDrawable surface_;
    SpeedLegend legend_;
    MoveGizmo moveGizmo_;
    //! The last offset reported during a move, so that only changes are reported.
    double lastMoveOffset_ = 0.0;
    QString notice_;

    SceneGizmos gizmos_;
    SceneBodies bodies_;
    BodyMeshCache meshes_;
    Aabb domain_;
    float sceneSpacing_ = 0.02f;
    float sceneDesignSpeed_ = 0.0f;
    bool hasScene_ = false;
    SceneItem selection_;
    std::shared_ptr<const FrameData> frame_;

    float particleSize_ = 1.0f;
    std::optional<float> speedScaleOverride_;
    bool showGrid_ = true;
    bool showAxes_ = true;
    bool showGizmos_ = true;
    bool showWater_ = true;
    bool showSurface_ = true;
    bool particlesUnderSurface_ = false;
    bool showBubbles_ = true;
    bool showSubgridBubbles_ = true;
    bool showSelection_ = true;
    bool bubblesThroughWater_ = true;
    //! Until the user navigates, a resize refits the view (the first fit may predate the layout).
    bool refitOnResize_ = false;
    //! Fires once the camera has rested a moment: the full frame is drawn again.
    QTimer cameraSettled_;
    bool glReady_ = false;
    QMetaObject::Connection contextConnection_;
};

} // namespace airtrap
