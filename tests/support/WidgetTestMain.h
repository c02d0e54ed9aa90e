// AIRTRAP_TEST_WIDGETS: the QTEST_MAIN of the editor's tests, with a QApplication. The editor's
// settings are a scratch store of the test's own (EditorSettings::useScratchStore), so no test
// reads or writes the user's (recent files, view options, window layout).
#pragma once

#include "TestMain.h"
#include "window/EditorSettings.h"

#include <QApplication>
#include <QStandardPaths>

#define AIRTRAP_TEST_WIDGETS(TestObject)                                                           \
    AIRTRAP_TEST_REGISTER_(                                                                        \
        TestObject, QApplication app(argc, argv); app.setAttribute(Qt::AA_Use96Dpi, true);         \
        QStandardPaths::setTestModeEnabled(true); airtrap::EditorSettings::useScratchStore();)
