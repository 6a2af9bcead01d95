// A material's own emission (openpbr emission_luminance, emission_color; brdf/emission.h) in the
// renderers, by closed forms whose paths have no variance at all, so every pixel of every sample is
// the exact value to float rounding:
//  - inside an emissive cavity: a black shell (base_weight and specular_weight 0) emitting
//    Le = emission_luminance emission_color on its inner wall, the camera looking at a Lambert ball
//    of reflectance rho in the middle: the ball's cosine-sampled bounce carries rho and reaches the
//    wall whatever its direction, so every pixel is rho Le. Only a path that hits the wall can
//    find it (no light samples it): the path tracer's BSDF-sampled hit with weight 1 under every
//    light-sampling mode, BDPT's s = 0 with weight 1 (a weight that counted another strategy
//    would darken it);
//  - outside an emissive sphere that fills the view: every pixel Le;
//  - inside that sphere's solid: nothing, since a solid's surface emits on its outer side only.
// Each on the host C++ build and on the OpenCL device. The light tracer, whose paths start on the
// lights only, refuses an emissive material by name, and a sphere light refuses an emissive
// material (its radiance is its "radiance").
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>

#include "common/input_error.hpp"
#include "opencl/runtime.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/render_inputs.hpp"

namespace {

using lab::render::Integrator;
using lab::render::LightSampling;

const char* kGlow = R"("glow": {"model": "openpbr", "base_weight": 0, "specular_weight": 0, "emission_luminance": 2, "emission_color": [0.5, 1, 0.25]})";
const char* kGrey = R"("grey": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}, "retroreflection": 0, "subsurface": 0})";

// The camera 0.9 from the centre of a ball of radius 0.5, 20 degrees either side of its axis: the
// ball (33.7 degrees) fills the view.
std::string cavity_scene() {
    return std::string(R"({"camera": {"type": "pinhole", "position": [0, 0, 0.9], "look_at": [0, 0, 0], "fov_degrees": 40},
      "materials": {)") + kGlow + ", " + kGrey + R"(},
      "objects": [{"name": "shell", "material": "glow", "shape": {"type": "subtraction", "children": [{"type": "sphere", "radius": 1.25}, {"type": "sphere", "radius": 1}]}},
                  {"name": "ball", "material": "grey", "shape": {"type": "sphere", "radius": 0.5}}]})";
}

// `position`: the camera's, looking at the centre of a glowing ball of radius 1 (from 2 away, the ball fills the view).
std::string glowing_ball_scene(const char* position) {
    return std::string(R"({"camera": {"type": "pinhole", "position": )") + position + R"(, "look_at": [0, 0, -1], "fov_degrees": 40},
      "materials": {)" + kGlow + R"(},
      "objects": [{"name": "ball", "material": "glow", "shape": {"type": "sphere", "radius": 1}}]})";
}

struct Case {
    const char* name;
    std::string scene;
    float expected[3];
};

std::vector<Case> cases() {
    return {{"a Lambert ball (0.5) inside an emissive cavity", cavity_scene(), {0.5f, 1.0f, 0.25f}},
            {"outside an emissive ball", glowing_ball_scene("[0, 0, 2]"), {1.0f, 2.0f, 0.5f}},
            {"inside an emissive ball's solid", glowing_ball_scene("[0, 0, 0]"), {0.0f, 0.0f, 0.0f}}};
}

lab::render::RenderInput case_input(const Case& c, Integrator integrator, LightSampling sampling) {
    lab::render::RenderInput input = render_input(std::nullopt, "", 8, sampling, 5, c.scene);
    input.settings.integrator = integrator;
    input.settings.max_depth = 4;
    return input;
}

// Every pixel, every channel, the closed form to float rounding.
void check_exact(const Case& c, lab::render::Renderer& renderer) {
    RenderResult r = render_samples(renderer, 8);
    size_t off = 0;
    float worst = 0.0f;
    for (size_t p = 0; p < r.image.pixel_count(); ++p)
        for (int k = 0; k < 3; ++k) {
            const float v = r.image.rgb[3 * p + size_t(k)], e = c.expected[k];
            const float error = std::fabs(v - e);
            worst = std::fmax(worst, error);
            if (!(error <= 1e-5f * std::fmax(e, 1e-3f))) ++off;
        }
    INFO(c.name << " on " << renderer.device_description() << ": " << off << " pixel channels off, largest error " << worst);
    CHECK(r.stats.nonfinite_samples == 0);
    CHECK(off == 0);
}

}  // namespace

TEST_CASE("Emissive materials: closed forms of the path tracer (every light sampling) and BDPT on the host", "[render][emission][closed-form][host]") {
    for (const Case& c : cases()) {
        for (LightSampling sampling : {LightSampling::mis, LightSampling::bsdf, LightSampling::lights}) {
            lab::render::HostRenderer pt(case_input(c, Integrator::pt, sampling));
            check_exact(c, pt);
        }
        lab::render::HostRenderer bdpt(case_input(c, Integrator::bdpt, LightSampling::mis));
        check_exact(c, bdpt);
    }
}

TEST_CASE("Emissive materials: closed forms of the path tracer and BDPT on the OpenCL device", "[render][emission][closed-form][opencl]") {
    lab::opencl::Runtime runtime("");
    for (const Case& c : cases())
        for (Integrator integrator : {Integrator::pt, Integrator::bdpt}) {
            lab::render::OpenClRenderer renderer(runtime, case_input(c, integrator, LightSampling::mis));
            check_exact(c, renderer);
        }
}

TEST_CASE("Emissive materials: the light tracer refuses them by name, and a sphere light takes none", "[render][emission]") {
    const Case c = cases()[0];
    CHECK_THROWS_WITH(lab::render::HostRenderer(case_input(c, Integrator::lt, LightSampling::mis)),
                      "test-scene.json: materials.glow: emission_luminance: the light tracer cannot see a material's emission (no light "
                      "subpath starts on it): use --integrator bdpt or pt");
    const std::string sphere_light = std::string(R"({"camera": {"type": "pinhole", "position": [0, 0, 3], "look_at": [0, 0, 0], "fov_degrees": 40},
      "materials": {)") + kGlow + R"(}, "emitters": [{"center": [0, 0, 0], "radius": 1, "radiance": [1, 1, 1], "material": "glow"}]})";
    CHECK_THROWS_WITH(lab::scene::parse_scene(sphere_light, "s.json"),
                      "s.json: emitters[0].material: material \"glow\" emits (emission_luminance): an emitter's radiance is its \"radiance\"");
}
