// Renders that outgrow one machine (render/sample_ranges.hpp, render/film_file.hpp): parts over
// disjoint sample ranges merge into the render one run would have made, and a resumed render
// continues it (its own-pixel sums bit for bit). The tolerance of a merge is the closed-form bound
// of float summation: n non-negative floats summed in any order (one by one, or as sums of parts
// added together) come within gamma(n - 1) = (n - 1) u / (1 - (n - 1) u) of the exact sum s,
// relative, with u = 2^-24 (Higham, Accuracy and Stability of Numerical Algorithms, section 4.2);
// the one run and the merge are two such orders, so they differ by at most 2 gamma(n - 1) s.
//
// What n is, counted from the render's settings and never from its output:
// - film.sum: a pixel's own samples, one term each, added by its work-item in sample order (a
//   sample's strategies are summed before it is added): n = samples per pixel.
// - film.splat (bdpt, lt, bdpt-cache): t = 1 connections, added by float atomics in the order they
//   arrive from every work-item. A light subpath makes at most one per vertex, max_vertices - 1, and
//   each may land on any pixel, so a pixel's splat is a sum of at most
//   light subpaths per sample x samples x (max_vertices - 1) terms, the light subpaths per sample
//   one per pixel for bdpt and lt, the cache's N_L for bdpt-cache (a loose count, but one that
//   holds for every pixel whatever the arrival order). Every term is radiance, non-negative. The path tracer
//   splats nothing: n = 0, and the splats must be equal.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "common/input_error.hpp"
#include "render/light_cache.hpp"
#include "opencl/runtime.hpp"
#include "render/film_file.hpp"
#include "render/film_resolve.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "render/progressive.hpp"
#include "render/vcm.hpp"
#include "scene/load_scene.hpp"
#include "tests/render_inputs.hpp"
#include "tests/worst_difference.hpp"

namespace fs = std::filesystem;
using lab::render::FilmFile;
using lab::render::FilmReadback;
using lab::render::SampleRanges;

namespace {

// A diffuse ball over a floor, lit by a sphere light and the sky: every pixel is noisy.
const char* kScene = R"({
  "camera": {"type": "pinhole", "position": [0, 1.0, 3.5], "look_at": [0, 0.4, 0], "fov_degrees": 45},
  "materials": {
    "floor": {"albedo": [0.6, 0.6, 0.6], "lobes": {"diffuse": 1}},
    "ball": {"albedo": [0.7, 0.3, 0.2], "roughness": 0.3, "lobes": {"diffuse": 0.7, "glossy": 0.3}}
  },
  "objects": [
    {"name": "floor", "material": "floor", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}},
    {"name": "ball", "material": "ball", "shape": {"type": "translate", "offset": [0, 0.5, 0], "child": {"type": "sphere", "radius": 0.5}}}
  ],
  "emitters": [{"center": [0.8, 2.0, 0.8], "radius": 0.3, "radiance": [6, 6, 5]}]
})";

lab::render::RenderInput split_input() {
    return render_input(std::nullopt, "constant:0.3,0.35,0.4", 10, lab::render::LightSampling::mis, 11, kScene);
}

