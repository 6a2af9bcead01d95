// The scene a preview renders: the built-in material test model (scenes/shader_ball.json, embedded
// in the binary) or a scene file, with the material under test put into its "sample" slot and the
// ground switched on or off, compiled into the preview kernel's source.
#pragma once

#include <optional>
#include <string>

#include "brdf/host/preset.hpp"
#include "ibl/preview_renderer.hpp"
#include "scene/scene.hpp"

namespace lab::ibl {

// The slot the material under test goes into, and the object --ground switches.
constexpr const char* kSampleMaterialSlot = "sample";
constexpr const char* kGroundObject = "ground";
constexpr const char* kTestModelFile = "scenes/shader_ball.json";

// The built-in test model, or the scene file at `path` (empty: the test model).
scene::Scene load_preview_scene(const std::string& path);

struct PreviewSceneOptions {
    std::optional<brdf::Preset> sample_material;  // replaces the scene's "sample" slot
    bool ground = true;                           // false: the object named "ground" is left out
};

// Compiles the scene into kernels/preview.cl's source. Throws lab::InputError naming the scene file
// when a material is given but the scene has no "sample" slot, or it has no "ground" to leave out.
PreviewScene compile_preview_scene(const scene::Scene& scene, const PreviewSceneOptions& options);

}  // namespace lab::ibl
