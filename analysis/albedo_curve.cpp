#include "analysis/albedo_curve.hpp"

#include <stdexcept>

#include "brdf/host/angles.hpp"

namespace lab::analysis {

std::vector<AlbedoPoint> albedo_curve(const brdf::Material& m, const AlbedoCurveOptions& options) {
    if (options.angles < 2 || options.strata < 1) throw std::invalid_argument("albedo curve: needs 2 angles and 1 stratum at least");
    std::vector<AlbedoPoint> curve;
    for (int k = 0; k < options.angles; ++k) {
        float theta = 90.0f * float(k) / float(options.angles - 1);
        brdf::float3 wi = brdf::direction_from_degrees(theta, options.phi_deg);
        // one seed per angle, so a curve does not depend on how many angles came before
        curve.push_back({theta, validation::directional_albedo(m, wi, options.strata, options.seed + uint64_t(k))});
    }
    return curve;
}

}  // namespace lab::analysis
