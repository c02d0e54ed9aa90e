#pragma once
// Scenes and helpers shared by the editor's bake, loader and timeline tests: the sample dam break
// cut down so that a bake takes seconds, and a cache folder baked synchronously through the
// engine to compare the editor's results with.
#include "bake/Baker.h"
#include "cache/FrameCache.h"
#include "core/Interrupter.h"
#include "scene/Scene.h"
#include "scene/SceneJson.h"

#include <QDir>
#include <QFile>
#include <QString>
#include <string>

namespace airtrap::test {

//! The dam break sample as shipped.
inline Scene sampleDamBreak() {
    return readSceneFile(AIRTRAP_SOURCE_DIR "/samples/dam_break.json");
}

//! A dam break of a few hundred particles: frames 2–4 bake in about a second.
inline Scene tinyDamBreak() {
    Scene scene = sampleDamBreak();
    scene.solver.particleSpacing = 0.05;
    scene.container.max = Vec3d(0.8, 0.6, 0.2);
    scene.fluidBlocks.at(0).max = Vec3d(0.25, 0.4, 0.2);
    scene.frames.endFrame = 4;
    scene.frames.fps = 30.0;
    return scene;
}

//! Bakes `scene` into `dir` on the calling thread, as the CLI would.
inline void bakeNow(const Scene& scene, const QString& dir) {
    Interrupter interrupter;
    Baker(scene, BakeOptions{.cacheDir = dir.toStdString(), .overwrite = true}).run(interrupter);
}

//! Copies the files of the cache folder `from` into `to` (which exists).
inline bool copyCache(const QString& from, const QString& to) {
    for (const QString& name : QDir(from).entryList(QDir::Files))
        if (!QFile::copy(from + "/" + name, to + "/" + name))
            return false;
    return true;
}

} // namespace airtrap::test
