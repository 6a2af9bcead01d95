// The bundled presets (presets/*.json, by file name) that a run builds a kernel for, where a kernel
// per preset is most of a test's cost (a cold PoCL build, about 2 s of CPU each): every preset that
// is the only one to need some feature (brdf/host/features.hpp), so each feature's code is built and
// run in every run, and a third of the others, drawn per run (tests/points_of_run.hpp:
// DTOADQ_SWEEP_POINTS_SEED repeats a draw, DTOADQ_SWEEP_POINTS=all takes every preset). `name`
// names the test's draw.
#pragma once

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "brdf/host/features.hpp"
#include "brdf/host/preset.hpp"
#include "tests/points_of_run.hpp"

inline std::vector<brdf::Preset> bundled_presets_of_run(const std::string& name) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator("presets"))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::vector<brdf::Preset> all;
    for (const std::filesystem::path& file : files) all.push_back(brdf::load_preset(file.string()));
    std::vector<std::vector<std::pair<std::string, bool>>> features;
    for (const brdf::Preset& p : all) features.push_back(brdf::used_features({p.material}));
    std::vector<int> always;
    for (size_t f = 0; f < (features.empty() ? 0 : features[0].size()); ++f) {
        std::vector<int> users;
        for (size_t i = 0; i < all.size(); ++i)
            if (features[i][f].second) users.push_back(int(i));
        if (users.size() == 1 && std::find(always.begin(), always.end(), users[0]) == always.end()) always.push_back(users[0]);
    }
    const int others = int(all.size()) - int(always.size());
    std::vector<brdf::Preset> chosen;
    std::string names;
    for (int i : sweep_points_of_run(name, int(all.size()), (others + 2) / 3, always)) {
        chosen.push_back(all[size_t(i)]);
        names += " " + files[size_t(i)].stem().string();
    }
    std::printf("%s: %zu of %zu presets:%s\n", name.c_str(), chosen.size(), all.size(), names.c_str());
    return chosen;
}
