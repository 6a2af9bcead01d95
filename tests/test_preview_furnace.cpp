// White-furnace tests of the preview (kernels/preview.cl on PoCL): the test model without its
// ground under a constant environment of radiance 1. A white Lambert surface then reflects exactly
// what it receives, however many bounces a path takes, so every pixel must be 1. Conductors of
// albedo 1 lose what their microfacet model loses (single scattering); on a convex sphere, where no
// reflected ray returns, every pixel lies between the material's smallest directional albedo and 1. A dark pixel would be a path that
// leaked, self-shadowed or got stuck; a bright one a pdf or weight that does not match its sampler.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "brdf/host/parameters.hpp"
#include "film/image_stats.hpp"
#include "ibl/environment.hpp"
#include "ibl/preview_renderer.hpp"
#include "ibl/preview_scene.hpp"
#include "opencl/runtime.hpp"
#include "scene/load_scene.hpp"
#include "tests/lobe_material.hpp"
#include "validation/albedo.hpp"

namespace {

using lab::film::ImageRgb;
using lab::ibl::IblSampling;

brdf::Preset preset_of(const brdf::Material& m, const std::string& name) {
    brdf::Preset p;
    p.name = name;
    p.material = m;
    return p;
}

brdf::Material white_lambert() {
    brdf::Material m = lobe_material(1, 0, 0, 0);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    return m;
}

// A conductor whose Fresnel is 1 at every angle: all the energy it loses is the microfacet model's.
brdf::Material white_conductor(int distribution, float roughness) {
    brdf::Material m = lobe_material(0, 1, 0, 0);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    m.metallic = 1.0f;
    m.roughness = roughness;
    m.distribution = distribution;
    m.hc_shape = 3.0f;
    return m;
}

struct Render {
    ImageRgb image;
    lab::ibl::PreviewStatistics stats;
};

// A lone sphere filling most of the image: convex, so every reflected ray escapes and a pixel
// shows exactly the single-scattering albedo at its view angle.
const char* kSphereScene = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 3.2], "look_at": [0, 0, 0], "fov_degrees": 40},
  "materials": {"sample": {"albedo": [1, 1, 1], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "ball", "material": "sample", "shape": {"type": "sphere", "radius": 1}}]
})";

Render furnace(const lab::opencl::Runtime& runtime, const brdf::Material& material, IblSampling sampling, int spp, uint64_t seed = 1,
               bool convex = false) {
    lab::ibl::PreviewSceneOptions options;
    options.sample_material = preset_of(material, "furnace");
    options.ground = convex;  // the sphere scene has no ground to switch off
    lab::scene::Scene model = convex ? lab::scene::parse_scene(kSphereScene, "furnace-sphere.json") : lab::ibl::load_preview_scene("");
    lab::ibl::PreviewScene scene = lab::ibl::compile_preview_scene(model, options);
    lab::ibl::Environment env = lab::ibl::load_environment("constant:1,1,1");
    lab::ibl::PreviewSettings settings;
    settings.width = settings.height = 48;
    // A white furnace never ends a path by roulette, only by depth; between the core and the shell a
    // path of albedo 1 can bounce hundreds of times before it finds the window.
    settings.max_depth = 512;
    settings.sampling = sampling;
    settings.seed = seed;
    lab::ibl::PreviewRenderer renderer(runtime, scene, env, settings);
    renderer.set_samples_per_launch(spp);
    renderer.add_samples(spp);
    return {renderer.image(), renderer.statistics()};
}

struct Range {
    float lo = INFINITY, hi = -INFINITY;
};

Range pixel_range(const ImageRgb& image) {
    Range r;
    for (float v : image.rgb) {
        r.lo = std::min(r.lo, v);
        r.hi = std::max(r.hi, v);
    }
    return r;
}

// Typical per-pixel noise of one render: two renders with different seeds differ by sqrt(2) sigma.
double pixel_noise(const ImageRgb& a, const ImageRgb& b) { return lab::film::image_error(a, b).rmse_mean / std::sqrt(2.0); }

}  // namespace

