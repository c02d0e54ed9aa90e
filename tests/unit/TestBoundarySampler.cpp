// Boundary particles: one layer on the box faces, unit normals on the water's side, an open top
// left out, and volumes that make a flat wall at the water's spacing stand for Δx³ each.
#include "rigid/BoundarySampler.h"
#include "sph/BoundaryVolumes.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cmath>

using namespace airtrap;

class TestBoundarySampler : public QObject {
    Q_OBJECT

    static constexpr double kSpacing = 0.02;

private Q_SLOTS:
    void samplesEveryFaceOnce() {
        const Aabb box{Vec3d::Zero(), Vec3d(0.2, 0.1, 0.1)}; // 10 × 5 × 5 lattice cells
        const BoundaryParticles closed =
            BoundarySampler::sampleBox(box, kSpacing, BoundarySampler::WaterSide::Outside, false);
        // Lattice points of the 11 × 6 × 6 grid minus its 9 × 4 × 4 interior.
        QCOMPARE(closed.size(), std::size_t(11 * 6 * 6 - 9 * 4 * 4));
        const BoundaryParticles open =
            BoundarySampler::sampleBox(box, kSpacing, BoundarySampler::WaterSide::Inside, true);
        QCOMPARE(open.size(), closed.size() - 11 * 6); // the top face's 11 × 6 points
        for (const Vec3f& p : open.positions)
            QVERIFY(p.y() < 0.1f - 1e-6f);
    }

    void normalsPointToTheWater() {
        const Aabb box{Vec3d::Zero(), Vec3d(0.2, 0.2, 0.2)};
        const Vec3f centre(0.1f, 0.1f, 0.1f);
        for (auto side :
             {BoundarySampler::WaterSide::Inside, BoundarySampler::WaterSide::Outside}) {
            const BoundaryParticles particles =
                BoundarySampler::sampleBox(box, kSpacing, side, false);
            const float sign = side == BoundarySampler::WaterSide::Inside ? -1.0f : 1.0f;
            for (std::size_t b = 0; b < particles.size(); ++b) {
                QVERIFY(std::abs(particles.normals[b].norm() - 1.0f) < 1e-5f);
                QVERIFY(sign * particles.normals[b].dot(particles.positions[b] - centre) > 0.0f);
            }
        }
    }

    void flatWallStandsForOneCubicSpacingPerParticle() {
        const CubicSplineKernel kernel(float(2.0 * kSpacing));
        const Aabb box{Vec3d::Zero(), Vec3d(1.0, 1.0, 1.0)};
        BoundaryParticles particles =
            BoundarySampler::sampleBox(box, kSpacing, BoundarySampler::WaterSide::Inside, true);
        BoundaryVolumes::compute(particles, kernel, kSpacing);
        const double cube = std::pow(kSpacing, 3);
        int faceParticles = 0;
        for (std::size_t b = 0; b < particles.size(); ++b) {
            const Vec3f& p = particles.positions[b];
            // The middle of the floor, away from edges.
            if (p.y() == 0.0f && p.x() > 0.2f && p.x() < 0.8f && p.z() > 0.2f && p.z() < 0.8f) {
                QVERIFY2(std::abs(particles.volumes[b] / cube - 1.0) < 1e-3,
                         qPrintable(QString::number(particles.volumes[b] / cube)));
                ++faceParticles;
            }
        }
        QVERIFY(faceParticles > 500);
        // A corner sees three quarter-planes of the layer instead of a whole plane: fewer
        // neighbours, so it stands for more.
        const std::size_t corner = 0; // (0, 0, 0) is the first lattice point sampled
        QCOMPARE(particles.positions[corner], Vec3f(0, 0, 0));
        qInfo("corner volume %.3f Δx³", particles.volumes[corner] / cube);
        QVERIFY(particles.volumes[corner] > 1.05 * cube && particles.volumes[corner] < 2.0 * cube);
    }
};

AIRTRAP_TEST_APPLESS(TestBoundarySampler)
#include "TestBoundarySampler.moc"
