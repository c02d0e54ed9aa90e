#pragma once
// What a frame holds must be something a bake can have written: a frame whose checksums hold may
// still carry values no simulation leaves behind (written by another tool, or by a build with a
// fault), and the readers behind the cache (post's rasterisation, the exporters, the viewport)
// size their work by the positions. Every reader of the cache gets frames through these checks
// (docs/CACHE_FORMAT.md "What a reader checks").
#include "cache/FrameFile.h"
#include "core/Math.h"

#include <string>

namespace airtrap {

//! Throws Error(CacheCorrupt, "<path>: <field> of <which> is <value>, expected a finite number")
//! for the first value of the water, the bodies, the bubbles, the clock or the warm start that
//! is NaN or infinite.
void checkFrameValuesAreFinite(const FrameData& frame, const std::string& path);

//! Throws Error(CacheCorrupt, ...) naming the first water particle or bubble centre outside
//! `domain` grown by `margin` (m): the simulation removes water that leaves the domain at every
//! step, so a frame can hold it at most a step's travel outside.
void checkFrameLiesInDomain(const FrameData& frame, const Aabb& domain, double margin,
                            const std::string& path);

} // namespace airtrap
