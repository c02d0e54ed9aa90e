#include "io/SequenceExporter.h"

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "io/BubblePoints.h"
#include "io/ExportListing.h"
#include "io/ObjExporter.h"
#include "io/PlyExporter.h"
#include "post/FrameSolids.h"
#include "post/Icosphere.h"
#include "post/SequenceName.h"
#include "post/WaterVolumeFile.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>

namespace airtrap {

namespace {

bool needsPostResults(ExportFormat format) {
    return format != ExportFormat::Ply;
}

//! The sub-grid bubbles as one mesh of small spheres: thousands of objects would slow an import.
TriangleMesh spheresAt(const std::vector<SubgridBubble>& bubbles, const TriangleMesh& unit) {
    TriangleMesh spheres;
    for (const SubgridBubble& bubble : bubbles) {
        const auto first = std::uint32_t(spheres.vertices.size());
        for (const Vec3d& v : unit.vertices)
            spheres.vertices.push_back(bubble.position + bubble.radius * v);
        for (const TriangleMesh::Triangle& t : unit.triangles)
            spheres.triangles.push_back({first + t[0], first + t[1], first + t[2]});
    }
    return spheres;
}

std::vector<BubblePoint> pointsOf(const std::vector<SubgridBubble>& bubbles) {
    std::vector<BubblePoint> points;
    points.reserve(bubbles.size());
    for (const SubgridBubble& bubble : bubbles)
        points.push_back({bubble.position, bubble.radius, bubble.velocity, bubble.age, bubble.id});
    return points;
}

std::string frameList(const std::vector<int>& frames) {
    std::string list;
    for (std::size_t i = 0; i < frames.size() && i < 10; ++i)
        list += (list.empty() ? "" : ", ") + std::to_string(frames[i]);
    return frames.size() > 10 ? list + " and " + std::to_string(frames.size() - 10) + " more"
                              : list;
}

} // namespace

SequenceExporter::SequenceExporter(const FrameCache& cache, const Scene& scene,
                                   ExportOptions options)
    : cache_(cache), scene_(scene), options_(std::move(options)), solids_(scene),
      bubbleMesh_(scene.bubbleMesh),
      store_(PostStore::openOrEmpty(cache.directory(), postListDamage_)),
      subgrid_(SubgridStore::openOrEmpty(cache.directory(), subgridListDamage_)),
      subgridSphere_(unitIcosphere(1)) {}

ExportFormat SequenceExporter::parseFormat(const std::string& name) {
    if (const std::optional<ExportFormat> format = exportFormatNamed(name))
        return *format;
    throw Error(ErrorKind::InvalidInput,
                "export format '" + name + "' is not known; expected " + exportFormatList());
}

bool SequenceExporter::exportsSubgrid() const {
    return scene_.bubbles.enabled && scene_.subgridBubbles.maxPerBubble > 0;
}

bool SequenceExporter::hasPostResults(const CacheManifest& manifest, int frame) const {
    const CacheFrameEntry* source = manifest.findFrame(frame);
    if (source == nullptr || !store_.isCurrent(frame, source->crc32))
        return false;
    return options_.format != ExportFormat::Obj || !exportsSubgrid() ||
           subgrid_.isCurrentIn(manifest, frame);
}

void SequenceExporter::checkReady(const std::vector<int>& frames) const {
    if (!needsPostResults(options_.format))
        return;
    const CacheManifest manifest = cache_.manifestSnapshot();
    std::vector<int> missing;
    for (const int frame : frames)
        if (!hasPostResults(manifest, frame))
            missing.push_back(frame);
    if (missing.empty())
        return;
    // Results listed but damaged are named: post makes them again.
    std::string damaged;
    for (const std::string* list : {&postListDamage_, &subgridListDamage_})
        if (!list->empty())
            damaged += "; damaged: " + *list;
    for (const std::string& problem : store_.verify())
        damaged += "; damaged: " + problem;
    throw Error(ErrorKind::InvalidInput,
                "frame(s) " + frameList(missing) + " of " + cache_.directory() +
                    " have no current post results (water mesh, volume, sub-grid bubbles)" +
                    damaged + "; run `airtrap-cli post " + cache_.directory() + "` first");
}

std::vector<std::string> SequenceExporter::comments(const FrameData& data) const {
    char time[32];
    std::snprintf(time, sizeof time, "%.6g", data.state.time);
    return {"Airtrap " AIRTRAP_VERSION,
            "frame " + std::to_string(data.state.frame) + ", t = " + time + " s",
            std::string("metres, ") + (options_.up == UpAxis::Y ? "Y" : "Z") + " up"};
}

void SequenceExporter::writeObjFiles(const FrameData& data, ExportReport& report) const {
    const int frame = data.state.frame;
    const std::vector<std::string> notes = comments(data);
    const std::string water = sequenceFileName("water", frame, "obj");
    std::vector<std::string> waterNotes = notes;
    waterNotes.push_back(scene_.surfaceMesh.mode == "closed"
                             ? "water mesh: closed (watertight, normals outward)"
                             : "water mesh: free_surface (no polygons along bodies and bubbles)");
    ObjExporter::write(path(water), {{"water", store_.readFreeSurface(frame)}}, options_.up,
                       waterNotes);
    report.files.push_back(water);
    if (scene_.bubbles.enabled) {
        std::vector<NamedMesh> bubbles;
        for (const BubbleState& bubble : data.state.bubbles)
            bubbles.push_back({"bubble_" + std::to_string(bubble.id), bubbleMesh_.build(bubble)});
        const std::string name = sequenceFileName("bubbles", frame, "obj");
        ObjExporter::write(path(name), bubbles, options_.up, notes);
        report.files.push_back(name);
    }
    if (exportsSubgrid()) {
        const TriangleMesh spheres = spheresAt(subgrid_.readFrame(frame).bubbles, subgridSphere_);
        const std::string name = sequenceFileName("subgrid", frame, "obj");
        ObjExporter::write(path(name), {{"subgrid_bubbles", spheres}}, options_.up, notes);
        report.files.push_back(name);
    }
    const std::vector<NamedMesh> bodies = FrameSolids(solids_, data.state).meshes();
    if (!bodies.empty()) {
        const std::string name = sequenceFileName("bodies", frame, "obj");
        ObjExporter::write(path(name), bodies, options_.up, notes);
        report.files.push_back(name);
    }
}

void SequenceExporter::writePlyFiles(const FrameData& data, ExportReport& report) const {
    const int frame = data.state.frame;
    const std::string particles = PlyExporter::fileName(frame);
    PlyExporter::write(path(particles), data.state.fluid, comments(data), options_.up);
    report.files.push_back(particles);
    if (!scene_.bubbles.enabled)
        return;
    std::vector<BubblePoint> points;
    for (const BubbleState& bubble : data.state.bubbles)
        points.push_back({bubble.body.position, bubble.radius, bubble.body.linearVelocity,
                          bubble.age, bubble.id});
    const std::string bubbles = sequenceFileName("bubbles", frame, "ply");
    BubblePoints::write(path(bubbles), points, comments(data), options_.up);
    report.files.push_back(bubbles);
    // Particles need no post run; the sub-grid bubbles come with it when one has made them.
    if (!exportsSubgrid() || !subgrid_.isCurrentIn(cache_.manifestSnapshot(), frame))
        return;
    const std::string subgrid = sequenceFileName("subgrid", frame, "ply");
    BubblePoints::write(path(subgrid), pointsOf(subgrid_.readFrame(frame).bubbles), comments(data),
                        options_.up);
    report.files.push_back(subgrid);
}

bool SequenceExporter::exportFrame(int frame, ExportReport& report) {
    std::string problem;
    const std::optional<FrameData> intact = cache_.readIntactFrame(frame, problem);
    if (!intact) {
        report.damaged.push_back(problem);
        return false;
    }
    const FrameData& data = *intact;
    switch (options_.format) {
    case ExportFormat::Ply:
        writePlyFiles(data, report);
        break;
    case ExportFormat::Obj:
        writeObjFiles(data, report);
        break;
    case ExportFormat::Vdb: {
        const std::string name = sequenceFileName("fluid", frame, "vdb");
        WaterVolumeFile::write(
            path(name), store_.readVolume(frame), options_.up,
            {{"frame", std::to_string(frame)}, {"creator", "Airtrap " AIRTRAP_VERSION}});
        report.files.push_back(name);
        break;
    }
    }
    return true;
}

std::set<std::string> SequenceExporter::stemsPresent() const {
    std::string extension = ".";
    extension += exportFormatName(options_.format);
    std::set<std::string> stems;
    std::error_code error;
    std::filesystem::directory_iterator item(options_.outDir, error);
    for (; !error && item != std::filesystem::directory_iterator(); item.increment(error)) {
        const std::string name = item->path().filename().string();
        const std::size_t underscore = name.rfind('_');
        if (name.ends_with(extension) && underscore != std::string::npos && underscore > 0)
            stems.insert(name.substr(0, underscore));
    }
    if (error)
        throw Error(ErrorKind::Io,
                    AtomicFile::errorMessage("cannot list folder", options_.outDir, error.value()));
    return stems;
}

ExportReport SequenceExporter::listFilesPresent(const std::vector<int>& frames) const {
    // Every writer has ended: what a killed one left is of no use.
    AtomicFile::removeOrphanedTemporaries(options_.outDir);
    ExportReport report;
    // The folder's listing only says which sequences there are. Each frame's file is then
    // looked up by its name: on a network file system a listing read here may not show yet
    // what another machine wrote a moment ago, while a lookup by name asks the server.
    for (const std::string& stem : stemsPresent())
        for (const int frame : frames) {
            const std::string name =
                sequenceFileName(stem, frame, std::string(exportFormatName(options_.format)));
            std::error_code error;
            if (std::filesystem::is_regular_file(path(name), error))
                report.files.push_back(name);
        }
    std::sort(report.files.begin(), report.files.end());
    writeListing(report.files);
    return report;
}

void SequenceExporter::writeListing(const std::vector<std::string>& files) const {
    ExportListing listing = ExportListing::readOrEmpty(options_.outDir);
    listing.setScene(scene_, options_.up);
    listing.addFiles(files, options_.up);
    listing.recordChecksums(options_.outDir, files);
    listing.write(options_.outDir);
}

ExportReport SequenceExporter::run(const std::vector<int>& frames, Interrupter& interrupter) {
    const auto start = std::chrono::steady_clock::now();
    if (options_.listing == ExportListingMode::Only)
        return listFilesPresent(frames);
    checkReady(frames);
    std::error_code error;
    std::filesystem::create_directories(options_.outDir, error);
    if (error)
        throw Error(ErrorKind::Io, AtomicFile::errorMessage("cannot create folder", options_.outDir,
                                                            error.value()));
    // An export killed mid-write left its temporary; this one writes that file again. Runs
    // beside others leave them: on another machine, a live writer's process is not seen here.
    if (options_.listing == ExportListingMode::Update)
        AtomicFile::removeOrphanedTemporaries(options_.outDir);
    ExportReport report;
    interrupter.start("export");
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (interrupter.wasInterrupted(100.0 * double(i) / double(frames.size()))) {
            report.stopped = true;
            break;
        }
        if (exportFrame(frames[i], report))
            ++report.framesWritten;
    }
    interrupter.end();
    // Also after a stop: every file written is whole, and the listing says which they are.
    if (options_.listing == ExportListingMode::Update)
        writeListing(report.files);
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

} // namespace airtrap
