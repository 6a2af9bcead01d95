// The render core's closed forms (tests/closed_form_scenes.hpp) with the path tracer, on the OpenCL
// device and on its host C++ build, with both light-selection modes.
#include <catch2/catch.hpp>

#include "opencl/runtime.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/closed_form_scenes.hpp"

using namespace closed_forms;

TEST_CASE("Closed forms: the path tracer on the OpenCL device gives the exact pixel values", "[render][closed-form][opencl]") {
    lab::opencl::Runtime runtime("");
    for (const Case& c : cases())
        for (LightSelection selection : {LightSelection::power, LightSelection::uniform}) {
            lab::render::OpenClRenderer renderer(runtime, case_input(c, selection, 24));
            check_case(c, selection, renderer, 512);
        }
}

TEST_CASE("Closed forms: the path tracer's host build gives the exact pixel values", "[render][closed-form][host]") {
    for (const Case& c : cases())
        for (LightSelection selection : {LightSelection::power, LightSelection::uniform}) {
            lab::render::HostRenderer renderer(case_input(c, selection, 12));
            check_case(c, selection, renderer, 1024);
        }
}
