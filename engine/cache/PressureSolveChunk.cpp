#include "cache/PressureSolveChunk.h"

#include "core/Error.h"

#include <cstring>

namespace airtrap {

namespace {
constexpr std::size_t kFiguresSize = 4 * sizeof(std::uint64_t) + 2 * sizeof(double);
} // namespace

void PressureSolveChunk::write(ByteWriter& out, const PressureWarmStart& warmStart,
                               const FrameStats& stats) {
    const std::size_t n = warmStart.divergence.size();
    out.u64(n);
    out.raw(warmStart.divergence.data(), n * sizeof(float));
    out.raw(warmStart.density.data(), n * sizeof(float));
    const PressureSolveStats& solve = stats.pressureSolve;
    out.u64(solve.steps);
    out.u64(solve.divergenceIterations);
    out.u64(solve.densityIterations);
    out.f64(solve.meanDensityError);
    out.f64(solve.maxDensityError);
    out.u64(solve.unconvergedSteps);
}

void PressureSolveChunk::read(const std::uint8_t* data, std::size_t size, const std::string& path,
                              std::size_t particles, PressureWarmStart& warmStart,
                              FrameStats& stats) {
    ByteReader in(data, size, path + ": chunk PSOL");
    const std::uint64_t n = in.u64();
    // The warm start belongs to the particles as the step left them; inflow emitted after it
    // may have added some (they start from zero), never removed any.
    if (n > particles || size != sizeof(std::uint64_t) + 2 * n * sizeof(float) + kFiguresSize)
        throw Error(ErrorKind::CacheCorrupt, path + ": chunk PSOL holds " + std::to_string(n) +
                                                 " warm-start values in " + std::to_string(size) +
                                                 " bytes for " + std::to_string(particles) +
                                                 " particles");
    for (std::vector<float>* values : {&warmStart.divergence, &warmStart.density}) {
        values->resize(static_cast<std::size_t>(n));
        std::memcpy(values->data(), in.take(n * sizeof(float)), n * sizeof(float));
    }
    PressureSolveStats& solve = stats.pressureSolve;
    solve.steps = in.u64();
    solve.divergenceIterations = in.u64();
    solve.densityIterations = in.u64();
    solve.meanDensityError = in.f64();
    solve.maxDensityError = in.f64();
    solve.unconvergedSteps = in.u64();
}

} // namespace airtrap
