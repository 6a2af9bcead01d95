// The integrators are single source (the path tracer; BDPT and the light tracer, one kernel): the OpenCL build on the device and the C++ build on the host
// trace the same paths from the same random numbers. Float rounding differs between the two
// compilers only in the last bits (the scene's field and the BRDF agree to 1e-5 or better, tested
// elsewhere), so most paths take the very same branches and give the same radiance to float
// precision; where rounding flips a branch (a grazing hit, a roulette draw on the edge) the path
// differs from there on, but both remain unbiased. The test requires both: nearly every pixel the
// same to 1e-3, and the image means equal within their noise; and nearly every pixel's variance
// (the film's sum of squares, pt and BDPT) the same to 1e-3.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "opencl/runtime.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "render/integrator.hpp"
#include "tests/render_inputs.hpp"

namespace {

// Every kind of light (the environment, a sphere light, a point light) and of lobe the path
// tracer meets: diffuse, glossy, mirror and glass.
const char* kScene = R"({
  "camera": {"type": "pinhole", "position": [0, 1.2, 4], "look_at": [0, 0.4, 0], "fov_degrees": 45},
  "materials": {
    "floor": {"albedo": [0.6, 0.6, 0.6], "lobes": {"diffuse": 1}},
    "plastic": {"albedo": [0.7, 0.2, 0.1], "roughness": 0.3, "lobes": {"diffuse": 0.7, "glossy": 0.3}},
    "mirror": {"albedo": [0.9, 0.9, 0.9], "metallic": 1, "lobes": {"specular": 1}},
    "glass": {"albedo": [1, 1, 1], "ior": 1.5, "roughness": 0, "lobes": {"transmission": 1}}
  },
  "objects": [
    {"name": "floor", "material": "floor", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}},
    {"name": "ball", "material": "plastic", "shape": {"type": "translate", "offset": [-0.9, 0.5, 0], "child": {"type": "sphere", "radius": 0.5}}},
    {"name": "mirror", "material": "mirror", "shape": {"type": "translate", "offset": [0.3, 0.4, -0.6], "child": {"type": "box", "half_size": [0.4, 0.4, 0.05]}}},
    {"name": "glass", "material": "glass", "shape": {"type": "translate", "offset": [0.9, 0.35, 0.4], "child": {"type": "sphere", "radius": 0.35}}}
  ],
  "emitters": [
    {"center": [0.5, 2.2, 0.5], "radius": 0.25, "radiance": [8, 7, 6]},
    {"type": "point", "position": [-1.5, 1.8, 1.5], "intensity": [2, 2, 3]}
  ]
})";

// The same with the plastic ball an emissive openpbr material under a rough coat and fuzz, which
// the path tracer and BDPT's s = 0 find where their paths hit it (brdf/emission.h).
const std::string kGlowScene = [] {
    std::string scene = kScene;
    const std::string plastic = R"("plastic": {"albedo": [0.7, 0.2, 0.1], "roughness": 0.3, "lobes": {"diffuse": 0.7, "glossy": 0.3}})";
    scene.replace(scene.find(plastic), plastic.size(),
                  R"("plastic": {"model": "openpbr", "base_color": [0.7, 0.2, 0.1], "coat_weight": 1, "coat_roughness": 0.3, "fuzz_weight": 0.5, "emission_luminance": 3, "emission_color": [1, 0.7, 0.4]})");
    return scene;
}();

double channel_mean(const lab::film::ImageRgb& image) {
    double sum = 0.0;
    for (float v : image.rgb) sum += v;
    return sum / double(image.rgb.size());
}

}  // namespace

