// Fuzzes the command line's size and option parsers: the input, split at newlines, is the argument
// list of an app with every option of `preview` (CLI11 and the lab's own checks), and each line is
// also given to the size, angle-pair, light-sampling, light-selection, integrator, normals and
// tone-map parsers. Invariants: each is refused with an error of its kind or accepted; an accepted
// size lies in 1 .. 16384 a side and reads back the same from "WxH"; an accepted angle pair is
// finite with theta in [0, 180]; an accepted word parses to a value whose name parses back to it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/options.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "film/tone_map.hpp"
#include "fuzz/fuzz_check.hpp"
#include "render/light_set.hpp"
#include "render/render_settings.hpp"

namespace {

void check_size(const std::string& text) {
    int width = 0, height = 0;
    try {
        lab::render::parse_image_size(text, "--size", &width, &height);
    } catch (const lab::InputError&) {
        return;
    }
    FUZZ_REQUIRE(width >= 1 && height >= 1 && width <= lab::render::kMaxImageSide && height <= lab::render::kMaxImageSide,
                 "an accepted size is outside 1 .. 16384");
    int w2 = 0, h2 = 0;
    lab::render::parse_image_size(std::to_string(width) + "x" + std::to_string(height), "--size", &w2, &h2);
    FUZZ_REQUIRE(w2 == width && h2 == height, "an accepted size does not read back the same");
}

void check_angles(const std::string& text) {
    float theta = -1.0f, phi = 0.0f;
    try {
        lab::cli::parse_angle_pair(text, "--wi", &theta, &phi);
    } catch (const lab::InputError&) {
        return;
    }
    FUZZ_REQUIRE(std::isfinite(theta) && std::isfinite(phi) && theta >= 0.0f && theta <= 180.0f, "an accepted angle pair is out of range");
}

// A word accepted by `parse` names a value whose name `parse` maps back to the same value
// (synonyms such as "brdf" for "bsdf" are accepted, and named by their first word).
template <typename Parse, typename Name>
void check_word(const std::string& text, Parse parse, Name name, const char* what) {
    try {
        auto value = parse(text);
        FUZZ_REQUIRE(parse(std::string(name(value))) == value, what);
    } catch (const lab::InputError&) {
    }
}

void check_words(const std::string& text) {
    if (text.size() > 16) return;  // no word is longer; refusing longer text is a plain comparison
    using namespace lab::render;
    check_word(text, [](const std::string& t) { return parse_light_sampling(t, "--light-sampling"); }, light_sampling_name,
               "a light-sampling word's name parses to another value");
    check_word(text, [](const std::string& t) { return parse_light_selection(t); }, light_selection_name,
               "a light-selection word's name parses to another value");
    check_word(text, [](const std::string& t) { return parse_integrator(t); }, integrator_name, "an integrator's name parses to another value");
    check_word(text, [](const std::string& t) { return parse_normal_method(t); }, normal_method_name,
               "a normals word's name parses to another value");
    check_word(text, [](const std::string& t) { return lab::film::parse_tone_map(t); }, lab::film::tone_map_name,
               "a tone map's name parses to another value");
}

// The preview's options through CLI11, then the checks `prepare_render_job` makes before it loads
// anything (checked_render_settings: the size, the words, the settings' ranges). The app is built
// once and cleared between inputs (building it is most of the cost); the options it fills are
// reset to their defaults.
void check_command_line(std::vector<std::string> args) {
    static lab::cli::RenderJobOptions options;
    static int spp = 64;
    static double seconds = 0.0;
    static CLI::App& app = [] () -> CLI::App& {
        static CLI::App a{"fuzz"};
        lab::cli::add_preview_options(a, &options);
        lab::cli::add_render_options(a, &options);
        a.add_option("--spp", spp);
        a.add_option("--time", seconds);
        return a;
    }();
    app.clear();
    options = lab::cli::RenderJobOptions{};
    options.light_sampling_option = "--ibl-sampling";  // as add_preview_options sets it
    spp = 64;
    seconds = 0.0;
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments back to front
    try {
        app.parse(args);
    } catch (const CLI::ParseError&) {
        return;
    }
    lab::render::RenderSettings settings;
    try {
        lab::render::LightSelection selection;
        settings = lab::cli::checked_render_settings(options, &selection);
    } catch (const lab::InputError&) {
        return;
    }
    FUZZ_REQUIRE(settings.over_relaxation >= 1.0f && settings.over_relaxation <= 2.0f, "an accepted over-relaxation is outside [1, 2]");
    FUZZ_REQUIRE(settings.max_depth >= 0 && settings.max_depth <= 1024 && settings.max_steps >= 1, "an accepted depth or step count is out of range");
    FUZZ_REQUIRE(settings.width >= 1 && settings.height >= 1 && settings.width <= lab::render::kMaxImageSide, "an accepted size is out of range");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> lines;
    size_t start = 0;
    while (start <= text.size() && lines.size() < 16) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    for (const std::string& line : lines) {
        check_size(line);
        check_angles(line);
        check_words(line);
    }
    check_command_line(lines);
    return 0;
}
