#pragma once
// The PSOL chunk of a frame file (docs/CACHE_FORMAT.md): a divergence-free bake's warm start —
// each particle's stiffness of both solves, in the order of the PATT chunks — and the frame's
// solver figures. Written only by DFSPH bakes, so WCSPH frames are as before; a frame without it
// reads as a WCSPH frame (empty warm start, no figures).
#include "cache/ByteReader.h"
#include "cache/ByteWriter.h"
#include "sim/FrameStats.h"
#include "sph/PressureWarmStart.h"

#include <string>

namespace airtrap {

class PressureSolveChunk {
public:
    static constexpr char kTag[] = "PSOL";

    static bool needed(const PressureWarmStart& warmStart, const FrameStats& stats) {
        return !warmStart.empty() || stats.pressureSolve.steps > 0;
    }
    //! u64 n, f32 × n divergence, f32 × n density, then the frame's figures: u64 steps,
    //! u64 × 2 iterations (divergence, density), f64 × 2 density error (mean, largest), u64
    //! steps that did not converge.
    static void write(ByteWriter& out, const PressureWarmStart& warmStart, const FrameStats& stats);
    //! Throws Error(CacheCorrupt) naming `path` when the sizes do not add up or the warm start
    //! does not have one value per particle.
    static void read(const std::uint8_t* data, std::size_t size, const std::string& path,
                     std::size_t particles, PressureWarmStart& warmStart, FrameStats& stats);
};

} // namespace airtrap
