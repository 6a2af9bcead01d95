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

// Per pixel and channel: the variance of the pixel's mean, s^2 / n, n its finite own samples, in
// double, clamped at 0 (where the float sums' rounding would make it negative):
// - squared per sample (squares.w = 0: the path tracer's film): s^2 = (sum x^2 - (sum x)^2 / n) /
//   (n - 1), the unbiased sample variance of its own samples; NaN where n < 2;
// - squared per pass (squares.w = m > 0 passes, add_pass_squares: an integrator that splats):
//   s^2 = (sum_j Y_j^2 / k_j - (sum_j Y_j)^2 / n) / (m - 1), Y_j a pass's k_j own samples and
//   what the light paths of that pass splatted onto the pixel, sum_j Y_j = accumulation + splat;
//   its expectation is the variance of one sample (own plus splats), since E[Y_j^2 / k_j] =
//   sigma^2 + k_j mu^2 and E[(sum Y)^2 / n] = sigma^2 + n mu^2; NaN where m < 2.
film::ImageRgb resolve_variance(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial = {});

// For an integrator that splats (IntegratorDescriptor::splats): the light paths of every pixel's
// work-item splat onto any pixel, so which of a pixel's samples a splat belongs to is unknown and
// a per-sample square cannot hold it; a whole pass can. Sets now->squares to start's plus, per
// pixel, Y^2 / pass_samples (xyz) and 1 (w), Y = the pass's own samples and splats (now - start,
// accumulation and splat): `start` and `*now` are the film before and after one complete pass of
// `pass_samples` samples per pixel. What the kernel wrote into the squares during the pass (its
// own samples' squares) is replaced.
void add_pass_squares(const FilmReadback& start, FilmReadback* now, int pass_samples);

}  // namespace lab::render