TEST_CASE("The integrators' host builds and their OpenCL builds trace the same paths", "[render][host-device][opencl]") {
    lab::opencl::Runtime runtime("");
    // BDPT and the light tracer splat: their splat sums round in the order splats land, far below 1e-3
    for (const std::string& scene : {std::string(kScene), kGlowScene})
    for (lab::render::Integrator integrator : {lab::render::Integrator::pt, lab::render::Integrator::bdpt, lab::render::Integrator::lt}) {
        if (scene == kGlowScene && integrator == lab::render::Integrator::lt) continue;  // the light tracer refuses an emissive material
        lab::render::RenderInput input = render_input(std::nullopt, "constant:0.3,0.4,0.5", 24, lab::render::LightSampling::mis, 3, scene);
        input.settings.max_depth = 6;
        input.settings.integrator = integrator;
        if (integrator == lab::render::Integrator::lt) input.environment.reset();  // the light tracer refuses an environment
        INFO(lab::render::integrator_name(integrator) << (scene == kGlowScene ? ", an emissive material" : ""));
        const int spp = 4;
        lab::render::OpenClRenderer device(runtime, input);
        lab::render::HostRenderer host(input);
        // BDPT and the light tracer square their films per pass (render::add_pass_squares): passes
        // of one sample give their variance spp - 1 degrees of freedom
        const int per_launch = lab::render::integrator_descriptor(integrator).splats() ? 1 : spp;
        auto render = [&](lab::render::Renderer& renderer) {
            renderer.set_samples_per_launch(per_launch);
            renderer.add_samples(spp);
            return RenderResult{renderer.image(), renderer.statistics()};
        };
        RenderResult d = render(device), h = render(host);
        REQUIRE(d.image.rgb.size() == h.image.rgb.size());

        size_t pixels = d.image.pixel_count(), same = 0, bit_identical = 0;
        double diff_sum = 0.0, diff_sum2 = 0.0;
        for (size_t p = 0; p < pixels; ++p) {
            bool equal = true;
            for (size_t c = 0; c < 3; ++c) {
                double a = d.image.rgb[3 * p + c], b = h.image.rgb[3 * p + c];
                equal = equal && std::fabs(a - b) <= 1e-3 * std::fmax(1.0, std::fabs(a));
                diff_sum += a - b;
                diff_sum2 += (a - b) * (a - b);
            }
            same += equal ? 1 : 0;
            bit_identical += std::equal(d.image.pixel(0, 0) + 3 * p, d.image.pixel(0, 0) + 3 * p + 3, h.image.pixel(0, 0) + 3 * p) ? 1 : 0;
        }
        double n = double(3 * pixels);
        double mean_diff = diff_sum / n;
        // The standard error of the mean difference, from the differences' own spread.
        double se = std::sqrt(std::max(0.0, diff_sum2 / n - mean_diff * mean_diff) / (n - 1.0));
        INFO("pixels the same to 1e-3: " << same << " of " << pixels << " (bit-identical: " << bit_identical << "); means device " << channel_mean(d.image) << ", host "
                                         << channel_mean(h.image) << ", difference " << mean_diff << " +- " << se);
        CHECK(d.stats.nonfinite_samples == 0);
        CHECK(h.stats.nonfinite_samples == 0);
        CHECK(double(same) >= 0.95 * double(pixels));
        CHECK(std::fabs(mean_diff) <= 4.0 * se + 1e-6);
        // the same number of rays within what the flipped paths account for
        CHECK(std::fabs(double(d.stats.rays) - double(h.stats.rays)) <= 0.05 * double(d.stats.rays));
        // the same paths' squares: the variance of the mean alike where the image is
        {
            const lab::film::ImageRgb dv = device.variance(), hv = host.variance();
            size_t same_variance = 0;
            for (size_t p = 0; p < pixels; ++p) {
                bool equal = true;
                for (size_t c = 0; c < 3; ++c)
                    equal = equal && std::fabs(dv.rgb[3 * p + c] - hv.rgb[3 * p + c]) <= 1e-3 * std::fmax(1e-3, std::fabs(dv.rgb[3 * p + c]));
                same_variance += equal ? 1 : 0;
            }
            INFO("pixels whose variance is the same to 1e-3: " << same_variance << " of " << pixels);
            CHECK(double(same_variance) >= 0.95 * double(pixels));
        }
    }
}

// A scene's kernel samples only its own kinds of light (kernels/lights/light_selection.h); the test
// above renders all three kinds, so a kernel built without a kind that its scene has fails it.
TEST_CASE("A scene's OpenCL kernel is built for its own kinds of light", "[render][host-device][opencl]") {
    lab::opencl::Runtime runtime("");
    auto built_for = [&](const std::string& env, const std::string& scene) {
        lab::render::RenderInput input = render_input(std::nullopt, env, 8, lab::render::LightSampling::mis, 1, scene);
        return lab::render::OpenClRenderer(runtime, input).build_options();
    };
    const char* kEnvironmentOnly = R"({
      "camera": {"type": "pinhole", "position": [0, 0, 4], "look_at": [0, 0, 0]},
      "materials": {"white": {"albedo": [0.8, 0.8, 0.8], "lobes": {"diffuse": 1}}},
      "objects": [{"name": "ball", "material": "white", "shape": {"type": "sphere", "radius": 1}}]
    })";
    const std::string all = " -DSCENE_LIGHT_TYPES=" + std::to_string((1 << LIGHT_ENVIRONMENT) | (1 << LIGHT_SPHERE) | (1 << LIGHT_POINT));
    CHECK_THAT(built_for("constant:0.3,0.4,0.5", kScene), Catch::Contains(all));
    CHECK_THAT(built_for("", kScene), Catch::Contains(" -DSCENE_LIGHT_TYPES=" + std::to_string((1 << LIGHT_SPHERE) | (1 << LIGHT_POINT))));
    CHECK_THAT(built_for("constant:0.3,0.4,0.5", kEnvironmentOnly), Catch::Contains(" -DSCENE_LIGHT_TYPES=" + std::to_string(1 << LIGHT_ENVIRONMENT)));
}
