#include "cli/strategy_images.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>

#include <unistd.h>

#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "kernels/host.hpp"
#include "render/integrator.hpp"

namespace lab::cli {

namespace fs = std::filesystem;

namespace {

// Copies `tile` into `sheet` with its top-left corner at (x0, y0).
void place(film::ImageRgb* sheet, const film::ImageRgb& tile, int x0, int y0) {
    for (int y = 0; y < tile.height; ++y)
        for (int x = 0; x < tile.width; ++x)
            for (int c = 0; c < 3; ++c) sheet->rgb[sheet->index(x0 + x, y0 + y) + c] = tile.rgb[tile.index(x, y) + c];
}

// Makes the folder `dir` and those above it where they do not exist; throws naming it unless it is then a folder.
void make_folder(const std::string& dir) {
    std::error_code error;
    if (fs::exists(dir, error) && !fs::is_directory(dir, error)) throw InputError(dir, "--strategies", "is a file, not a folder");
    fs::create_directories(dir, error);
    if (error || !fs::is_directory(dir, error))
        throw InputError(dir, "--strategies", "cannot create the folder" + (error ? " (" + error.message() + ")" : std::string()));
}

}  // namespace

void check_strategy_folder(const std::string& dir) {
    const fs::path folder(dir);
    fs::path outermost_new;  // the outermost folder that create_directories makes here
    for (fs::path p = folder; !p.empty(); p = p.parent_path()) {
        std::error_code ignored;
        if (fs::exists(p, ignored)) break;
        outermost_new = p;
        if (p == p.parent_path()) break;
    }
    make_folder(dir);
    const fs::path probe = folder / (".dtoadq-write-check-" + std::to_string(::getpid()));
    std::FILE* f = std::fopen(probe.string().c_str(), "wb");
    const bool writable = f != nullptr && std::fclose(f) == 0;
    std::error_code ignored;
    fs::remove(probe, ignored);
    if (!outermost_new.empty()) fs::remove_all(outermost_new, ignored);
    if (!writable) throw InputError(dir, "--strategies", "cannot write into the folder");
}

void render_strategies(const RenderJob& job, const std::string& device, int spp, bool unweighted, std::optional<opencl::Runtime>* runtime,
                       const std::function<void(const StrategyImage&)>& use) {
    const render::RenderSettings& settings = job.input.settings;
    render::check_integrator_has_strategies(settings.integrator, "--strategies");
    const int n = render::bdpt_max_vertices(settings);
    for (int length = 2; length <= n; ++length)
        for (int s = 0; s < length; ++s) {
            const int t = length - s;
            if (!render::integrator_runs_strategy(settings.integrator, s, t)) continue;
            for (bool without_weight : {true, false}) {
                if (without_weight && !unweighted) continue;
                RenderJob one = job;
                one.input.settings.strategy_debug.strategy_s = s;
                one.input.settings.strategy_debug.strategy_t = t;
                one.input.settings.strategy_debug.strategy_unweighted = without_weight;
                std::unique_ptr<render::Renderer> renderer = make_renderer(one, device, runtime);
                renderer->set_samples_per_launch(spp);
                renderer->add_samples(spp);
                StrategyImage strategy{s, t, without_weight, renderer->image(), {}};
                strategy.metadata = job_metadata(one, *renderer, renderer->statistics());  // with the strategy
                use(strategy);
            }
        }
}

void write_strategy_images(const RenderJob& job, const std::string& device, int spp, const std::string& dir, bool quiet) {
    const render::RenderSettings& settings = job.input.settings;
    render::check_integrator_has_strategies(settings.integrator, "--strategies");
    make_folder(dir);  // again: the folder may have gone during the render
    const int n = render::bdpt_max_vertices(settings), w = settings.width, h = settings.height;
    // rows: path lengths 2 .. n vertices; columns: s = 0 .. n - 1, twice (unweighted, weighted)
    film::ImageRgb sheet(2 * n * w, (n - 1) * h);
    std::optional<opencl::Runtime> runtime;
    render_strategies(job, device, spp, true, &runtime, [&](const StrategyImage& one) {
        std::string name = "s" + std::to_string(one.s) + "_t" + std::to_string(one.t) + (one.unweighted ? "_unweighted" : "_weighted") + ".exr";
        film::write_exr((fs::path(dir) / name).string(), one.image, one.metadata);
        place(&sheet, one.image, (one.unweighted ? 0 : n * w) + one.s * w, (one.s + one.t - 2) * h);
        if (!quiet) std::fprintf(stderr, "wrote %s\n", (fs::path(dir) / name).string().c_str());
    });
    std::string contact = (fs::path(dir) / "contact_sheet.png").string();
    film::write_png(contact, sheet, film::ToneMap::Aces, 0.0f, film::ImageMetadata{});
    if (!quiet) std::fprintf(stderr, "wrote %s\n", contact.c_str());
}

}  // namespace lab::cli
