// The display denoiser's pass on the OpenCL device (kernels/denoise.cl) against the host's
// (film/denoise.cpp): the same single-source function, compiled twice.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "film/denoise.hpp"
#include "kernels/host/denoise_device.hpp"
#include "opencl/runtime.hpp"

#include "tests/worst_difference.hpp"

TEST_CASE("Denoiser: the OpenCL device's passes give the host's", "[denoise][opencl]") {
    // A noisy image with edges of every kind and a strip of background.
    const int width = 70, height = 50;
    std::mt19937 rng(5);
    std::normal_distribution<float> noise(0.0f, 0.1f);
    lab::film::ImageRgb radiance(width, height);
    lab::film::DenoiseGuide guide;
    guide.albedo = lab::film::ImageRgb(width, height);
    guide.normal = lab::film::ImageRgb(width, height);
    guide.depth.assign(size_t(width * height), 0.0f);
    guide.variance.assign(size_t(width * height), 0.01f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float a = x < width / 2 ? 0.3f : 0.8f;
            const bool tilted = y > height / 2;
            guide.albedo.set(x, y, a, a * 0.9f, a * 0.5f);
            guide.normal.set(x, y, tilted ? 0.6f : 0.0f, 0.0f, tilted ? 0.8f : 1.0f);
            guide.depth[size_t(y * width + x)] = x < 3 ? 0.0f : (x > 50 ? 9.0f : 4.0f);
            // each channel's light its own, so that a pass that mixes channels up (the device's
            // lanes shuffle them apart) differs from the host's
            const float light = 1.0f + 0.3f * float(tilted);
            radiance.set(x, y, a * (light + noise(rng)), a * 0.9f * (light + noise(rng)), a * 0.5f * (light + noise(rng)));
        }
    lab::film::DenoiseOptions options;
    lab::film::AtrousBuffers host = lab::film::demodulate(radiance, guide), device = host;
    lab::film::atrous_passes(&host, options);
    lab::opencl::Runtime runtime;
    lab::kernels::DeviceDenoiser denoiser(runtime);
    denoiser.passes(&device, options);
    // exp, pow and sqrt of the two math libraries differ by an ulp or two: 1e-5 relative after
    // the passes of sums of nine terms, and the device's multiply-adds fused where the host's round twice.
    double worst = 0.0;
    for (size_t p = 0; p < host.illumination.size(); ++p)
        for (int c = 0; c < 4; ++c)
            worst = worse_of(worst, std::fabs(double(host.illumination[p][size_t(c)]) - double(device.illumination[p][size_t(c)])) /
                                        std::max(1e-3, std::fabs(double(host.illumination[p][size_t(c)]))));
    INFO("largest relative difference " << worst);
    CHECK(worst <= 1e-5);
}
