// OpenPBR's base as a mix of pure parts, for formats that blend whole BSDFs (Mitsuba's blendbsdf,
// pbrt's mix material): base_metalness mixes the dielectric base (weight 1 - m) with the metal (m),
// and transmission_weight mixes, inside the dielectric, the opaque base with the transmissive
// interface. A material with both weights at 0 or 1 is one pure part.
#pragma once

#include "brdf/brdf.hpp"

namespace interchange {

struct BaseMix {
    float weight;             // of `second`
    brdf::Material first;     // weight 1 - weight
    brdf::Material second;
};

// The first of the two mixes that is partial (metal over dielectric, then transmission over opaque):
// false when the material is a pure part already.
bool split_base_mix(const brdf::Material& m, BaseMix* mix);

}  // namespace interchange