FilmFile part_of(lab::render::Renderer& r, const std::string& name) {
    FilmFile f;
    f.path = name;
    f.width = r.settings().width;
    f.height = r.settings().height;
    f.film = r.film();
    f.ranges = r.sample_ranges();
    f.metadata.set("seed", "11");
    f.metadata.set("spp", int(f.ranges.count()));
    return f;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// 2 gamma(n - 1) s, the most by which two summation orders of n non-negative terms can differ,
// with s the exact sum; `sum` is one order's float result, within gamma(n - 1) of s.
double summation_bound(double terms, double sum) {
    if (terms <= 1.0) return 0.0;  // one term or none: no rounding
    const double nu = (terms - 1.0) * std::ldexp(1.0, -24), gamma = nu / (1.0 - nu);
    return 2.0 * gamma * std::fabs(sum) / (1.0 - gamma);
}

// The terms in each pixel's sums of `full` (see the top of the file).
struct SumTerms {
    double own = 0.0, splat = 0.0;
};

SumTerms sum_terms(const lab::render::RenderSettings& s, int samples) {
    SumTerms terms;
    terms.own = samples;
    const lab::render::IntegratorDescriptor& integrator = lab::render::integrator_descriptor(s.integrator);
    const double light_paths = integrator.light_cache ? double(lab::render::light_cache_paths(s)) : double(s.width) * s.height;
    if (integrator.splats()) terms.splat = light_paths * samples * (lab::render::bdpt_max_vertices(s) - 1);
    return terms;
}

// The largest |a - b| over the bound `terms` allows, over every value: 0 when equal, above 1 outside
// the bound. `stride` > 0 skips every stride-th value from `skip` on (the non-finite counts).
double worst_over_bound(const std::vector<float>& a, const std::vector<float>& b, double terms, size_t stride = 0, size_t skip = 0) {
    double worst = 0.0;
    for (size_t i = 0; i < b.size(); ++i) {
        if (stride > 0 && i % stride == skip) continue;
        double difference = std::fabs(double(a[i]) - double(b[i]));
        if (difference == 0.0) continue;
        double bound = summation_bound(terms, b[i]);
        worst = worse_of(worst, bound > 0.0 ? difference / bound : HUGE_VAL);
    }
    return worst;
}

// The same for two images resolved from films that differ within those bounds: a pixel is
// sum / finite + splat / samples (render/film_resolve.cpp, in double), rounded once to float in
// each image, so the images differ by at most the sums' bounds over their divisors plus 2 u of the
// pixel; 3 u leaves room for the rounding of the double arithmetic (under 2^-50, relative).
double worst_image_over_bound(const lab::film::ImageRgb& a, const lab::film::ImageRgb& b, const FilmReadback& film, SumTerms terms, int samples) {
    const double u = std::ldexp(1.0, -24);
    double worst = 0.0;
    for (size_t p = 0; p < b.pixel_count(); ++p) {
        double finite = samples - double(film.accumulation[4 * p + 3]);
        for (size_t c = 0; c < 3; ++c) {
            double difference = std::fabs(double(a.rgb[3 * p + c]) - double(b.rgb[3 * p + c]));
            if (difference == 0.0) continue;
            double bound = summation_bound(terms.own, film.accumulation[4 * p + c]) / finite +
                           summation_bound(terms.splat, film.splat[3 * p + c]) / samples + 3.0 * u * std::fabs(double(b.rgb[3 * p + c]));
            worst = worse_of(worst, bound > 0.0 ? difference / bound : HUGE_VAL);
        }
    }
    return worst;
}

// Renders the full range [0, 8) in one run, and the parts [0, 2) and [2, 8), on fresh renderers
// made by `make`; checks merge and resume: the film's sums and splats and the image.
template <class MakeRenderer>
void check_split_and_resume(MakeRenderer make) {
    const int n = 8;
    auto full = make();
    render_samples(*full, n);
    auto first = make();
    first->set_first_sample(0);
    render_samples(*first, 2);
    auto second = make();
    second->set_first_sample(2);
    render_samples(*second, 6);
    CHECK(second->sample_ranges().to_string() == "2:8");
    const SumTerms terms = sum_terms(full->settings(), n);
    const bool splats = terms.splat > 0.0;

    FilmFile merged = lab::render::merge_film_files({part_of(*first, "first.exr"), part_of(*second, "second.exr")});
    CHECK(merged.ranges.to_string() == "0:8");
    FilmReadback f = full->film();
    lab::film::ImageRgb one = full->image();
    lab::film::ImageRgb merged_image = lab::render::resolve_film(merged.film, n, merged.width, merged.height);
    INFO("worst |merged - full| over the float-summation bound: film.sum "
         << worst_over_bound(merged.film.accumulation, f.accumulation, terms.own, 4, 3) << ", film.splat "
         << worst_over_bound(merged.film.splat, f.splat, terms.splat) << ", image "
         << worst_image_over_bound(merged_image, one, f, terms, n));
    CHECK(worst_over_bound(merged.film.accumulation, f.accumulation, terms.own, 4, 3) <= 1.0);
    for (size_t i = 3; i < f.accumulation.size(); i += 4) CHECK(merged.film.accumulation[i] == f.accumulation[i]);
    CHECK(worst_over_bound(merged.film.splat, f.splat, terms.splat) <= 1.0);
    CHECK(worst_image_over_bound(merged_image, one, f, terms, n) <= 1.0);

    // The checks have power: averaging the two parts' images (a merge that forgets they hold 2 and 6
    // samples) is far outside the bound, and so is a merge that keeps the first part's splats alone.
    lab::film::ImageRgb a = first->image(), b = second->image(), averaged(one.width, one.height);
    for (size_t i = 0; i < one.rgb.size(); ++i) averaged.rgb[i] = 0.5f * (a.rgb[i] + b.rgb[i]);
    CHECK(worst_image_over_bound(averaged, one, f, terms, n) > 10.0);
    if (splats) {
        CHECK(std::any_of(f.splat.begin(), f.splat.end(), [](float v) { return v > 0.0f; }));
        FilmReadback first_splats_only = merged.film;
        first_splats_only.splat = first->film().splat;
        CHECK(worst_over_bound(first_splats_only.splat, f.splat, terms.splat) > 10.0);
        lab::film::ImageRgb without = lab::render::resolve_film(first_splats_only, n, merged.width, merged.height);
        CHECK(worst_image_over_bound(without, one, f, terms, n) > 10.0);
    }

    // Resumed from the first part's film: the own-pixel sums are the very same bits as one run; the
    // splats (and so the image) within the bound when there are any, else the same bits.
    auto resumed = make();
    resumed->restore_film(first->film(), first->sample_ranges());
    CHECK(resumed->statistics().samples_per_pixel == 2);
    render_samples(*resumed, 6);
    CHECK(resumed->sample_ranges().to_string() == "0:8");
    CHECK(resumed->statistics().samples_per_pixel == n);
    CHECK(same_bits(resumed->film().accumulation, f.accumulation));
    CHECK(worst_over_bound(resumed->film().splat, f.splat, terms.splat) <= 1.0);
    if (splats) CHECK(worst_image_over_bound(resumed->image(), one, f, terms, n) <= 1.0);
    else CHECK(same_bits(resumed->image().rgb, one.rgb));
}

// The Cornell box at 16 x 16 (a sphere light, no environment) for the bidirectional integrators,
// paths of up to 8 vertices (6 scattering events).
lab::render::RenderInput bidirectional_input(lab::render::Integrator integrator) {
    lab::render::RenderInput input;
    input.scene = lab::scene::load_scene("scenes/cornell_box.json");
    input.settings.width = input.settings.height = 16;
    input.settings.integrator = integrator;
    input.settings.max_depth = 6;
    input.settings.seed = 11;
    // vcm: a radius whose merges find light vertices among the 64 light subpaths of a 16 x 16 sample
    if (integrator == lab::render::Integrator::vcm) input.settings.bdpt.merge_radius = 0.2f;
    return input;
}

fs::path temp_file(const std::string& name) { return fs::temp_directory_path() / ("dtoadq-test-" + std::to_string(::getpid()) + "-" + name); }

}  // namespace

