#include "controller/CacheReader.h"

#include "core/Error.h"
#include "post/PostStore.h"
#include "scene/SceneJson.h"

#include <utility>

namespace airtrap {

Scene CacheReader::sceneOf(const std::string& directory) {
    const FrameCache cache = FrameCache::open(directory);
    return sceneFromJson(cache.manifest().scene, directory + "/manifest.json");
}

void CacheReader::open(const std::string& directory) {
    directory_ = directory;
    cache_.reset();
    openError_.clear();
    changedFrames_.clear();
    ensureOpen();
}

void CacheReader::reload() {
    if (cache_)
        reloadOpenCache();
    else
        ensureOpen();
}

FrameData CacheReader::read(int frame) {
    if (!ensureOpen())
        throw Error(ErrorKind::InvalidInput, openError_);
    if (!cache_->hasFrame(frame)) {
        // The bake may have written it since the manifest was last read.
        reloadOpenCache();
        if (!cache_ || !cache_->hasFrame(frame))
            throw notCached(frame, "is not in");
    }
    try {
        return cache_->readFrame(frame);
    } catch (const Error&) {
        // A concurrent discard or fresh bake may have just dropped or replaced the file: look
        // again before blaming it. A frame still listed and still unreadable is really damaged,
        // and the second read throws the engine's message naming the file.
        reloadOpenCache();
        if (!cache_ || !cache_->hasFrame(frame))
            throw notCached(frame, "is no longer in");
        return cache_->readFrame(frame);
    }
}

std::vector<int> CacheReader::frames() const {
    return cache_ ? cache_->frames() : std::vector<int>{};
}

std::vector<int> CacheReader::renderOutputFrames() const {
    if (!cache_)
        return {};
    std::string damage;
    const PostStore outputs = PostStore::openOrEmpty(directory_, damage);
    std::vector<int> made;
    for (const CacheFrameEntry& entry : cache_->manifest().frames)
        if (outputs.isListedFrom(entry.frame, entry.crc32))
            made.push_back(entry.frame);
    return made;
}

std::vector<int> CacheReader::takeChangedFrames() {
    return std::exchange(changedFrames_, {});
}

bool CacheReader::ensureOpen() {
    if (cache_)
        return true;
    if (directory_.empty()) {
        openError_ = "no frame cache is open";
        return false;
    }
    try {
        cache_ = FrameCache::open(directory_);
        return true;
    } catch (const Error& error) {
        openError_ = error.what();
        return false;
    }
}

void CacheReader::reloadOpenCache() {
    const std::vector<CacheFrameEntry> before = cache_->manifestSnapshot().frames;
    try {
        cache_->reload();
    } catch (const Error& error) {
        // A fresh bake over the folder deletes the manifest first; until it writes a new one
        // the folder holds no cache, and nothing loaded from the old one is current.
        openError_ = error.what();
        cache_.reset();
        for (const CacheFrameEntry& entry : before)
            changedFrames_.push_back(entry.frame);
        return;
    }
    const CacheManifest after = cache_->manifestSnapshot();
    for (const CacheFrameEntry& entry : before) {
        const CacheFrameEntry* now = after.findFrame(entry.frame);
        if (!now || !(*now == entry))
            changedFrames_.push_back(entry.frame);
    }
}

Error CacheReader::notCached(int frame, const char* why) const {
    return Error(ErrorKind::InvalidInput,
                 directory_ + ": frame " + std::to_string(frame) + " " + why + " the cache");
}

} // namespace airtrap
