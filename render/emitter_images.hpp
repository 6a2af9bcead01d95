// The images that rect and disk emitters show (docs/scenes.md, kernels/lights/image_emitter.h):
// read from their files, checked, and made into the texels and alias tables the kernels read after
// the environment's own.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ibl/frame_source.hpp"
#include "kernels/host.hpp"
#include "render/light_set.hpp"
#include "scene/compile.hpp"

namespace lab::render {

// The most texels an emitter's image has along either side (its tables then hold 64 M cells, well
// within an int, and its float4 texels 1 GiB).
constexpr int kMaxEmitterImageSide = 4096;

struct EmitterImage {
    int width = 0, height = 0;
    // H W: row r covers t in [r/H, (r+1)/H] (the file's last row is row 0), xyz the linear RGB texel,
    // w the probability with which `alias` draws it (ibl::row_texel_probabilities)
    std::vector<brdf::float4> texels;
    // H + H W entries: ibl::build_row_alias_tables over H rows of W texels of equal measure
    std::vector<kernel::AliasEntry> alias;
    std::array<double, 3> mean_rgb{};  // of the texels: the emitter's mean radiance before its scale
};

// Per emitter, the mean RGB of its image (build_light_set's image_means).
std::vector<std::optional<std::array<double, 3>>> emitter_image_means(const std::vector<std::optional<EmitterImage>>& images);

// The image from width x height linear RGB pixels, rows from the top. Throws lab::InputError naming
// `path` and the pixel for a NaN, infinite or negative value, and for a size outside
// [1, kMaxEmitterImageSide] on either side.
EmitterImage emitter_image_from_pixels(const std::string& path, int width, int height, const std::vector<float>& rgb);

// The file that holds what `source` shows at scene time `time` (seconds): a still's own, a
// sequence's frame floor(time * fps), a video's own. Throws lab::InputError naming that file and
// the frame when a sequence's frame file is missing or the frame is past a video's end.
std::string emitter_frame_file(const ibl::FrameSource& source, double time);

// The one place an emitter's image is read: what `source` shows at scene time `time` (a still
// image the same at every time). OpenEXR, Radiance HDR or PNG, a sequence of them, or a video
// frame (a PNG's and a video's 8-bit values decoded from sRGB to linear), through
// ibl::read_radiance_image with its checks. Throws lab::InputError naming the file.
EmitterImage load_emitter_image(const ibl::FrameSource& source, double time);

// An emitter's image as a frame source (its video opened for its frame count and rate). An error
// names the scene file and the emitter's "image" field, then the file's own line.
ibl::FrameSource emitter_frame_source(const std::string& scene_file, const scene::Emitter& e);

// Throws, as load_emitter_images would, when an emitter of the scene has no frame at one of the
// scene times k / fps of a sequence's frames k = first .. end - 1, without reading a pixel: what a
// sequence render checks before its first frame.
void check_emitter_frames(const scene::Scene& scene, int64_t first, int64_t end, double fps);

// Per emitter of the scene (scene.emitters), its image at scene time `time`, or none. An error names
// the scene file and the emitter's "image" field, then the image's own line.
std::vector<std::optional<EmitterImage>> load_emitter_images(const scene::CompiledScene& scene, double time);

// Appends each emitter's image after what `texels` and `alias` hold (the environment's buffers) and
// sets its light's `image` (kernels/lights/light.h) to its header: lights.lights holds the emitters
// in scene order after the environment, as build_light_set makes it.
void bind_emitter_images(const std::vector<std::optional<EmitterImage>>& images, LightSet* lights, std::vector<brdf::float4>* texels,
                         std::vector<kernel::AliasEntry>* alias);

}  // namespace lab::render