TEST_CASE("Sample ranges: parsed, joined and checked for overlap", "[render][sample-ranges]") {
    SampleRanges r = SampleRanges::parse_range("4:12", "--samples");
    CHECK(r.count() == 8);
    CHECK(r.end() == 12);
    CHECK(r.joined(SampleRanges(0, 4)).to_string() == "0:12");  // adjacent ranges join
    CHECK(r.joined(SampleRanges(20, 24)).to_string() == "4:12,20:24");
    CHECK(r.overlaps(SampleRanges(11, 13)));
    CHECK_FALSE(r.overlaps(SampleRanges(12, 13)));
    CHECK(SampleRanges::parse("0:4,8:12", "f.exr", "dtoadq:sample_ranges").to_string() == "0:4,8:12");
    for (const char* bad : {"12:4", "4:4", "4", "a:b", "-1:3", "0:2147483648", "0:4:8", ""})
        CHECK_THROWS_AS(SampleRanges::parse_range(bad, "--samples"), lab::InputError);
    CHECK_THROWS_WITH(SampleRanges::parse("0:8,4:12", "f.exr", "dtoadq:sample_ranges"), Catch::Contains("overlapping"));
}

TEST_CASE("Film file: the film's buffers go through the EXR bit for bit, and a plain EXR is refused by name", "[render][film-file]") {
    FilmReadback film;
    film.accumulation = {1.5f, 2.25f, 1e-40f, 0.0f, 3e38f, 0.1f, 0.2f, 2.0f};  // a denormal, a huge sum, a non-finite count
    film.splat = {0.125f, 0.0f, 7.0f, 1e-7f, 5.0f, 6.0f};
    film.squares = {2.5f, 1e-38f, 3e38f, 0.0f, 0.5f, 9.0f, 1e-20f, 0.0f};
    lab::film::ImageRgb image = lab::render::resolve_film(film, 4, 2, 1);
    lab::film::ImageMetadata m;
    m.set("sample_ranges", "0:2,6:8");
    m.set("seed", "3");
    fs::path path = temp_file("film.exr");
    lab::render::write_render_images(path.string(), image, lab::film::ToneMap::Aces, 0.0f, m, &film);
    FilmFile back = lab::render::read_film_file(path.string());
    CHECK(back.width == 2);
    CHECK(back.height == 1);
    CHECK(same_bits(back.film.accumulation, film.accumulation));
    CHECK(same_bits(back.film.splat, film.splat));
    CHECK(same_bits(back.film.squares, film.squares));
    CHECK(back.ranges.to_string() == "0:2,6:8");

    fs::path plain = temp_file("plain.exr");
    lab::film::write_exr(plain.string(), image, m);
    CHECK_THROWS_WITH(lab::render::read_film_file(plain.string()), Catch::Contains(plain.string()) && Catch::Contains("film.sum.R"));
    for (const fs::path& p : {path, plain, fs::path(lab::render::png_beside(path.string()))}) fs::remove(p);
}

