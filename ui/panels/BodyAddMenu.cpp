#include "panels/BodyAddMenu.h"

#include "controller/BodyMeshCache.h"
#include "core/Error.h"
#include "document/BodyTemplate.h"
#include "document/SceneDocument.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>

namespace airtrap {

namespace {
constexpr auto kSection = "bodies";
} // namespace

BodyAddMenu::BodyAddMenu(SceneDocument& document, QWidget* parent)
    : QMenu(tr("&Body"), parent), document_(document),
      chooseMeshFile_([this] { return chooseWithDialog(); }) {
    setObjectName(QStringLiteral("addBodyMenu"));
    const struct {
        const char* shape;
        QString text;
    } primitives[] = {
        {"box", tr("&Box")}, {"sphere", tr("&Sphere")}, {"cylinder", tr("&Cylinder")}};
    for (const auto& primitive : primitives) {
        const std::string shape = primitive.shape;
        QAction* action = addAction(primitive.text, this, [this, shape] { addPrimitive(shape); });
        action->setObjectName(QStringLiteral("add_bodies_") + QLatin1String(primitive.shape));
        action->setStatusTip(
            tr("Add a %1 body above the water").arg(QLatin1String(primitive.shape)));
    }
    QAction* mesh = addAction(tr("&Mesh from File…"), this, &BodyAddMenu::chooseAndAddMesh);
    mesh->setObjectName(QStringLiteral("add_bodies_mesh"));
    mesh->setStatusTip(tr("Add a body shaped like a closed triangle mesh from a file"));
}

QString BodyAddMenu::meshFileFilter() {
    return tr("Meshes (*.obj *.ply *.stl *.fbx *.dae *.3ds *.off);;All files (*)");
}

QString BodyAddMenu::meshReference(const QString& sceneFile, const QString& file) {
    const QString absolute = QFileInfo(file).absoluteFilePath();
    if (sceneFile.isEmpty())
        return absolute;
    return QFileInfo(sceneFile).absoluteDir().relativeFilePath(absolute);
}

void BodyAddMenu::addPrimitive(const std::string& shape) {
    const nlohmann::json body = BodyTemplate::primitive(document_.scene(), shape);
    const QString name = QString::fromStdString(body["name"].get<std::string>());
    Q_EMIT bodyAdded(document_.addElement(kSection, body, tr("Add %1").arg(name)));
}

QString BodyAddMenu::chooseWithDialog() const {
    const QString folder =
        document_.filePath().isEmpty() ? QString() : QFileInfo(document_.filePath()).absolutePath();
    return QFileDialog::getOpenFileName(parentWidget(), tr("Add Mesh Body"), folder,
                                        meshFileFilter());
}

void BodyAddMenu::chooseAndAddMesh() {
    const QString file = chooseMeshFile_();
    if (!file.isEmpty())
        addMesh(file);
}

void BodyAddMenu::addMesh(const QString& file) {
    const std::string reference = meshReference(document_.filePath(), file).toStdString();
    // Checked as the bake will read it: the scene with this body in it, so the engine's message
    // names the body it would have been.
    Scene scene = document_.scene();
    RigidBodySettings candidate;
    candidate.shape = "mesh";
    candidate.mesh = reference;
    scene.bodies.push_back(candidate);
    TriangleMesh mesh;
    try {
        mesh = BodyMeshCache::readMesh(scene, scene.bodies.back());
    } catch (const Error& error) {
        Q_EMIT meshRefused(QString::fromUtf8(error.what()));
        return;
    }
    const nlohmann::json body = BodyTemplate::mesh(document_.scene(), reference, mesh);
    const QString name = QString::fromStdString(body["name"].get<std::string>());
    Q_EMIT bodyAdded(document_.addElement(kSection, body, tr("Add %1").arg(name)));
}

} // namespace airtrap
