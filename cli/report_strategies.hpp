// The stability atlas's integrator entry (docs/report.md): per scene, BDPT's strategies rendered one
// by one with the balance heuristic (cli/strategy_images.hpp), and the map of which group of them
// (the path tracer's, light tracing's, connections) carries each pixel's light (report/strategy_shares.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/stability_atlas.hpp"
#include "report/strategy_shares.hpp"

namespace lab::cli {

struct StrategyAtlasOptions {
    std::vector<std::string> scenes;  // scene files, each rendered under its own lights
    std::string size = "96x72";
    int spp = 16;       // per strategy
    int max_depth = 3;  // scattering events: paths of up to five vertices, the caustic's light through a glass ball
    std::string device;
};

struct StrategyAtlasScene {
    std::string scene;        // the file's name
    std::string image;        // the groups' map beside the BDPT image, in the report folder
    report::StrategyShares shares;
};

struct StrategyAtlas {
    StrategyAtlasOptions options;
    std::vector<StrategyAtlasScene> scenes;
    std::string image, csv;  // all scenes' maps on one sheet, and every strategy's share
};

// Renders and writes atlas_strategies.png/.csv and atlas_strategies_SCENE_*.png into `folder`.
// *device: the device's description. Throws lab::InputError for a scene that cannot be loaded (the
// report checks beforehand that each has a light of its own: without, BDPT's image is black).
StrategyAtlas write_strategy_atlas(const StrategyAtlasOptions& options, const std::filesystem::path& folder, std::string* device);

// The atlas entry: the sheet, each group's share of the light per scene, where it carries under a
// tenth, its strongest strategy, and the finding in numbers.
report::AtlasEntry strategy_atlas_entry(const StrategyAtlas& atlas);

}  // namespace lab::cli
