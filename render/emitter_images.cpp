#include "render/emitter_images.hpp"

#include <cmath>
#include <filesystem>

#include "common/input_error.hpp"
#include "common/message_number.hpp"
#include "film/tone_map.hpp"
#include "ibl/distribution.hpp"
#include "ibl/radiance_image.hpp"

namespace lab::render {

namespace {

void check_size(const std::string& path, int width, int height) {
    if (width < 1 || height < 1 || width > kMaxEmitterImageSide || height > kMaxEmitterImageSide)
        throw InputError(path, "size",
                         std::to_string(width) + " x " + std::to_string(height) + " (an emitter's image has 1 to " +
                             std::to_string(kMaxEmitterImageSide) + " texels a side)");
}

}  // namespace

EmitterImage emitter_image_from_pixels(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    check_size(path, width, height);
    if (rgb.size() != size_t(width) * size_t(height) * 3)
        throw std::invalid_argument("emitter_image_from_pixels: pixels hold width x height x 3 floats");
    static const char* const kChannel[3] = {"R", "G", "B"};
    EmitterImage image;
    image.width = width;
    image.height = height;
    image.texels.resize(size_t(width) * size_t(height));
    std::array<double, 3> sum{};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t p = size_t(y) * size_t(width) + size_t(x);
            for (int c = 0; c < 3; ++c) {
                const float v = rgb[p * 3 + size_t(c)];
                if (!std::isfinite(v) || v < 0.0f)
                    throw InputError(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")",
                                     std::string(kChannel[c]) + " is " + (std::isnan(v) ? "NaN" : (std::isinf(v) ? "infinite" : "negative")) +
                                         " (radiance must be finite and >= 0)");
            }
            // the file's rows run from the top, the texels' from t = 0 (kernels/lights/image_emitter.h)
            const size_t row = size_t(height - 1 - y);
            image.texels[row * size_t(width) + size_t(x)] = brdf::float4(rgb[p * 3], rgb[p * 3 + 1], rgb[p * 3 + 2], 0.0f);
            for (size_t c = 0; c < 3; ++c) sum[c] += double(rgb[p * 3 + c]);
        }
    }
    for (size_t c = 0; c < 3; ++c) image.mean_rgb[c] = sum[c] / (double(width) * double(height));
    // every texel covers the same area of the emitter (a disk's through the area-keeping concentric map)
    image.alias = ibl::build_row_alias_tables(image.texels, height, width, [](int, int) { return 1.0; });
    const std::vector<float> probability = ibl::row_texel_probabilities(image.alias, height, width);
    for (size_t t = 0; t < image.texels.size(); ++t) image.texels[t].w = probability[t];
    return image;
}

namespace {

// The file of frame `frame`, shown at scene time `time` (for the messages), checked as
// emitter_frame_file says.
std::string checked_frame_file(const ibl::FrameSource& source, long long frame, double time) {
    const std::string path = ibl::frame_file(source, frame);
    const std::string at = " at t = " + message_number(time) + " s";
    std::error_code ec;
    if (source.kind == ibl::FrameSource::Kind::sequence && !std::filesystem::exists(path, ec))
        throw InputError(path, "", "no such file: frame " + std::to_string(frame) + " of the sequence " + source.path + at);
    if (source.kind == ibl::FrameSource::Kind::video && frame >= source.frames)
        throw InputError(path, "frames", "frame " + std::to_string(frame) + at + " is past the video's end: it holds " + std::to_string(source.frames) + " (" +
                                             message_number(double(source.frames) / source.fps) + " s at " + message_number(source.fps) + " fps)");
    return path;
}

// f(), its lab::InputError (a line naming an image file) prefixed with the scene file and the
// emitter's "image" field.
template <class F>
auto naming_emitter(const std::string& scene_file, const scene::Emitter& e, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const InputError& error) {
        throw InputError(scene_file, e.image_field, error.what());
    }
}

}  // namespace

std::string emitter_frame_file(const ibl::FrameSource& source, double time) {
    return checked_frame_file(source, ibl::frame_at_time(source, time), time);
}

