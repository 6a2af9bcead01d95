#include "validation/report.hpp"

#include <cstdio>

#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "validation/chi_square.hpp"
#include "validation/reciprocity.hpp"

namespace lab::validation {

namespace {

// The chi-square suite's incident directions: near-normal to grazing, azimuths off the tangent.
const float kThetas[5] = {0.0f, 28.0f, 52.0f, 71.0f, 86.0f};
const float kPhis[5] = {0.0f, 40.0f, 200.0f, 115.0f, 300.0f};

const char* verdict(bool passed) { return passed ? "PASS" : "FAIL"; }

}  // namespace

MaterialValidation validate_material(const brdf::Preset& preset, const ValidationOptions& options) {
    const brdf::Material& m = preset.material;
    MaterialValidation v;
    v.name = preset.name;
    v.source = preset.source;
    v.model = m.model;

    std::vector<float> thetas(kThetas, kThetas + 5);
    if (transmits(m))
        for (float t : kThetas) thetas.push_back(180.0f - t);
    v.chi_square_tests = int(thetas.size());
    auto stop = [&] { return v.cancelled = options.cancelled && options.cancelled(); };
    for (size_t i = 0; i < thetas.size(); ++i) {
        if (stop()) return v;
        ChiSquareOptions c;
        c.samples = options.chi_square_samples;
        c.significance = options.significance;
        c.tests = v.chi_square_tests;
        c.seed = options.seed * 7919 + i;
        c.threads = options.threads;
        ChiSquareResult r = chi_square_bsdf(m, brdf::direction_from_degrees(thetas[i], kPhis[i % 5]), c);
        v.alpha = r.alpha;
        if (r.dof > 0) v.continuous = true;
        if (r.dof > 0 && r.p_value < v.smallest_p_value) {
            v.smallest_p_value = r.p_value;
            v.smallest_p_theta = thetas[i];
        }
        if (!r.passed && v.chi_square_failure.empty()) {
            char where[64];
            std::snprintf(where, sizeof where, "theta %.0f phi %.0f: ", thetas[i], kPhis[i % 5]);
            v.chi_square_failure = where + r.failure;
        }
    }

    if (stop()) return v;
    v.reciprocity_error = reciprocity_error(m, options.reciprocity_pairs, options.seed).max_relative_error;
    v.reciprocity_tolerance = options.reciprocity_tolerance;
    if (stop()) return v;
    v.albedo = max_directional_albedo(m, options.furnace);
    v.albedo_limit = options.furnace.limit;
    return v;
}

void print_validation_table(std::ostream& out, const std::vector<MaterialValidation>& results) {
    char line[320];
    const char* row = "%-28.28s %-10s  %-24s  %-19s  %-29s  %s\n";
    std::snprintf(line, sizeof line, row, "material", "model", "chi-square (smallest p)", "reciprocity (worst)",
                  "energy (largest albedo at)", "result");
    out << line;
    for (const MaterialValidation& v : results) {
        char chi[64], recip[64], energy[80];
        if (v.continuous)
            std::snprintf(chi, sizeof chi, "%2d dirs p %-9.3g %s", v.chi_square_tests, v.smallest_p_value,
                          verdict(v.chi_square_passed()));
        else
            std::snprintf(chi, sizeof chi, "%2d dirs delta only  %s", v.chi_square_tests, verdict(v.chi_square_passed()));
        std::snprintf(recip, sizeof recip, "%-10.2g %s", v.reciprocity_error, v.reciprocity_by_design() ? "scaled" : verdict(v.reciprocity_passed()));
        std::snprintf(energy, sizeof energy, "%.4f th %5.1f ph %5.1f %s", v.albedo.albedo, v.albedo.theta_deg,
                      v.albedo.phi_deg, verdict(v.energy_passed()));
        std::snprintf(line, sizeof line, row, v.name.c_str(), brdf::model_name(v.model), chi, recip, energy,
                      verdict(v.passed()));
        out << line;
    }
    for (const MaterialValidation& v : results) {
        if (!v.chi_square_passed())
            out << v.name << ": chi-square (level " << v.alpha << " per direction) failed at " << v.chi_square_failure << "\n";
        if (!v.reciprocity_passed())
            out << v.name << ": reciprocity error " << v.reciprocity_error << " above " << v.reciprocity_tolerance << "\n";
        if (!v.energy_passed())
            out << v.name << ": directional albedo " << v.albedo.albedo << " above 1 + " << v.albedo_limit << " at theta "
                << v.albedo.theta_deg << " phi " << v.albedo.phi_deg
                << (v.albedo.strata > 0 ? " (estimated, standard error " + std::to_string(v.albedo.std_error) + ")"
                                        : std::string(" (by quadrature)"))
                << "\n";
    }
}

}  // namespace lab::validation
