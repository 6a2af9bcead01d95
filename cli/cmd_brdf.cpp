// dtoadq brdf eval | sample: the BRDF at the command line, one direction per line.
#include <cstdio>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include "brdf/brdf.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "common/input_error.hpp"

namespace lab::cli {
namespace {

struct BrdfOptions {
    std::string material;
    std::string wi = "0,0";
    long count = 16;
    uint64_t seed = 1;
};

void print_row(brdf::float3 w, brdf::float3 f, float pdf) {
    float theta, phi;
    degrees_from_direction(w, &theta, &phi);
    std::printf("%.6g %.6g %.9g %.9g %.9g %.9g\n", theta, phi, f.x, f.y, f.z, pdf);
}

void run_eval(const BrdfOptions& o) {
    brdf::Preset preset = brdf::load_preset(o.material);
    float theta_in, phi_in;
    parse_angle_pair(o.wi, "--wi", &theta_in, &phi_in);
    brdf::float3 wi = direction_from_degrees(theta_in, phi_in);
    std::string line;
    long line_number = 0;
    while (std::getline(std::cin, line)) {
        ++line_number;
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream in(line);
        double theta, phi;
        if (!(in >> theta >> phi) || !(in >> std::ws).eof() || !std::isfinite(theta) || !std::isfinite(phi))
            throw InputError("standard input", "line " + std::to_string(line_number), "expected \"theta phi\" in degrees, got \"" + line + "\"");
        brdf::float3 wo = direction_from_degrees(float(theta), float(phi));
        // the given --wi is the BSDF's first (conditioning) argument, as in `brdf sample`, so the two
        // commands print the same f and pdf for the same pair; in reflection f is reciprocal anyway
        print_row(wo, brdf::bsdf_eval(&preset.material, wi, wo), brdf::bsdf_pdf(&preset.material, wi, wo));
    }
}

void run_sample(const BrdfOptions& o) {
    brdf::Preset preset = brdf::load_preset(o.material);
    float theta_in, phi_in;
    parse_angle_pair(o.wi, "--wi", &theta_in, &phi_in);
    if (o.count < 0) throw InputError("command line", "-n", "must not be negative");
    brdf::float3 wi = direction_from_degrees(theta_in, phi_in);
    std::mt19937_64 rng(o.seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (long i = 0; i < o.count; ++i) {
        brdf::float3 u(uniform(rng), uniform(rng), uniform(rng));
        // the sampler draws the BSDF's second argument given its first (see run_eval)
        brdf::BsdfSample s = brdf::bsdf_sample(&preset.material, wi, u);
        if (!s.flags)
            print_row(s.wi, brdf::float3(0.0f), 0.0f);
        else
            print_row(s.wi, s.f, s.pdf);
    }
}

}  // namespace

void register_brdf(CLI::App& app) {
    auto* brdf_cmd = app.add_subcommand("brdf", "Evaluate or sample a material's BSDF at the command line");
    brdf_cmd->require_subcommand(1);
    auto options = std::make_shared<BrdfOptions>();

    auto* eval = brdf_cmd->add_subcommand("eval", "Read 'theta phi' (degrees) per line on stdin, print 'theta phi f_r f_g f_b pdf'");
    eval->add_option("--material", options->material, "Material preset (JSON)")->required();
    eval->add_option("--wi", options->wi, "Incident direction THETA,PHI in degrees (theta from the normal, phi from the tangent)")->required();
    eval->callback([options] { run_eval(*options); });

    auto* sample = brdf_cmd->add_subcommand("sample", "Print N sampled outgoing directions as 'theta phi f_r f_g f_b pdf'");
    sample->add_option("--material", options->material, "Material preset (JSON)")->required();
    sample->add_option("--wi", options->wi, "Incident direction THETA,PHI in degrees")->required();
    sample->add_option("-n", options->count, "Number of samples")->capture_default_str();
    sample->add_option("--seed", options->seed, "Random seed")->capture_default_str();
    sample->callback([options] { run_sample(*options); });
}

}  // namespace lab::cli
