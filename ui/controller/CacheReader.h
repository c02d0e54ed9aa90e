#pragma once
// The frame loader's view of one cache folder, used only on the loader thread. The folder may
// not hold a cache yet (a bake is about to start) and may change under it (the bake adds frames,
// a discard or a fresh bake replaces them), so every question re-reads the manifest when the
// answer could be stale instead of failing.
#include "cache/FrameCache.h"
#include "core/Error.h"
#include "scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace airtrap {

class CacheReader {
public:
    //! The scene a cache folder was baked from (its manifest's copy). Throws airtrap::Error
    //! naming the folder or the manifest when there is no readable cache.
    static Scene sceneOf(const std::string& directory);

    //! Switches to `directory` ("" = none) and reads its manifest if there is one.
    void open(const std::string& directory);
    //! Re-reads the manifest (opening the cache if it appeared since). A folder without a
    //! readable cache lists no frames.
    void reload();

    //! Loads a frame. Throws airtrap::Error with a message for the user: the engine's (naming
    //! the file) for a damaged frame, or one saying the frame is not (or no longer) cached.
    FrameData read(int frame);

    //! The frames the manifest lists, as last read.
    std::vector<int> frames() const;
    //! The cached frames whose render outputs (post/) were made from them as they are now;
    //! none when no post run finished a frame or its list is damaged.
    std::vector<int> renderOutputFrames() const;
    //! Frames whose file changed or disappeared at a manifest re-read since the last call; data
    //! loaded for them before is stale.
    std::vector<int> takeChangedFrames();

private:
    //! Opens the cache if it is not open yet; false (and the reason in openError_) when the
    //! folder holds none.
    bool ensureOpen();
    //! Re-reads the manifest of the open cache, noting changed frames.
    void reloadOpenCache();
    Error notCached(int frame, const char* why) const;

    std::string directory_;
    std::optional<FrameCache> cache_;
    std::string openError_;
    std::vector<int> changedFrames_;
};

} // namespace airtrap
