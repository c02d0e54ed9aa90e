// The cubic spline kernel: normalisation, compact support, gradient antisymmetry and agreement
// with a finite-difference derivative.
#include "sph/CubicSplineKernel.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using namespace airtrap;

class TestKernel : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void integratesToOne_data() {
        QTest::addColumn<float>("support");
        QTest::newRow("H = 0.04") << 0.04f;
        QTest::newRow("H = 1") << 1.0f;
    }

    void integratesToOne() {
        QFETCH(float, support);
        const CubicSplineKernel kernel(support);
        // Midpoint rule on a lattice fine enough for 1e-3.
        const int cells = 80;
        const double step = 2.0 * support / cells;
        double integral = 0.0;
        for (int k = 0; k < cells; ++k)
            for (int j = 0; j < cells; ++j)
                for (int i = 0; i < cells; ++i) {
                    const Eigen::Vector3d x =
                        (Eigen::Vector3d(i, j, k) + Eigen::Vector3d::Constant(0.5)) * step -
                        Eigen::Vector3d::Constant(support);
                    integral += kernel.value(static_cast<float>(x.norm()));
                }
        integral *= step * step * step;
        QVERIFY2(std::abs(integral - 1.0) < 1e-3, qPrintable(QString::number(integral)));
    }

    void vanishesAtSupport() {
        const CubicSplineKernel kernel(0.1f);
        QCOMPARE(kernel.value(0.1f), 0.0f);
        QCOMPARE(kernel.value(0.15f), 0.0f);
        QVERIFY(kernel.value(0.0999f) > 0.0f);
        QCOMPARE(kernel.gradient(Vec3f(0.12f, 0, 0), 0.12f), Vec3f::Zero());
    }

    void gradientIsAntisymmetric() {
        const CubicSplineKernel kernel(0.1f);
        for (const Vec3f& d : {Vec3f(0.01f, 0.02f, -0.03f), Vec3f(0.06f, -0.01f, 0.02f)}) {
            const Vec3f forward = kernel.gradient(d, d.norm());
            const Vec3f backward = kernel.gradient(-d, d.norm());
            QVERIFY((forward + backward).norm() < 1e-6f * forward.norm());
            QVERIFY(forward.dot(d) < 0.0f); // W falls with distance
        }
    }

    void gradientMatchesFiniteDifference() {
        const CubicSplineKernel kernel(0.1f);
        const float eps = 1e-4f;
        for (float r : {0.02f, 0.049f, 0.051f, 0.08f}) {
            const float numeric = (kernel.value(r + eps) - kernel.value(r - eps)) / (2 * eps);
            const float analytic = kernel.gradient(Vec3f(r, 0, 0), r).x();
            QVERIFY2(std::abs(numeric - analytic) < 1e-3f * std::abs(analytic),
                     qPrintable(
                         QString("r=%1 numeric %2 analytic %3").arg(r).arg(numeric).arg(analytic)));
        }
    }

    void tabulatedGradientMatchesAnalytic() {
        const CubicSplineKernel kernel(0.1f);
        // |∇W| peaks at q = 1/3; the table's error is measured against that scale.
        const float peak = kernel.gradient(Vec3f(0.1f / 3, 0, 0), 0.1f / 3).norm();
        for (float r = 0.1f / 16; r < 0.1f; r += 0.00037f) {
            const Vec3f d = Vec3f(0.3f, -0.5f, 0.8f).normalized() * r;
            const Vec3f exact = kernel.gradient(d, r);
            const Vec3f table = kernel.gradientFromSquared(d, r * r);
            QVERIFY2(
                (exact - table).norm() <= 1e-4f * peak,
                qPrintable(QString("r=%1: %2 vs %3").arg(r).arg(exact.norm()).arg(table.norm())));
            QVERIFY((kernel.gradientFromSquared(-d, r * r) + table).norm() == 0.0f);
        }
        QCOMPARE(kernel.gradientFromSquared(Vec3f(0.101f, 0, 0), 0.0102f), Vec3f::Zero());
    }

    void gradientFactorCodesStayWithinHalfAStep() {
        const CubicSplineKernel kernel(0.1f);
        const float largest = std::abs(kernel.gradientFactor(0.0f));
        QCOMPARE(kernel.gradientFactorCode(0.0f), std::uint16_t(65535));
        QCOMPARE(kernel.gradientFactorCode(0.0101f), std::uint16_t(0));
        for (float r = 0.0f; r < 0.1f; r += 0.0007f) {
            const float exact = kernel.gradientFactor(r * r);
            const float decoded =
                kernel.gradientFactorStep() * float(kernel.gradientFactorCode(r * r));
            QVERIFY2(std::abs(decoded - exact) <= 8e-6f * largest,
                     qPrintable(QString("r=%1: %2 vs %3").arg(r).arg(decoded).arg(exact)));
        }
    }

    //! The batch forms (four at a time on SSE2) give the same bits as value() and
    //! gradientFactorCode() one by one, at every distance within the support and past it, for a
    //! count that is not a multiple of four.
    void batchValuesAndCodesMatchOneByOne() {
        const CubicSplineKernel kernel(0.04f);
        std::vector<float> r2;
        for (float r = 0.0f; r < 0.045f; r += 0.000037f)
            r2.push_back(r * r);
        r2.push_back(0.04f * 0.04f);
        r2.push_back(0.25f * 0.04f * 0.04f); // q = ½ exactly
        QVERIFY(r2.size() % 4 != 0);
        const std::size_t count = r2.size();
        r2.resize(count + 3, 0.0f);
        std::vector<float> values(count + 3);
        std::vector<std::int32_t> codes(count + 3);
        kernel.valuesAndFactorCodes(r2.data(), count, values.data(), codes.data());
        std::vector<float> valuesAlone(count + 3);
        kernel.valuesOfSquared(r2.data(), count, valuesAlone.data());
        for (std::size_t k = 0; k < count; ++k) {
            const float oneByOne = kernel.value(std::sqrt(r2[k]));
            QVERIFY(std::memcmp(&valuesAlone[k], &oneByOne, sizeof(float)) == 0);
            QVERIFY2(
                std::memcmp(&values[k], &oneByOne, sizeof(float)) == 0,
                qPrintable(QString("r² = %1: %2 vs %3").arg(r2[k]).arg(values[k]).arg(oneByOne)));
            QCOMPARE(codes[k], std::int32_t(kernel.gradientFactorCode(r2[k])));
        }
    }
};

AIRTRAP_TEST_APPLESS(TestKernel)
#include "TestKernel.moc"
