// The film as the device holds it (kernels/film.h), read back to the host.
#pragma once

#include <vector>

namespace lab::render {

struct FilmReadback {
    std::vector<float> accumulation;  // 4 per pixel: sum of finite samples, count of non-finite ones
    std::vector<float> squares;       // 4 per pixel: sum of the finite samples' squares, and 0
    std::vector<float> splat;         // 3 per pixel
};

}  // namespace lab::render
