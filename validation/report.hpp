// The physical checks of one material, together: chi-square of its sampler at five incident
// directions (and five from inside when it transmits), reciprocity in reflection, and the white
// furnace. Used by `dtoadq validate` and `dtoadq report`.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "brdf/host/preset.hpp"
#include "validation/energy.hpp"

namespace lab::validation {

struct ValidationOptions {
    long chi_square_samples = 1000000;  // per incident direction
    double significance = 0.01;         // family-wise over the material's chi-square tests (Sidak)
    long reciprocity_pairs = 200000;
    double reciprocity_tolerance = 1e-4;  // largest relative error allowed
    FurnaceOptions furnace;               // its `limit` is the albedo allowed above 1
    int threads = 2;
    uint64_t seed = 1;
    // Asked between checks (and between chi-square directions): true stops the run early, with
    // MaterialValidation::cancelled set. The viewer's badges cancel a run a newer edit made stale.
    std::function<bool()> cancelled;
};

struct MaterialValidation {
    std::string name, source;
    int model = BRDF_MODEL_LAB;

    int chi_square_tests = 0;        // incident directions
    double smallest_p_value = 1.0;   // over them (1 when no continuous lobe was sampled)
    float smallest_p_theta = 0.0f;   // where it occurs, degrees (> 90: from inside)
    double alpha = 0.0;              // the per-test level after the Sidak correction
    bool continuous = false;         // whether any direction had a continuous lobe to test
    std::string chi_square_failure;  // the first failing direction and why; empty when all passed

    double reciprocity_error = 0.0;
    double reciprocity_tolerance = 0.0;

    AlbedoPeak albedo;
    double albedo_limit = 0.0;
    bool cancelled = false;  // stopped early by ValidationOptions::cancelled: the figures are partial

    bool chi_square_passed() const { return chi_square_failure.empty(); }
    // openpbr's albedo scaling departs from reciprocity by design (docs/materials.md): its figure is
    // shown with the badge "scaled" instead of a verdict
    bool reciprocity_by_design() const { return model == BRDF_MODEL_OPENPBR; }
    bool reciprocity_passed() const { return reciprocity_by_design() || reciprocity_error <= reciprocity_tolerance; }
    bool energy_passed() const { return albedo.albedo <= 1.0 + albedo_limit; }
    bool passed() const { return chi_square_passed() && reciprocity_passed() && energy_passed(); }
};

MaterialValidation validate_material(const brdf::Preset& preset, const ValidationOptions& options);

// One row per material with the figures and PASS/FAIL per check, then a line per failure.
void print_validation_table(std::ostream& out, const std::vector<MaterialValidation>& results);

}  // namespace lab::validation
