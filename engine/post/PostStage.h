#pragma once
// `airtrap-cli post` and the editor's Post action (the data flow Scene → Simulation → FrameCache →
// Post → Exporters): for each chosen cache frame, the water volume and its free-surface mesh
// (paper §4.1), stored beside the cache (PostStore), then the sub-grid bubbles (§4.2,
// SubgridPass). Frames run in parallel; a frame whose stored
// result is current is skipped, so a second run after a longer bake only does the new frames,
// and a run after a settings change redoes them all. Stops between frames and inside OpenVDB's
// tools when asked; what finished is kept.
#include "cache/FrameCache.h"
#include "core/Interrupter.h"
#include "post/PostStore.h"
#include "post/SceneSolids.h"
#include "post/SubgridPass.h"
#include "scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace airtrap {

struct PostReport {
    int made = 0;                     //!< frames whose results were made in this run
    int alreadyCurrent = 0;           //!< frames skipped: their stored results were current
    std::vector<std::string> damaged; //!< "<path>: <reason>" per cache frame that failed its checks
    double seconds = 0.0;             //!< wall time of the run
    double secondsPerFrame = 0.0;     //!< mean wall time of a frame made (threads included)
    bool stopped = false;
    SubgridReport subgrid; //!< the sub-grid bubbles' pass, after the surfaces'
    //! A damaged post.json or subgrid.json, replaced by this run: "<path>: <reason>".
    std::vector<std::string> replacedLists;
    int mergedFrames = 0; //!< frames listed from the part lists of earlier part runs
};

//! How one post run shares the store with others (docs/FARM.md).
struct PostOptions {
    //! Non-empty: the run lists what it makes in its own part list (PostStore::openPart), so
    //! that runs over other frames may write at once; it leaves the sub-grid pass, which goes
    //! in frame order, to the run that merges the parts. Empty: the run merges the part lists
    //! others left, then works on post.json.
    std::string part;
    //! False leaves the sub-grid pass out (paper §4.2: it carries each frame's bubbles to the
    //! next, so it cannot be split over frame chunks).
    bool subgrid = true;
};

class PostStage {
public:
    //! `scene` supplies the render settings and the solids; usually the cache's own scene,
    //! perhaps with its render settings changed. Loads mesh bodies (Error(InvalidInput) when one
    //! cannot be read) and opens the store; a damaged post.json is started afresh
    //! (PostReport::replacedLists).
    PostStage(const FrameCache& cache, const Scene& scene, PostOptions options = {});

    //! The render settings as the store records them.
    static nlohmann::json settingsOf(const Scene& scene);

    //! Makes the results of `frames` (listed cache frames): their surfaces, then the sub-grid
    //! bubbles of every frame up to the last of them. Progress goes to `interrupter` as the
    //! share of `frames` done, under the stage name "post", then of the sub-grid frames under
    //! "sub-grid bubbles". Error(Io) stops the run.
    PostReport run(const std::vector<int>& frames, Interrupter& interrupter);

    const PostStore& store() const { return store_; }

private:
    //! Makes one frame's results, or records in `report` why not (current already, damaged).
    void makeFrame(int frame, Interrupter& interrupter, PostReport& report);
    //! The sub-grid pass up to `lastFrame`, its damaged frame added to the report's list.
    void addSubgridBubbles(int lastFrame, Interrupter& interrupter, PostReport& report);

    //! Before the frames: a whole run clears what killed runs left and merges the part lists.
    void prepareStore(PostReport& report);

    const FrameCache& cache_;
    Scene scene_;
    PostOptions options_;
    SceneSolids solids_;
    std::string storeDamage_; //!< why post.json was started afresh ("" when it was whole)
    PostStore store_;
    std::optional<SubgridPass> subgrid_; //!< none when this run leaves the sub-grid pass out
    std::mutex reportMutex_;
};

} // namespace airtrap