TEST_CASE("Merge: a part of another render, or samples held twice, is refused naming the file and the field", "[render][film-file]") {
    FilmFile a, b;
    a.path = "a.exr";
    b.path = "b.exr";
    a.width = b.width = 1;
    a.height = b.height = 1;
    a.film.accumulation = b.film.accumulation = {1, 1, 1, 0};
    a.film.splat = b.film.splat = {0, 0, 0};
    a.film.squares = b.film.squares = {1, 1, 1, 0};
    a.ranges = SampleRanges(0, 4);
    b.ranges = SampleRanges(4, 8);
    a.metadata.set("seed", "1");
    b.metadata.set("seed", "1");
    a.metadata.set("device", "cpu");
    b.metadata.set("device", "gpu");  // differs between parts: fine
    CHECK(lab::render::merge_film_files({a, b}).ranges.to_string() == "0:8");
    FilmFile twice = b;
    twice.ranges = SampleRanges(2, 6);
    CHECK_THROWS_WITH(lab::render::merge_film_files({a, twice}), Catch::StartsWith("b.exr: dtoadq:sample_ranges") && Catch::Contains("twice"));
    FilmFile other_seed = b;
    other_seed.metadata.set("seed", "2");
    CHECK_THROWS_WITH(lab::render::merge_film_files({a, other_seed}), Catch::StartsWith("b.exr: dtoadq:seed"));
    FilmFile other_size = b;
    other_size.width = 2;
    CHECK_THROWS_WITH(lab::render::merge_film_files({a, other_size}), Catch::StartsWith("b.exr: size"));
}

TEST_CASE("Sample ranges on the host build: merged parts equal one run to float rounding, a resumed run is bit-identical",
          "[render][sample-ranges][host]") {
    check_split_and_resume([] { return std::make_unique<lab::render::HostRenderer>(split_input(), 2); });
}

TEST_CASE("Sample ranges on the OpenCL device: merged parts equal one run to float rounding, a resumed run is bit-identical",
          "[render][sample-ranges][opencl]") {
    lab::opencl::Runtime runtime("");
    check_split_and_resume([&] { return std::make_unique<lab::render::OpenClRenderer>(runtime, split_input()); });
}

TEST_CASE("Sample ranges with BDPT and light tracing on the host build: merged parts equal one run to float rounding, splats included",
          "[render][sample-ranges][bdpt][host]") {
    for (lab::render::Integrator integrator :
         {lab::render::Integrator::bdpt, lab::render::Integrator::lt, lab::render::Integrator::bdpt_cache, lab::render::Integrator::vcm}) {
        INFO(lab::render::integrator_name(integrator));
        check_split_and_resume([&] { return std::make_unique<lab::render::HostRenderer>(bidirectional_input(integrator), 2); });
    }
}

TEST_CASE("Sample ranges with BDPT and light tracing on the OpenCL device: merged parts equal one run to float rounding, splats included",
          "[render][sample-ranges][bdpt][opencl]") {
    lab::opencl::Runtime runtime("");
    for (lab::render::Integrator integrator :
         {lab::render::Integrator::bdpt, lab::render::Integrator::lt, lab::render::Integrator::bdpt_cache, lab::render::Integrator::vcm}) {
        INFO(lab::render::integrator_name(integrator));
        check_split_and_resume([&] { return std::make_unique<lab::render::OpenClRenderer>(runtime, bidirectional_input(integrator)); });
    }
}

