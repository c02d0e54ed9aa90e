#pragma once
// Helpers shared by the scene tests: capture an engine error, write a scene file to a temporary
// folder.
#include "core/Error.h"
#include "core/Math.h"

#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace airtrap::test {

//! The message of the Error `action` throws, or an empty string when it throws nothing.
inline std::string errorMessage(const std::function<void()>& action,
                                ErrorKind expected = ErrorKind::InvalidScene) {
    try {
        action();
    } catch (const Error& error) {
        if (error.kind() != expected)
            return std::string("wrong error kind: ") + error.what();
        return error.what();
    }
    return {};
}

//! Writes `text` to `name` inside `folder` and returns the file's path.
inline std::string writeFile(const QTemporaryDir& folder, const std::string& name,
                             const std::string& text) {
    const std::string path = folder.path().toStdString() + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

//! The whole of the file at `path` (empty when it cannot be read).
inline std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

//! True when `text` contains `part`; for QVERIFY2 with the text as the failure message.
inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace airtrap::test

// QCOMPARE prints the values it compares only for types QTest knows how to print.
namespace QTest {
template <>
inline char* toString(const std::string& text) {
    return qstrdup(("\"" + text + "\"").c_str());
}
template <>
inline char* toString(const airtrap::Vec3d& vector) {
    return qstrdup(QByteArray("[" + QByteArray::number(vector.x()) + ", " +
                              QByteArray::number(vector.y()) + ", " +
                              QByteArray::number(vector.z()) + "]")
                       .constData());
}
} // namespace QTest
