// The render on screen and the window on disk: an OpenGL texture that takes the tone-mapped film,
// and the window's pixels read back as a PNG (the headless --screenshot).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lab::viewer {

class GlTexture {
public:
    GlTexture();
    ~GlTexture();
    GlTexture(const GlTexture&) = delete;
    GlTexture& operator=(const GlTexture&) = delete;
    // 8-bit sRGB, 3 bytes per pixel, top row first (film::to_srgb8).
    void upload(const std::vector<uint8_t>& rgb, int width, int height);
    unsigned id() const { return id_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    unsigned id_ = 0;
    int width_ = 0, height_ = 0;
};

// The current framebuffer (width x height) as an sRGB PNG; throws lab::InputError naming the path.
void write_screenshot(const std::string& path, int width, int height);

}  // namespace lab::viewer
