// Render inputs for the tests: the test model (or a scene given as JSON text) with a material in its
// "sample" slot, under an environment, and a render of a fixed number of samples on any renderer.
#pragma once

#include <optional>
#include <string>

#include "brdf/brdf.hpp"
#include "film/image.hpp"
#include "ibl/environment.hpp"
#include "render/renderer.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "scene/test_model.hpp"

// `scene_json` empty: the test model. `ground` false leaves the test model's ground out.
inline lab::render::RenderInput render_input(const std::optional<brdf::Material>& sample, const std::string& env, int size,
                                             lab::render::LightSampling sampling, uint64_t seed, const std::string& scene_json = "",
                                             bool ground = true) {
    lab::scene::CompileOptions options;
    if (sample) options.material_overrides[lab::scene::kSampleMaterialSlot] = *sample;
    if (!ground) options.disabled_objects.push_back(lab::scene::kGroundObject);
    lab::scene::Scene scene = scene_json.empty() ? lab::scene::load_test_model() : lab::scene::parse_scene(scene_json, "test-scene.json");
    lab::render::RenderInput input;
    input.scene = lab::scene::apply_options(scene, options);
    if (!env.empty()) input.environment = lab::ibl::load_environment(env);
    input.settings.width = input.settings.height = size;
    input.settings.light_sampling = sampling;
    input.settings.seed = seed;
    return input;
}

// A white Lambert sphere of radius 1 in the middle of the view, no light of its own: what the
// non-finite checks of the path tracer and BDPT render under a sky that overflows.
inline const char* const kWhiteSphereScene = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 3.2], "look_at": [0, 0, 0], "fov_degrees": 40},
  "materials": {"sample": {"albedo": [1, 1, 1], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "ball", "material": "sample", "shape": {"type": "sphere", "radius": 1}}]
})";

struct RenderResult {
    lab::film::ImageRgb image;
    lab::render::RenderStatistics stats;
};

// `spp` samples per pixel in one launch.
inline RenderResult render_samples(lab::render::Renderer& renderer, int spp) {
    renderer.set_samples_per_launch(spp);
    renderer.add_samples(spp);
    return {renderer.image(), renderer.statistics()};
}
