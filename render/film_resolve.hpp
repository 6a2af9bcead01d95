// The film's buffers (kernels/film.h) turned into the image they estimate.
#pragma once

#include "film/image.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// Per pixel: accumulation.xyz / (samples - non-finite count) + splat / samples. A pixel whose
// samples were all non-finite is NaN (it shows, magenta in a PNG); before the first sample every
// pixel is 0.
film::ImageRgb resolve_film(const FilmReadback& film, int samples_per_pixel, int width, int height);

}  // namespace lab::render
