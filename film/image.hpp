// A linear RGB image in memory: what a render produces and what the image files hold.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace lab::film {

// Linear radiance, row-major, top row first, 3 floats (r, g, b) per pixel. Non-finite values are
// kept as they are: they are bugs to be seen (see film/image_stats.hpp), never hidden.
struct ImageRgb {
    int width = 0, height = 0;
    std::vector<float> rgb;

    ImageRgb() = default;
    // A black image of the given size.
    ImageRgb(int w, int h) : width(w), height(h), rgb(size_t(w > 0 ? w : 0) * size_t(h > 0 ? h : 0) * 3, 0.0f) {}

    size_t pixel_count() const { return size_t(width) * size_t(height); }
    // The first of the pixel's three floats.
    size_t index(int x, int y) const { return (size_t(y) * size_t(width) + size_t(x)) * 3; }
    float* pixel(int x, int y) { return rgb.data() + index(x, y); }
    const float* pixel(int x, int y) const { return rgb.data() + index(x, y); }
    std::array<float, 3> at(int x, int y) const {
        const float* p = pixel(x, y);
        return {p[0], p[1], p[2]};
    }
    void set(int x, int y, float r, float g, float b) {
        float* p = pixel(x, y);
        p[0] = r;
        p[1] = g;
        p[2] = b;
    }
    // The sizes agree with each other: width, height >= 1 and 3 floats per pixel.
    bool valid() const { return width > 0 && height > 0 && rgb.size() == pixel_count() * 3; }
};

}  // namespace lab::film
