#include "viewer/gl_image.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "film/image_output.hpp"

namespace lab::viewer {

GlTexture::GlTexture() {
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // pixels stay pixels when zoomed
}

GlTexture::~GlTexture() { glDeleteTextures(1, &id_); }

void GlTexture::upload(const std::vector<uint8_t>& rgb, int width, int height) {
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 3-byte pixels are not 4-byte aligned
    if (width != width_ || height != height_) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width, height, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        width_ = width;
        height_ = height;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    }
}

void write_screenshot(const std::string& path, int width, int height) {
    std::vector<uint8_t> pixels(size_t(width) * size_t(height) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // OpenGL's rows start at the bottom; a PNG's at the top.
    std::vector<uint8_t> flipped(pixels.size());
    const size_t row = size_t(width) * 3;
    for (int y = 0; y < height; ++y)
        std::copy(pixels.begin() + ptrdiff_t(size_t(height - 1 - y) * row), pixels.begin() + ptrdiff_t(size_t(height - y) * row),
                  flipped.begin() + ptrdiff_t(size_t(y) * row));
    film::write_srgb8_png(path, width, height, flipped, film::ImageMetadata{});
}

}  // namespace lab::viewer
