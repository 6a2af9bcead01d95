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
#include "ibl/environment.hpp"
#include "ibl/preview_renderer.hpp"
#include "ibl/preview_scene.hpp"
#include "opencl/runtime.hpp"

namespace fs = std::filesystem;
using lab::ibl::IblSampling;

namespace {

lab::film::ImageRgb render(const lab::opencl::Runtime& runtime, const lab::ibl::PreviewScene& scene, const lab::ibl::Environment& env,
                           IblSampling sampling, int size, int spp, uint64_t seed, lab::ibl::PreviewStatistics* stats = nullptr) {
    lab::ibl::PreviewSettings settings;
    settings.width = settings.height = size;
    settings.sampling = sampling;
    settings.seed = seed;
    settings.max_depth = 8;
    lab::ibl::PreviewRenderer renderer(runtime, scene, env, settings);
    renderer.set_samples_per_launch(spp);
    renderer.add_samples(spp);
    if (stats) *stats = renderer.statistics();
    return renderer.image();
}

double image_mean(const lab::film::ImageRgb& image) {
    lab::film::ImageStats s = lab::film::image_stats(image);
    return (s.mean[0] + s.mean[1] + s.mean[2]) / 3.0;
}

}  // namespace

TEST_CASE("BRDF, environment and MIS sampling converge to the same image mean", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::ibl::PreviewSceneOptions options;
    options.sample_material = brdf::load_preset("presets/glossy_plastic.json");
    lab::ibl::PreviewScene scene = lab::ibl::compile_preview_scene(lab::ibl::load_preview_scene(""), options);
    lab::ibl::Environment env = lab::ibl::load_environment("envmaps/courtyard.exr");
    // Each strategy's mean over 4 seeds; the spread of those means gives its standard error.
    std::vector<double> means, errors;
    for (IblSampling sampling : {IblSampling::brdf, IblSampling::env, IblSampling::mis}) {
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

TEST_CASE("A render is a pure function of its seed", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::ibl::PreviewScene scene = lab::ibl::compile_preview_scene(lab::ibl::load_preview_scene(""), {});
    lab::ibl::Environment env = lab::ibl::load_environment("constant:0.5,0.7,1");
    lab::film::ImageRgb a = render(runtime, scene, env, IblSampling::mis, 16, 4, 7);
    lab::film::ImageRgb b = render(runtime, scene, env, IblSampling::mis, 16, 4, 7);
    lab::film::ImageRgb c = render(runtime, scene, env, IblSampling::mis, 16, 4, 8);
    CHECK(a.rgb == b.rgb);
    CHECK(a.rgb != c.rgb);
}

TEST_CASE("Every bundled preset renders without NaN or infinity", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::ibl::Environment env = lab::ibl::load_environment("envmaps/sunset.exr");  // a sun of 6520: a stress test
    for (const auto& entry : fs::directory_iterator("presets")) {
        if (entry.path().extension() != ".json") continue;
        lab::ibl::PreviewSceneOptions options;
        options.sample_material = brdf::load_preset(entry.path().string());
        lab::ibl::PreviewScene scene = lab::ibl::compile_preview_scene(lab::ibl::load_preview_scene(""), options);
        lab::ibl::PreviewStatistics stats;
        lab::film::ImageRgb image = render(runtime, scene, env, IblSampling::mis, 24, 4, 1, &stats);
        INFO(entry.path().string());
        CHECK(stats.nonfinite_samples == 0);
        CHECK(lab::film::image_stats(image).non_finite_pixels == 0);
        CHECK(image_mean(image) > 0.0);
    }
}
