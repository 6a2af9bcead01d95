// The preview under a real environment: the three environment-sampling strategies estimate the
// same image (their means agree within noise), renders are a pure function of the seed, and every
// bundled preset renders without a NaN or an infinity.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "brdf/host/preset.hpp"
#include "film/image_stats.hpp"
#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
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

double image_mean(const lab::film::ImageRgb& image) {
    lab::film::ImageStats s = lab::film::image_stats(image);
    return (s.mean[0] + s.mean[1] + s.mean[2]) / 3.0;
}

}  // namespace

TEST_CASE("BRDF, environment and MIS sampling converge to the same image mean", "[preview]") {
    lab::opencl::Runtime runtime("");
    brdf::Material scene = brdf::load_preset("presets/glossy_plastic.json").material;
    std::string env = "envmaps/courtyard.exr";
    // Each strategy's mean over 4 seeds; the spread of those means gives its standard error.
    std::vector<double> means, errors;
    for (IblSampling sampling : {IblSampling::bsdf, IblSampling::lights, IblSampling::mis}) {
        std::vector<double> m;
        for (uint64_t seed = 1; seed <= 4; ++seed) m.push_back(image_mean(render(runtime, scene, env, sampling, 32, 16, seed)));
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

TEST_CASE("A render is a pure function of its seed", "[preview]") {
    lab::opencl::Runtime runtime("");
    std::optional<brdf::Material> scene;  // the test model's own material
    std::string env = "constant:0.5,0.7,1";
    lab::film::ImageRgb a = render(runtime, scene, env, IblSampling::mis, 16, 4, 7);
    lab::film::ImageRgb b = render(runtime, scene, env, IblSampling::mis, 16, 4, 7);
    lab::film::ImageRgb c = render(runtime, scene, env, IblSampling::mis, 16, 4, 8);
    CHECK(a.rgb == b.rgb);
    CHECK(a.rgb != c.rgb);
}

TEST_CASE("Every bundled preset renders without NaN or infinity", "[preview]") {
    lab::opencl::Runtime runtime("");
    std::string env = "envmaps/sunset.exr";  // a sun of 6520: a stress test
    for (const auto& entry : fs::directory_iterator("presets")) {
        if (entry.path().extension() != ".json") continue;
        brdf::Material scene = brdf::load_preset(entry.path().string()).material;
        lab::render::RenderStatistics stats;
        lab::film::ImageRgb image = render(runtime, scene, env, IblSampling::mis, 24, 4, 1, &stats);
        INFO(entry.path().string());
        CHECK(stats.nonfinite_samples == 0);
        CHECK(lab::film::image_stats(image).non_finite_pixels == 0);
        CHECK(image_mean(image) > 0.0);
    }
}
