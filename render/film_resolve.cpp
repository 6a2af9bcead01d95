#include "render/film_resolve.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <stdexcept>

namespace lab::render {

namespace {

void check_film(const FilmReadback& film, size_t pixels, PartialPass partial, const char* caller) {
    if (film.accumulation.size() != 4 * pixels || film.splat.size() != 3 * pixels)
        throw std::invalid_argument(std::string(caller) + ": buffers do not match the image size");
    if (partial.pixels < 0 || size_t(partial.pixels) > pixels || partial.samples < 0)
        throw std::invalid_argument(std::string(caller) + ": the partial pass is outside the image");
}

// Pixel p's own samples: the complete passes', and the partial pass's where it has reached.
double own_samples(size_t p, int samples_per_pixel, PartialPass partial) {
    return double(samples_per_pixel) + (p < size_t(partial.pixels) ? double(partial.samples) : 0.0);
}

}  // namespace

film::ImageRgb resolve_film(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial) {
    film::ImageRgb out(width, height);
    size_t pixels = out.pixel_count();
    check_film(film, pixels, partial, "resolve_film");
    const double light_paths = double(samples_per_pixel) + double(partial.samples) * double(partial.pixels) / double(pixels);
    for (size_t p = 0; p < pixels; ++p) {
        const double samples = own_samples(p, samples_per_pixel, partial);
        if (samples <= 0.0) continue;  // not reached yet: 0
        double finite = samples - double(film.accumulation[4 * p + 3]);
        for (size_t c = 0; c < 3; ++c) {
            double own = finite > 0.0 ? double(film.accumulation[4 * p + c]) / finite : std::numeric_limits<double>::quiet_NaN();
            out.rgb[3 * p + c] = float(own + double(film.splat[3 * p + c]) / light_paths);
        }
    }
    return out;
}

std::vector<float> finite_sample_counts(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial) {
    const size_t pixels = size_t(width) * size_t(height);
    check_film(film, pixels, partial, "finite_sample_counts");
    std::vector<float> counts(pixels);
    for (size_t p = 0; p < pixels; ++p) counts[p] = float(own_samples(p, samples_per_pixel, partial) - double(film.accumulation[4 * p + 3]));
    return counts;
}

film::ImageRgb resolve_variance(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial) {
    film::ImageRgb out(width, height);
    const size_t pixels = out.pixel_count();
    check_film(film, pixels, partial, "resolve_variance");
    if (film.squares.size() != 4 * pixels) throw std::invalid_argument("resolve_variance: the squares do not match the image size");
    const std::vector<float> counts = finite_sample_counts(film, samples_per_pixel, width, height, partial);
    for (size_t p = 0; p < pixels; ++p) {
        const double n = double(counts[p]);
        for (size_t c = 0; c < 3; ++c) {
            if (n < 2.0) {
                out.rgb[3 * p + c] = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            const double passes = double(film.squares[4 * p + 3]);
            const bool per_pass = passes > 0.0;
            if (per_pass && passes < 2.0) {
                out.rgb[3 * p + c] = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            const double sum = double(film.accumulation[4 * p + c]) + (per_pass ? double(film.splat[3 * p + c]) : 0.0);
            const double squares = double(film.squares[4 * p + c]);
            const double sample_variance = std::max(0.0, (squares - sum * sum / n) / ((per_pass ? passes : n) - 1.0));
            out.rgb[3 * p + c] = float(sample_variance / n);
        }
    }
    return out;
}

void add_pass_squares(const FilmReadback& start, FilmReadback* now, int pass_samples) {
    const size_t pixels = now->accumulation.size() / 4;
    if (start.accumulation.size() != now->accumulation.size() || start.squares.size() != now->squares.size() ||
        start.splat.size() != now->splat.size() || now->squares.size() != 4 * pixels || now->splat.size() != 3 * pixels || pass_samples < 1)
        throw std::invalid_argument("add_pass_squares: the films before and after the pass do not match");
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 3; ++c) {
            const double y = double(now->accumulation[4 * p + c]) - double(start.accumulation[4 * p + c]) + double(now->splat[3 * p + c]) -
                             double(start.splat[3 * p + c]);
            now->squares[4 * p + c] = float(double(start.squares[4 * p + c]) + y * y / double(pass_samples));
        }
        now->squares[4 * p + 3] = start.squares[4 * p + 3] + 1.0f;
    }
}

}  // namespace lab::render
