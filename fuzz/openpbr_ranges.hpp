// The invariant both interchange harnesses check on a material they accepted: every openpbr
// parameter finite and within its range (brdf/host/parameters.hpp).
#pragma once

#include <cmath>

#include "brdf/host/parameters.hpp"
#include "interchange/openpbr_mapping.hpp"

inline bool openpbr_parameters_within_ranges(const brdf::Material& m) {
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
        const std::array<float, 3> v = interchange::parameter_value(m, p);
        for (int c = 0; c < interchange::parameter_components(p); ++c)
            if (!(std::isfinite(v[c]) && v[c] >= p.min && v[c] <= p.max)) return false;
    }
    return true;
}
