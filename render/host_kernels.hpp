// The integrators' single-source kernel code compiled as C++ for the host, once for every host
// user (the host renderer, the viewer's pixel probe, the tests of the kernels' parts): namespace
// lab::render::host_kernels. The kernels call the scene's distance field as free functions (in a
// kernel the generated scene/generated.h defines them); here they are scene/field_for_kernel_headers.hpp's,
// which evaluate the scene a HostSceneScope set for the thread through the host interpreter.
#pragma once

#include "kernels/host.hpp"
#include "scene/field_for_kernel_headers.hpp"

namespace lab::render {

namespace host_kernels {

using namespace ::kernel;
using namespace scene::field_for_kernel_headers;

#include "sdf/march.h"
#include "sdf/normals.h"
#include "kernels/path_tracer.h"
#include "kernels/bdpt_cache.h"
#include "kernels/first_hit.h"

}  // namespace host_kernels

// While it lives, the host kernels evaluate `scene` on this thread (then the scene they evaluated before).
class HostSceneScope {
public:
    explicit HostSceneScope(const scene::Scene& scene) : previous_(scene::field_for_kernel_headers::current_scene) {
        scene::field_for_kernel_headers::current_scene = &scene;
    }
    ~HostSceneScope() { scene::field_for_kernel_headers::current_scene = previous_; }
    HostSceneScope(const HostSceneScope&) = delete;
    HostSceneScope& operator=(const HostSceneScope&) = delete;

private:
    const scene::Scene* previous_;
};

}  // namespace lab::render
