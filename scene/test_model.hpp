// The material test model (scenes/shader_ball.json, embedded in the binary so `dtoadq preview`
// works from any folder): the slot the material under test goes into and the object the preview's
// --ground switches.
#pragma once

#include "scene/scene.hpp"

namespace lab::scene {

constexpr const char* kSampleMaterialSlot = "sample";
constexpr const char* kGroundObject = "ground";
constexpr const char* kTestModelFile = "scenes/shader_ball.json";

Scene load_test_model();

}  // namespace lab::scene
