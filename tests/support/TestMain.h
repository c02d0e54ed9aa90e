// Registers a Qt Test class with its executable's main() (TestMain.cpp). These stand in for
// QTEST_APPLESS_MAIN, QTEST_GUILESS_MAIN and QTEST_MAIN and set up the same application objects.
#pragma once

#include "TestRegistry.h"

#include <QTest>

#define AIRTRAP_TEST_CONCAT_(a, b) a##b
#define AIRTRAP_TEST_CONCAT(a, b) AIRTRAP_TEST_CONCAT_(a, b)

// __COUNTER__ keeps the registration variables apart when one unity batch holds several tests.
#define AIRTRAP_TEST_REGISTER_(TestObject, ...)                                                    \
    static const bool AIRTRAP_TEST_CONCAT(airtrapTestRegistered, __COUNTER__) =                    \
        airtrap::testing::TestRegistry::add(#TestObject, [](int argc, char** argv) -> int {        \
            QTest::Internal::callInitMain<TestObject>();                                           \
            __VA_ARGS__                                                                            \
            TestObject test;                                                                       \
            QTEST_SET_MAIN_SOURCE_PATH                                                             \
            return QTest::qExec(&test, argc, argv);                                                \
        });

// No application object: most engine tests.
#define AIRTRAP_TEST_APPLESS(TestObject) AIRTRAP_TEST_REGISTER_(TestObject)

// A QCoreApplication: tests that run processes or use an event loop.
#define AIRTRAP_TEST_GUILESS(TestObject)                                                           \
    AIRTRAP_TEST_REGISTER_(TestObject, QCoreApplication app(argc, argv);                           \
                           app.setAttribute(Qt::AA_Use96Dpi, true);)
