#pragma once
// Helpers for the fault-injection tests (docs/TESTING.md "Fault injection"): a reference run to
// compare with, the preload library that makes writes fail, processes stopped at chosen moments,
// and comparisons of whole folders that ignore only what two correct runs may differ in (the
// wall-clock times a frame and the post list record, the UUID OpenVDB gives every file).
#include "cache/FrameFile.h"
#include "cli/CliTestSupport.h"
#include "post/SequenceName.h"

#include <QProcess>
#include <QThread>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <openvdb/openvdb.h>
#include <string>
#include <vector>

namespace airtrap::faulttest {

using namespace airtrap::clitest;
namespace fs = std::filesystem;

//! The cli tests' tiny tank with bubbles on, so that post writes every kind of result: water
//! meshes, volumes, sub-grid bubbles and both lists.
inline std::string bubbleSceneText(int endFrame) {
    nlohmann::json scene = nlohmann::json::parse(tinySceneText(endFrame));
    scene["bubbles"] = {{"enabled", true}};
    return scene.dump(4) + "\n";
}

//! What the preload library (tests/faults/shim/WriteFault.cpp) does to writes under `dir`.
struct DiskFault {
    std::string dir;
    long long writeLimit = -1;  //!< bytes until the disk is full; -1: never
    std::string openError = {}; //!< "EROFS" or "EACCES": every open for writing fails
};

inline QProcessEnvironment environmentWith(const DiskFault& fault) {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("LD_PRELOAD", AIRTRAP_WRITE_FAULT_LIBRARY);
    environment.insert("AIRTRAP_FAULT_DIR", QString::fromStdString(fault.dir));
    if (fault.writeLimit >= 0)
        environment.insert("AIRTRAP_FAULT_WRITE_LIMIT", QString::number(fault.writeLimit));
    if (!fault.openError.empty())
        environment.insert("AIRTRAP_FAULT_OPEN_ERROR", QString::fromStdString(fault.openError));
    return environment;
}

inline CliResult runCliWith(const DiskFault& fault, const QStringList& arguments) {
    return runCli(arguments, {}, environmentWith(fault));
}

//! How a run stopped from outside ended.
struct StoppedRun {
    bool stoppedEarly = false; //!< false: it had finished before the signal was due
    int exitCode = -1;         //!< -1 when the signal killed it
    QByteArray err;
};

//! Runs airtrap-cli and sends `signal` after `delay`, unless it finished first.
inline StoppedRun runAndSignal(const QStringList& arguments, std::chrono::milliseconds delay,
                               int signal) {
    QProcess process;
    process.start(cliPath(), arguments);
    StoppedRun run;
    if (!process.waitForStarted(10000))
        return run;
    if (!process.waitForFinished(int(delay.count()))) {
        run.stoppedEarly = true;
        ::kill(pid_t(process.processId()), signal);
        process.waitForFinished(60000);
    }
    run.err = process.readAllStandardError();
    if (process.exitStatus() == QProcess::NormalExit)
        run.exitCode = process.exitCode();
    return run;
}

//! Starts airtrap-cli, waits until its stderr shows `mark`, then sends `signal`. Returns the
//! run's end; `stoppedEarly` is false when the mark never came.
inline StoppedRun signalAtMark(const QStringList& arguments, const QByteArray& mark, int signal) {
    QProcess process;
    process.setReadChannel(QProcess::StandardError);
    process.start(cliPath(), arguments);
    StoppedRun run;
    if (!process.waitForStarted(10000))
        return run;
    while (!run.err.contains(mark) && process.waitForReadyRead(60000))
        run.err += process.readAllStandardError();
    if (run.err.contains(mark)) {
        run.stoppedEarly = true;
        ::kill(pid_t(process.processId()), signal);
    }
    process.waitForFinished(60000);
    run.err += process.readAllStandardError();
    if (process.exitStatus() == QProcess::NormalExit)
        run.exitCode = process.exitCode();
    return run;
}

//! Every regular file under `dir`, as paths relative to it, sorted.
inline std::vector<std::string> filesUnder(const std::string& dir) {
    std::vector<std::string> files;
    if (!fs::exists(dir))
        return files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file())
            files.push_back(fs::relative(entry.path(), dir).string());
    std::sort(files.begin(), files.end());
    return files;
}

//! The files AtomicFile leaves when its writer dies before the rename.
inline std::vector<std::string> temporariesUnder(const std::string& dir) {
    std::vector<std::string> found;
    for (const std::string& file : filesUnder(dir))
        if (file.ends_with(".tmp"))
            found.push_back(file);
    return found;
}

//! A frame's simulated state as bytes, without its wall-clock statistics.
inline std::vector<std::uint8_t> frameState(const std::string& path) {
    return encodeFrame(decodeFrame(readBytes(path), path).state, FrameStats{});
}

//! A list file without what differs between two correct runs: the seconds each frame took, the
//! CRC-32 of each volume file (which holds OpenVDB's random UUID) and of each source frame (which
//! holds the bake's wall-clock statistics), and the sub-grid chain built from the latter. The
//! files these name are compared one by one.
inline nlohmann::json withoutRunDetails(nlohmann::json json) {
    if (json.is_object()) {
        for (const char* key : {"seconds", "fluid_crc32", "source_crc32", "chain_crc32"})
            json.erase(key);
        for (auto& [key, value] : json.items())
            value = withoutRunDetails(value);
    } else if (json.is_array()) {
        for (auto& value : json)
            value = withoutRunDetails(value);
    }
    return json;
}

