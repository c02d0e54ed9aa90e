// Compiles: rigid is below sph. The LayerRuleControl test builds this file, so that LayerRule's
// failure is known to come from the include, not from the probe's set-up.
#include "rigid/RigidBody.h"
#include "sph/WcsphSolver.h"
