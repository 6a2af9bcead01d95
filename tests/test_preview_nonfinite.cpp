// Non-finite samples are counted and reported, never hidden in the image: a sky of radiance 3e38,
// the largest a loader accepts, makes environment sampling's estimate 4 cos x 3e38 overflow to
// infinity wherever cos > 0.29, while BSDF sampling of white Lambert returns exactly the sky's
// radiance (weight f cos / pdf = 1), which stays finite. One sample per pixel: the sum of several
// such finite samples would itself overflow the float accumulation. A pixel left with no finite
// sample is NaN in the image, so it shows (magenta in a PNG) instead of passing for black.
#include <catch2/catch.hpp>

#include <cmath>

#include "film/image_stats.hpp"
#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/render_inputs.hpp"

namespace {

lab::render::RenderStatistics render(const lab::opencl::Runtime& runtime, lab::render::LightSampling sampling, lab::film::ImageRgb* image) {
    lab::render::RenderInput input = render_input(std::nullopt, "constant:3e38,3e38,3e38", 16, sampling, 0, kWhiteSphereScene);
    input.settings.max_depth = 4;
    lab::render::OpenClRenderer renderer(runtime, input);
    RenderResult r = render_samples(renderer, 1);
    *image = r.image;
    return r.stats;
}

}  // namespace

TEST_CASE("Non-finite samples are counted and left out of the image", "[preview][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::film::ImageRgb image;
    const lab::render::RenderStatistics env = render(runtime, lab::render::LightSampling::lights, &image);
    INFO("environment sampling: " << env.nonfinite_samples << " non-finite samples of " << env.paths);
    CHECK(env.nonfinite_samples > 0);
    CHECK(env.nonfinite_samples < env.paths);  // the backdrop's samples are the sky itself: finite
    // one sample per pixel: exactly the pixels whose sample was not finite have none, and show
    CHECK(lab::film::image_stats(image).non_finite_pixels == env.nonfinite_samples);
    // the control: the same sky through BSDF sampling stays finite
    const lab::render::RenderStatistics bsdf = render(runtime, lab::render::LightSampling::bsdf, &image);
    CHECK(bsdf.nonfinite_samples == 0);
    CHECK(lab::film::image_stats(image).non_finite_pixels == 0);
}
