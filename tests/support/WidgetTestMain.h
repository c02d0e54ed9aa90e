// AIRTRAP_TEST_WIDGETS: the QTEST_MAIN of the editor's tests, with a QApplication.
#pragma once

#include "TestMain.h"

#include <QApplication>

#define AIRTRAP_TEST_WIDGETS(TestObject)                                                           \
    AIRTRAP_TEST_REGISTER_(TestObject, QApplication app(argc, argv);                               \
                           app.setAttribute(Qt::AA_Use96Dpi, true);)
