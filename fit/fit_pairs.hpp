// The direction pairs a fit compares at: a stratified subset of the measured table's bin centres,
// where the table's entry is the measurement itself (no interpolation). Strata are blocks of
// stride bins along theta_h, theta_d and phi_d; each contributes the bin at its middle. Like the
// table, they are dense near the highlight (theta_h bins are spaced as sqrt(theta_h)). Pairs with
// either direction at or below the horizon are left out: the table holds no measurement there; so
// are entries the file marks unmeasured (MERL's files hold -1 there; brdf::is_unmeasured).
#pragma once

#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/merl_file.hpp"

namespace lab::fit {

struct PairGrid {
    int theta_h_stride = 2, theta_d_stride = 2, phi_d_stride = 6;  // bins per stratum
    // Copies of each pair turned about the normal by phi_h = k pi / phi_h_count: an anisotropic
    // model depends on phi_h, the (isotropic) table does not.
    int phi_h_count = 1;
};

struct FitPair {
    brdf::float3 wo, wi;
    brdf::float3 measured;  // the table's entry, 1/sr
    int ih, id, ip;         // its bin
};

// Throws std::invalid_argument for a stride outside [1, the bin count] or phi_h_count < 1.
std::vector<FitPair> fit_pairs(const brdf::MeasuredTable& table, const PairGrid& grid);

}  // namespace lab::fit
