#include "window/ViewPreferences.h"

#include "viewport/SurfaceShading.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/EditorSettings.h"

#include <QAction>
#include <QActionGroup>

namespace airtrap {

namespace {

constexpr auto kShowWaterKey = "view/showWater";
constexpr auto kShowSurfaceKey = "view/showSurface";
constexpr auto kSurfaceShadingKey = "view/surfaceShading";
constexpr auto kParticlesUnderSurfaceKey = "view/particlesUnderSurface";
constexpr auto kBubblesThroughWaterKey = "view/bubblesThroughWater";
constexpr auto kParticleSizeKey = "view/particleSize";

//! Checks `action` as it was last left (its own state the first time) and stores each change.
void remember(QAction* action, const char* key) {
    QSettings& settings = EditorSettings::store();
    action->setChecked(settings.value(QLatin1String(key), action->isChecked()).toBool());
    QObject::connect(action, &QAction::toggled, action, [key](bool checked) {
        EditorSettings::store().setValue(QLatin1String(key), checked);
    });
}

SurfaceShading shadingOf(const QAction* action) {
    return surfaceShadingNamed(action->data().toString().toStdString())
        .value_or(SurfaceShading::Translucent);
}

} // namespace

ViewPreferences::ViewPreferences(const EditorActions& actions, ViewportWidget& viewport,
                                 QObject* parent)
    : QObject(parent), actions_(actions), viewport_(viewport) {
    connectLayers();
    connectSurfaceShading();
    connectParticleSize();
}

void ViewPreferences::connectLayers() {
    const struct {
        QAction* action;
        void (ViewportWidget::*apply)(bool);
        const char* key;
    } layers[] = {
        {actions_.showWater, &ViewportWidget::setShowWater, kShowWaterKey},
        {actions_.showSurface, &ViewportWidget::setShowSurface, kShowSurfaceKey},
        {actions_.particlesUnderSurface, &ViewportWidget::setParticlesUnderSurface,
         kParticlesUnderSurfaceKey},
        {actions_.bubblesThroughWater, &ViewportWidget::setBubblesThroughWater,
         kBubblesThroughWaterKey},
    };
    for (const auto& layer : layers) {
        connect(layer.action, &QAction::toggled, &viewport_, layer.apply);
        remember(layer.action, layer.key);
        (viewport_.*layer.apply)(layer.action->isChecked());
    }
}

void ViewPreferences::connectSurfaceShading() {
    const QString saved =
        EditorSettings::store().value(QLatin1String(kSurfaceShadingKey)).toString();
    for (QAction* action : actions_.surfaceShading->actions())
        if (action->data().toString() == saved)
            action->setChecked(true);
    // Each action's own toggle, not the group's trigger: setChecked() (a screenshot's --surface)
    // must reach the viewport too.
    for (QAction* action : actions_.surfaceShading->actions())
        connect(action, &QAction::toggled, this, [this, action](bool checked) {
            if (!checked)
                return;
            viewport_.setSurfaceShading(shadingOf(action));
            EditorSettings::store().setValue(QLatin1String(kSurfaceShadingKey), action->data());
        });
    viewport_.setSurfaceShading(shadingOf(actions_.surfaceShading->checkedAction()));
}

void ViewPreferences::connectParticleSize() {
    connect(actions_.largerParticles, &QAction::triggered, this,
            [this] { setParticleSize(viewport_.particleSize() * kParticleSizeStep); });
    connect(actions_.smallerParticles, &QAction::triggered, this,
            [this] { setParticleSize(viewport_.particleSize() / kParticleSizeStep); });
    connect(actions_.defaultParticleSize, &QAction::triggered, this,
            [this] { setParticleSize(1.0f); });
    viewport_.setParticleSize(
        EditorSettings::store().value(QLatin1String(kParticleSizeKey), 1.0).toFloat());
}

void ViewPreferences::setParticleSize(float factor) {
    viewport_.setParticleSize(factor);
    EditorSettings::store().setValue(QLatin1String(kParticleSizeKey), viewport_.particleSize());
}

} // namespace airtrap
