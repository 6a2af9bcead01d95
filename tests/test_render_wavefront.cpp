// The path tracer's CPU wavefront (kernels/path_tracer_wavefront.h) keeps several samples of every
// pixel in flight on small images (OpenClTuning::wavefront_paths) and adds each pixel's paths to
// the film in sample order afterwards (render_pt_resolve). Whatever the number in flight, and with
// the image split into parts (one sample in flight there), the film must hold the bits of the
// work-item kernel, which traces each pixel's samples one after the other in one work-item, and the
// same ray counts. A pinhole's camera rays are begun on the packets' lanes (march_camera_rays), a
// thin lens's by the camera step, one path per work-item: the scenes have both. Checked once by
// hand: a resolve that adds the slots last to first fails the film of every case with more than one
// sample in flight (6 of the 30 checks), and paths that all draw the launch's first sample fail 17;
// lanes that draw their ray's numbers in the order y, x fail the film of all 10 pinhole cases, and
// a thin-lens camera step that stores its generator before the ray's four numbers fails the 5 of
// the thin lens.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "bench/wavefront_launch_timer.hpp"
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
    input.settings.opencl.packets = packets;
    input.settings.opencl.wavefront_paths = wavefront_paths;
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

// A scene file's render input at a small size.
lab::render::RenderInput small_input(const char* file, int width, int height) {
    lab::render::RenderInput input;
    input.scene = lab::scene::load_scene(file);
    input.settings.width = width;
    input.settings.height = height;
    return input;
}

// The wavefront runs on CPU devices only: false, with a warning, on any other.
bool wavefront_device(const lab::opencl::Runtime& runtime) {
    if (runtime.device().type == "cpu") return true;
    WARN("the wavefront runs on CPU devices only");
    return false;
}

}  // namespace

TEST_CASE("Wavefront: any number of samples in flight gives the work-item kernel's film bits and ray counts",
          "[render][wavefront][opencl]") {
    lab::opencl::Runtime runtime("");
    if (!wavefront_device(runtime)) return;
    struct Scene {
        const char* what;
        lab::render::RenderInput input;
    };
    Scene scenes[] = {{"test model under courtyard", render_input(std::nullopt, "envmaps/courtyard.exr", 20, lab::render::LightSampling::mis, 5)},
                      {"Cornell box", small_input("scenes/cornell_box.json", 24, 18)},
                      {"thin lens (depth of field)", small_input("scenes/depth_of_field.json", 20, 14)}};
    REQUIRE(scenes[2].input.scene.camera.aperture_radius > 0.0f);
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
            CHECK(same_film_bits(f.film.squares, reference.film.squares));
            CHECK(f.rays == reference.rays);
            CHECK(f.lost == reference.lost);
        }
    }
}

// With --geometry march every object is marched, and the packet program has no exact object at all
// (the Cornell box above marches nothing: its packets find the exact hits alone). Checked once by
// hand: a packet kernel that names EXACT_MISS, which only a scene with exact objects defines, fails
// this build.
TEST_CASE("Wavefront: a packet program without exact objects (--geometry march) gives the work-item kernel's film bits",
          "[render][wavefront][opencl]") {
    lab::opencl::Runtime runtime("");
    if (!wavefront_device(runtime)) return;
    lab::render::RenderInput input = small_input("scenes/cornell_box.json", 24, 18);
    input.settings.march_everything = true;
    const InFlightFilm reference = render_in_flight(runtime, input, false, 0, 7, 7, 0);
    const InFlightFilm f = render_in_flight(runtime, input, true, 0, 7, 7, 0);
    INFO("rays " << f.rays << " against " << reference.rays);
    CHECK(same_film_bits(f.film.accumulation, reference.film.accumulation));
    CHECK(f.rays == reference.rays);
    CHECK(f.lost == reference.lost);
}

// `bench breakdown` times the wavefront's launches by kind (bench::WavefrontLaunchTimer). Whatever
// the scene, a launch of samples runs one march of its camera rays (begun in it for a pinhole, after
// a camera step for a thin lens) and one last step (the one that leaves nothing to march), every
// scatter step is followed by one march of what it left, and several samples in flight end with one
// resolve; timing must not change a bit of the film. Checked once by hand: a last step counted as a
// scatter step fails 2 of these checks per camera, a resolve left uncounted 1, and a pinhole
// rendered through the camera step 1.
TEST_CASE("Wavefront: timed launches are counted by kind and keep the film's bits", "[render][wavefront][opencl]") {
    lab::opencl::Runtime runtime("");
    if (!wavefront_device(runtime)) return;
    const lab::render::RenderInput thin_lens = small_input("scenes/depth_of_field.json", 20, 14);
    struct Camera {
        const char* what;
        lab::render::RenderInput input;
        int camera_steps_per_launch;
    } cameras[] = {{"pinhole (test model)", render_input(std::nullopt, "envmaps/courtyard.exr", 16, lab::render::LightSampling::mis, 5), 0},
                   {"thin lens (depth of field)", thin_lens, 1}};
    for (const Camera& c : cameras) {
        const int spp = 7, per_launch = 3, batches = 3;  // launches of 3, 3 and 1 samples
        const InFlightFilm untimed = render_in_flight(runtime, c.input, true, 0, spp, per_launch, 0);

        lab::render::OpenClRenderer renderer(runtime, c.input);
        REQUIRE(renderer.wavefront());
        renderer.set_samples_per_launch(per_launch);
        lab::bench::WavefrontLaunchTimer timer;
        renderer.observe_wavefront_launches(&timer);
        renderer.add_samples(spp);
        const lab::bench::WavefrontLaunchTimes t = timer.times();
        INFO(c.what << ": camera steps " << t.camera_steps.launches << ", camera marches " << t.camera_marches.launches
                    << ", scatter steps " << t.scatter_steps.launches << ", marches " << t.marches.launches << ", last steps "
                    << t.last_steps.launches << ", resolves " << t.resolves.launches);
        CHECK(t.camera_steps.launches == c.camera_steps_per_launch * batches);
        CHECK(t.camera_marches.launches == batches);
        CHECK(t.last_steps.launches == batches);
        CHECK(t.scatter_steps.launches >= batches);  // both scenes scatter at least once per launch
        CHECK(t.scatter_steps.launches == t.marches.launches);
        CHECK(t.resolves.launches == batches - 1);  // the last launch holds one sample: nothing to resolve
        CHECK(t.camera_marches.seconds > 0.0);
        CHECK(t.scatter_steps.seconds > 0.0);
        CHECK(same_film_bits(renderer.film().accumulation, untimed.film.accumulation));

        timer.restart();  // starts again at 0
        CHECK(timer.times().camera_marches.launches == 0);
        CHECK(timer.times().total() == 0.0);
    }
}
