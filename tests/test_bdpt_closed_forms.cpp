// The render core's closed forms (tests/closed_form_scenes.hpp) with BDPT (every strategy) and the
// light tracer (t = 1 alone): BDPT on the host C++ build of kernels/bdpt.h, the light tracer on the
// OpenCL build of the same source. Paths of up to 16 vertices: the Lambert walls' 0.5^14 of the
// light is below what the test can see. The same standard-error requirement as the path tracer's:
// a 1 % error must be at least 4 standard errors.
#include <catch2/catch.hpp>

#include "opencl/runtime.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/closed_form_scenes.hpp"

using namespace closed_forms;

namespace {

lab::render::RenderInput bdpt_input(const Case& c, lab::render::Integrator integrator, int size) {
    lab::render::RenderInput input = case_input(c, LightSelection::power, size);
    input.settings.integrator = integrator;
    input.settings.max_vertices = 16;
    return input;
}

}  // namespace

TEST_CASE("Closed forms: BDPT on the host gives the exact pixel values", "[render][closed-form][bdpt][host]") {
    std::vector<Case> all = cases();
    for (const Case& c : {all[0], all[1]}) {
        lab::render::HostRenderer renderer(bdpt_input(c, lab::render::Integrator::bdpt, 12));
        check_case(c, LightSelection::power, renderer, 512);
    }
}

// The light tracer's estimate is far noisier per path (every path splats wherever it lands): it
// needs 16 times BDPT's paths for the same standard error, which the compiled kernel gives faster.
TEST_CASE("Closed forms: the light tracer on the OpenCL device gives the exact pixel values", "[render][closed-form][bdpt][opencl]") {
    lab::opencl::Runtime runtime("");
    std::vector<Case> all = cases();
    for (const Case& c : {all[0], all[1]}) {
        lab::render::OpenClRenderer renderer(runtime, bdpt_input(c, lab::render::Integrator::lt, 12));
        check_case(c, LightSelection::power, renderer, 9216);
    }
}
