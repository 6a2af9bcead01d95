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
    input.settings.max_depth = 14;
    return input;
}

}  // namespace

TEST_CASE("Closed forms: BDPT on the host gives the exact pixel values", "[render][closed-form][bdpt][host]") {
    for (const Case& c : cases()) {
        lab::render::HostRenderer renderer(bdpt_input(c, lab::render::Integrator::bdpt, 12));
        check_case(c, LightSelection::power, renderer, 512);
    }
}

// The same with the light-vertex cache (bdpt-cache, its default counts: 36 light subpaths per sample
// here), and with bdpt's connection roulette at W = 0.2 (connections of weight below 0.2 trace their
// ray with probability w / 0.2 and count 1 / that): both are unbiased, so the exact values hold. The
// roulette's variance takes 768 samples to meet the standard-error requirement on the black sphere's
// scene (512 leave it within 1 % of the bound, on one side or the other with the random streams).
TEST_CASE("Closed forms: bdpt-cache, and BDPT with connection roulette, on the host give the exact pixel values",
          "[render][closed-form][bdpt][host]") {
    for (const Case& c : cases()) {
        lab::render::HostRenderer cache(bdpt_input(c, lab::render::Integrator::bdpt_cache, 12));
        INFO("bdpt-cache");
        check_case(c, LightSelection::power, cache, 512);
    }
    for (const Case& c : cases()) {
        lab::render::RenderInput input = bdpt_input(c, lab::render::Integrator::bdpt, 12);
        input.settings.bdpt.connection_roulette = 0.2f;
        lab::render::HostRenderer roulette(input);
        INFO("bdpt, connection roulette 0.2");
        check_case(c, LightSelection::power, roulette, 768);
    }
}

// The light tracer's estimate is far noisier per path (every path splats wherever it lands): it
// needs 16 times BDPT's paths for the same standard error, which the compiled kernel gives faster.
// The first two cases: under an environment it has no strategy for a camera ray that escapes, and
// in the black sphere's scene, whose camera sees a small part of the wall, its standard error at
// this budget is 0.9 % (it would need 13 times the paths).
TEST_CASE("Closed forms: the light tracer on the OpenCL device gives the exact pixel values", "[render][closed-form][bdpt][opencl]") {
    lab::opencl::Runtime runtime("");
    std::vector<Case> all = cases();
    for (const Case& c : {all[0], all[1]}) {
        lab::render::OpenClRenderer renderer(runtime, bdpt_input(c, lab::render::Integrator::lt, 12));
        check_case(c, LightSelection::power, renderer, 9216);
    }
}

// Each strategy alone, unweighted: inside an emitting Lambert sphere (Le = 0.25, rho = 0.5, the
// camera at its centre; no point light), the paths of s + t = k vertices carry Le rho^(k-2) to every
// pixel, and each of the k strategies (0, k), (1, k - 1), ..., (k - 1, 1) samples all of them. So
// every unweighted strategy image of a length converges to the same value; checked for k = 3, 4
// against the closed form within 2 %, each with its own standard error at most 0.5 %. The strategies
// that end their camera subpath on the emitter (s = 0) or connect it to a point sampled on it (s = 1)
// carry next to no variance here (uniform emission seen from the centre: a standard error of 0.005 %
// at 1024 samples), so 64 samples meet the bound a hundred times over; the others need 1024, and
// light tracing's splats (t = 1) 4096.
TEST_CASE("BDPT: each strategy alone converges to the same image", "[render][bdpt][strategies]") {
    std::string scene = std::string(R"({"camera": {"type": "pinhole", "position": [0, 0, 0], "look_at": [0, 0, -1], "fov_degrees": 60},
      "materials": {)") + kWall + R"(},
      "emitters": [{"center": [0, 0, 0], "radius": 1, "radiance": [0.25, 0.25, 0.25], "material": "wall"}]})";
    for (int k : {3, 4}) {
        Case c{"emitting Lambert sphere, paths of " + std::to_string(k) + " vertices", scene, 0.25 * std::pow(0.5, k - 2), ""};
        for (int s = 0; s < k; ++s) {
            bool splats = k - s == 1;  // light tracing's paths spread over the film: 16 times the paths for its error
            lab::render::RenderInput input = bdpt_input(c, lab::render::Integrator::bdpt, splats ? 16 : 8);
            input.settings.max_depth = k - 2;
            input.settings.strategy_debug.strategy_s = s;
            input.settings.strategy_debug.strategy_t = k - s;
            input.settings.strategy_debug.strategy_unweighted = true;
            input.settings.roulette_depth = 64;  // no Russian roulette: its noise is not the strategy's
            lab::render::HostRenderer renderer(input);
            // the splats' error is close to its bound at the full budget: the sanitized build keeps it
            const int divisor = splats ? 1 : kPathDivisor;
            RenderResult r = render_samples(renderer, (splats ? 4096 : s <= 1 ? 64 : 1024) / divisor);
            Mean m = image_mean(r.image);
            INFO(c.name << ", strategy (" << s << ", " << k - s << "): mean " << m.value << " +- " << m.standard_error << ", exact "
                        << c.expected);
            REQUIRE(m.standard_error < bound(0.005, divisor) * c.expected);
            CHECK(std::fabs(m.value - c.expected) < bound(0.02, divisor) * c.expected);
        }
    }
}
