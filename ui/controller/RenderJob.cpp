#include "controller/RenderJob.h"

#include "cache/FrameCache.h"
#include "core/Error.h"
#include "post/PostStage.h"
#include "scene/SceneJson.h"

#include <cstdio>

namespace airtrap {

namespace {

std::vector<int> framesIn(const std::vector<int>& listed, int first, int last) {
    std::vector<int> frames;
    for (const int frame : listed)
        if (frame >= first && (last == 0 || frame <= last))
            frames.push_back(frame);
    return frames;
}

} // namespace

RenderJob::RenderJob(RenderRequest request, ProgressListener listener)
    : request_(std::move(request)), interrupter_(std::move(listener)) {}

RenderResult RenderJob::run() {
    try {
        std::string summary = runStages();
        if (interrupter_.stopRequested())
            return {RenderResult::Outcome::Stopped, "stopped; finished frames are kept"};
        return {RenderResult::Outcome::Completed, summary};
    } catch (const Error& error) {
        return {RenderResult::Outcome::Failed, error.what()};
    } catch (const std::exception& error) {
        return {RenderResult::Outcome::Failed, std::string("unexpected error: ") + error.what()};
    }
}

std::string RenderJob::runStages() {
    const FrameCache cache = FrameCache::open(request_.cacheDir);
    Scene scene = sceneFromJson(cache.manifest().scene, cache.manifestPath());
    scene.surfaceMesh = request_.surfaceMesh;
    scene.bubbleMesh = request_.bubbleMesh;
    scene.subgridBubbles = request_.subgridBubbles;
    const std::vector<int> frames =
        framesIn(cache.frames(), request_.firstFrame, request_.lastFrame);
    if (frames.empty())
        throw Error(ErrorKind::InvalidInput, request_.cacheDir + " holds no frames in the range");

    PostStage post(cache, scene);
    const PostReport made = post.run(frames, interrupter_);
    char line[200];
    std::snprintf(line, sizeof line,
                  "post: %d frame(s) made, %d already current; sub-grid bubbles: %d frame(s) "
                  "made, %u in frame %d",
                  made.made, made.alreadyCurrent, made.subgrid.made, made.subgrid.lastFrameBubbles,
                  made.subgrid.lastFrame);
    std::string summary = line;
    for (const std::string& problem : made.damaged)
        summary += "; skipped " + problem;
    for (const ExportFormat format : request_.formats) {
        if (interrupter_.stopRequested())
            break;
        SequenceExporter exporter(cache, scene, {format, request_.outDir, request_.up});
        const ExportReport report = exporter.run(frames, interrupter_);
        summary += "; " + std::string(exportFormatName(format)) + ": " +
                   std::to_string(report.files.size()) + " file(s)";
        for (const std::string& problem : report.damaged)
            summary += "; skipped " + problem;
    }
    if (!request_.formats.empty())
        summary += " in " + request_.outDir;
    return summary;
}

} // namespace airtrap
