// Non-finite samples are counted and reported, never hidden in the image: a sky of radiance 3e38,
// the largest a loader accepts, makes environment sampling's estimate 4 cos x 3e38 overflow to
// infinity wherever cos > 0.29, while BSDF sampling of white Lambert returns exactly the sky's
// radiance (weight f cos / pdf = 1), which stays finite. One sample per pixel: the sum of several
// such finite samples would itself overflow the float accumulation.
#include <catch2/catch.hpp>

#include <cmath>

#include "brdf/host/preset.hpp"
#include "film/image_stats.hpp"
#include "ibl/environment.hpp"
#include "ibl/preview_renderer.hpp"
#include "ibl/preview_scene.hpp"
#include "opencl/runtime.hpp"
#include "scene/load_scene.hpp"

namespace {

const char* kSphere = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 3.2], "look_at": [0, 0, 0], "fov_degrees": 40},
  "materials": {"sample": {"albedo": [1, 1, 1], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "ball", "material": "sample", "shape": {"type": "sphere", "radius": 1}}]
})";

lab::ibl::PreviewStatistics render(const lab::opencl::Runtime& runtime, lab::ibl::IblSampling sampling, lab::film::ImageRgb* image) {
    lab::ibl::PreviewScene scene =
        lab::ibl::compile_preview_scene(lab::scene::parse_scene(kSphere, "nonfinite.json"), lab::ibl::PreviewSceneOptions{{}, true});
    lab::ibl::Environment sky = lab::ibl::load_environment("constant:3e38,3e38,3e38");
    lab::ibl::PreviewSettings settings;
    settings.width = settings.height = 16;
    settings.sampling = sampling;
    settings.max_depth = 4;
    lab::ibl::PreviewRenderer renderer(runtime, scene, sky, settings);
    renderer.add_samples(1);
    *image = renderer.image();
    return renderer.statistics();
}

}  // namespace

TEST_CASE("Non-finite samples are counted and left out of the image", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::film::ImageRgb image;
    const lab::ibl::PreviewStatistics env = render(runtime, lab::ibl::IblSampling::env, &image);
    INFO("environment sampling: " << env.nonfinite_samples << " non-finite samples of " << env.paths);
    CHECK(env.nonfinite_samples > 0);
    CHECK(env.nonfinite_samples < env.paths);  // the backdrop's samples are the sky itself: finite
    CHECK(lab::film::image_stats(image).non_finite_pixels == 0);
    // the control: the same sky through BSDF sampling stays finite
    const lab::ibl::PreviewStatistics bsdf = render(runtime, lab::ibl::IblSampling::brdf, &image);
    CHECK(bsdf.nonfinite_samples == 0);
}
