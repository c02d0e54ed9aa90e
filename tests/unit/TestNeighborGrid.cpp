// The neighbour grid finds exactly the pairs a brute-force search finds (also through the
// batched sweep the SPH passes use, which skips rows out of reach), sorts stably by cell, drops
// points outside the domain, and reports occupancy.
#include "sph/NeighborGrid.h"
#include "sph/NeighborSweep.h"
#include "support/TestMain.h"

#include <QtTest>
#include <algorithm>
#include <random>
#include <set>
#include <utility>

using namespace airtrap;

namespace {

std::vector<Vec3f> randomPoints(std::size_t count, const Aabb& box, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Vec3f> points(count);
    for (Vec3f& p : points)
        p = box.min.cast<float>() +
            Vec3f(u(rng), u(rng), u(rng)).cwiseProduct(box.size().cast<float>());
    return points;
}

} // namespace

class TestNeighborGrid : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void neighboursEqualBruteForce_data() {
        QTest::addColumn<int>("count");
        QTest::addColumn<float>("radius");
        QTest::newRow("sparse") << 500 << 0.05f;
        QTest::newRow("dense") << 4000 << 0.12f;
    }

    void neighboursEqualBruteForce() {
        QFETCH(int, count);
        QFETCH(float, radius);
        const Aabb domain{Vec3d(-0.3, 0.0, 0.1), Vec3d(0.7, 0.6, 0.5)};
        const std::vector<Vec3f> points = randomPoints(count, domain, 42);
        NeighborGrid grid(domain, radius);
        grid.build(points);
        const auto& order = grid.order();
        QCOMPARE(order.size(), points.size());

        const float r2 = radius * radius;
        std::set<std::pair<std::uint32_t, std::uint32_t>> fromGrid, bruteForce;
        for (std::uint32_t s = 0; s < order.size(); ++s) {
            const Vec3f& x = points[order[s]];
            grid.forEachNeighborRange(x, radius, [&](std::uint32_t begin, std::uint32_t end) {
                for (std::uint32_t t = begin; t < end; ++t)
                    if (t != s && (x - points[order[t]]).squaredNorm() < r2)
                        fromGrid.insert({order[s], order[t]});
            });
        }
        for (std::uint32_t a = 0; a < points.size(); ++a)
            for (std::uint32_t b = 0; b < points.size(); ++b)
                if (a != b && (points[a] - points[b]).squaredNorm() < r2)
                    bruteForce.insert({a, b});
        QVERIFY(!bruteForce.empty());
        QCOMPARE(fromGrid.size(), bruteForce.size());
        QVERIFY(fromGrid == bruteForce);
    }

    void sweepEqualsBruteForce() {
        const Aabb domain{Vec3d(0.0, -0.2, 0.0), Vec3d(0.8, 0.4, 0.5)};
        const std::vector<Vec3f> points = randomPoints(3000, domain, 11);
        const float radius = 0.09f;
        NeighborGrid grid(domain, radius);
        grid.build(points);
        const auto& order = grid.order();
        PositionArrays sorted;
        sorted.resize(order.size());
        for (std::size_t s = 0; s < order.size(); ++s) {
            sorted.x[s] = points[order[s]].x();
            sorted.y[s] = points[order[s]].y();
            sorted.z[s] = points[order[s]].z();
        }
        std::size_t pairs = 0;
        for (std::size_t s = 0; s < order.size(); ++s) {
            std::set<std::uint32_t> found, expected;
            sweepNeighbors(grid, sorted, s, radius * radius,
                           [&](std::uint32_t j, const Vec3f&, float) { found.insert(order[j]); });
            for (std::uint32_t b = 0; b < points.size(); ++b)
                if (b != order[s] && (points[order[s]] - points[b]).squaredNorm() < radius * radius)
                    expected.insert(b);
            QVERIFY(found == expected);
            pairs += found.size();
        }
        QVERIFY(pairs > 10 * order.size());
    }

    void ballRangesHoldEveryPointWithinTheRadiusOnce_data() {
        QTest::addColumn<double>("radius");
        QTest::addColumn<bool>("trimmed"); // whether the ball leaves out corners of its box
        QTest::newRow("inside one cell") << 0.05 << false;
        QTest::newRow("three cells") << 0.25 << true;
        QTest::newRow("past the domain") << 0.6 << false;
    }

    void ballRangesHoldEveryPointWithinTheRadiusOnce() {
        QFETCH(double, radius);
        QFETCH(bool, trimmed);
        const Aabb domain{Vec3d(0.0, -0.2, 0.0), Vec3d(0.8, 0.4, 0.5)};
        const std::vector<Vec3f> points = randomPoints(20000, domain, 5);
        NeighborGrid grid(domain, 0.09f);
        grid.build(points);
        const auto& order = grid.order();
        for (const Vec3d& centre : {Vec3d(0.4, 0.1, 0.25), Vec3d(0.05, 0.35, 0.47)}) {
            std::vector<int> visits(points.size(), 0);
            std::size_t visited = 0;
            grid.forEachRangeInBall(centre, radius, [&](std::uint32_t begin, std::uint32_t end) {
                for (std::uint32_t s = begin; s < end; ++s, ++visited)
                    ++visits[order[s]];
            });
            std::size_t inside = 0, inBox = 0;
            for (std::size_t p = 0; p < points.size(); ++p) {
                const Vec3d offset = points[p].cast<double>() - centre;
                QVERIFY(visits[p] <= 1);
                if (offset.norm() < radius) {
                    QVERIFY(visits[p] == 1);
                    ++inside;
                }
                inBox += (offset.cwiseAbs().array() < radius + grid.cellSize()).all();
            }
            QVERIFY(inside > 0);
            // The rows are trimmed to the ball: fewer points than the cells of its bounding box.
            if (trimmed)
                QVERIFY2(
                    visited < inBox,
                    qPrintable(QString("%1 visited of %2 in the box").arg(visited).arg(inBox)));
        }
    }

    void reshapedGridSortsItsPointsAsTheWholeGridDoes() {
        const Aabb whole{Vec3d::Zero(), Vec3d::Ones()};
        const std::vector<Vec3f> points =
            randomPoints(500, Aabb{Vec3d(0.3, 0.4, 0.2), Vec3d(0.6, 0.7, 0.5)}, 3);
        NeighborGrid full(whole, 0.1f);
        full.build(points);
        NeighborGrid window(whole, 0.1f);
        window.reshape(Aabb{Vec3d(0.2, 0.3, 0.1), Vec3d(0.7, 0.8, 0.6)}); // whole cells
        window.build(points);
        QVERIFY(window.cellTotal() < full.cellTotal() / 4);
        QCOMPARE(window.order(), full.order());
        QVERIFY(window.contains(points[0]));
        QVERIFY(!window.contains(Vec3f(0.1f, 0.5f, 0.5f)));
    }

    void sortIsStableAndGroupsCells() {
        const Aabb domain{Vec3d::Zero(), Vec3d::Ones()};
        const std::vector<Vec3f> points = randomPoints(2000, domain, 7);
        NeighborGrid grid(domain, 0.1f);
        grid.build(points);
        const auto& order = grid.order();
        int previousCell = -1;
        std::uint32_t previousIndex = 0;
        for (std::uint32_t s = 0; s < order.size(); ++s) {
            const Vec3i c = grid.cellCoordinates(points[order[s]]);
            const int cell = grid.linearIndex(c.x(), c.y(), c.z());
            QVERIFY(cell >= previousCell);
            if (cell == previousCell)
                QVERIFY(order[s] > previousIndex); // stable: input order kept within a cell
            previousCell = cell;
            previousIndex = order[s];
        }
    }

    void dropsPointsOutsideTheDomain() {
        const Aabb domain{Vec3d::Zero(), Vec3d::Ones()};
        std::vector<Vec3f> points = {Vec3f(0.5f, 0.5f, 0.5f), Vec3f(1.5f, 0.5f, 0.5f),
                                     Vec3f(0.2f, std::nanf(""), 0.1f), Vec3f(0.9f, 0.9f, 0.9f)};
        NeighborGrid grid(domain, 0.25f);
        grid.build(points);
        QCOMPARE(grid.outsideCount(), std::size_t(2));
        QCOMPARE(grid.order(), (std::vector<std::uint32_t>{0, 3}));
    }

    void reportsOccupancy() {
        const Aabb domain{Vec3d::Zero(), Vec3d::Ones()};
        const std::vector<Vec3f> points = {Vec3f(0.1f, 0.1f, 0.1f), Vec3f(0.15f, 0.12f, 0.1f),
                                           Vec3f(0.9f, 0.9f, 0.9f)};
        NeighborGrid grid(domain, 0.25f);
        grid.build(points);
        std::uint32_t total = 0;
        int occupied = 0;
        for (std::size_t c = 0; c < grid.cellTotal(); ++c) {
            total += grid.cellCount(static_cast<int>(c));
            occupied += grid.cellCount(static_cast<int>(c)) > 0;
        }
        QCOMPARE(total, 3u);
        QCOMPARE(occupied, 2);
        const Vec3i c = grid.cellCoordinates(points[0]);
        QCOMPARE(grid.cellCount(grid.linearIndex(c.x(), c.y(), c.z())), 2u);
        QCOMPARE(grid.dimensions(), Vec3i(6, 6, 6)); // 4 cells + a ghost layer on each side
    }
};

AIRTRAP_TEST_APPLESS(TestNeighborGrid)
#include "TestNeighborGrid.moc"
