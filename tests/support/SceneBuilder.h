#pragma once
// A test scene in a few lines: the settings a physics test chooses (spacing, speed limit, frames,
// the tank, the water, bodies), Scene's defaults for the rest, other fields through scene().
//   Scene scene = SceneBuilder().spacing(0.02).maxSpeed(4.0).tank({1.0, 1.4, 0.2})
//                     .water({0, 0, 0}, {0.3, 0.4, 0.2}).build();
#include "scene/Scene.h"

#include <string>

namespace airtrap::test {

class SceneBuilder {
public:
    //! m, the particle spacing.
    SceneBuilder& spacing(double metres) {
        scene_.solver.particleSpacing = metres;
        return *this;
    }
    //! m/s, u_max: the speed of sound is ten times this.
    SceneBuilder& maxSpeed(double metresPerSecond) {
        scene_.solver.maxSpeed = metresPerSecond;
        return *this;
    }
    //! Frames per second and the last frame (frame 1 is t = 0).
    SceneBuilder& frames(double fps, int endFrame) {
        scene_.frames.fps = fps;
        scene_.frames.endFrame = endFrame;
        return *this;
    }
    //! The tank from the origin to `max` (m), `headroom` m of domain above its rim.
    SceneBuilder& tank(const Vec3d& max, double headroom = ContainerSettings{}.headroom) {
        scene_.container.min = Vec3d::Zero();
        scene_.container.max = max;
        scene_.container.headroom = headroom;
        return *this;
    }
    //! A block of water from `min` to `max` (m) moving at `velocity` (m/s).
    SceneBuilder& water(const Vec3d& min, const Vec3d& max, const Vec3d& velocity = Vec3d::Zero(),
                        const std::string& name = FluidBlock{}.name) {
        FluidBlock block;
        block.name = name;
        block.min = min;
        block.max = max;
        block.initialVelocity = velocity;
        scene_.fluidBlocks.push_back(block);
        return *this;
    }
    SceneBuilder& body(const RigidBodySettings& body) {
        scene_.bodies.push_back(body);
        return *this;
    }
    //! Bubbles on, with none created on their own when `created` is false (the test places
    //! its own).
    SceneBuilder& bubbles(bool created = true) {
        scene_.bubbles.enabled = true;
        if (!created)
            scene_.bubbles.maxNewPerFrame = 0;
        return *this;
    }

    //! For the fields the builder has no word for.
    Scene& scene() { return scene_; }
    Scene build() const { return scene_; }

private:
    Scene scene_;
};

} // namespace airtrap::test
