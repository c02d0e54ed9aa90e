#include "viewport/ViewportWidget.h"

#include "document/ElementMover.h"
#include "viewport/QtVectors.h"
#include "viewport/RenderContext.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

constexpr float kOrbitDegreesPerPixel = 0.4f;
constexpr float kZoomPerWheelStep = 0.85f; // distance factor of one notch towards the scene
// While the camera moves, at most this many particles are drawn (a spread subset): about what
// software OpenGL on two cores draws at 10+ frames per second at 1280×720
// (docs/PERFORMANCE.md, airtrap-viewport-bench). A GPU draws every frame in full either way.
constexpr int kMovingParticleBudget = 60000;
// The full frame returns when the camera has not moved for this long.
constexpr int kCameraSettleMs = 200;
constexpr float kAxesShareOfDomain = 0.2f;
constexpr float kMinAxesLength = 0.2f; // m
// Anti-aliased edges: thin grid lines, wireframes and small particles crawl without. Four
// samples smooth them well; more cost software OpenGL more than they show.
constexpr int kMultisamples = 4;

} // namespace

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent) {
    // Set per widget as well as by default: tests and embedders may not go through main().
    // Multisampling is the widget's own: it draws into a multisampled framebuffer object, which
    // needs nothing of the window system (an X server may offer no multisampled visuals).
    QSurfaceFormat format = surfaceFormat();
    format.setSamples(kMultisamples);
    setFormat(format);
    setMinimumSize(320, 240);
    setFocusPolicy(Qt::StrongFocus); // for F
    particles_.setMovingBudget(kMovingParticleBudget);
    cameraSettled_.setSingleShot(true);
    cameraSettled_.setInterval(kCameraSettleMs);
    connect(&cameraSettled_, &QTimer::timeout, this, [this] {
        particles_.setMoving(false);
        update();
    });
}

ViewportWidget::~ViewportWidget() {
    // The base class destroys the context after this body: free the GL objects while it lives,
    // and do not let its last signal reach the members that are gone by then.
    disconnect(contextConnection_);
    releaseGl();
}

QSurfaceFormat ViewportWidget::surfaceFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    return format;
}

// --- Data ----------------------------------------------------------------------------------------

void ViewportWidget::setScene(const Scene& scene) {
    const bool first = !hasScene_;
    hasScene_ = true;
    gizmos_ = SceneGizmos(scene);
    domain_ = scene.domain();
    sceneSpacing_ = float(scene.solver.particleSpacing);
    sceneDesignSpeed_ = float(scene.solver.maxSpeed);
    grid_.fitAround(Aabb{scene.container.min, scene.container.max});
    const float largestSide = float(domain_.size().maxCoeff());
    axes_.setLength(std::max(kMinAxesLength, kAxesShareOfDomain * largestSide));
    boxes_.setGizmos(gizmos_);
    bodies_ = SceneBodies(scene, meshes_);
    placeBodies();
    bubbleDrawable_.setShape(scene.bubbleMesh);
    bubbleDrawable_.setBubbles(frame_ ? frame_->state.bubbles : std::vector<BubbleState>());
    updateParticleLook();
    if (first) {
        frameAll();
    }
    update();
}

void ViewportWidget::setSelection(const SceneItem& item) {
    selection_ = item;
    setShowSelection(showSelection_);
}

void ViewportWidget::setFrame(std::shared_ptr<const FrameData> frame) {
    frame_ = std::move(frame);
    particles_.setFrame(frame_);
    bubbleDrawable_.setBubbles(frame_ ? frame_->state.bubbles : std::vector<BubbleState>());
    boxes_.setFluidBlocksVisible(!frame_);
    placeBodies();
    update();
}

void ViewportWidget::placeBodies() {
    bodies_.showStates(frame_ ? &frame_->state.bodies : nullptr);
    bodyDrawable_.setBodies(bodies_);
}

void ViewportWidget::frameAll() {
    camera_.fit(domain_, aspectRatio());
    refitOnResize_ = true;
    update();
}

void ViewportWidget::setCameraView(CameraView view) {
    // Pitch 0 looks level; the top view stops at the camera's ±89° so that "up" stays defined.
    switch (view) {
    case CameraView::Perspective:
        camera_.setAngles(OrbitCamera().yaw(), OrbitCamera().pitch());
        setOrthographic(false);
        break;
    case CameraView::Front:
        camera_.setAngles(0.0f, 0.0f);
        break;
    case CameraView::Side:
        camera_.setAngles(90.0f, 0.0f);
        break;
    case CameraView::Top:
        camera_.setAngles(0.0f, 89.0f);
        break;
    }
    frameAll();
}

