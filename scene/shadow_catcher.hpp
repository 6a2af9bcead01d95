// `--shadow-catcher`: a ground that catches the model's shadows on the backdrop (docs/environments.md,
// "Shadow catcher"), added under the scene's objects as the look-dev references are added in view.
#pragma once

#include "scene/scene.hpp"

namespace lab::scene {

// The catcher's object and material slot.
constexpr const char* kShadowCatcherObject = "shadow_catcher";
// Its material: white Lambert. Differential rendering's local scene is the ground the plate shows;
// with albedo 1 the unshadowed ground under a uniform sky of radiance L sends L, the plate's own
// radiance, so a shadow is the plate times the share of the sky left.
constexpr float kShadowCatcherAlbedo = 1.0f;

// The scene with a shadow catcher: the scene's object named "ground" (the test model's,
// scene/test_model.hpp) becomes a plane of the same shape flagged as the catcher, or, without one,
// an endless plane y = Y is added, Y the lowest point of the bounded objects' boxes
// (scene/lipschitz.hpp; 0 when none is bounded in y). Its slot comes after all of the scene's (whose
// indices do not change), its object after the scene's.
Scene with_shadow_catcher(const Scene& scene);

}  // namespace lab::scene