TEST_CASE("Furnace: a white Lambert test model is 1 in every pixel (BSDF sampling, no noise)", "[furnace][preview][opencl]") {
    lab::opencl::Runtime runtime("");
    Render r = furnace(runtime, white_lambert(), IblSampling::brdf, 4);
    Range range = pixel_range(r.image);
    INFO("pixels in [" << range.lo << ", " << range.hi << "], lost rays " << r.stats.lost_rays << " of " << r.stats.rays);
    CHECK(r.stats.nonfinite_samples == 0);
    CHECK(range.lo > 0.99f);
    CHECK(range.hi < 1.01f);
}

TEST_CASE("Furnace: environment sampling and MIS also give 1, within their noise", "[furnace][preview][opencl]") {
    lab::opencl::Runtime runtime("");
    for (IblSampling sampling : {IblSampling::env, IblSampling::mis}) {
        Render a = furnace(runtime, white_lambert(), sampling, 64, 1), b = furnace(runtime, white_lambert(), sampling, 64, 2);
        double noise = pixel_noise(a.image, b.image);
        lab::film::ImageStats stats = lab::film::image_stats(a.image);
        Range range = pixel_range(a.image);
        INFO(lab::ibl::ibl_sampling_name(sampling) << ": mean " << stats.mean[0] << ", pixels in [" << range.lo << ", " << range.hi
                                                  << "], pixel noise " << noise);
        CHECK(a.stats.nonfinite_samples == 0);
        // the mean of 48 x 48 pixels: its standard error is noise / 48
        CHECK(std::fabs(stats.mean[0] - 1.0) < 0.002 + 4.0 * noise / 48.0);
        // 8 sigma: the estimators' distributions are skewed (an unoccluded light sample is worth 4 cos)
        CHECK(range.lo > 1.0f - 0.01f - 8.0f * float(noise));
        CHECK(range.hi < 1.0f + 0.01f + 8.0f * float(noise));
        if (sampling == IblSampling::mis) CHECK(noise < 0.03);  // MIS of a constant sky must not be noisy
    }
}

TEST_CASE("Furnace: white GGX and Hyper-Cauchy conductor spheres lose only their single-scattering energy", "[furnace][preview][opencl]") {
    lab::opencl::Runtime runtime("");
    struct Case {
        const char* name;
        brdf::Material material;
    };
    for (const Case& c : {Case{"GGX roughness 0.6", white_conductor(BRDF_DISTRIBUTION_GGX, 0.6f)},
                          Case{"Hyper-Cauchy roughness 0.6 shape 3", white_conductor(BRDF_DISTRIBUTION_HYPER_CAUCHY, 0.6f)}}) {
        // The smallest directional albedo over the view angles the model shows (to 88 degrees).
        double smallest = 1.0;
        for (float theta = 0.0f; theta <= 88.0f; theta += 4.0f) {
            float t = theta * float(M_PI / 180.0);
            brdf::float3 wo(std::sin(t), 0.0f, std::cos(t));
            smallest = std::min(smallest, double(lab::validation::directional_albedo(c.material, wo, 64).value.x));
        }
        Render a = furnace(runtime, c.material, IblSampling::mis, 32, 1, true), b = furnace(runtime, c.material, IblSampling::mis, 32, 2, true);
        double noise = pixel_noise(a.image, b.image);
        Range range = pixel_range(a.image);
        INFO(c.name << ": smallest albedo " << smallest << ", pixels in [" << range.lo << ", " << range.hi << "], pixel noise " << noise);
        CHECK(a.stats.nonfinite_samples == 0);
        CHECK(smallest < 0.999);  // the loss is real: otherwise this test would not test it
        CHECK(range.lo > smallest - 0.01 - 5.0 * noise);
        CHECK(range.hi < 1.0 + 0.01 + 5.0 * noise);
    }
}
