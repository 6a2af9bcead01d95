// What the interchange tests share: the bundled openpbr presets, and the comparison of a material
// read back against the one written, parameter by parameter: exact (the float read back is the
// float written) unless the writer's notes name the parameter.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
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

// The parameters whose value read back differs from the one written and that no note names,
// as "key: written -> read" lines; `skip` lists parameters the caller checks otherwise.
inline std::vector<std::string> silent_changes(const brdf::Material& written, const brdf::Material& read, const interchange::Notes& notes,
                                               const std::vector<std::string>& skip = {}) {
    std::vector<std::string> out;
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
        bool skipped = false;
        for (const std::string& s : skip) skipped = skipped || s == p.key;
        if (skipped || notes.names(p.key)) continue;
        const auto a = interchange::parameter_value(written, p), b = interchange::parameter_value(read, p);
        if (a != b)
            out.push_back(std::string(p.key) + ": " + interchange::float_text(a[0]) + " " + interchange::float_text(a[1]) + " " +
                          interchange::float_text(a[2]) + " -> " + interchange::float_text(b[0]) + " " + interchange::float_text(b[1]) + " " +
                          interchange::float_text(b[2]));
    }
    if (written.energy_compensation != read.energy_compensation && !notes.names("energy_compensation")) out.push_back("energy_compensation");
    return out;
}

}  // namespace interchange_checks
