// dtoadq validate: the physical checks (chi-square of the sampler, reciprocity, white furnace) of
// one or more materials, as a PASS/FAIL table; exits non-zero when a check fails.
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "common/input_error.hpp"
#include "validation/report.hpp"

namespace lab::cli {
namespace {

struct ValidateOptions {
    std::vector<std::string> materials;
    long samples = 1000000;
    uint64_t seed = 1;
};

void run_validate(const ValidateOptions& o) {
    if (o.samples < 10000 || o.samples > 100000000)
        throw InputError("command line", "--samples", "must be in [10000, 100000000]");
    std::vector<brdf::Preset> presets = load_presets(o.materials);
    validation::ValidationOptions options;
    options.chi_square_samples = o.samples;
    options.seed = o.seed;
    std::vector<validation::MaterialValidation> results;
    for (const brdf::Preset& p : presets) {
        std::fprintf(stderr, "validate: %s\n", p.source.c_str());
        results.push_back(validation::validate_material(p, options));
    }
    validation::print_validation_table(std::cout, results);
    std::cout.flush();
    int failed = 0;
    for (const validation::MaterialValidation& r : results) failed += !r.passed();
    if (failed > 0) {
        std::fprintf(stderr, "dtoadq: validate: %d of %zu material(s) failed a physical check\n", failed, results.size());
        throw CLI::RuntimeError(1);
    }
}

}  // namespace

void register_validate(CLI::App& app) {
    auto options = std::make_shared<ValidateOptions>();
    auto* cmd = app.add_subcommand("validate", "Chi-square, reciprocity and white-furnace checks of materials (PASS/FAIL table)");
    cmd->add_option("--material", options->materials, "Material preset (JSON); repeat for several")->required();
    cmd->add_option("--samples", options->samples, "Chi-square samples per incident direction")->capture_default_str();
    cmd->add_option("--seed", options->seed, "Random seed")->capture_default_str();
    cmd->callback([options] { run_validate(*options); });
}

}  // namespace lab::cli
