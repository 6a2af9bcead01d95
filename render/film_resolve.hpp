// The film's buffers (kernels/film.h) turned into the image they estimate.
#pragma once

#include <vector>

#include "film/image.hpp"
#include "render/film_readback.hpp"

namespace lab::render {

// A pass of launches over part of the image so far (Renderer::set_launch_pixels): its first `pixels`
// pixels, in row order, hold `samples` more samples than the others.
struct PartialPass {
    int pixels = 0;
    int samples = 0;
};

// Per pixel: accumulation.xyz / (own samples - non-finite count) + splat / light paths per pixel.
// A pixel's own samples are samples_per_pixel, plus the partial pass's where it has reached. The
// splats come from light paths every pixel's work-item traced, one per sample, landing anywhere:
// they are scaled by all of them, samples_per_pixel + partial.samples * partial.pixels / pixels
// per pixel (pbrt-v4's splat scale when there is no partial pass). A pixel whose samples were all
// non-finite is NaN (it shows, magenta in a PNG); a pixel without a sample is 0.
film::ImageRgb resolve_film(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial = {});

// Per pixel: how many of its own samples are finite (those its mean is over), as resolve_film counts them.
std::vector<float> finite_sample_counts(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial = {});

// Per pixel and channel: the variance of the pixel's mean, s^2 / n, from its n finite own samples'
// sum and sum of squares, s^2 = (sum x^2 - (sum x)^2 / n) / (n - 1) the unbiased sample variance
// (in double; clamped at 0, where the float sums' rounding would make it negative). NaN where
// n < 2 (no spread to estimate). What was splatted onto the pixel (the light tracer's t = 1
// connections) is not in it.
film::ImageRgb resolve_variance(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial = {});

}  // namespace lab::render
