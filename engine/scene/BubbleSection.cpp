#include "scene/BubbleSection.h"

#include "scene/SchemaBinding.h"

namespace airtrap {
namespace {

using namespace schema;

using BubbleAccess = ObjectAccess<&Scene::bubbles>;

std::vector<BoundParameter> creationParameters() {
    return {
        bind<BubbleAccess>({.key = "enabled",
                            .label = "Simulate bubbles",
                            .help = "Turns air pockets the water encloses into bubbles. Off, the "
                                    "water bakes exactly as a water-only scene."},
                           &BubbleSettings::enabled),
        bind<BubbleAccess>({.key = "density_ratio",
                            .label = "Density ratio",
                            .minimum = 0.01,
                            .maximum = 1.0,
                            .help = "Bubble density over water density. Real air is 0.001; "
                                    "weakly compressible SPH stays stable down to about 0.1 "
                                    "(paper §3.2)."},
                           &BubbleSettings::densityRatio),
        bind<BubbleAccess>({.key = "min_radius",
                            .label = "Minimum radius",
                            .unit = "× spacing",
                            .minimum = 1.0,
                            .maximum = 20.0,
                            .help = "Air pockets whose fitted bubble would be smaller make no "
                                    "bubble (they are left to the sub-grid bubbles). One spacing "
                                    "lets a single empty grid cell (two spacings wide) count."},
                           &BubbleSettings::minRadius),
        bind<BubbleAccess>({.key = "max_new_per_frame",
                            .label = "New bubbles per frame",
                            .minimum = 0,
                            .maximum = 1000,
                            .help = "At most this many pockets, chosen at random with the "
                                    "scene's seed, become bubbles in each frame."},
                           &BubbleSettings::maxNewPerFrame),
        bind<BubbleAccess>({.key = "min_water_share",
                            .label = "Water around a new bubble",
                            .minimum = 0.5,
                            .maximum = 1.0,
                            .help = "A pocket becomes a bubble only under water: the water must "
                                    "cover its top and at least this share of the 26 probes "
                                    "around the bubble (docs/METHOD.md, \"Creation\"). Lower "
                                    "lets pockets in a splash's crown, half in air, make bubbles "
                                    "that leave the water at once."},
                           &BubbleSettings::minWaterShare),
        bind<BubbleAccess>({.key = "pocket_interval",
                            .label = "Pocket search interval",
                            .unit = "s",
                            .minimum = 1e-4,
                            .maximum = 0.05,
                            .help = "Simulated time between searches for air pockets (a "
                                    "search every step when the steps are longer). Without "
                                    "air pressure a trapped pocket closes within a few "
                                    "hundredths of a second, so it must be found soon after it "
                                    "forms."},
                           &BubbleSettings::pocketInterval),
    };
}

std::vector<BoundParameter> dynamicsParameters() {
    return {
        bind<BubbleAccess>({.key = "kinematic_viscosity",
                            .label = "Water viscosity ν",
                            .unit = "m²/s",
                            .minimum = 1.0e-7,
                            .maximum = 1.0e-2,
                            .help = "Kinematic viscosity in the Stokes rise speed "
                                    "v = 2/9 g R² / ν (paper eq. 5) and the Stokes drag. Water "
                                    "at 20 °C: 1.0e-6."},
                           &BubbleSettings::kinematicViscosity),
        bind<BubbleAccess>({.key = "max_rise_speed",
                            .label = "Rise speed cap",
                            .unit = "m/s",
                            .minimum = 0.01,
                            .maximum = 10.0,
                            .help = "Caps the Stokes speed, which grows with R² (2.2 m/s at "
                                    "R = 1 mm). Real centimetre bubbles rise at 0.2–0.3 m/s."},
                           &BubbleSettings::maxRiseSpeed),
        bind<BubbleAccess>({.key = "rise_time",
                            .label = "Rise response time",
                            .unit = "s",
                            .minimum = 0.001,
                            .maximum = 10.0,
                            .help = "Time constant with which the auxiliary buoyancy steers a "
                                    "submerged bubble's vertical speed toward the water's plus "
                                    "the capped Stokes speed."},
                           &BubbleSettings::riseTime),
        bind<BubbleAccess>({.key = "drag",
                            .label = "Drag rate",
                            .unit = "1/s",
                            .minimum = 0.0,
                            .maximum = 1000.0,
                            .help = "The object's friction k of eq. 6, per unit of bubble mass: "
                                    "the rate at which a bubble takes on the surrounding water's "
                                    "velocity, on top of the Stokes drag 6πρνR."},
                           &BubbleSettings::drag),
        bind<BubbleAccess>({.key = "approach_restitution",
                            .label = "Restitution approaching (ε₁)",
                            .minimum = -1.0,
                            .maximum = 0.0,
                            .help = "Non-positive coefficient of restitution between bubbles "
                                    "that touch and approach (paper §3.3.2): −1 no interaction, "
                                    "between −1 and 0 a weak repulsion that lets them overlap."},
                           &BubbleSettings::approachRestitution),
        bind<BubbleAccess>({.key = "overlap_restitution",
                            .label = "Restitution overlapping (ε₂)",
                            .minimum = -1.0,
                            .maximum = 0.0,
                            .help = "The same between bubbles that already overlap; at least "
                                    "ε₁. Nearer 0 slows their merging down."},
                           &BubbleSettings::overlapRestitution),
    };
}

std::vector<BoundParameter> deletionParameters() {
    return {
        bind<BubbleAccess>({.key = "max_age",
                            .label = "Maximum age",
                            .unit = "s",
                            .minimum = 0.0,
                            .maximum = 1000.0,
                            .help = "A bubble older than this is deleted (rule 1 of §3.4)."},
                           &BubbleSettings::maxAge),
        bind<BubbleAccess>({.key = "max_floating_time",
                            .label = "Maximum floating time",
                            .unit = "s",
                            .minimum = 0.0,
                            .maximum = 1000.0,
                            .help = "A bubble floating at the free surface (water against a "
                                    "quarter to a half of it) for longer than this pops (rule 2). "
                                    "One with less water around it has left the water and pops "
                                    "at once (surfaced)."},
                           &BubbleSettings::maxFloatingTime),
        bind<BubbleAccess>({.key = "max_overlap",
                            .label = "Maximum overlap",
                            .minimum = 0.0,
                            .maximum = 1.0,
                            .help = "When two bubbles overlap by more than this share of the "
                                    "smaller one's diameter, the smaller is deleted (rule 3)."},
                           &BubbleSettings::maxOverlap),
        bind<BubbleAccess>({.key = "impact_speed",
                            .label = "Impact speed",
                            .unit = "m/s",
                            .minimum = 0.0,
                            .maximum = 100.0,
                            .help = "A floating bubble hit by water approaching faster than this "
                                    "pops (rule 4)."},
                           &BubbleSettings::impactSpeed),
    };
}

} // namespace

SchemaSection bubblesSection() {
    std::vector<BoundParameter> parameters = creationParameters();
    for (auto group : {dynamicsParameters(), deletionParameters()})
        parameters.insert(parameters.end(), group.begin(), group.end());
    return objectSection("bubbles", "Bubbles",
                         "Trapped air bubbles: light spheres created where the water encloses "
                         "air, rising toward their Stokes speed and deleted by age, time at the "
                         "surface, overlap, impact, or on leaving the water (paper §3.2–3.4).",
                         std::move(parameters));
}

} // namespace airtrap
