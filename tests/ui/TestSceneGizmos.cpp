// The gizmos the viewport draws and picks: an emitter is drawn as its nozzle (a disc or a
// rectangle across the jet) with an arrow along the jet, and picked by the box around it.
#include "support/TestMain.h"
#include "viewport/SceneGizmos.h"

#include <QTest>
#include <cmath>

namespace airtrap {

namespace {

Scene sceneWithEmitter(const std::string& shape) {
    Scene scene;
    InflowEmitterSettings emitter;
    emitter.shape = shape;
    emitter.position = Vec3d(0.5, 0.8, 0.5);
    emitter.direction = Vec3d(0.0, -2.0, 0.0); // any length: normalised when used
    emitter.radius = 0.04;
    emitter.width = 0.1;
    emitter.height = 0.06;
    scene.emitters.push_back(emitter);
    return scene;
}

const GizmoBox& emitterGizmo(const SceneGizmos& gizmos) {
    return gizmos.boxes().back(); // container first, emitters last
}

} // namespace

class TestSceneGizmos : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void aDiscNozzleIsACircleAcrossTheJet() {
        const SceneGizmos gizmos(sceneWithEmitter("disc"));
        const GizmoBox& box = emitterGizmo(gizmos);
        QCOMPARE(box.kind, GizmoBox::Kind::Emitter);
        QCOMPARE(box.outline.size(), std::size_t(48));
        for (const QVector3D& point : box.outline) {
            QCOMPARE_LT(std::abs((point - box.centre).length() - 0.04f), 1e-5f);
            QCOMPARE_LT(std::abs(point.y() - 0.8f), 1e-6f); // in the exit plane
        }
        // The arrow points along the jet, down, twice the nozzle's size long.
        QVERIFY(qFuzzyCompare(box.jet, QVector3D(0.0f, -0.08f, 0.0f)));
    }

    void aRectangleNozzleHasItsFourCorners() {
        const SceneGizmos gizmos(sceneWithEmitter("rectangle"));
        const GizmoBox& box = emitterGizmo(gizmos);
        QCOMPARE(box.outline.size(), std::size_t(4));
        float area = 0.0f;
        for (std::size_t k = 0; k < 4; ++k) {
            const QVector3D a = box.outline[k] - box.centre;
            const QVector3D b = box.outline[(k + 1) % 4] - box.centre;
            area += 0.5f * QVector3D::crossProduct(a, b).length();
            QCOMPARE_LT(std::abs(box.outline[k].y() - 0.8f), 1e-6f);
        }
        QCOMPARE_LT(std::abs(area - 0.1f * 0.06f), 1e-6f);
    }

    void theNozzleStaysPickable() {
        const SceneGizmos gizmos(sceneWithEmitter("disc"));
        const Ray down{QVector3D(0.5f, 2.0f, 0.5f), QVector3D(0.0f, -1.0f, 0.0f)};
        QCOMPARE(gizmos.pick(down, SceneGizmos::PickOptions{}),
                 SceneItem::elementItem("emitters", 0));
    }
};

} // namespace airtrap

AIRTRAP_TEST_GUILESS(airtrap::TestSceneGizmos)
#include "TestSceneGizmos.moc"
