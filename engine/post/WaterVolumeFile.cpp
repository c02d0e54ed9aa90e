// One of the few translation units that include OpenVDB's tools: their headers take long to
// compile, so they stay out of headers and out of most .cpp files.
#include "post/WaterVolumeFile.h"

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "post/WaterGrids.h"

#include <cmath>
#include <new>
#include <openvdb/io/Stream.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <sstream>
#include <stdexcept>

namespace airtrap {

namespace {

constexpr double kQuarterTurn = 1.57079632679489661923;

//! Turns a grid's index space a quarter about x after its voxel scaling (y up → z up).
void turnToZUp(openvdb::GridBase& grid) {
    grid.transform().postRotate(kQuarterTurn, openvdb::math::X_AXIS);
}

openvdb::GridPtrVec exportGrids(const WaterVolume& water, UpAxis up) {
    const WaterGrids* source = water.grids();
    openvdb::FloatGrid::Ptr surface =
        source ? source->surface->deepCopy() : openvdb::createLevelSet<openvdb::FloatGrid>();
    surface->setName("surface");
    // The fog is the level set remapped over its inside band: 1 at the band's inner edge.
    openvdb::FloatGrid::Ptr density = surface->deepCopy();
    openvdb::tools::sdfToFogVolume(*density);
    density->setName("density");
    openvdb::Vec3SGrid::Ptr velocity =
        source && source->velocity ? source->velocity->deepCopy() : openvdb::Vec3SGrid::create();
    velocity->setName("vel");
    velocity->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
    velocity->setTransform(surface->transform().copy());
    if (up == UpAxis::Z) {
        for (auto value = velocity->beginValueOn(); value; ++value) {
            const openvdb::Vec3s v = *value;
            value.setValue(openvdb::Vec3s(v.x(), -v.z(), v.y()));
        }
        for (openvdb::GridBase* grid : {static_cast<openvdb::GridBase*>(surface.get()),
                                        static_cast<openvdb::GridBase*>(density.get()),
                                        static_cast<openvdb::GridBase*>(velocity.get())})
            turnToZUp(*grid);
    }
    return {surface, density, velocity};
}

} // namespace

void WaterVolumeFile::write(const std::string& path, const WaterVolume& water, UpAxis up,
                            const Metadata& metadata) {
    openvdb::initialize();
    const openvdb::GridPtrVec grids = exportGrids(water, up);
    openvdb::MetaMap fileMetadata;
    fileMetadata.insertMeta("units", openvdb::StringMetadata("metres"));
    fileMetadata.insertMeta("up_axis", openvdb::StringMetadata(up == UpAxis::Y ? "y" : "z"));
    const double voxel = grids.front()->voxelSize().x();
    fileMetadata.insertMeta("voxel_size", openvdb::DoubleMetadata(voxel));
    fileMetadata.insertMeta("particle_volume", openvdb::DoubleMetadata(water.particleVolume()));
    for (const auto& [key, value] : metadata)
        fileMetadata.insertMeta(key, openvdb::StringMetadata(value));
    std::ostringstream bytes(std::ios::binary);
    openvdb::io::Stream(bytes).write(grids, fileMetadata);
    AtomicFile::write(path, bytes.str());
}

WaterVolume WaterVolumeFile::read(const std::string& path) {
    openvdb::initialize();
    const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
    try {
        std::istringstream in(std::string(bytes.begin(), bytes.end()), std::ios::binary);
        // Not delay-loaded: OpenVDB would first copy the stream to a temporary file of its own,
        // which fails under a file-size limit or a full /tmp while the bytes are already here.
        openvdb::io::Stream stream(in, /*delayLoad=*/false);
        auto grids = std::make_shared<WaterGrids>();
        for (const openvdb::GridBase::Ptr& grid : *stream.getGrids()) {
            if (grid->getName() == "surface")
                grids->surface = openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
            else if (grid->getName() == "vel")
                grids->velocity = openvdb::gridPtrCast<openvdb::Vec3SGrid>(grid);
        }
        if (!grids->surface || grids->surface->getGridClass() != openvdb::GRID_LEVEL_SET)
            throw Error(ErrorKind::CacheCorrupt, path + ": no level-set grid named 'surface'");
        const openvdb::MetaMap::Ptr metadata = stream.getMetadata();
        const auto particleVolume =
            metadata->getMetadata<openvdb::DoubleMetadata>("particle_volume");
        return WaterVolume(grids, particleVolume ? particleVolume->value() : 0.0);
    } catch (const openvdb::Exception& error) {
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": not a readable OpenVDB file (" + std::string(error.what()) + ")");
    } catch (const std::bad_alloc&) {
        // OpenVDB allocates by the sizes the file states: damaged ones ask for terabytes.
        throw Error(ErrorKind::CacheCorrupt,
                    path +
                        ": not a readable OpenVDB file (it asks for more memory than there is: "
                        "its sizes are damaged, or the volume is larger than this machine holds)");
    } catch (const std::length_error&) {
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": not a readable OpenVDB file (a damaged size in it)");
    }
}

} // namespace airtrap
