// Tait equation of state (paper eq. 3): p = B((ρ/ρ₀)^7 − 1), B = ρ₀c²/7, c = 10·u_max, with the
// negative branch clamped to zero.
#include "sph/TaitEquationOfState.h"
#include "support/TestMain.h"

#include <QtTest>
#include <cmath>

using namespace airtrap;

class TestEquationOfState : public QObject {
    Q_OBJECT

    static TaitEquationOfState equationWith(double maxSpeed) {
        SolverSettings settings;
        settings.maxSpeed = maxSpeed;
        return TaitEquationOfState(settings);
    }

private Q_SLOTS:
    void speedOfSoundIsTenTimesMaxSpeed() { QCOMPARE(equationWith(4.0).speedOfSound(), 40.0); }

    void restDensityHasZeroPressure() { QCOMPARE(equationWith(10.0).pressure(1000.0f), 0.0f); }

    void matchesTaitAtOnePercentCompression() {
        const TaitEquationOfState equation = equationWith(10.0);
        const double b = 1000.0 * 100.0 * 100.0 / 7.0;           // B = ρ₀c²/γ with c = 100 m/s
        const double expected = b * (std::pow(1.01, 7.0) - 1.0); // ≈ 1.03e5 Pa
        QVERIFY(std::abs(equation.pressure(1010.0f) - expected) < 1e-4 * expected);
    }

    void clampsTensionToZero() { QCOMPARE(equationWith(10.0).pressure(990.0f), 0.0f); }

    void densityForPressureInvertsTheEquation() {
        const TaitEquationOfState equation = equationWith(3.0);
        for (double p : {0.0, 981.0, 4905.0, 2.0e4}) {
            const float rho = equation.densityForPressure(p);
            QVERIFY2(std::abs(equation.pressure(rho) - p) < 1e-3 * std::max(p, 1.0) + 0.5,
                     qPrintable(QString("p=%1 rho=%2").arg(p).arg(rho)));
        }
    }
};

AIRTRAP_TEST_APPLESS(TestEquationOfState)
#include "TestEquationOfState.moc"
