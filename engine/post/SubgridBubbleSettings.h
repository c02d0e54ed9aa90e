#pragma once
// The sub-grid bubbles' controls (paper §4.2): how many a new trapped air bubble sheds, how big,
// how many generations, and how long they live. The rise is the trapped bubbles' own (Stokes
// speed from `bubbles.kinematic_viscosity`, capped by `bubbles.max_rise_speed`).
namespace airtrap {

struct SubgridBubbleSettings {
    int maxPerBubble = 24;     //!< shed by a new bubble entirely in air (area fraction 0)
    double minSize = 0.15;     //!< smallest radius, as a share of the parent's
    double maxSize = 0.35;     //!< largest radius, as a share of the parent's
    int generations = 1;       //!< 1: from trapped bubbles only; each more sheds from the last
    int childrenPerBubble = 3; //!< shed by a sub-grid bubble of a generation before the last
    double lifetime = 3.0;     //!< s; older ones are deleted
    int substeps = 4;          //!< RK2 steps per frame
};

} // namespace airtrap
