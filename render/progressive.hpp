// The progressive driver every render command shares: adds samples to any renderer until a sample
// count or a time is reached or the user presses Ctrl-C, with a progress bar (samples/s, ETA); and
// writes what it made as a linear EXR with its metadata plus a tone-mapped PNG, never losing a
// finished render to a bad output path.
#pragma once

#include <string>
#include <vector>

#include "film/image.hpp"
#include "film/image_metadata.hpp"
#include "film/image_output.hpp"
#include "film/tone_map.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// When a progressive render stops: after `samples` per pixel, or when `seconds` (> 0) have passed
// (then `samples` caps it only when given).
struct RenderLimits {
    int samples = 64;
    bool samples_given = false;
    double seconds = 0.0;
    bool quiet = false;  // no progress bar
};

// How a progressive render ended.
struct ProgressiveOutcome {
    bool interrupted = false;  // Ctrl-C ended it
    std::string failure;       // a launch failed (an OpenCL error: out of device memory, a lost device)
};

// Adds samples until a limit is reached, the user interrupts, or a launch fails. Ctrl-C ends the
// current launch (render/interrupt.hpp: a second Ctrl-C stops the process at once). A failed launch
// is not rethrown: the caller writes the samples of the launches before it (the renderer counts
// only completed launches), then reports the failure (fail_after_writing). Launches grow while
// they take under an eighth of a second, so the bar moves and few launches are made.
ProgressiveOutcome render_progressively(Renderer& renderer, const RenderLimits& limits);

// After a failed render's image was written: throws the failure as one line that says where the
// samples rendered before it went.
[[noreturn]] void fail_after_writing(const ProgressiveOutcome& outcome, int samples_per_pixel, const std::string& written_to);

// What every render's metadata holds: samples and the sample indices, time, device, seed,
// non-finite samples, lost rays, and every setting that changes what the render estimates (for
// bdpt and lt also the vertex limit, the MIS heuristic and a strategy mask or single strategy:
// merge and --resume compare them all). Callers add what they know besides (material, scene,
// environment, tone map).
film::ImageMetadata render_metadata(const Renderer& renderer, const RenderStatistics& stats);

// Whether `path` names an OpenEXR file (.exr, any case), and the PNG that goes beside it.
bool is_exr_path(const std::string& path);
std::string png_beside(const std::string& exr_path);

// Fails before rendering when the output (and the PNG beside an .exr) cannot be written.
void check_render_output(const std::string& output);

// An .exr output gets the linear EXR and the tone-mapped PNG beside it; a .png only the PNG. When
// they cannot be written the EXR goes to the temporary folder instead, and the InputError thrown
// says where: a finished render is never lost to a bad path. With `film`, the EXR holds the film's
// buffers too (render/film_file.hpp), so it can be merged with other parts or resumed; `aovs`
// (render/aov_layers.hpp) are further layers of the EXR.
void write_render_images(const std::string& output, const film::ImageRgb& image, film::ToneMap tone_map, float exposure_stops,
                         const film::ImageMetadata& metadata, const FilmReadback* film = nullptr,
                         const std::vector<film::ImageChannel>& aovs = {});

// Samples, time, paths/s, rays/s and rays that ran out of steps; non-finite samples, if any, on
// stderr as a warning even when quiet (they are never silently dropped).
void print_render_statistics(const RenderStatistics& stats, bool quiet);

}  // namespace lab::render
