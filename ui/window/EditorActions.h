#pragma once
// Every menu and toolbar action of the editor, with its text, shortcut, icon and status tip, in
// one place so the menus, the toolbar and the tests find the same objects. MainWindow connects
// them; this class only makes them.
#include <QObject>

class QAction;
class QActionGroup;
class QWidget;

namespace airtrap {

class EditorActions : public QObject {
    Q_OBJECT

public:
    //! The actions are children of `window`, so their shortcuts work anywhere in it.
    explicit EditorActions(QWidget* window);

    // File
    QAction* newScene;
    QAction* openScene;
    QAction* openCache;
    QAction* saveScene;
    QAction* saveSceneAs;
    QAction* quit;
    // Edit (Undo and Redo come from the undo stack)
    QAction* duplicate;
    QAction* remove;
    QAction* rename;
    // Simulation
    QAction* bake;
    QAction* pause;
    QAction* resume;
    QAction* stop;
    QAction* clearCache;
    QAction* post;
    QAction* exportSequences;
    QAction* cancelRenderOutputs;
    // View
    QAction* frameAll;
    QAction* frameSelected;
    QAction* viewFront;
    QAction* viewSide;
    QAction* viewTop;
    QAction* viewPerspective;
    QAction* orthographic;
    QAction* showGrid;
    QAction* showAxes;
    QAction* showGizmos;
    QAction* showWater;
    QAction* showSurface;
    QAction* particlesUnderSurface;
    // The surface's shading, one of three (exclusive; each action's data is its shading's name)
    QAction* translucentSurface;
    QAction* opaqueSurface;
    QAction* wireframeSurface;
    QActionGroup* surfaceShading;
    QAction* bubblesThroughWater;
    // The particles' drawn size
    QAction* largerParticles;
    QAction* smallerParticles;
    QAction* defaultParticleSize;
    // Playback
    QAction* playPause;
    QAction* stepForward;
    QAction* stepBackward;
    QAction* firstFrame;
    QAction* lastFrame;
    QAction* loop;
    // Help
    QAction* guide;
    QAction* shortcutSheet;
    QAction* about;

private:
    QAction* make(const char* objectName, const QString& text, const QString& statusTip);
    void makeCameraActions();
    void makeFileActions();
    void makeEditActions();
    void makeSimulationActions();
    void makeViewActions();
    void makeSurfaceShadingActions();
    void makeParticleSizeActions();
    void makePlaybackActions();

    QWidget* window_;
};

} // namespace airtrap
