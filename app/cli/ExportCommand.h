#pragma once
// `airtrap-cli export DIR --format ply --out OUTDIR [--frames A:B]`: one file per cached frame.
// PLY particles exist now; OBJ meshes and OpenVDB volumes need the post stage and answer "not
// available yet" without writing anything.
#include "Command.h"

#include <string>
#include <vector>

namespace airtrap {
class FrameCache;
class Interrupter;
} // namespace airtrap

namespace airtrap::cli {

class ExportCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    //! The listed frames inside --frames; refuses a range that holds none.
    std::vector<int> selectFrames(const FrameCache& cache) const;
    void createOutputFolder() const;
    //! Writes one frame; false when the frame is damaged (reported, skipped).
    bool exportFrame(const FrameCache& cache, int frame) const;

    std::string cacheDir_;
    std::string format_;
    std::string outDir_;
    std::string framesText_;
    bool quiet_ = false;
};

} // namespace airtrap::cli