//! When both grids are of type `Grid`, whether every active voxel of `a` has its value in `b`;
//! true for grids of another type.
template <class Grid>
bool sameValues(const openvdb::GridBase& a, const openvdb::GridBase& b) {
    const auto* typedA = dynamic_cast<const Grid*>(&a);
    const auto* typedB = dynamic_cast<const Grid*>(&b);
    if (typedA == nullptr || typedB == nullptr)
        return true;
    const auto accessor = typedB->getConstAccessor();
    for (auto voxel = typedA->cbeginValueOn(); voxel; ++voxel)
        if (accessor.getValue(voxel.getCoord()) != *voxel)
            return false;
    return true;
}

//! Two OpenVDB files hold the same grids with the same values (their UUIDs differ).
inline bool sameVolumes(const std::string& path, const std::string& reference) {
    openvdb::initialize();
    const auto gridsOf = [](const std::string& file) {
        openvdb::io::File vdb(file);
        vdb.open(false);
        openvdb::GridPtrVecPtr grids = vdb.getGrids();
        vdb.close();
        return grids;
    };
    const openvdb::GridPtrVecPtr a = gridsOf(path);
    const openvdb::GridPtrVecPtr b = gridsOf(reference);
    if (a->size() != b->size())
        return false;
    for (std::size_t i = 0; i < a->size(); ++i) {
        const auto& gridA = (*a)[i];
        const auto& gridB = (*b)[i];
        if (gridA->getName() != gridB->getName() || gridA->type() != gridB->type() ||
            gridA->activeVoxelCount() != gridB->activeVoxelCount())
            return false;
        if (!sameValues<openvdb::FloatGrid>(*gridA, *gridB) ||
            !sameValues<openvdb::Vec3SGrid>(*gridA, *gridB))
            return false;
    }
    return true;
}

//! export.json as compared between runs: every CRC-32 it lists checked against the file beside
//! it (a wrong one is kept under "wrong_crc32", so the comparison fails), then the volume's
//! dropped: OpenVDB writes a UUID it draws at random into each file, so a volume's bytes, and
//! its checksum, differ from run to run.
inline nlohmann::json exportListingEssentials(const std::string& path) {
    nlohmann::json json = readJson(path);
    const std::string folder = fs::path(path).parent_path().string();
    for (auto& [key, entry] : json["sequences"].items()) {
        const std::string stem = key.substr(0, key.rfind('.'));
        const std::string ext = key.substr(key.rfind('.') + 1);
        for (const auto& [frame, crc] : entry["crc32"].items()) {
            const std::string file = folder + "/" + sequenceFileName(stem, std::stoi(frame), ext);
            const std::vector<std::uint8_t> bytes = readBytes(file);
            if (computeCrc32(bytes.data(), bytes.size()) != crc.get<std::uint32_t>())
                json["wrong_crc32"].push_back(file);
        }
        if (key == "fluid.vdb")
            entry.erase("crc32");
    }
    return json;
}

//! Whether one file holds what its reference holds, by its kind.
inline bool sameContent(const std::string& path, const std::string& reference) {
    const std::string extension = fs::path(path).extension().string();
    if (extension == ".atf")
        return frameState(path) == frameState(reference);
    if (extension == ".vdb")
        return sameVolumes(path, reference);
    if (fs::path(path).filename() == "manifest.json") {
        // Frame CRCs cover the wall-clock statistics; the frames are compared one by one.
        const auto essentials = [](const std::string& file) {
            nlohmann::json json = readJson(file);
            json.erase("frames");
            return json;
        };
        return essentials(path) == essentials(reference);
    }
    if (fs::path(path).filename() == "export.json")
        return exportListingEssentials(path) == exportListingEssentials(reference);
    if (extension == ".json")
        return withoutRunDetails(readJson(path)) == withoutRunDetails(readJson(reference));
    return readBytes(path) == readBytes(reference);
}

//! The first difference between `dir` and `reference` (a file only one has, or a file whose
//! content differs), or empty when they hold the same.
inline std::string differenceFrom(const std::string& dir, const std::string& reference) {
    const std::vector<std::string> files = filesUnder(dir);
    const std::vector<std::string> expected = filesUnder(reference);
    for (const std::string& file : expected)
        if (!std::binary_search(files.begin(), files.end(), file))
            return "missing " + dir + "/" + file;
    for (const std::string& file : files)
        if (!std::binary_search(expected.begin(), expected.end(), file))
            return "unexpected " + dir + "/" + file;
    for (const std::string& file : files)
        if (!sameContent(dir + "/" + file, reference + "/" + file))
            return "differs from the undisturbed run: " + dir + "/" + file;
    return {};
}

//! Copies a whole folder, replacing `to`.
inline void copyFolder(const std::string& from, const std::string& to) {
    fs::remove_all(to);
    fs::copy(from, to, fs::copy_options::recursive);
}

} // namespace airtrap::faulttest

//! Fails naming the difference when the folder is not what the undisturbed run left.
#define QVERIFY_SAME_AS(dir, reference)                                                            \
    do {                                                                                           \
        const std::string difference = airtrap::faulttest::differenceFrom(dir, reference);         \
        QVERIFY2(difference.empty(), difference.c_str());                                          \
    } while (false)