void ViewportWidget::setOrthographic(bool orthographic) {
    if (orthographic == camera_.isOrthographic()) {
        return;
    }
    camera_.setOrthographic(orthographic);
    update();
    Q_EMIT orthographicChanged(orthographic);
}

void ViewportWidget::frameSelected() {
    const std::optional<Aabb> bounds = selectionBounds();
    if (!bounds) {
        frameAll();
        return;
    }
    camera_.fit(*bounds, aspectRatio());
    refitOnResize_ = false;
    update();
}

std::optional<Aabb> ViewportWidget::selectionBounds() const {
    for (const GizmoBox& box : gizmos_.boxes()) {
        if (box.item == selection_) {
            return Aabb{toVec3d(box.min), toVec3d(box.max)};
        }
    }
    for (const SceneBodies::Body& body : bodies_.bodies()) {
        if (body.item == selection_ && body.solid) {
            const Vec3d centre = toVec3d(body.pose.map(QVector3D(0.0f, 0.0f, 0.0f)));
            const Vec3d reach = Vec3d::Constant(body.boundingRadius);
            return Aabb{centre - reach, centre + reach};
        }
    }
    return std::nullopt;
}

bool ViewportWidget::drawsParticles() const {
    // Once post has made the frame's surface, the surface is the water: particles under it would
    // hide the bubbles inside. They come back when asked for over the surface, or when it is off.
    const bool surfaceOnScreen = surfaceTriangleCount() > 0;
    return showWater_ && (!surfaceOnScreen || particlesUnderSurface_);
}

void ViewportWidget::setParticlesUnderSurface(bool show) {
    particlesUnderSurface_ = show;
    update();
}

void ViewportWidget::setShowBubbles(bool show) {
    showBubbles_ = show;
    update();
}

void ViewportWidget::setShowSubgridBubbles(bool show) {
    showSubgridBubbles_ = show;
    update();
}

void ViewportWidget::setShowSelection(bool show) {
    showSelection_ = show;
    const SceneItem drawn = show ? selection_ : SceneItem::none();
    boxes_.setSelection(drawn);
    bodyDrawable_.setSelection(drawn);
    update();
}

void ViewportWidget::setShowGrid(bool show) {
    showGrid_ = show;
    update();
}

void ViewportWidget::setShowAxes(bool show) {
    showAxes_ = show;
    update();
}

void ViewportWidget::setShowGizmos(bool show) {
    showGizmos_ = show;
    update();
}

void ViewportWidget::setShowWater(bool show) {
    showWater_ = show;
    update();
}

void ViewportWidget::setWaterSurface(std::shared_ptr<const TriangleMesh> mesh) {
    surface_.setMesh(std::move(mesh));
    update();
}

void ViewportWidget::setSubgridBubbles(const std::vector<SubgridBubble>& bubbles) {
    subgridBubbles_.setBubbles(bubbles);
    update();
}

void ViewportWidget::setShowSurface(bool show) {
    showSurface_ = show;
    update();
}

void ViewportWidget::setSurfaceShading(SurfaceShading shading) {
    surface_.setShading(shading);
    update();
}

void ViewportWidget::setBubblesThroughWater(bool through) {
    bubblesThroughWater_ = through;
    update();
}

void ViewportWidget::setParticleSize(float factor) {
    particleSize_ = std::clamp(factor, kMinParticleSize, kMaxParticleSize);
    updateParticleLook();
    update();
}

void ViewportWidget::setSpeedScale(float metresPerSecond) {
    speedScaleOverride_ = std::max(metresPerSecond, 0.0f);
    updateParticleLook();
    update();
}

float ViewportWidget::particleRadius() const {
    return 0.5f * sceneSpacing_ * particleSize_;
}

void ViewportWidget::updateParticleLook() {
    particles_.setRadius(particleRadius());
    particles_.setSpeedScale(speedScaleOverride_.value_or(sceneDesignSpeed_));
}

SceneItem ViewportWidget::itemAt(const QPointF& position) const {
    if (!hasScene_) {
        return SceneItem::none();
    }
    const Ray ray = camera_.ray(position, size());
    // Bodies are solids like the water, drawn with or without the gizmos.
    std::optional<PickHit> nearest = bodies_.pick(ray);
    if (showGizmos_) {
        SceneGizmos::PickOptions options;
        options.fluidBlocks = !isPlayback();
        options.metresPerPixelPerDepth = camera_.metresPerPixel(1.0f, size());
        const std::optional<PickHit> gizmo = gizmos_.hit(ray, options);
        if (gizmo && (!nearest || gizmo->distance < nearest->distance)) {
            nearest = gizmo;
        }
    }
    return nearest ? nearest->item : SceneItem::none();
}

