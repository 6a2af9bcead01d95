// What a path costs in march work, from the measurement build of the kernel: rays per path, march
// steps per ray and distance functions evaluated per step (scene/generated_source.cpp's
// SCENE_COUNT_EVALUATIONS). The counting build traces the very paths of the default build, so the
// three come from two renders of the same samples. Used by `bench render` and `bench breakdown`.
#pragma once

#include "opencl/runtime.hpp"
#include "render/renderer.hpp"

namespace lab::bench {

struct MarchCost {
    double rays_per_path = 0.0;
    double steps_per_ray = 0.0;         // distance-field evaluations of the marches (normals not included)
    double evaluations_per_step = 0.0;  // objects' and emitters' distance functions per march step
    bool same_film = false;             // the counting build's film has the default build's bits
};

// Renders `samples` samples per pixel of `input` twice (default and counting builds).
MarchCost measure_march_cost(const opencl::Runtime& runtime, render::RenderInput input, int samples);

}  // namespace lab::bench
