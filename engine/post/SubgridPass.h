#pragma once
// The post stage's second pass (paper §4.2): the sub-grid bubbles of each cache frame, made from
// the frame before it, so it runs in frame order. Each frame the bubbles are carried through the
// frame's water by SubgridAdvector, and every trapped bubble born since the last frame sheds new
// ones (SubgridSpawner); those in air pop. Frames whose stored bubbles are current are skipped, so
// posting frames 40–50 after 1–39 only does the new ones, and a post of 40–50 on a fresh cache
// makes 1–39 first: their bubbles are what frame 40 starts from.
#include "cache/FrameCache.h"
#include "core/Interrupter.h"
#include "post/SubgridAdvector.h"
#include "post/SubgridSpawner.h"
#include "post/SubgridStore.h"
#include "scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace airtrap {

struct SubgridReport {
    int made = 0;           //!< frames whose bubbles were made in this run
    int alreadyCurrent = 0; //!< frames skipped: their stored bubbles were current
    std::string damaged;    //!< the damaged cache frame the pass stopped at ("" when none)
    bool stopped = false;   //!< asked to stop before the last frame
    int lastFrame = 0;      //!< the last frame with current bubbles after the run (0: none)
    std::uint32_t lastFrameBubbles = 0; //!< how many bubbles it holds
    double seconds = 0.0;               //!< wall time of the pass
};

class SubgridPass {
public:
    //! `scene` supplies the settings (Error(InvalidInput) when out of range). Opens the store
    //! (Error(CacheCorrupt) when subgrid.json is damaged).
    SubgridPass(const FrameCache& cache, const Scene& scene);

    //! The settings the store records: the section's own and what the motion depends on.
    static nlohmann::json settingsOf(const Scene& scene);

    //! Brings every listed cache frame up to `lastFrame` up to date, in order. Stops at a damaged
    //! cache frame (the frames after it need it) and when `interrupter` asks, keeping what it
    //! finished. Progress goes to `interrupter` under the stage name "sub-grid bubbles".
    SubgridReport run(int lastFrame, Interrupter& interrupter);

    //! One frame: `previous` carried `seconds` on through `state`'s water, plus what the trapped
    //! bubbles born since shed.
    SubgridFrame step(const SubgridFrame& previous, const SimulationState& state,
                      double seconds) const;

    const SubgridStore& store() const { return store_; }
    //! Why subgrid.json was started afresh ("" when it was whole).
    const std::string& storeDamage() const { return storeDamage_; }

private:
    //! `trustStore` false remakes every frame, for when a stored one turns out damaged.
    SubgridReport walk(int lastFrame, bool trustStore, Interrupter& interrupter);
    //! Makes `entry`'s frame from `previous` (read from the store when empty), which it becomes;
    //! false when the cache frame is damaged (its reason in the report).
    bool makeFrame(const CacheFrameEntry& entry, std::uint32_t chain, int previousFrame,
                   std::optional<SubgridFrame>& previous, SubgridReport& report);

    const FrameCache& cache_;
    Scene scene_;
    SubgridSpawner spawner_;
    SubgridAdvector advector_;
    std::string storeDamage_;
    SubgridStore store_;
};

} // namespace airtrap
