// Renders that outgrow one machine (render/sample_ranges.hpp, render/film_file.hpp): parts over
// disjoint sample ranges merge into the render one run would have made, and a resumed render
// continues it bit for bit. The tolerance of a merge is the closed-form bound of float summation:
// a sum of n non-negative floats added one by one is within (n - 1) u of the exact sum, relative,
// with u = 2^-24 (Higham, Accuracy and Stability of Numerical Algorithms, section 4.2); the one run
// and the merge are two such orders, so they differ by at most 2 (n - 1) u of the sum.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "common/input_error.hpp"
#include "opencl/runtime.hpp"
#include "render/film_file.hpp"
#include "render/film_resolve.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "render/progressive.hpp"
#include "tests/render_inputs.hpp"

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

// The largest |merged - full| over the summation bound 2 (n - 1) u |full|, over every sum.
double worst_over_bound(const FilmReadback& merged, const FilmReadback& full, int n) {
    const double u = std::ldexp(1.0, -24);
    double worst = 0.0;
    for (size_t i = 0; i < full.accumulation.size(); ++i) {
        if (i % 4 == 3) continue;  // the non-finite counts are integers: compared exactly elsewhere
        double bound = 2.0 * (n - 1) * u * std::fabs(double(full.accumulation[i])) + 1e-30;
        worst = std::max(worst, std::fabs(double(merged.accumulation[i]) - double(full.accumulation[i])) / bound);
    }
    return worst;
}

// Renders the full range [0, 8) in one run, and the parts [0, 2) and [2, 8), on fresh renderers
// made by `make`; checks merge and resume.
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

    FilmFile merged = lab::render::merge_film_files({part_of(*first, "first.exr"), part_of(*second, "second.exr")});
    CHECK(merged.ranges.to_string() == "0:8");
    FilmReadback f = full->film();
    INFO("worst |merged - full| over the float-summation bound: " << worst_over_bound(merged.film, f, n));
    CHECK(worst_over_bound(merged.film, f, n) <= 1.0);
    for (size_t i = 3; i < f.accumulation.size(); i += 4) CHECK(merged.film.accumulation[i] == f.accumulation[i]);

    // The check has power: averaging the two parts' images (a merge that forgets they hold 2 and 6
    // samples) is far outside the bound.
    lab::film::ImageRgb a = first->image(), b = second->image(), one = full->image();
    double worst_naive = 0.0;
    for (size_t i = 0; i < one.rgb.size(); ++i)
        worst_naive = std::max(worst_naive, std::fabs(0.5 * (double(a.rgb[i]) + double(b.rgb[i])) - double(one.rgb[i])) /
                                                (2.0 * (n - 1) * std::ldexp(1.0, -24) * std::fabs(double(one.rgb[i])) + 1e-30));
    CHECK(worst_naive > 1e3);

    // Resumed from the first part's film: the very same bits as one run.
    auto resumed = make();
    resumed->restore_film(first->film(), first->sample_ranges());
    CHECK(resumed->statistics().samples_per_pixel == 2);
    render_samples(*resumed, 6);
    CHECK(resumed->sample_ranges().to_string() == "0:8");
    CHECK(resumed->statistics().samples_per_pixel == n);
    CHECK(same_bits(resumed->film().accumulation, f.accumulation));
    CHECK(same_bits(resumed->image().rgb, one.rgb));
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
