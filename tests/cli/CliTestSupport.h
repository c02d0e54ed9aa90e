#pragma once
// Helpers for the airtrap-cli tests: run the real binary, write tiny scenes, read files back.
#include "bubbles/BubbleState.h"
#include "core/Math.h"

#include <QProcess>
#include <QtTest/QtTest>
#include <cstdint>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap::clitest {

//! How one run of airtrap-cli ended.
struct CliResult {
    int exitCode = -1; //!< -1 when it crashed or timed out
    QString out;
    QString err;
};

inline QString cliPath() {
    return QStringLiteral(AIRTRAP_BINARY_DIR "/bin/airtrap-cli");
}

//! Runs airtrap-cli to the end. `modifier` runs in the child before exec (limits, signals);
//! `environment` is the child's (the fault tests preload a library through it).
inline CliResult
runCli(const QStringList& arguments, const std::function<void()>& modifier = {},
       const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment()) {
    QProcess process;
    process.setProcessEnvironment(environment);
    if (modifier)
        process.setChildProcessModifier(modifier);
    process.start(cliPath(), arguments);
    CliResult result;
    if (!process.waitForStarted(10000) || !process.waitForFinished(300000)) {
        process.kill();
        process.waitForFinished();
        result.err = "did not start or finish: " + process.errorString();
        return result;
    }
    result.out = QString::fromUtf8(process.readAllStandardOutput());
    result.err = QString::fromUtf8(process.readAllStandardError());
    if (process.exitStatus() == QProcess::NormalExit)
        result.exitCode = process.exitCode();
    return result;
}

//! A 0.2 m cube of water (125 particles at 0.04 m) in a 0.3 m tank: a bake of a few frames
//! takes well under a second.
inline std::string tinySceneText(int endFrame) {
    const nlohmann::json scene = {
        {"format_version", 1},
        {"name", "Tiny"},
        {"solver", {{"particle_spacing", 0.04}, {"max_speed", 2.0}}},
        {"frames", {{"fps", 60.0}, {"end_frame", endFrame}}},
        {"container", {{"min", {0, 0, 0}}, {"max", {0.3, 0.3, 0.3}}, {"headroom", 0.2}}},
        {"fluid_blocks", {{{"name", "Water"}, {"min", {0, 0, 0}}, {"max", {0.2, 0.2, 0.2}}}}}};
    return scene.dump(4) + "\n";
}

inline void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

inline std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

//! A bubble of `radius` at `centre`, rising at `velocity`, `age` seconds old.
inline BubbleState bubbleAt(std::uint32_t id, const Vec3d& centre, double radius,
                            const Vec3d& velocity, double age) {
    BubbleState bubble;
    bubble.id = id;
    bubble.birthFrame = 2;
    bubble.radius = radius;
    bubble.body.position = centre;
    bubble.body.linearVelocity = velocity;
    bubble.age = age;
    return bubble;
}

//! The tiny scene with bubbles switched on.
inline std::string tinyBubbleSceneText(int endFrame) {
    nlohmann::json scene = nlohmann::json::parse(tinySceneText(endFrame));
    scene["bubbles"] = {{"enabled", true}};
    return scene.dump(4) + "\n";
}

inline nlohmann::json readJson(const std::string& path) {
    return nlohmann::json::parse(readBytes(path));
}

inline QStringList args(std::initializer_list<std::string> words) {
    QStringList list;
    for (const std::string& word : words)
        list << QString::fromStdString(word);
    return list;
}

} // namespace airtrap::clitest

//! Fails with the run's stderr when the exit code differs: that is where the reason is.
#define QCOMPARE_EXIT(result, expected)                                                            \
    QVERIFY2((result).exitCode == (expected),                                                      \
             qPrintable(QStringLiteral("exit %1, expected %2; stderr: %3")                         \
                            .arg((result).exitCode)                                                \
                            .arg(expected)                                                         \
                            .arg((result).err)))

//! `text` (a QString) contains `part`, else fails showing the text.
#define QVERIFY_CONTAINS(text, part)                                                               \
    QVERIFY2((text).contains(QString::fromStdString(std::string(part))),                           \
             qPrintable(QStringLiteral("lacks \"%1\": %2")                                         \
                            .arg(QString::fromStdString(std::string(part)), text)))
