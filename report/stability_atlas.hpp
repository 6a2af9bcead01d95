// The stability atlas of `dtoadq report`: where each method fails, as charts with a one-line finding each.
// The BRDF models' energy: the directional albedo of a white conductor over roughness and incident
// angle for the lab model with single scattering only, with energy compensation, and for the 2017
// model, where a value below 1 is energy lost and above 1 energy created.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"

namespace lab::report {

// One panel's extremes: its least and greatest value and where they lie.
struct AtlasExtremes {
    std::string panel;
    double least = 0.0, greatest = 0.0;
    double least_roughness = 0.0, least_theta = 0.0, greatest_roughness = 0.0, greatest_theta = 0.0;
    double least_error = -1.0, greatest_error = -1.0;  // the standard errors of those two estimates; < 0: none (not an estimate)
};

struct AtlasEntry {
    std::string title;
    std::string image, csv;  // in the report folder
    std::string finding;     // one line
    std::string how;         // how it was measured
    std::vector<AtlasExtremes> extremes;
};

// The atlas's test material: a white conductor (F0 = 1, albedo 1; GGX, isotropic) of the given
// model and roughness, with or without energy compensation: any albedo other than 1 is energy lost
// or created.
brdf::Material atlas_white_conductor(int model, float roughness, bool compensated);

// Computes the entries and writes their charts and CSV into `folder`.
std::vector<AtlasEntry> write_stability_atlas(const std::filesystem::path& folder);

}  // namespace lab::report
