// dtoadq convert: a material from one format into another (docs/interchange.md): a lab preset
// (.json, openpbr), MaterialX (.mtlx) or glTF 2.0 (.gltf) in; any of them, Mitsuba 3 (.xml) or
// pbrt-v4 (.pbrt) out, chosen by the output's extension or --to. Every parameter or element the
// conversion could not carry exactly is printed as one note on stderr.
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "fit/fit_optimizer.hpp"
#include "interchange/export_material.hpp"
#include "interchange/formats.hpp"

namespace lab::cli {

namespace {

struct ConvertOptions {
    std::string input;
    std::string output;
    std::string to;
    std::string material;
    int fit_starts = 8;
    int fit_evaluations = 3000;
    bool quiet = false;
};

void print_notes(const std::string& file, const interchange::Notes& notes) {
    for (const interchange::Note& n : notes.items)
        std::fprintf(stderr, "dtoadq: note: %s\n", interchange::note_line(file, n).c_str());
}

void run_convert(const ConvertOptions& o) {
    lab::fit::FitOptions options;
    options.starts = o.fit_starts;
    options.max_evaluations = o.fit_evaluations;
    lab::fit::check_fit_options(options, "--fit-starts", "--fit-evaluations");
    const interchange::Format from = interchange::format_of_file(o.input);
    const interchange::Format to = o.to.empty() ? interchange::format_of_file(o.output) : interchange::format_named(o.to, "command line", "--to");
    const interchange::Imported imported = interchange::read_material(o.input, from, o.material);
    print_notes(o.input, imported.notes);
    const interchange::Notes written = interchange::export_material(imported.preset, to, o.output, options);
    print_notes(o.output, written);
    if (!o.quiet)
        std::printf("converted %s (%s) to %s (%s): %zu note(s)\n", o.input.c_str(), interchange::format_name(from), o.output.c_str(),
                    interchange::format_name(to), imported.notes.items.size() + written.items.size());
}

}  // namespace

void register_convert(CLI::App& app) {
    auto o = std::make_shared<ConvertOptions>();
    auto* cmd = app.add_subcommand("convert", "Convert a material between a lab preset (.json), MaterialX (.mtlx) and glTF 2.0 (.gltf); write it for Mitsuba 3 (.xml) and pbrt-v4 (.pbrt)");
    cmd->add_option("input", o->input, "The material: a preset (.json; a lab, dtoadq2017 or measured one is fitted to openpbr first), a MaterialX document (.mtlx) or a glTF 2.0 file (.gltf)")->required();
    cmd->add_option("-o,--output", o->output, "The converted material; its extension chooses the format unless --to does")->required();
    cmd->add_option("--material", o->material, "Which of the document's materials: a <surfacematerial>'s name, or a glTF material's name or index (default: the first)");
    cmd->add_option("--to", o->to, "The output's format: mtlx, gltf, mitsuba (.xml), pbrt or preset");
    cmd->add_option("--fit-starts", o->fit_starts, "A lab or measured material is fitted to openpbr first: starts of the search (as dtoadq fit)")->capture_default_str();
    cmd->add_option("--fit-evaluations", o->fit_evaluations, "... and evaluations per start")->capture_default_str();
    cmd->add_flag("--quiet", o->quiet, "Print nothing but the notes on success");
    cmd->callback([o] { run_convert(*o); });
}

}  // namespace lab::cli
