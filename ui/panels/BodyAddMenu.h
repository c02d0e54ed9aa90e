#pragma once
// Add ▸ Body: one entry per shape — Box, Sphere, Cylinder, and Mesh from file…, which checks the
// mesh with the engine's own loader before anything is added, so a mesh the bake would refuse
// (not closed, unreadable) never enters the scene.
#include "document/SceneItem.h"

#include <QMenu>
#include <functional>
#include <string>

namespace airtrap {

class SceneDocument;

class BodyAddMenu : public QMenu {
    Q_OBJECT

public:
    //! Asks for a mesh file; an empty string cancels.
    using MeshFileChooser = std::function<QString()>;

    BodyAddMenu(SceneDocument& document, QWidget* parent = nullptr);

    //! Replaces the file dialog of "Mesh from file…" (for tests).
    void setMeshFileChooser(MeshFileChooser chooser) { chooseMeshFile_ = std::move(chooser); }
    //! The file dialog's name filter: the formats the engine's mesh loader reads.
    static QString meshFileFilter();
    //! How the scene stores `file`: relative to the scene file's folder when the scene has been
    //! saved (the scene and its meshes move together), else absolute.
    static QString meshReference(const QString& sceneFile, const QString& file);

public Q_SLOTS:
    //! Adds a body of `shape` ("box", "sphere", "cylinder"), one undo step.
    void addPrimitive(const std::string& shape);
    //! Asks for a file, then adds a mesh body for it (see addMesh).
    void chooseAndAddMesh();
    //! Adds a mesh body for `file` when the engine can use the mesh; otherwise emits
    //! meshRefused with the engine's reason and adds nothing.
    void addMesh(const QString& file);

Q_SIGNALS:
    //! A body was added (select it).
    void bodyAdded(const airtrap::SceneItem& item);
    //! The mesh file cannot be a body: the engine's message, naming the file and the reason.
    void meshRefused(const QString& reason);

private:
    QString chooseWithDialog() const;

    SceneDocument& document_;
    MeshFileChooser chooseMeshFile_;
};

} // namespace airtrap
