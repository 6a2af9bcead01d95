// What `preview`, `report` and `bench preview` share: the options that choose the scene, material,
// environment and sampling, turned into a ready job; and the metadata and statistics they print.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "film/image.hpp"
#include "film/image_metadata.hpp"
#include "film/tone_map.hpp"
#include "ibl/environment.hpp"
#include "ibl/preview_renderer.hpp"

namespace lab::cli {

struct PreviewJobOptions {
    std::string scene;     // empty: the built-in test model
    std::string material;  // preset for the "sample" slot; empty: the scene's own
    std::string env;       // file or constant:R,G,B; empty: the scene's, else constant:1,1,1
    float env_rotation = 0.0f;
    float env_exposure = 0.0f;
    std::string size = "512x512";
    std::string ground = "on";
    std::string sampling = "mis";
    std::string normals = "tetrahedral";
    int max_depth = 16;
    int max_steps = 1024;
    float over_relaxation = 1.0f;
    unsigned long long seed = 0;
    std::string device;
};

void add_preview_job_options(CLI::App& cmd, PreviewJobOptions* options);

struct PreviewJob {
    ibl::PreviewScene scene;
    ibl::Environment environment;
    ibl::PreviewSettings settings;
    std::string scene_name, material_name, environment_name;
    std::string description;        // one line: material, scene, environment, size, strategy
    std::vector<std::string> warnings;  // the scene compiler's: a Lipschitz bound above 1, a broken bound
};

// Loads and checks everything (scene, preset, environment, sizes, words); throws lab::InputError.
PreviewJob prepare_preview_job(const PreviewJobOptions& options);

// "WxH" with both in [1, 16384]; `option` names the flag in errors.
void parse_image_size(const std::string& text, const std::string& option, int* width, int* height);

film::ImageMetadata preview_metadata(const PreviewJob& job, const ibl::PreviewStatistics& stats, const std::string& device);

// When a progressive render stops: after `samples` per pixel, or when `seconds` (> 0) have passed
// (then `samples` caps it only when given).
struct RenderLimits {
    int samples = 64;
    bool samples_given = false;
    double seconds = 0.0;
    bool quiet = false;  // no progress bar
};

// Whether `path` names an OpenEXR file (.exr, any case), and the PNG that goes beside it.
bool is_exr_path(const std::string& path);
std::string png_beside(const std::string& exr_path);

// An .exr output gets the linear EXR and the tone-mapped PNG beside it; a .png only the PNG. When
// they cannot be written the EXR goes to the temporary folder instead, and the InputError thrown
// says where: a finished render is never lost to a bad path.
void write_preview_images(const std::string& output, const film::ImageRgb& image, film::ToneMap tone_map, float exposure_stops,
                          const film::ImageMetadata& metadata);

// Adds samples until a limit is reached or the user interrupts (Ctrl-C ends the current launch and
// returns true, so the caller writes the image so far), with a progress bar on stderr.
bool render_progressively(ibl::PreviewRenderer& renderer, const RenderLimits& limits);

// Samples, time, paths/s, rays/s and rays that ran out of steps; non-finite samples, if any, on
// stderr as a warning even when quiet (they are never silently dropped).
void print_preview_statistics(const ibl::PreviewStatistics& stats, bool quiet);

}  // namespace lab::cli
