#pragma once
// One run of the render outputs as the editor asks for it: the post stage on a baked cache
// (PostStage), and, for an export, the chosen sequences after it (SequenceExporter). The scene is
// the cache's own, with the document's render settings (surface_mesh, bubble_mesh), so an artist
// can change the look and post again without re-baking. Knows nothing of Qt:
// RenderOutputController runs it on its worker thread.
#include "core/Interrupter.h"
#include "io/SequenceExporter.h"
#include "scene/Scene.h"

#include <functional>
#include <string>
#include <vector>

namespace airtrap {

struct RenderRequest {
    std::string cacheDir;
    SurfaceMeshSettings surfaceMesh; //!< the document's render settings
    BubbleMeshSettings bubbleMesh;
    SubgridBubbleSettings subgridBubbles;
    //! Export these after the post stage; none: post only.
    std::vector<ExportFormat> formats;
    std::string outDir;
    UpAxis up = UpAxis::Y;
    int firstFrame = 1; //!< of the cached frames, those in [first, last] (0 = the last cached)
    int lastFrame = 0;
};

struct RenderResult {
    enum class Outcome { Completed, Stopped, Failed };
    Outcome outcome = Outcome::Failed;
    //! What was done ("post: 60 frames made ...; exported 120 files to ..."), or the engine's
    //! message when it failed.
    std::string message;
};

class RenderJob {
public:
    //! Called on the job's thread with the stage ("post", "export obj") and its share done.
    using ProgressListener = std::function<void(const std::string& stage, double percent)>;

    RenderJob(RenderRequest request, ProgressListener listener);

    //! Runs to the end, a stop or an error; never throws.
    RenderResult run();
    //! Any thread: ends the run at the next frame (or inside one, in OpenVDB's tools).
    void stop() { interrupter_.requestStop(); }

private:
    std::string runStages();

    RenderRequest request_;
    Interrupter interrupter_;
};

} // namespace airtrap
