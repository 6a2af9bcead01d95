// Batches of disjoint sample ranges from one renderer, as the region tests compare them
// (validation/region_t_test.hpp): `count` renders of `spp` samples each, from the ranges
// [b spp, (b + 1) spp), independent estimates of the same image.
#pragma once

#include <vector>

#include <catch2/catch.hpp>

#include "film/image.hpp"
#include "render/renderer.hpp"

// Every sample of every batch is finite: the renderer counts (and leaves out) a path whose radiance
// is not.
inline std::vector<lab::film::ImageRgb> render_sample_batches(lab::render::Renderer& renderer, int count, int spp) {
    renderer.set_samples_per_launch(spp);
    std::vector<lab::film::ImageRgb> batches;
    for (int b = 0; b < count; ++b) {
        renderer.set_first_sample(b * spp);
        renderer.add_samples(spp);
        batches.push_back(renderer.image());
        CHECK(renderer.statistics().nonfinite_samples == 0);
    }
    return batches;
}

// The mean of channel c over every pixel of every batch.
inline double batches_channel_mean(const std::vector<lab::film::ImageRgb>& batches, int c) {
    double sum = 0.0;
    for (const lab::film::ImageRgb& image : batches)
        for (size_t p = 0; p < image.pixel_count(); ++p) sum += image.rgb[3 * p + c];
    return sum / double(batches.size() * batches[0].pixel_count());
}
