#pragma once
// The pressure solvers a physics test runs with, as QtTest rows: one column "method" holding the
// scene's solver.method.
#include <QtTest>

namespace airtrap::test {

inline void addSolverMethodRows() {
    QTest::addColumn<QString>("method");
    QTest::newRow("wcsph") << "wcsph";
    QTest::newRow("dfsph") << "dfsph";
}

} // namespace airtrap::test
