// The fit's error: the cosine-weighted log-space RMSE of Löw et al. (2012),
//   E = sqrt( mean over pairs k and channels c of [ ln(1 + cos_i f_model) - ln(1 + cos_i f_measured) ]^2 )
// with cos_i the incident direction's cosine. The log compresses the highlight's dynamic range, so
// the tails and the diffuse part count too; the cosine weighs values by the light they reflect,
// so near-grazing entries (the least reliable measurements) count less. The mean is over the
// stratified pairs of fit/fit_pairs.hpp.
#pragma once

#include <vector>

#include "brdf/brdf.hpp"
#include "fit/fit_pairs.hpp"

namespace lab::fit {

// The per-channel residual of one pair (the term inside the square above).
brdf::float3 log_residual(brdf::float3 model, brdf::float3 measured, float cos_i);

// The model f(wo, wi) as the fit evaluates it: the lab BSDF without the cosine.
brdf::float3 model_value(const brdf::Material& m, const FitPair& pair);

// E over the pairs (0 for none), on the machine's threads.
double fit_error(const brdf::Material& m, const std::vector<FitPair>& pairs);

// E split up: per channel, and per band of incident angle theta_i.
struct IncidenceBand {
    double theta_min_deg, theta_max_deg;
    int pairs;
    double error;  // E over the band's pairs; NaN when it has none
};
struct ErrorBreakdown {
    double total = 0.0;
    double channel[3] = {0.0, 0.0, 0.0};
    std::vector<IncidenceBand> incidence;  // 9 bands of 10 degrees
};
ErrorBreakdown error_breakdown(const brdf::Material& m, const std::vector<FitPair>& pairs);

// E per (theta_h bin, theta_d bin) of the table, over every phi_d_stride-th phi_d bin and the
// channels: the heat map. NaN where every pair of the cell lies below the horizon.
struct ErrorMap {
    std::vector<double> error;  // MERL_THETA_H_BINS rows x MERL_THETA_D_BINS columns
};
ErrorMap error_map(const brdf::MeasuredTable& table, const brdf::Material& m, int phi_d_stride);

}  // namespace lab::fit
