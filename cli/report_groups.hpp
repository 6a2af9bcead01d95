// How `dtoadq report` groups presets for overlaid lobe plots: materials that are compared with each
// other sit in one chart.
#pragma once

#include <string>
#include <vector>

#include "brdf/host/preset.hpp"

namespace lab::cli {

struct PresetGroup {
    std::string id;     // file-name friendly
    std::string title;
    std::vector<brdf::Preset> presets;
};

// conductors, opaque dielectrics, transmissive materials, and the dtoadq2017 model shown beside the
// lab presets it is usually compared with (opaque dielectrics); empty groups are left out.
std::vector<PresetGroup> group_presets(const std::vector<brdf::Preset>& presets);

}  // namespace lab::cli
