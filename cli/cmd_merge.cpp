// dtoadq merge: parts of one render over disjoint sample ranges (render --samples A:B, on one
// machine or many) combined into the render one run over all their samples would have made: the
// films' sums are added and resolved once (render/film_file.hpp). The result is itself a part that
// can be merged further or resumed.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "common/input_error.hpp"
#include "film/tone_map.hpp"
#include "render/film_file.hpp"
#include "render/film_resolve.hpp"
#include "render/progressive.hpp"

namespace lab::cli {

namespace {

struct MergeOptions {
    std::vector<std::string> parts;
    std::string output;
    std::string tone_map = "aces";
    float exposure = 0.0f;
    bool quiet = false;
};

void run_merge(const MergeOptions& o) {
    if (!render::is_exr_path(o.output)) throw InputError(o.output, "", "merge writes an .exr (with its film, and the PNG beside it)");
    render::check_render_output(o.output);
    film::ToneMap tone_map = film::parse_tone_map(o.tone_map);
    if (!(o.exposure >= -64.0f && o.exposure <= 64.0f)) throw InputError("--exposure", "", "must be a number of stops in [-64, 64]");
    std::vector<render::FilmFile> parts;
    for (const std::string& path : o.parts) parts.push_back(render::read_film_file(path));
    render::FilmFile merged = render::merge_film_files(parts);
    merged.metadata.set("tonemap", o.tone_map);
    merged.metadata.set("exposure", o.exposure);
    int spp = int(merged.ranges.count());
    film::ImageRgb image = render::resolve_film(merged.film, spp, merged.width, merged.height);
    render::write_render_images(o.output, image, tone_map, o.exposure, merged.metadata, &merged.film);
    if (!o.quiet)
        std::printf("merged %zu parts (samples %s, %d per pixel) into %s and %s\n", parts.size(), merged.ranges.to_string().c_str(), spp,
                    o.output.c_str(), render::png_beside(o.output).c_str());
}

}  // namespace

void register_merge(CLI::App& app) {
    auto o = std::make_shared<MergeOptions>();
    auto* cmd = app.add_subcommand("merge", "Combine parts of one render over disjoint sample ranges (render --samples A:B) into one");
    cmd->add_option("parts", o->parts, "The parts: EXR files written by dtoadq render or preview")->required()->expected(1, -1);
    cmd->add_option("-o,--output", o->output, "The merged render (.exr, with the PNG beside it)")->required();
    cmd->add_option("--tonemap", o->tone_map, "Tone map of the PNG: aces, reinhard or clamp")->capture_default_str();
    cmd->add_option("--exposure", o->exposure, "Exposure of the PNG in stops")->capture_default_str();
    cmd->add_flag("--quiet", o->quiet, "Print nothing on success");
    cmd->callback([o] { run_merge(*o); });
}

}  // namespace lab::cli