float ViewportWidget::aspectRatio() const {
    return height() > 0 ? float(width()) / float(height()) : 1.0f;
}

// --- OpenGL --------------------------------------------------------------------------------------

std::array<Drawable*, 9> ViewportWidget::drawables() {
    return {&bubbleDrawable_, &subgridBubbles_, &bodyDrawable_, &particles_, &surface_,
            &grid_,           &axes_,           &boxes_,        &moveGizmo_};
}

void ViewportWidget::initializeGL() {
    // A widget moved to another window gets a new context: free the old one's objects first.
    disconnect(contextConnection_);
    contextConnection_ = connect(context(), &QOpenGLContext::aboutToBeDestroyed, this,
                                 &ViewportWidget::releaseGl, Qt::DirectConnection);
    for (Drawable* drawable : drawables()) {
        drawable->initialize();
    }
    glReady_ = true;
}

void ViewportWidget::releaseGl() {
    if (!glReady_) {
        return;
    }
    makeCurrent();
    for (Drawable* drawable : drawables()) {
        drawable->release();
    }
    doneCurrent();
    glReady_ = false;
}

void ViewportWidget::resizeGL(int, int) {
    if (refitOnResize_ && hasScene_) {
        camera_.fit(domain_, aspectRatio());
    }
}

void ViewportWidget::paintGL() {
    QOpenGLExtraFunctions* gl = context()->extraFunctions();
    // Set on every frame, not once in initializeGL: the context is shared with Qt's compositor,
    // which may leave its own clear colour behind.
    const QColor background = clearColor();
    gl->glClearColor(background.redF(), background.greenF(), background.blueF(), 1.0f);
    gl->glClearStencil(0);
    gl->glStencilMask(0xFF);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (hasScene_ || isPlayback()) {
        drawScene();
    }
    // The picture is opaque: translucent layers (the water surface) leave alpha below 1 in the
    // framebuffer, which whoever composes the widget (the window's grab, a compositor) would
    // take for see-through pixels and blend into false colours.
    gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // The legend explains the water's colours: without water it explains nothing.
    if (isPlayback() && drawsParticles()) {
        paintLegend();
    }
    if (!notice_.isEmpty()) {
        paintNotice();
    }
}

void ViewportWidget::drawScene() {
    const float ratio = float(devicePixelRatioF());
    const QSize pixels(int(std::lround(width() * ratio)), int(std::lround(height() * ratio)));
    const RenderContext context{*QOpenGLContext::currentContext()->extraFunctions(),
                                camera_.viewMatrix(),
                                camera_.projectionMatrix(aspectRatio()),
                                camera_.projectionMatrix(aspectRatio()) * camera_.viewMatrix(),
                                pixels,
                                ratio};
    context.gl.glEnable(GL_DEPTH_TEST);
    context.gl.glDepthFunc(GL_LEQUAL); // lines on box faces and the floor win ties
    drawSolids(context);
    if (hasScene_ && showGrid_) {
        grid_.draw(context);
    }
    if (hasScene_ && showAxes_) {
        axes_.draw(context);
    }
    if (hasScene_ && showGizmos_) {
        boxes_.draw(context);
        updateMoveGizmo();
        moveGizmo_.draw(context);
    }
    // Translucent: last, so that everything behind it is there to show through.
    if (showSurface_ && frame_)
        surface_.draw(context);
    context.gl.glDisable(GL_DEPTH_TEST);
}

void ViewportWidget::drawSolids(const RenderContext& context) {
    // Bubbles through water: the water must not cover a bubble, a body in front must. Depth alone
    // cannot tell the two apart, so the stencil marks the pixels where a bubble is the nearest
    // solid: the bubbles set the mark, the bodies drawn next clear it where they pass in front,
    // and the water is then kept off the marked pixels. Each part is drawn once, and the depth
    // left behind is the bubble's where it shows, so the lines drawn later still sort with it.
    // The bubbles stay opaque: blended with the water's bright speed colours a translucent sphere
    // would be hard to tell from the water, and its own colour is what the artist looks for.
    QOpenGLExtraFunctions& gl = context.gl;
    const bool overWater = bubblesThroughWater_ && drawsParticles();
    if (overWater) {
        gl.glEnable(GL_STENCIL_TEST);
        gl.glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE); // on depth pass, write the reference
        gl.glStencilFunc(GL_ALWAYS, 1, 0xFF);
    }
    if (showBubbles_)
        bubbleDrawable_.draw(context);
    if (showSubgridBubbles_)
        subgridBubbles_.draw(context);
    if (overWater)
        gl.glStencilFunc(GL_ALWAYS, 0, 0xFF);
    if (hasScene_)
        bodyDrawable_.draw(context);
    if (overWater) {
        gl.glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        gl.glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
    }
    if (drawsParticles())
        particles_.draw(context);
    gl.glDisable(GL_STENCIL_TEST);
}

