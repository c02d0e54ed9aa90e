#pragma once
// Writes a baked (and, for meshes and volumes, post-processed) cache as the file sequences
// renderers read (docs/CLI.md "export"), for `airtrap-cli export` and the editor's Export dialog
// alike:
//   ply  particles_0001.ply                 water particles (PlyExporter)
//        bubbles_0001.ply                   bubbles as points for instancing (BubblePoints), when
//                                           the scene simulates bubbles
//        subgrid_0001.ply                   sub-grid bubbles as points, when the post stage has
//                                           made the frame's (paper §4.2)
//   obj  water_0001.obj                     the free-surface mesh from the post stage
//        bubbles_0001.obj                   one oscillating ellipsoid per bubble (paper eqs. 7–10),
//                                           when the scene simulates bubbles
//        subgrid_0001.obj                   the sub-grid bubbles as small spheres, one object
//        bodies_0001.obj                    obstacles and rigid bodies, when the scene has any
//   vdb  fluid_0001.vdb                     surface, density and vel (WaterVolumeFile)
//        export.json                        what the folder holds: scene, fps, frames, units and
//                                           each sequence's frames and axes (ExportListing)
// Metres; y up, or z up on request. Every file is written atomically.
#include "cache/FrameCache.h"
#include "core/Interrupter.h"
#include "core/UpAxis.h"
#include "io/ExportFormat.h"
#include "post/OscillatingBubbleMesh.h"
#include "post/PostStore.h"
#include "post/SceneSolids.h"
#include "post/SubgridStore.h"
#include "scene/Scene.h"

#include <set>
#include <string>
#include <vector>

namespace airtrap {

//! Who writes export.json when several runs export other frames into one folder at once (a
//! farm's job array, docs/FARM.md): rewriting it from each would lose another run's frames.
enum class ExportListingMode {
    Update, //!< write the frames, then add them to export.json (one run at a time)
    Leave,  //!< write the frames only; leave export.json and other runs' temporaries alone
    Only,   //!< write no frame: list in export.json the format's files of the frames present
};

struct ExportOptions {
    ExportFormat format = ExportFormat::Obj;
    std::string outDir;
    UpAxis up = UpAxis::Y;
    ExportListingMode listing = ExportListingMode::Update;
};

struct ExportReport {
    int framesWritten = 0;
    std::vector<std::string> files;   //!< names written, in order
    std::vector<std::string> damaged; //!< "<path>: <reason>" per frame skipped
    double seconds = 0.0;
    bool stopped = false;
};

class SequenceExporter {
public:
    //! `scene` is the cache's (its render settings perhaps changed). Loads mesh bodies for OBJ.
    SequenceExporter(const FrameCache& cache, const Scene& scene, ExportOptions options);

    //! "obj" → ExportFormat::Obj; Error(InvalidInput) listing the formats for anything else.
    static ExportFormat parseFormat(const std::string& name);

    //! Refuses, before anything is written, frames whose post results an OBJ or VDB export needs
    //! but which are missing or older than their cache frame (Error(InvalidInput) naming them
    //! and the command that makes them).
    void checkReady(const std::vector<int>& frames) const;
    //! Creates the output folder and writes every frame; a damaged cache frame is skipped and
    //! recorded. Stops between frames when asked. Error(Io) stops the run.
    ExportReport run(const std::vector<int>& frames, Interrupter& interrupter);

private:
    //! The files of one frame; false when the cache frame is damaged.
    bool exportFrame(int frame, ExportReport& report);
    std::vector<std::string> comments(const FrameData& data) const;
    void writeObjFiles(const FrameData& data, ExportReport& report) const;
    void writePlyFiles(const FrameData& data, ExportReport& report) const;
    //! ExportListingMode::Only: lists the files of this format and `frames` in the folder.
    ExportReport listFilesPresent(const std::vector<int>& frames) const;
    //! The stems ("water", "bubbles") of this format's files in the output folder.
    std::set<std::string> stemsPresent() const;
    void writeListing(const std::vector<std::string>& files) const;
    //! The scene makes sub-grid bubbles: it simulates bubbles and sheds some.
    bool exportsSubgrid() const;
    //! True when frame `frame` has every post result the format needs, current.
    bool hasPostResults(const CacheManifest& manifest, int frame) const;
    std::string path(const std::string& name) const { return options_.outDir + "/" + name; }

    const FrameCache& cache_;
    Scene scene_;
    ExportOptions options_;
    SceneSolids solids_;
    OscillatingBubbleMesh bubbleMesh_;
    // Damaged lists read as empty, so that a PLY export, which needs neither, is not stopped by
    // them; an OBJ or VDB export names them (checkReady()) and post replaces them.
    std::string postListDamage_;
    std::string subgridListDamage_;
    PostStore store_;
    SubgridStore subgrid_;
    TriangleMesh subgridSphere_; //!< unit sphere each sub-grid bubble is scaled from in OBJ
};

} // namespace airtrap
