// `dtoadq render ... --strategies DIR`: BDPT's strategies one by one, as pbrt-v4's
// visualize-strategies mode shows them (docs/bdpt.md).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "film/image_output.hpp"

#include "cli/render_job.hpp"

namespace lab::cli {

// For every strategy (s, t) the job's integrator runs (bdpt: all of s + t <= max_vertices but
// (1, 1); lt: t = 1), `spp` samples of its contribution alone, unweighted and weighted by its MIS
// weight: DIR/s<S>_t<T>_unweighted.exr and DIR/s<S>_t<T>_weighted.exr, and DIR/contact_sheet.png,
// one row per path length (s + t vertices), one column per s, the unweighted sheet left of the
// weighted one. Throws lab::InputError for the pt integrator or an unwritable DIR.
// Throws lab::InputError naming `dir` and --strategies unless it is a folder, or can be made one,
// that a file can be written into. The render command calls it before the render, which the
// strategy images follow, so that a bad folder stops the command before any sample. Leaves
// nothing behind: a folder it made for the check, and its probe file, are removed again.
void check_strategy_folder(const std::string& dir);

void write_strategy_images(const RenderJob& job, const std::string& device, int spp, const std::string& dir, bool quiet);

// One strategy's render: its contribution alone, weighted by its MIS weight or not.
struct StrategyImage {
    int s = 0, t = 0;
    bool unweighted = false;
    film::ImageRgb image;
    film::ImageMetadata metadata;  // the job's, with the strategy
};

// Renders, `spp` samples each, every strategy (s, t) the job's integrator runs, by path length (s + t
// vertices) and then s, the unweighted render before the weighted one where `unweighted` asks for
// both, and hands each to `use` in turn. `runtime` keeps the OpenCL runtime from one render to the
// next. Throws lab::InputError for the pt integrator.
void render_strategies(const RenderJob& job, const std::string& device, int spp, bool unweighted, std::optional<opencl::Runtime>* runtime,
                       const std::function<void(const StrategyImage&)>& use);

}  // namespace lab::cli
