#pragma once
// A cache folder (docs/CACHE_FORMAT.md): manifest.json plus one frame_NNNN.atf per
// frame. Used by the bake loop (write, resume), the CLI (info, export) and the editor (timeline).
//
// Consistency: every file is replaced atomically, and the manifest is only ever updated after the
// frame file it lists is complete, so an interrupted bake (crash, Ctrl-C, disk full) leaves a
// cache whose listed frames are all whole. A frame that is damaged anyway is reported by name
// and never loaded.
//
// Threads: one object may be shared — its manifest is guarded by a mutex and frame files are
// read without it (a file being replaced is safe to read because of rename). The intended use is
// still one object per thread: the bake thread writes through its own, the editor's loader thread
// open()s another and calls reload() to see new frames. A reader that hits a frame the writer has
// just dropped (truncateAfter) gets CacheCorrupt and should reload() before reporting it.
#include "cache/CacheManifest.h"
#include "cache/FrameFile.h"
#include "core/Math.h"

#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace airtrap {

class FrameCache {
public:
    //! Creates (with parents) or re-initialises `dir` as an empty cache with status "baking".
    //! A folder that already holds a cache is refused (InvalidInput) unless `overwrite`; then only
    //! manifest.json, frame_*.atf and the cache's own *.tmp files are deleted, nothing else.
    //! Cannot create or write → Error(Io) naming the path.
    static FrameCache create(const std::string& dir, const nlohmann::json& sceneJson,
                             const std::string& parameterHash, double fps, bool overwrite = false);
    //! Opens an existing cache. No manifest → InvalidInput "not an Airtrap cache: ..."; a
    //! malformed one → CacheCorrupt naming the field.
    static FrameCache open(const std::string& dir);
    //! True when `dir` contains a manifest.json (whether or not it is valid).
    static bool isCache(const std::string& dir);
    //! True when `dir` contains frame files (frame_NNNN.atf), with or without a manifest.
    static bool holdsFrameFiles(const std::string& dir);
    //! A cache whose manifest.json is lost or damaged, listed again from its frame files: each
    //! that decodes (its own checksums hold) and holds its frame's time of a bake at `fps`, in an
    //! unbroken run from frame 1; the run ends at the first that does not. The manifest takes the
    //! given scene, hash and fps (a resume's own) and status "stopped". What was listed, and
    //! where the run ended, go to `notes`. A resume then verifies and continues it as any cache.
    //! `why` ("was missing") begins the note that says so.
    static FrameCache rebuild(const std::string& dir, const nlohmann::json& sceneJson,
                              const std::string& parameterHash, double fps, const std::string& why,
                              std::vector<std::string>& notes);

    FrameCache(FrameCache&& other) noexcept;
    FrameCache& operator=(FrameCache&& other) noexcept;
    FrameCache(const FrameCache&) = delete;
    FrameCache& operator=(const FrameCache&) = delete;

    //! Writes frame `state.frame` atomically, then lists it in the manifest (replacing an older
    //! entry). Error(Io) (disk full, permission denied) leaves a consistent cache: a new frame is
    //! not listed; a listed frame being re-written is unlisted first, so the manifest never
    //! describes a file that was replaced.
    void writeFrame(const SimulationState& state, const FrameStats& stats);
    //! Loads a listed frame, verified against its own header and checksums and against the
    //! manifest's size and CRC. Damaged or missing file → CacheCorrupt naming it; a frame not
    //! listed → InvalidInput.
    FrameData readFrame(int frame) const;
    //! readFrame() for loops that skip damaged frames: a frame that fails its checks gives
    //! nothing and its "<path>: <reason>" in `problem`; other errors (Io, not listed) propagate.
    std::optional<FrameData> readIntactFrame(int frame, std::string& problem) const;

    //! Listed frame numbers, ascending.
    std::vector<int> frames() const;
    bool hasFrame(int frame) const;
    //! The manifest as last read or written. Not safe while another thread writes through this
    //! object; use manifestSnapshot() then.
    const CacheManifest& manifest() const { return manifest_; }
    CacheManifest manifestSnapshot() const;
    //! Re-reads manifest.json, e.g. to see frames another FrameCache object has written.
    void reload();

    const std::string& directory() const { return dir_; }
    std::string manifestPath() const;
    //! Where frame `frame` is stored: <dir>/frame_%04d.atf.
    std::string framePath(int frame) const;
    //! "frame_0001.atf" (4 digits, more when needed).
    static std::string frameFileName(int frame);

    //! Sets "baking", "complete", "stopped" or "failed: <reason>" and writes the manifest.
    void setStatus(const std::string& status);

    //! Empty when the scene the manifest records reads back and has the recorded parameter
    //! hash; else what is wrong. A damaged byte there leaves the manifest readable, but post and
    //! export could no longer read the bake's scene.
    std::string recordedSceneDamage() const;

    //! Records that the frames from now on are baked from another scene (an edit in the middle of
    //! a bake, continued from the last kept frame).
    void replaceScene(const nlohmann::json& sceneJson, const std::string& parameterHash);

    //! The newest listed frame that fully verifies (0 if none). Each damaged frame met on the
    //! way down is appended to `problems` as "<path>: <reason>". Io errors propagate: an
    //! unreadable file is not evidence of a bad frame.
    int lastGoodFrame(std::vector<std::string>* problems = nullptr) const;
    //! The frame a resume continues from: the last of the unbroken run of intact frames from
    //! frame 1 (0 if frame 1 is damaged or nothing is listed). Frames after the first damaged or
    //! missing one depend on it and are baked again. The first damage found is appended to
    //! `problems`. Reads every frame up to it; Io errors propagate.
    int lastFrameBeforeDamage(std::vector<std::string>* problems = nullptr) const;
    //! Verifies every listed frame; returns "<path>: <reason>" per damaged one.
    std::vector<std::string> verify() const;
    //! Unlists and deletes every frame after `frame` (manifest first, then files), including
    //! unlisted frame files left by an interrupted write.
    void truncateAfter(int frame);

private:
    FrameCache(std::string dir, CacheManifest manifest);
    CacheFrameEntry entryOf(int frame) const;
    std::optional<Aabb> sceneDomainSnapshot() const;
    //! Applies `change` to a copy of the manifest, writes it, and only then adopts it, so memory
    //! and disk agree even when the write fails. Call with mutex_ held.
    template <typename Change>
    void updateManifest(Change&& change);

    std::string dir_;
    CacheManifest manifest_;
    //! The scene's domain, against which every frame read is checked (FrameValueCheck).
    std::optional<Aabb> domain_;
    mutable std::mutex mutex_;
};

} // namespace airtrap
