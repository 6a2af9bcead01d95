#include "render/film_resolve.hpp"

#include <limits>
#include <stdexcept>

namespace lab::render {

film::ImageRgb resolve_film(const FilmReadback& film, int samples_per_pixel, int width, int height, PartialPass partial) {
    film::ImageRgb out(width, height);
    size_t pixels = out.pixel_count();
    if (film.accumulation.size() != 4 * pixels || film.splat.size() != 3 * pixels)
        throw std::invalid_argument("resolve_film: buffers do not match the image size");
    if (partial.pixels < 0 || size_t(partial.pixels) > pixels || partial.samples < 0)
        throw std::invalid_argument("resolve_film: the partial pass is outside the image");
    const double light_paths = double(samples_per_pixel) + double(partial.samples) * double(partial.pixels) / double(pixels);
    for (size_t p = 0; p < pixels; ++p) {
        const double samples = double(samples_per_pixel) + (p < size_t(partial.pixels) ? double(partial.samples) : 0.0);
        if (samples <= 0.0) continue;  // not reached yet: 0
        double finite = samples - double(film.accumulation[4 * p + 3]);
        for (size_t c = 0; c < 3; ++c) {
            double own = finite > 0.0 ? double(film.accumulation[4 * p + c]) / finite : std::numeric_limits<double>::quiet_NaN();
            out.rgb[3 * p + c] = float(own + double(film.splat[3 * p + c]) / light_paths);
        }
    }
    return out;
}

}  // namespace lab::render
