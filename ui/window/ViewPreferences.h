#pragma once
// The View menu's display options, tied to the viewport: what the water of a cached frame is
// drawn as (particles, surface mesh and its shading, particle size) and whether bubbles show
// through it. Each choice is kept in the editor's settings as it is made, not on quit, so it
// survives a crash too, and the editor opens as the user left it.
#include <QObject>

namespace airtrap {

class EditorActions;
class ViewportWidget;

class ViewPreferences : public QObject {
    Q_OBJECT

public:
    //! Restores the remembered choices into `actions` and `viewport` and follows every change.
    ViewPreferences(const EditorActions& actions, ViewportWidget& viewport, QObject* parent);

    //! How much larger or smaller one step of the particle size actions draws them.
    static constexpr float kParticleSizeStep = 1.25f;

private:
    void connectLayers();
    void connectSurfaceShading();
    void connectParticleSize();
    void setParticleSize(float factor);

    const EditorActions& actions_;
    ViewportWidget& viewport_;
};

} // namespace airtrap