EmitterImage load_emitter_image(const ibl::FrameSource& source, double time) {
    const long long frame = ibl::frame_at_time(source, time);
    const std::string path = checked_frame_file(source, frame, time);
    const bool video = source.kind == ibl::FrameSource::Kind::video;
    ibl::RadianceImage read = ibl::read_radiance_image(path, video ? ibl::kVideos : std::vector<ibl::RadianceFormat>{ibl::kOpenExr, ibl::kRadianceHdr, ibl::kPng},
                                                       [&](int width, int height) { check_size(path, width, height); }, video ? int(frame) : 0);
    const size_t pixels = size_t(read.width) * size_t(read.height);
    // a PNG's and a video's 8-bit values are display-encoded
    const bool grey = read.channel_names.size() == 1, srgb = read.format == ibl::kPng.format || video;
    std::vector<float> rgb(pixels * 3);
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < 3; ++c) {
            const float v = read.pixels[grey ? p : p * 3 + c];
            rgb[p * 3 + c] = srgb ? film::srgb_decode(v) : v;
        }
    return emitter_image_from_pixels(path, read.width, read.height, rgb);
}

ibl::FrameSource emitter_frame_source(const std::string& scene_file, const scene::Emitter& e) {
    // its fps was checked when the scene was read
    ibl::FrameSource source = ibl::frame_source(e.image, e.image_fps, scene_file, e.image_field, e.image_fps_field);
    if (source.kind == ibl::FrameSource::Kind::video) naming_emitter(scene_file, e, [&] { ibl::open_video(&source); });
    return source;
}

void check_emitter_frames(const scene::Scene& scene, int64_t first, int64_t end, double fps) {
    for (const scene::Emitter& e : scene.emitters) {
        if (e.image.empty()) continue;
        const ibl::FrameSource source = emitter_frame_source(scene.file, e);
        for (int64_t k = first; k < end; ++k) naming_emitter(scene.file, e, [&] { return emitter_frame_file(source, double(k) / fps); });
    }
}

std::vector<std::optional<EmitterImage>> load_emitter_images(const scene::CompiledScene& scene, double time) {
    std::vector<std::optional<EmitterImage>> images;
    for (const scene::Emitter& e : scene.emitters) {
        images.emplace_back();
        if (e.image.empty()) continue;
        const ibl::FrameSource source = emitter_frame_source(scene.file, e);
        images.back() = naming_emitter(scene.file, e, [&] { return load_emitter_image(source, time); });
    }
    return images;
}

std::vector<std::optional<std::array<double, 3>>> emitter_image_means(const std::vector<std::optional<EmitterImage>>& images) {
    std::vector<std::optional<std::array<double, 3>>> means;
    for (const std::optional<EmitterImage>& image : images) means.push_back(image ? std::optional<std::array<double, 3>>(image->mean_rgb) : std::nullopt);
    return means;
}

void bind_emitter_images(const std::vector<std::optional<EmitterImage>>& images, LightSet* lights, std::vector<brdf::float4>* texels,
                         std::vector<kernel::AliasEntry>* alias) {
    const size_t first = !lights->lights.empty() && lights->lights[0].type == LIGHT_ENVIRONMENT ? 1 : 0;
    for (size_t k = 0; k < images.size(); ++k) {
        kernel::Light& light = lights->lights.at(first + k);
        light.image = 0;
        if (!images[k]) continue;
        const EmitterImage& image = *images[k];
        if (alias->size() + EMITTER_IMAGE_HEADER + image.alias.size() > size_t(INT32_MAX) || texels->size() + image.texels.size() > size_t(INT32_MAX))
            throw std::length_error("bind_emitter_images: the buffers outgrow an int's offsets");
        light.image = int(alias->size());
        alias->push_back(kernel::AliasEntry{0.0f, image.width});
        alias->push_back(kernel::AliasEntry{0.0f, image.height});
        alias->push_back(kernel::AliasEntry{0.0f, int(texels->size())});
        alias->insert(alias->end(), image.alias.begin(), image.alias.end());
        texels->insert(texels->end(), image.texels.begin(), image.texels.end());
    }
}

}  // namespace lab::render