TEST_CASE("Render metadata: BDPT's vertex limit, MIS heuristic and strategies are written, and a part that differs in them is refused",
          "[render][film-file][bdpt]") {
    using lab::render::Integrator;
    auto metadata_of = [](const lab::render::RenderInput& input) {
        lab::render::HostRenderer renderer(input, 1);
        return lab::render::render_metadata(renderer, renderer.statistics());
    };
    auto text = [](const lab::film::ImageMetadata& m, const std::string& key) {
        REQUIRE(m.find(key) != nullptr);
        return lab::film::metadata_text(*m.find(key));
    };
    lab::render::RenderInput input = bidirectional_input(Integrator::bdpt);
    const lab::film::ImageMetadata bdpt = metadata_of(input);
    CHECK(text(bdpt, "integrator") == "bdpt");
    CHECK(text(bdpt, "mis_heuristic") == "balance");
    CHECK(text(bdpt, "max_vertices") == std::to_string(lab::render::bdpt_max_vertices(input.settings)));
    CHECK(bdpt.find("strategy_s") == nullptr);  // every strategy of the integrator
    input.settings.bdpt.mis_heuristic = lab::render::MisHeuristic::power;
    CHECK(text(metadata_of(input), "mis_heuristic") == "power");
    input.settings.strategy_debug.strategy_s = 2;
    input.settings.strategy_debug.strategy_t = 1;
    input.settings.strategy_debug.strategy_unweighted = true;
    const lab::film::ImageMetadata one_strategy = metadata_of(input);
    CHECK(text(one_strategy, "strategy_s") == "2");
    CHECK(text(one_strategy, "strategy_t") == "1");
    CHECK(text(one_strategy, "mis_weighted") == "0");
    CHECK(metadata_of(bidirectional_input(Integrator::pt)).find("mis_heuristic") == nullptr);  // the path tracer has none
    CHECK(bdpt.find("light_paths") == nullptr);  // the light-vertex cache's alone
    lab::render::RenderInput cache_input = bidirectional_input(Integrator::bdpt_cache);
    cache_input.settings.bdpt.light_paths = 0.5f;
    cache_input.settings.bdpt.connections = 3;
    const lab::film::ImageMetadata cache = metadata_of(cache_input);
    CHECK(text(cache, "light_paths") == lab::film::metadata_text(lab::film::MetadataValue(0.5f)));
    CHECK(text(cache, "connections") == "3");

    // merge and --resume compare every field but those that differ between parts of one render
    FilmFile part;
    part.path = "b.exr";
    part.width = part.height = 16;
    for (const auto& [key, value] : std::vector<std::pair<std::string, lab::film::MetadataValue>>{
             {"integrator", std::string("lt")}, {"mis_heuristic", std::string("power")}, {"max_vertices", 6},
             {"max_depth", 4}, {"strategies", 3}, {"strategy_s", 2}, {"mis_weighted", 0}}) {
        INFO(key);
        part.metadata = bdpt;
        part.metadata.values[key] = value;
        CHECK_THROWS_WITH(lab::render::check_same_render("a.exr", bdpt, 16, 16, part), Catch::StartsWith("b.exr: dtoadq:" + key + ": "));
    }
    for (const auto& [key, value] : std::vector<std::pair<std::string, lab::film::MetadataValue>>{{"light_paths", 2.0f}, {"connections", 1}}) {
        INFO(key);
        part.metadata = cache;
        part.metadata.values[key] = value;
        CHECK_THROWS_WITH(lab::render::check_same_render("a.exr", cache, 16, 16, part), Catch::StartsWith("b.exr: dtoadq:" + key + ": "));
    }
    part.metadata = bdpt;
    part.metadata.set("seconds", 99.0f);  // differs between parts: fine
    CHECK_NOTHROW(lab::render::check_same_render("a.exr", bdpt, 16, 16, part));
    // a film written before scene time (no scene_time) is a part of a render at time 0, not of one at 0.5
    lab::film::ImageMetadata at_zero = bdpt, later = bdpt;
    at_zero.set("scene_time", "0");
    later.set("scene_time", "0.5");
    part.metadata = bdpt;
    REQUIRE(part.metadata.find("scene_time") == nullptr);
    CHECK_NOTHROW(lab::render::check_same_render("a.exr", at_zero, 16, 16, part));
    CHECK_THROWS_WITH(lab::render::check_same_render("a.exr", later, 16, 16, part), Catch::StartsWith("b.exr: dtoadq:scene_time: \"0\", but"));
    // vcm: its first radius (0: the scene's share) and the radius's shrinking
    CHECK(cache.find("merge_radius") == nullptr);
    const lab::film::ImageMetadata vcm = metadata_of(bidirectional_input(Integrator::vcm));
    CHECK(text(vcm, "merge_radius") == lab::film::metadata_text(lab::film::MetadataValue(0.2f)));
    CHECK(text(vcm, "merge_alpha") == lab::film::metadata_text(lab::film::MetadataValue(lab::render::kMergeRadiusAlpha)));
    for (const char* key : {"merge_radius", "merge_alpha"}) {
        INFO(key);
        part.metadata = vcm;
        part.metadata.values[key] = 0.5f;
        CHECK_THROWS_WITH(lab::render::check_same_render("a.exr", vcm, 16, 16, part), Catch::StartsWith(std::string("b.exr: dtoadq:") + key + ": "));
    }
}
