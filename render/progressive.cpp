#include "render/progressive.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "film/progress_bar.hpp"
#include "render/film_file.hpp"
#include "render/interrupt.hpp"
#include "render/vcm.hpp"

namespace lab::render {

namespace fs = std::filesystem;

ProgressiveOutcome render_progressively(Renderer& renderer, const RenderLimits& limits) {
    bool timed = limits.seconds > 0.0;
    int target = timed && !limits.samples_given ? (1 << 24) : limits.samples;
    film::ProgressOptions progress_options;
    progress_options.quiet = limits.quiet;
    const RenderSettings& settings = renderer.settings();
    film::ProgressBar progress(timed ? film::ProgressMode::Time : film::ProgressMode::Samples, timed ? limits.seconds : double(target),
                               double(settings.width) * settings.height, progress_options);
    InterruptScope interrupt_scope;
    ProgressiveOutcome outcome;
    int done = 0;
    while (done < target && !interrupt_requested()) {
        if (timed && progress.elapsed_seconds() >= limits.seconds) break;
        int n = std::min(renderer.samples_per_launch(), target - done);
        auto start = std::chrono::steady_clock::now();
        try {
            renderer.add_samples(n);
        } catch (const std::exception& e) {
            outcome.failure = e.what();
            break;
        }
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        done += n;
        progress.update(done);
        if (seconds < 0.125) renderer.set_samples_per_launch(renderer.samples_per_launch() * 2);
        if (timed) {  // do not start a launch that would end well past the time
            double per_sample = seconds / n, left = limits.seconds - progress.elapsed_seconds();
            int fit = int(left / per_sample);
            if (fit < renderer.samples_per_launch()) renderer.set_samples_per_launch(std::max(1, fit));
        }
    }
    progress.finish();
    outcome.interrupted = interrupt_requested();
    return outcome;
}

void fail_after_writing(const ProgressiveOutcome& outcome, int samples_per_pixel, const std::string& written_to) {
    if (samples_per_pixel == 0) throw std::runtime_error(outcome.failure + " (before the first sample: nothing to keep)");
    throw std::runtime_error(outcome.failure + "; the " + std::to_string(samples_per_pixel) +
                             " samples per pixel rendered before it were written to " + written_to);
}

film::ImageMetadata render_metadata(const Renderer& renderer, const RenderStatistics& stats) {
    const RenderSettings& s = renderer.settings();
    film::ImageMetadata m;
    m.set("spp", stats.samples_per_pixel);
    m.set("sample_ranges", renderer.sample_ranges().to_string());
    m.set("seconds", stats.render_seconds);
    m.set("integrator", integrator_name(s.integrator));
    m.set("light_sampling", light_sampling_name(s.light_sampling));
    m.set("light_selection", light_selection_name(renderer.light_selection()));
    m.set("max_depth", s.max_depth);
    m.set("roulette_depth", s.roulette_depth);
    if (integrator_descriptor(s.integrator).bidirectional()) {  // what only the bidirectional kernel reads
        m.set("max_vertices", bdpt_max_vertices(s));
        m.set("mis_heuristic", mis_heuristic_name(s.bdpt.mis_heuristic));
        if (s.bdpt.connection_roulette > 0.0f) m.set("connection_roulette", s.bdpt.connection_roulette);
        if (integrator_descriptor(s.integrator).light_cache) {  // the cache's sizes change its estimator's noise, not its mean
            m.set("light_paths", s.bdpt.light_paths);
            m.set("connections", s.bdpt.connections);
        }
        if (integrator_descriptor(s.integrator).merges) {  // r_0 (0: the scene's share) and its shrinking
            m.set("merge_radius", s.bdpt.merge_radius);
            m.set("merge_alpha", kMergeRadiusAlpha);
        }
        if (s.strategy_debug.strategies != 0) m.set("strategies", s.strategy_debug.strategies);  // a STRATEGY_* mask other than the integrator's own
        if (s.strategy_debug.strategy_s >= 0) {  // one strategy alone (--strategies DIR)
            m.set("strategy_s", s.strategy_debug.strategy_s);
            m.set("strategy_t", s.strategy_debug.strategy_t);
            m.set("mis_weighted", s.strategy_debug.strategy_unweighted ? 0 : 1);
        }
    }
    m.set("max_steps", s.max_steps);
    m.set("max_distance", s.max_distance);
    m.set("over_relaxation", s.over_relaxation);
    m.set("background_opacity", s.background_opacity);
    m.set("background_blur", s.background_blur_degrees);
    m.set("object_bounds", s.object_bounds ? "on" : "off");
    m.set("geometry", s.march_everything ? "march" : "auto");
    m.set("normals", normal_method_name(s.normals));
    m.set("normal_step", s.normal_step);
    m.set("seed", std::to_string(s.seed));
    m.set("device", renderer.device_description());
    m.set("nonfinite_samples", std::to_string(stats.nonfinite_samples));
    m.set("lost_rays", std::to_string(stats.lost_rays));
    return m;
}

bool is_exr_path(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    return extension == ".exr" || extension == ".EXR";
}

std::string png_beside(const std::string& exr_path) { return fs::path(exr_path).replace_extension(".png").string(); }

void check_render_output(const std::string& output) {
    film::check_output_path(output);
    if (is_exr_path(output)) film::check_output_path(png_beside(output));
}

void write_render_images(const std::string& output, const film::ImageRgb& image, film::ToneMap tone_map, float exposure_stops,
                         const film::ImageMetadata& metadata, const FilmReadback* film, const std::vector<film::ImageChannel>& aovs) {
    std::vector<film::ImageChannel> channels = film ? film_channels(*film) : std::vector<film::ImageChannel>();
    channels.insert(channels.end(), aovs.begin(), aovs.end());
    try {
        if (is_exr_path(output)) {
            film::write_exr(output, image, metadata, channels);
            film::write_png(png_beside(output), image, tone_map, exposure_stops, metadata);
        } else {
            film::write_png(output, image, tone_map, exposure_stops, metadata);
        }
    } catch (const InputError& e) {
        fs::path rescue = fs::temp_directory_path() / ("dtoadq-render-" + std::to_string(::getpid()) + ".exr");
        film::write_exr(rescue.string(), image, metadata, channels);
        throw InputError(output, "", std::string("cannot write (") + e.what() + "); the render was saved to " + rescue.string());
    }
}

void print_render_statistics(const RenderStatistics& s, bool quiet) {
    if (!quiet)
        std::printf("%d spp in %.2f s: %.3g paths/s, %.3g rays/s (%.2f rays per path)\n", s.samples_per_pixel, s.render_seconds,
                    s.paths_per_second(), s.rays_per_second(), s.paths ? double(s.rays) / double(s.paths) : 0.0);
    if (s.nonfinite_samples)
        std::fprintf(stderr, "dtoadq: warning: %llu non-finite samples (NaN or infinite) were left out of the image\n",
                     (unsigned long long)s.nonfinite_samples);
    if (s.lost_rays && !quiet)  // grazing rays; counted as escaping (or shadowed, for shadow rays)
        std::printf("%llu of %llu rays ran out of sphere-tracing steps (%.3g%%)\n", (unsigned long long)s.lost_rays,
                    (unsigned long long)s.rays, 100.0 * double(s.lost_rays) / double(s.rays));
}

}  // namespace lab::render
