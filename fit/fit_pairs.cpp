#include "fit/fit_pairs.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lab::fit {
namespace {

void check_stride(int stride, int bins, const char* name) {
    if (stride < 1 || stride > bins)
        throw std::invalid_argument(std::string("fit: ") + name + " stride " + std::to_string(stride) + " is outside [1, " +
                                    std::to_string(bins) + "]");
}

// The middle bin of each block of `stride` bins (the last block may be shorter).
std::vector<int> stratum_centres(int bins, int stride) {
    std::vector<int> centres;
    for (int first = 0; first < bins; first += stride) centres.push_back(std::min(first + stride / 2, bins - 1));
    return centres;
}

brdf::float3 turned(brdf::float3 v, float phi) {
    const float c = std::cos(phi), s = std::sin(phi);
    return brdf::float3(c * v.x - s * v.y, s * v.x + c * v.y, v.z);
}

}  // namespace

std::vector<FitPair> fit_pairs(const brdf::MeasuredTable& table, const PairGrid& grid) {
    check_stride(grid.theta_h_stride, MERL_THETA_H_BINS, "theta_h");
    check_stride(grid.theta_d_stride, MERL_THETA_D_BINS, "theta_d");
    check_stride(grid.phi_d_stride, MERL_PHI_D_BINS, "phi_d");
    if (grid.phi_h_count < 1) throw std::invalid_argument("fit: phi_h_count must be at least 1");
    if (table.rgb.size() != std::size_t(3) * MERL_ENTRY_COUNT) throw std::invalid_argument("fit: the measured table is incomplete");
    std::vector<FitPair> pairs;
    for (int ih : stratum_centres(MERL_THETA_H_BINS, grid.theta_h_stride))
        for (int id : stratum_centres(MERL_THETA_D_BINS, grid.theta_d_stride))
            for (int ip : stratum_centres(MERL_PHI_D_BINS, grid.phi_d_stride)) {
                brdf::float3 wo, wi;
                brdf::directions_from_half_diff(brdf::merl_bin_center(ih, id, ip), &wo, &wi);
                if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) continue;
                const brdf::float3 measured = brdf::merl_entry(table.rgb.data(), brdf::merl_entry_index(ih, id, ip));
                // MERL marks unmeasured entries with -1 in every channel; the reader's fill is no measurement to fit
                if (brdf::is_unmeasured(table, brdf::merl_entry_index(ih, id, ip))) continue;
                for (int k = 0; k < grid.phi_h_count; ++k) {
                    const float phi_h = float(M_PI) * float(k) / float(grid.phi_h_count);
                    pairs.push_back({turned(wo, phi_h), turned(wi, phi_h), measured, ih, id, ip});
                }
            }
    return pairs;
}

}  // namespace lab::fit
