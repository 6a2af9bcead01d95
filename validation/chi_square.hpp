// Chi-square goodness-of-fit of a direction sampler against its claimed density (the test Mitsuba 3
// runs on its BSDFs): a histogram of samples over equal-area cells of the whole sphere is compared
// with the density integrated over each cell.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "brdf/brdf.hpp"

namespace lab::validation {

enum class SampleKind { Failed, Delta, Continuous };

struct DirectionSample {
    SampleKind kind = SampleKind::Failed;
    brdf::float3 wi{0.0f, 0.0f, 1.0f};
    std::string defect;  // non-empty: the sampler broke a promise (the test fails and reports it)
};

// u: three uniform numbers in [0, 1). Called from several threads at once.
using DirectionSampler = std::function<DirectionSample(brdf::float3 u)>;
// Solid-angle density of the Continuous samples; deltas and failures carry the missing mass.
using DirectionDensity = std::function<double(brdf::float3 wi)>;

struct ChiSquareOptions {
    long samples = 1000000;
    int z_cells = 100;    // over cos theta in [-1, 1]: equal-area bands, the horizon on a band edge
    int phi_cells = 100;  // over phi in [0, 2 pi)
    double significance = 0.01;
    int tests = 1;        // Sidak correction over this many tests
    uint64_t seed = 1;
    int threads = 2;
};

struct ChiSquareResult {
    bool passed = false;
    std::string failure;          // why it failed; empty when it passed
    double statistic = 0.0;
    int dof = 0;
    double p_value = 0.0;
    double alpha = 0.0;           // the Sidak-corrected level p_value is compared with
    double pdf_integral = 0.0;    // of the density over the sphere
    double continuous_fraction = 0.0, delta_fraction = 0.0, failed_fraction = 0.0;  // of the samples
    int cells = 0;                // after pooling cells expected to hold fewer than 5 samples
    std::string worst_cell;       // the cell adding most to the statistic, for diagnosis
};

ChiSquareResult chi_square_test(const DirectionSampler& sampler, const DirectionDensity& density,
                                const ChiSquareOptions& options);

// One line: p-value, statistic, dof, masses; and the failure if any.
std::string describe(const ChiSquareResult& result);

// The BSDF's sampler for a fixed wo. Each non-delta sample must also carry pdf == bsdf_pdf(wo, wi)
// and f == bsdf_eval(wo, wi) (relative 1e-4; checked on one sample in eight, chosen by u), flags
// matching the side of wi, and delta samples a positive discrete probability; a broken promise is
// reported as a defect.
DirectionSampler bsdf_direction_sampler(const brdf::Material& material, brdf::float3 wo);
DirectionDensity bsdf_direction_density(const brdf::Material& material, brdf::float3 wo);

ChiSquareResult chi_square_bsdf(const brdf::Material& material, brdf::float3 wo, const ChiSquareOptions& options);

}  // namespace lab::validation
