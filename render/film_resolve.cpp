#include "render/film_resolve.hpp"

#include <limits>
#include <stdexcept>

namespace lab::render {

film::ImageRgb resolve_film(const FilmReadback& film, int samples_per_pixel, int width, int height) {
    film::ImageRgb out(width, height);
    size_t pixels = out.pixel_count();
    if (film.accumulation.size() != 4 * pixels || film.splat.size() != 3 * pixels)
        throw std::invalid_argument("resolve_film: buffers do not match the image size");
    if (samples_per_pixel <= 0) return out;
    double samples = double(samples_per_pixel);
    for (size_t p = 0; p < pixels; ++p) {
        double finite = samples - double(film.accumulation[4 * p + 3]);
        for (size_t c = 0; c < 3; ++c) {
            double own = finite > 0.0 ? double(film.accumulation[4 * p + c]) / finite : std::numeric_limits<double>::quiet_NaN();
            out.rgb[3 * p + c] = float(own + double(film.splat[3 * p + c]) / samples);
        }
    }
    return out;
}

}  // namespace lab::render
