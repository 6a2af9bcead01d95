// Random points for the scene tests: half over a box that holds everything in scenes/ and
// tests/scene_data/ (the colonnade of scenes/repetition.json goes on beyond it), half over the
// region near the models where the blends and the concave parts are.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "validation/uniform_random.hpp"

namespace scene_test {

inline std::vector<lab::scene::Vec3> random_points(size_t count, uint64_t seed) {
    lab::validation::UniformRandom rng(seed);
    std::vector<lab::scene::Vec3> points;
    for (size_t i = 0; i < count; ++i) {
        bool near = i % 2 == 1;
        lab::scene::Vec3 lo = near ? lab::scene::Vec3(-2.5f, -0.5f, -2.5f) : lab::scene::Vec3(-6.0f, -1.0f, -9.0f);
        lab::scene::Vec3 hi = near ? lab::scene::Vec3(2.5f, 3.0f, 2.5f) : lab::scene::Vec3(6.0f, 4.0f, 6.0f);
        float x = rng.uniform(lo.x, hi.x), y = rng.uniform(lo.y, hi.y);
        points.emplace_back(x, y, rng.uniform(lo.z, hi.z));
    }
    return points;
}

// Unit vectors, uniform on the sphere.
inline lab::scene::Vec3 random_direction(lab::validation::UniformRandom& rng) {
    float z = rng.uniform(-1.0f, 1.0f), phi = rng.uniform(0.0f, 6.28318530718f);
    float r = std::sqrt(std::fmax(0.0f, 1.0f - z * z));
    return lab::scene::Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// Every scene in scenes/ (so a new one is covered without being listed), then the test scenes.
inline std::vector<std::string> all_scene_files() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator("scenes"))
        if (entry.path().extension() == ".json") files.push_back("scenes/" + entry.path().filename().string());
    std::sort(files.begin(), files.end());
    for (const char* f : {"tests/scene_data/combinators.json", "tests/scene_data/displaced.json", "tests/scene_data/asymmetric_repeat.json"})
        files.push_back(f);
    return files;
}

}  // namespace scene_test
