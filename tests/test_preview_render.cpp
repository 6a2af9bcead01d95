// The preview under a real environment: the three environment-sampling strategies estimate the
// same image (their means agree within noise), renders are a pure function of the seed, and every
// bundled preset renders without a NaN or an infinity.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "brdf/host/preset.hpp"
#include "film/image_stats.hpp"
#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/bundled_presets_of_run.hpp"
#include "tests/render_inputs.hpp"

namespace fs = std::filesystem;
using IblSampling = lab::render::LightSampling;

namespace {

lab::film::ImageRgb render(const lab::opencl::Runtime& runtime, const std::optional<brdf::Material>& sample, const std::string& env,
                           IblSampling sampling, int size, int spp, uint64_t seed, lab::render::RenderStatistics* stats = nullptr) {
    lab::render::RenderInput input = render_input(sample, env, size, sampling, seed);
    input.settings.max_depth = 8;
    lab::render::OpenClRenderer renderer(runtime, input);
    RenderResult r = render_samples(renderer, spp);
    if (stats) *stats = r.stats;
    return r.image;
}

// The pixels that see the scene rather than the environment directly: there the strategies differ,
// while a pixel whose camera rays all escape is the same in every strategy for the same seed.
std::vector<bool> scene_pixels(const std::vector<lab::film::ImageRgb>& same_seed_renders) {
    const lab::film::ImageRgb& first = same_seed_renders.front();
    std::vector<bool> mask(first.rgb.size() / 3, false);
    for (size_t p = 0; p < mask.size(); ++p)
        for (const lab::film::ImageRgb& other : same_seed_renders)
            for (int c = 0; c < 3; ++c) mask[p] = mask[p] || other.rgb[p * 3 + c] != first.rgb[p * 3 + c];
    return mask;
}

double masked_mean(const lab::film::ImageRgb& image, const std::vector<bool>& mask) {
    double sum = 0.0;
    long n = 0;
    for (size_t p = 0; p < mask.size(); ++p)
        if (mask[p]) {
            sum += (double(image.rgb[p * 3]) + image.rgb[p * 3 + 1] + image.rgb[p * 3 + 2]) / 3.0;
            ++n;
        }
    return n ? sum / double(n) : 0.0;
}

}  // namespace

TEST_CASE("BRDF, environment and MIS sampling converge to the same image mean", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    brdf::Material scene = brdf::load_preset("presets/glossy_plastic.json").material;
    std::string env = "envmaps/courtyard.exr";
    // Each strategy's mean over 4 seeds, over the pixels that see the scene (the backdrop is the same
    // in every strategy by construction and would only dilute a difference); the spread of those
    // means gives its standard error.
    const IblSampling strategies[3] = {IblSampling::bsdf, IblSampling::lights, IblSampling::mis};
    std::vector<std::vector<lab::film::ImageRgb>> images(3);
    for (int k = 0; k < 3; ++k)
        for (uint64_t seed = 1; seed <= 4; ++seed) images[size_t(k)].push_back(render(runtime, scene, env, strategies[k], 32, 16, seed));
    const std::vector<bool> mask = scene_pixels({images[0][0], images[1][0], images[2][0]});
    const long seen = std::count(mask.begin(), mask.end(), true);
    INFO(seen << " of " << mask.size() << " pixels see the scene");
    REQUIRE(seen > long(mask.size()) / 4);
    std::vector<double> means, errors;
    for (int k = 0; k < 3; ++k) {
        std::vector<double> m;
        for (const lab::film::ImageRgb& image : images[size_t(k)]) m.push_back(masked_mean(image, mask));
        double mean = (m[0] + m[1] + m[2] + m[3]) / 4.0, var = 0.0;
        for (double v : m) var += (v - mean) * (v - mean) / 3.0;
        means.push_back(mean);
        errors.push_back(std::sqrt(var / 4.0));
    }
    INFO("means brdf " << means[0] << " +- " << errors[0] << ", env " << means[1] << " +- " << errors[1] << ", mis " << means[2] << " +- "
                       << errors[2]);
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b) {
            double sigma = std::sqrt(errors[size_t(a)] * errors[size_t(a)] + errors[size_t(b)] * errors[size_t(b)]);
            // 4 sigma, and at least 0.2 % (the mean of 4 seeds' spreads is itself uncertain)
            CHECK(std::fabs(means[size_t(a)] - means[size_t(b)]) < std::fmax(4.0 * sigma, 0.002 * means[2]));
        }
    CHECK(errors[2] <= errors[0] * 1.5);  // MIS is never much worse than BSDF sampling alone
}

TEST_CASE("A render is a pure function of its seed", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    std::optional<brdf::Material> scene;  // the test model's own material
    std::string env = "constant:0.5,0.7,1";
    lab::film::ImageRgb a = render(runtime, scene, env, IblSampling::mis, 16, 4, 7);
    lab::film::ImageRgb b = render(runtime, scene, env, IblSampling::mis, 16, 4, 7);
    lab::film::ImageRgb c = render(runtime, scene, env, IblSampling::mis, 16, 4, 8);
    CHECK(a.rgb == b.rgb);
    CHECK(a.rgb != c.rgb);
}

// The presets of the run (tests/bundled_presets_of_run.hpp): each preset that alone needs a feature,
// and half of the others, drawn per run; a kernel build each.
TEST_CASE("Every bundled preset renders without NaN or infinity", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    std::string env = "envmaps/sunset.exr";  // a sun of 6520: a stress test
    for (const brdf::Preset& preset : bundled_presets_of_run("preview presets")) {
        lab::render::RenderStatistics stats;
        lab::film::ImageRgb image = render(runtime, preset.material, env, IblSampling::mis, 24, 4, 1, &stats);
        INFO(preset.source);
        CHECK(stats.nonfinite_samples == 0);
        CHECK(lab::film::image_stats(image).non_finite_pixels == 0);
        CHECK(lab::film::image_stats(image).mean[0] > 0.0);
    }
}

// The bundled scenes with a light of its own render with every integrator in the integrator
// agreement matrix (tests/test_integrator_agreement.cpp; cornell_box and half of the others, drawn
// per run), which checks that each of their samples is finite; here the scenes without one, under
// the courtyard as the commands light them.
TEST_CASE("Every bundled scene without a light renders under an environment without NaN or infinity", "[render][opencl]") {
    lab::opencl::Runtime runtime("");
    int rendered = 0;
    for (const auto& entry : fs::directory_iterator("scenes")) {
        if (entry.path().extension() != ".json") continue;
        lab::scene::Scene scene = lab::scene::load_scene(entry.path().string());
        if (lab::scene::has_own_light(scene)) continue;
        ++rendered;
        lab::render::RenderInput input;
        input.scene = scene;
        input.environment = lab::ibl::load_environment("envmaps/courtyard.exr");
        input.settings.width = input.settings.height = 24;
        input.settings.max_depth = 8;
        lab::render::OpenClRenderer renderer(runtime, input);
        RenderResult r = render_samples(renderer, 2);
        INFO(entry.path().string() << ": " << r.stats.lost_rays << " lost rays of " << r.stats.rays);
        CHECK(r.stats.nonfinite_samples == 0);
        CHECK(lab::film::image_stats(r.image).non_finite_pixels == 0);
        lab::film::ImageStats stats = lab::film::image_stats(r.image);
        CHECK(stats.mean[0] + stats.mean[1] + stats.mean[2] > 0.0);
    }
    CHECK(rendered >= 3);
}
