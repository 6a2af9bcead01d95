// The stability atlas of `dtoadq report`: where each method fails, as charts with a one-line finding
// each. Here an entry, and the BRDF models' entries over roughness and incident angle: the energy
// (the directional albedo of a white conductor for the lab model with single scattering only, with
// energy compensation, and for the 2017 model, where a value below 1 is energy lost and above 1
// energy created), the samplers against cosine sampling, and reciprocity. The geometry entries are
// report/atlas_geometry.hpp's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "report/html_page.hpp"

namespace lab::report {

struct AtlasEntry {
    std::string title;
    std::string image, csv;  // in the report folder
    std::string finding;     // one line
    std::string how;         // how it was measured
    Table table;             // its numbers beside the chart; the page writes its CSV
};

// The atlas's test material: a white conductor (F0 = 1, albedo 1; GGX, isotropic) of the given
// model and roughness, with or without energy compensation: any albedo other than 1 is energy lost
// or created.
brdf::Material atlas_white_conductor(int model, float roughness, bool compensated);

// Computes the entries and writes their charts and CSV into `folder`.
std::vector<AtlasEntry> write_stability_atlas(const std::filesystem::path& folder);

}  // namespace lab::report
