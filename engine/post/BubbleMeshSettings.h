#pragma once
// The oscillating bubble mesh's controls (paper §4.1, eq. 10).
namespace airtrap {

struct BubbleMeshSettings {
    int subdivisions = 2;   //!< of the icosphere: 20·4^n triangles (2: 320)
    double magnitude = 0.1; //!< k: the largest change of the cross radius, as a share of r (≪ 1)
    double duration = 0.5;  //!< T, s: how long a bubble wobbles after its birth
    double cycles = 3.0;    //!< n: oscillations within T
};

} // namespace airtrap
