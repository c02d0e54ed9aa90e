// Must not compile: sph is below sim, so the header is not on sph's include path
// (docs/ARCHITECTURE.md "Engine folders as layers"). The LayerRule test builds this file and
// passes only when the compiler cannot find the header.
#include "sim/Simulation.h"