void ViewportWidget::paintLegend() {
    // QPainter draws with the same context: it sets up the state it needs itself.
    QPainter painter(this);
    legend_.paint(painter, rect(), particles_.effectiveSpeedScale());
}

void ViewportWidget::setNotice(const QString& text) {
    if (text == notice_) {
        return;
    }
    notice_ = text;
    update();
}

void ViewportWidget::paintNotice() {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 1.2);
    painter.setFont(font);
    const QFontMetrics metrics(font);
    const int padding = metrics.height() / 2;
    QRect box =
        metrics.boundingRect(notice_).adjusted(-padding, -padding / 2, padding, padding / 2);
    box.moveCenter(QPoint(width() / 2, metrics.height() + padding));
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 150));
    painter.drawRoundedRect(box, padding / 2.0, padding / 2.0);
    painter.setPen(Qt::white);
    painter.drawText(box, Qt::AlignCenter, notice_);
}

// --- Navigation and picking ----------------------------------------------------------------------

void ViewportWidget::cameraMovedByUser() {
    refitOnResize_ = false;
    particles_.setMoving(true);
    cameraSettled_.start();
    update();
}

void ViewportWidget::updateMoveGizmo() {
    const bool shown = hasScene_ && showGizmos_ && showSelection_ && !isPlayback() &&
                       ElementMover::canMove(selection_);
    const std::optional<Aabb> bounds = shown ? selectionBounds() : std::nullopt;
    moveGizmo_.setOrigin(bounds ? std::optional(toQVector3D(bounds->center())) : std::nullopt);
    moveGizmo_.fitTo(camera_, size());
}

bool ViewportWidget::startMove(const QPointF& position) {
    updateMoveGizmo();
    const std::optional<int> axis = moveGizmo_.axisAt(position, camera_, size());
    if (!axis || !moveGizmo_.beginDrag(*axis, position, camera_, size())) {
        return false;
    }
    lastMoveOffset_ = 0.0;
    Q_EMIT moveStarted(selection_);
    update();
    return true;
}

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
    event->accept();
    if (event->button() == Qt::LeftButton && event->modifiers() == Qt::NoModifier &&
        startMove(event->position())) {
        return;
    }
    drag_.press(event->position(), event->button(), event->modifiers());
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
    if (const std::optional<int> axis = moveGizmo_.draggedAxis()) {
        const double offset = moveGizmo_.dragOffset(event->position(), camera_, size());
        if (offset != lastMoveOffset_) {
            lastMoveOffset_ = offset;
            Q_EMIT moveDragged(selection_, *axis, offset);
        }
        return;
    }
    const std::optional<QPointF> delta = drag_.move(event->position());
    if (!delta) {
        return;
    }
    if (drag_.mode() == DragTracker::Mode::Orbit) {
        // Dragging right turns the scene right, i.e. the eye left.
        camera_.orbit(-float(delta->x()) * kOrbitDegreesPerPixel,
                      float(delta->y()) * kOrbitDegreesPerPixel);
        cameraMovedByUser();
    } else if (drag_.mode() == DragTracker::Mode::Pan) {
        camera_.pan(*delta, size());
        cameraMovedByUser();
    }
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
    if (moveGizmo_.draggedAxis()) {
        if (event->button() == Qt::LeftButton) {
            moveGizmo_.endDrag();
            Q_EMIT moveFinished(selection_);
            update();
        }
        return;
    }
    if (drag_.release(event->button())) {
        Q_EMIT itemPicked(itemAt(event->position()));
    }
}

void ViewportWidget::mouseDoubleClickEvent(QMouseEvent* event) {
    // Replaces the second press; the first click of the pair has already picked.
    drag_.press(event->position(), event->button(), event->modifiers());
    drag_.cancel();
    if (event->button() == Qt::LeftButton && hasScene_ && itemAt(event->position()).isNone()) {
        frameAll();
    }
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
    const float steps = float(event->angleDelta().y()) / 120.0f;
    if (steps == 0.0f) {
        return;
    }
    camera_.zoomToward(event->position(), size(), std::pow(kZoomPerWheelStep, steps));
    cameraMovedByUser();
    event->accept();
}

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_F && event->modifiers() == Qt::NoModifier) {
        frameAll();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

} // namespace airtrap
