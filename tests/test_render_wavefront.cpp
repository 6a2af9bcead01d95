// The path tracer's CPU wavefront (kernels/path_tracer_wavefront.h) keeps several samples of every
// pixel in flight on small images (RenderSettings::wavefront_paths) and adds each pixel's paths to
// the film in sample order afterwards (render_pt_resolve). Whatever the number in flight, and with
// the image split into parts (one sample in flight there), the film must hold the bits of the
// work-item kernel, which traces each pixel's samples one after the other in one work-item, and the
// same ray counts. Checked once by hand: a resolve that adds the slots last to first fails the film
// of every case with more than one sample in flight (6 of the 30 checks), and paths that all draw
// the launch's first sample fail 17.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/render_inputs.hpp"

namespace {

struct InFlightFilm {
    lab::render::FilmReadback film;
    uint64_t rays = 0, lost = 0;
};

// `spp` samples in launches of `per_launch` samples (in parts of `part_pixels` pixels, 0: whole).
InFlightFilm render_in_flight(const lab::opencl::Runtime& runtime, lab::render::RenderInput input, bool packets, int wavefront_paths, int spp, int per_launch,
            int part_pixels) {
    input.settings.packets = packets;
    input.settings.wavefront_paths = wavefront_paths;
    lab::render::OpenClRenderer renderer(runtime, input);
    renderer.set_samples_per_launch(per_launch);
    if (part_pixels > 0) renderer.set_launch_pixels(part_pixels);
    renderer.add_samples(spp);
    InFlightFilm f;
    f.film = renderer.film();
    const lab::render::RenderStatistics stats = renderer.statistics();
    f.rays = stats.rays;
    f.lost = stats.lost_rays;
    return f;
}

bool same_film_bits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("Wavefront: any number of samples in flight gives the work-item kernel's film bits and ray counts",
          "[render][wavefront][opencl]") {
    lab::opencl::Runtime runtime("");
    if (runtime.device().type != "cpu") {
        WARN("the wavefront runs on CPU devices only");
        return;
    }
    struct Scene {
        const char* what;
        lab::render::RenderInput input;
    };
    Scene scenes[] = {{"test model under courtyard", render_input(std::nullopt, "envmaps/courtyard.exr", 20, lab::render::LightSampling::mis, 5)},
                      {"Cornell box", lab::render::RenderInput{}}};
    scenes[1].input.scene = lab::scene::load_scene("scenes/cornell_box.json");
    scenes[1].input.settings.width = 24;
    scenes[1].input.settings.height = 18;
    for (Scene& s : scenes) {
        const int pixels = s.input.settings.width * s.input.settings.height;
        const InFlightFilm reference = render_in_flight(runtime, s.input, false, 0, 7, 7, 0);
        struct Case {
            const char* what;
            int wavefront_paths, per_launch, part_pixels;
        } cases[] = {{"one sample in flight", 1, 7, 0},
                     {"three in flight (launches of 3, 3, 1)", 3 * pixels, 7, 0},
                     {"all seven in flight", 0, 7, 0},
                     {"launches of two samples, two in flight", 0, 2, 0},
                     {"parts of 128 pixels", 0, 7, 128}};
        for (const Case& c : cases) {
            const InFlightFilm f = render_in_flight(runtime, s.input, true, c.wavefront_paths, 7, c.per_launch, c.part_pixels);
            INFO(s.what << ", " << c.what << ": rays " << f.rays << " against " << reference.rays << ", lost " << f.lost << " against "
                        << reference.lost);
            CHECK(same_film_bits(f.film.accumulation, reference.film.accumulation));
            CHECK(f.rays == reference.rays);
            CHECK(f.lost == reference.lost);
        }
    }
}
