// What the interchange tests share: the bundled openpbr presets, and the message of a reader's
// lab::InputError.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "interchange/openpbr_mapping.hpp"

namespace interchange_checks {

inline std::vector<brdf::Preset> openpbr_presets() {
    std::vector<brdf::Preset> out;
    for (const auto& entry : std::filesystem::directory_iterator("presets")) {
        if (entry.path().extension() != ".json") continue;
        brdf::Preset p = brdf::load_preset(entry.path().string());
        if (p.material.model == BRDF_MODEL_OPENPBR) out.push_back(p);
    }
    return out;
}

// The message of the lab::InputError `read` throws, or "" when it throws none.
template <class Read>
std::string input_error_of(const Read& read) {
    try {
        read();
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace interchange_checks
