// The progressive driver (render/progressive.hpp) with a renderer whose device fails mid-render, as
// an OpenCL error (out of device memory, a lost device) would: the driver stops at the failed
// launch and hands back what it said, the renderer keeps exactly the samples of the launches
// before it, and fail_after_writing turns it into one line that says where those samples went.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "render/progressive.hpp"
#include "tests/render_inputs.hpp"

namespace {

// A film whose every sample is 0.25; the launch numbered `fail_at` (from 1) throws, as the OpenCL
// runtime does when a launch fails.
class FailingRenderer final : public lab::render::Renderer {
public:
    FailingRenderer(lab::render::RenderInput input, int fail_at) : Renderer(std::move(input)), fail_at_(fail_at) { initialize(); }
    std::string device_description() const override { return "a device that fails"; }

private:
    void build_kernel() override {}
    void upload_scene() override {}
    void clear_film() override {
        size_t pixels = size_t(input_.settings.width) * size_t(input_.settings.height);
        film_.accumulation.assign(4 * pixels, 0.0f);
        film_.squares.assign(4 * pixels, 0.0f);
        film_.splat.assign(3 * pixels, 0.0f);
    }
    void launch(const kernel::RenderKernelSettings& settings, lab::render::PixelRange) override {
        if (++launches_ == fail_at_) throw std::runtime_error("clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (-5)");
        for (size_t p = 0; p < film_.accumulation.size(); p += 4)
            for (size_t c = 0; c < 3; ++c) film_.accumulation[p + c] += 0.25f * float(settings.sample_count);
    }
    lab::render::FilmReadback read_film() const override { return film_; }
    void write_film(const lab::render::FilmReadback& film) override { film_ = film; }
    void read_ray_counts(uint64_t* rays, uint64_t* lost) const override { *rays = *lost = 0; }

    int fail_at_, launches_ = 0;
    lab::render::FilmReadback film_;
};

}  // namespace

TEST_CASE("Progressive driver: a launch that fails ends the render, and the samples before it stand", "[render][driver]") {
    lab::render::RenderInput input = render_input(std::nullopt, "constant:1,1,1", 4, lab::render::LightSampling::mis, 0);
    FailingRenderer renderer(input, 3);
    lab::render::RenderLimits limits;
    limits.samples = 100;
    limits.quiet = true;
    lab::render::ProgressiveOutcome outcome = lab::render::render_progressively(renderer, limits);
    CHECK_FALSE(outcome.interrupted);
    CHECK(outcome.failure == "clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (-5)");
    // launches of 1 and then 2 samples (the driver doubles short launches) completed; the third failed
    int kept = renderer.statistics().samples_per_pixel;
    CHECK(kept == 3);
    lab::film::ImageRgb image = renderer.image();
    CHECK(image.rgb.front() == 0.25f);  // the mean of the kept samples: no trace of the failed launch
    try {
        lab::render::fail_after_writing(outcome, kept, "out.exr");
        FAIL("fail_after_writing returned");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()) ==
              "clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (-5); the 3 samples per pixel rendered before it were written to out.exr");
    }
}

TEST_CASE("Progressive driver: a render that fails at its first launch has nothing to keep", "[render][driver]") {
    lab::render::RenderInput input = render_input(std::nullopt, "constant:1,1,1", 4, lab::render::LightSampling::mis, 0);
    FailingRenderer renderer(input, 1);
    lab::render::RenderLimits limits;
    limits.quiet = true;
    lab::render::ProgressiveOutcome outcome = lab::render::render_progressively(renderer, limits);
    CHECK(renderer.statistics().samples_per_pixel == 0);
    CHECK_THROWS_WITH(lab::render::fail_after_writing(outcome, 0, ""), Catch::Contains("nothing to keep"));
}
