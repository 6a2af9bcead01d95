// The integrators cross-checked on every bundled scene: BDPT (per pixel, and with its light subpaths
// shared in a light-vertex cache, bdpt-cache) and the light tracer estimate the image the path
// tracer estimates (the path tracer agrees with Mitsuba 3 within 0.3 %, docs/render.md), so
// each is compared with it region by region (validation/region_t_test.hpp; Jung et al., JCGT 2020)
// on batches of disjoint sample ranges, with no converged reference.
//
// The matrix: every scene in scenes/ with a light of its own under its own lights, and scenes under
// environments (a constant one and envmaps/courtyard.exr, over an endless plane and on bundled
// scenes). Scenes without any light (primitives, repetition, shader_ball: the commands light them
// with courtyard.exr) have no image to compare under their own lights; they are in the matrix under
// an environment (a test below checks that they declare no light). The light tracer runs where it
// can make every path the path tracer makes and the t-test can judge it: no environment (it has no
// strategy for a camera ray that escapes), no delta surface seen from the camera (its one strategy,
// t = 1, cannot connect the lens to a delta vertex: caustic, material_showcase), and no near-mirror
// glossy surface seen from it (glossy_large_light, veach_mis, studio, tv_room's floor: its splats through such a lobe are so
// heavy-tailed that batch means of this budget are skewed, and Welch's test rejects with no bias).
//
// Each case states its power: per region and channel, the smallest relative difference its test
// rejects with probability 0.9 at the comparison's level (validation::detectable_difference), and
// the case requires the worst of them to be within the case's stated bound. Regions darker than
// kDarkRegion of the image's mean in a channel are tested but left out of the bound: they hold
// next to none of the image's light. The budget (batches, samples per batch) is the smallest found
// to reach the bound. The batches render on the OpenCL device: its compiled scene renders these
// budgets about 8 times faster than the host C++ build's scene interpreter, which pays for the two
// programs PoCL builds per scene (pt, and bdpt for bdpt, lt and bdpt-cache) even with an empty kernel
// cache.
// Both builds give the same images, so the figures below hold for either.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "brdf/host/preset.hpp"
#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "render/scene_environment.hpp"
#include "scene/load_scene.hpp"
#include "tests/render_inputs.hpp"
#include "tests/points_of_run.hpp"
#include "tests/sample_batches.hpp"
#include "validation/region_t_test.hpp"

namespace {

using lab::film::ImageRgb;
using lab::render::Integrator;
using lab::validation::Pairing;
using lab::validation::RegionComparison;
using lab::validation::RegionTest;

constexpr int kSize = 16;             // pixels a side
constexpr int kRegions = 2;           // kRegions x kRegions regions
constexpr double kSignificance = 0.01;  // family-wise level of each comparison (Sidak over its regions and channels)
constexpr double kDarkRegion = 0.05;  // of the image's mean: a darker region is not in the stated power

struct Case {
    std::string name;
    std::string scene;  // a file, or a scene's JSON text (starting with '{')
    std::string env;    // empty: the scene's own lights (and its own environment, if it has one); else the environment that replaces it
    int max_depth;      // scattering events per path, every integrator (BDPT: two vertices more, the lens and the light)
    int batches, spp;   // `batches` renders of `spp` samples, pt and bdpt
    int lt_spp;         // the light tracer's samples per batch; 0: not compared (above)
    double power;       // the stated bound on the detectable difference
    lab::render::LightSampling sampling = lab::render::LightSampling::mis;  // the path tracer's (BDPT has its own)
    bool without_point_lights = false;  // the path tracer cannot sample a point light seen through smooth glass (below)
    std::string sample_preset = {};     // not empty: the preview's input, the test model with this preset in its sample slot (`scene` unused)
    bool with_cache = true;             // bdpt-cache compared too (see the emissive material's cases for when not)
    // > 0: vcm compared too at this merge radius r_0 (paired, bdpt's budget and bound), one at which
    // merges carry much of the weight (at the default radius, 16 x 16 pixels' 64 light subpaths
    // rarely merge: a merge estimate 4 times too large passes there); tests/test_vcm.cpp has its radii
    float vcm_radius = 0.0f;
};

lab::render::RenderInput case_input(const Case& c) {
    if (!c.sample_preset.empty()) {
        lab::render::RenderInput input = render_input(brdf::load_preset(c.sample_preset).material, c.env, kSize, c.sampling, 0);
        input.settings.max_depth = c.max_depth;
        return input;
    }
    lab::render::RenderInput input;
    input.scene = c.scene[0] == '{' ? lab::scene::parse_scene(c.scene, c.name + ".json") : lab::scene::load_scene(c.scene);
    input.environment = c.env.empty() ? lab::render::load_scene_environment(input.scene) : lab::ibl::load_environment(c.env);
    input.settings.width = input.settings.height = kSize;
    input.settings.max_depth = c.max_depth;
    input.settings.light_sampling = c.sampling;
    if (c.without_point_lights) input.scene.point_lights.clear();
    return input;
}

// The batches (tests/sample_batches.hpp) of one integrator on the OpenCL device.
std::vector<ImageRgb> render_batches(lab::render::RenderInput input, Integrator integrator, uint64_t seed, int count, int spp) {
    static const lab::opencl::Runtime runtime("");
    input.settings.integrator = integrator;
    input.settings.seed = seed;
    lab::render::OpenClRenderer renderer(runtime, input);
    return render_sample_batches(renderer, count, spp);
}

struct Verdict {
    RegionComparison comparison;
    double power = 0.0;  // the largest detectable difference over the regions not dark
};

// `a` against the path tracer's batches, every region printed; `pairing` as compare_by_region.
Verdict compare(const char* integrator, const std::vector<ImageRgb>& a, const std::vector<ImageRgb>& pt, Pairing pairing) {
    Verdict v{lab::validation::compare_by_region(a, pt, kRegions, kRegions, kSignificance, pairing)};
    const double means[3] = {batches_channel_mean(pt, 0), batches_channel_mean(pt, 1), batches_channel_mean(pt, 2)};
    for (const RegionTest& r : v.comparison.regions) {
        const double detectable = lab::validation::detectable_difference(r, v.comparison.level);
        const bool dark = r.result.mean_b < kDarkRegion * means[r.channel];
        if (!dark) v.power = std::fmax(v.power, detectable);
        std::printf("  %-4s region (%2d, %2d) %c: %.5g, pt %.5g (%+.2f %%), t %+6.2f, dof %4.1f, p %.3g, detectable %.2f %%%s\n",
                    integrator, r.x0, r.y0, "rgb"[r.channel], r.result.mean_a, r.result.mean_b,
                    100.0 * (r.result.mean_a / r.result.mean_b - 1.0), r.result.t, r.result.dof, r.result.p_value, 100.0 * detectable,
                    dark ? " (dark: not in the bound)" : "");
    }
    return v;
}

// BDPT and bdpt-cache against the path tracer, paired: the same seed and sample ranges give them the
// same camera rays (bdpt_camera_subpath draws them as the path tracer does), so the noise of their
// jitter across a light's or an object's edge cancels. The light tracer draws no camera rays: its
// own seed and batches, by Welch's test. The cache's case has the same stated power as bdpt's.
void check_case(const Case& c) {
    auto start = std::chrono::steady_clock::now();
    lab::render::RenderInput input = case_input(c);
    std::printf("%s: %dx%d, %d batches of %d spp (lt %d), max depth %d, %dx%d regions, family-wise level %.2g\n", c.name.c_str(), kSize,
                kSize, c.batches, c.spp, c.lt_spp, c.max_depth, kRegions, kRegions, kSignificance);
    std::vector<ImageRgb> pt = render_batches(input, Integrator::pt, 1, c.batches, c.spp);
    Verdict bdpt = compare("bdpt", render_batches(input, Integrator::bdpt, 1, c.batches, c.spp), pt, Pairing::paired);
    Verdict cache;
    if (c.with_cache) cache = compare("bdpt-cache", render_batches(input, Integrator::bdpt_cache, 1, c.batches, c.spp), pt, Pairing::paired);
    Verdict vcm;
    if (c.vcm_radius > 0.0f) {
        lab::render::RenderInput merging = input;
        merging.settings.bdpt.merge_radius = c.vcm_radius;
        vcm = compare("vcm", render_batches(merging, Integrator::vcm, 1, c.batches, c.spp), pt, Pairing::paired);
    }
    Verdict lt;
    if (c.lt_spp > 0) lt = compare("lt", render_batches(input, Integrator::lt, 2, c.batches, c.lt_spp), pt, Pairing::independent);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: bdpt %d of %zu rejected, detectable %.2f %%; bdpt-cache ", c.name.c_str(), bdpt.comparison.rejected,
                bdpt.comparison.regions.size(), 100.0 * bdpt.power);
    if (c.with_cache) std::printf("%d rejected, detectable %.2f %%", cache.comparison.rejected, 100.0 * cache.power);
    else std::printf("not compared");
    if (c.vcm_radius > 0.0f) std::printf("; vcm %d rejected, detectable %.2f %%", vcm.comparison.rejected, 100.0 * vcm.power);
    std::printf("; lt ");
    if (c.lt_spp > 0) std::printf("%d rejected, detectable %.2f %%", lt.comparison.rejected, 100.0 * lt.power);
    else std::printf("not compared");
    std::printf("; stated bound %.1f %%; %.1f s\n", 100.0 * c.power, seconds);
    INFO(c.name << ": detectable difference bdpt " << 100.0 * bdpt.power << " %, bdpt-cache " << 100.0 * cache.power << " %, lt "
                << 100.0 * lt.power << " %, stated bound " << 100.0 * c.power << " %");
    CHECK(std::fmax(std::fmax(std::fmax(bdpt.power, cache.power), vcm.power), lt.power) <= c.power);
    CHECK(bdpt.comparison.rejected == 0);
    CHECK(cache.comparison.rejected == 0);
    CHECK(vcm.comparison.rejected == 0);
    CHECK(lt.comparison.rejected == 0);
}

// An endless Lambert plane (albedo 0.5), the camera 2 m above it looking at the horizon.
const char* kBarePlane = R"({"camera": {"type": "pinhole", "position": [0, 2, 0], "look_at": [0, 1, -10], "fov_degrees": 50},
  "materials": {"ground": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "ground", "material": "ground", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}}]})";

// A Lambert sphere and a glossy one on an endless plane, seen by the camera `camera` (JSON), with
// `lights`: more members of the scene's object (",\n  \"emitters\": [...]"), or none.
std::string spheres_on_plane(const std::string& camera, const std::string& lights) {
    return R"({"camera": )" + camera + R"(,
  "materials": {"ground": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}},
                "white": {"albedo": [0.8, 0.8, 0.8], "lobes": {"diffuse": 1}},
                "glossy": {"albedo": [0.8, 0.3, 0.2], "roughness": 0.2, "lobes": {"diffuse": 0.6, "glossy": 0.4}}},
  "objects": [{"name": "ground", "material": "ground", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}},
              {"name": "left", "material": "white", "shape": {"type": "translate", "offset": [-0.6, 0.5, 0], "child": {"type": "sphere", "radius": 0.5}}},
              {"name": "right", "material": "glossy", "shape": {"type": "translate", "offset": [0.6, 0.5, -0.3], "child": {"type": "sphere", "radius": 0.5}}}])" +
           lights + "}";
}

// Under an environment: the camera sees the spheres, the plane and the sky.
const std::string kSpheresOnPlane = spheres_on_plane(R"({"type": "pinhole", "position": [0, 1.2, 4], "look_at": [0, 0.5, 0], "fov_degrees": 40})", "");

// Lit by a sphere light, seen from above (the plane fills the view).
const std::string kSpheresUnderLight =
    spheres_on_plane(R"({"type": "pinhole", "position": [0, 2.5, 3.5], "look_at": [0, 0.3, 0], "fov_degrees": 40})",
                     R"(,
  "emitters": [{"center": [-1, 3, 1.5], "radius": 0.8, "radiance": [4, 4, 4]}])");

// Every bundled scene with a light of its own. Budgets and bounds per scene, and where the bound is
// over 10 %, why:
//  - caustic: one scattering event (the glass ball's caustics, two and more, are the path tracer's
//    fireflies: it finds them only by BSDF sampling), the path tracer by next-event estimation alone
//    (its MIS shows fireflies at one event too). The region of the ball's highlight, the 5 cm light
//    of radiance 400 seen in the glass, is still noisy: each integrator picks reflection or refraction
//    there with its own random number, so the pairing does not cancel it (20 %; the other regions
//    under 1 %).
//  - cornell_box_rect: its light in view, 0.47 x 0.38 of radiance up to 17: the path tracer's batches
//    jitter across its edges, and the light tracer is compared unpaired (Welch), so the two top
//    regions can see 10.8 % against lt (the same at 64 and 96 lt samples: the path tracer's noise;
//    bdpt and bdpt-cache, paired, 3 %; the lower regions under 3 %).
//  - door_ajar: lit only indirectly, through the door (15 %).
//  - veach_mis: the plates' highlights of the small lights and their glossy caustics on the floor
//    (20 % in the other regions), and the small lights seen directly (35 %). bdpt takes those from
//    light tracing, (1, 1), which shares no random numbers with the path tracer's camera rays, so
//    the pairing does not cancel them, and at 16 x 16 they are smaller than a pixel: the path
//    tracer's batch means of the top left region are heavy-tailed (0.487 from 32 x 64 spp against
//    0.556 at 65,536 spp). More samples buy little there: 33 % at 64 per batch, 21 % at 192 and at 256.
//  - tv_room: lit by its screen alone, whose edges and texels the path tracer's batches jitter
//    across, paired with bdpt's camera rays but not with its light subpaths (12.4 %, bdpt-cache
//    13.3 %; the light tracer 38.8 %, through the glossy floor).
//  - material_showcase, without its point light: the path tracer cannot sample the point light's
//    caustic under the smooth glass ball (light - glass - floor - eye: next-event estimation from
//    the floor is blocked by the glass, and no BSDF sample hits a point), which BDPT's light
//    subpaths carry. With the point light, bdpt is 3 % brighter than pt in that quadrant (t 5-6);
//    lit by the point light alone, 8.5 % (64 x 32, 6 x 64 spp, z 28 in the ball's block); without
//    it, the two agree everywhere.
std::vector<Case> own_light_cases() {
    using lab::render::LightSampling;
    return {
        {"cornell_box", "scenes/cornell_box.json", "", 6, 32, 32, 64, 0.10, LightSampling::mis, false, {}, true, 0.3f},
        {"cornell_box_rect", "scenes/cornell_box_rect.json", "", 6, 32, 32, 64, 0.12},
        {"caustic", "scenes/caustic.json", "", 1, 32, 192, 0, 0.20, LightSampling::lights},
        {"depth_of_field", "scenes/depth_of_field.json", "", 6, 32, 64, 0, 0.12},
        {"door_ajar", "scenes/door_ajar.json", "", 6, 32, 48, 96, 0.15},
        {"glossy_large_light", "scenes/glossy_large_light.json", "", 6, 32, 32, 0, 0.10},
        {"material_showcase", "scenes/material_showcase.json", "", 6, 32, 128, 0, 0.14, LightSampling::mis, true},
        {"metaballs", "scenes/metaballs.json", "", 6, 32, 32, 64, 0.10},
        {"veach_mis", "scenes/veach_mis.json", "", 6, 32, 64, 0, 0.35},
        {"studio", "scenes/studio.json", "", 6, 32, 32, 0, 0.10},
        {"tv_room", "scenes/tv_room.json", "", 6, 32, 32, 0, 0.15},
    };
}

// The bundled scenes with no light at all.
const std::vector<std::string> kUnlitScenes = {"primitives", "repetition", "shader_ball"};

// The bundled scenes whose light reaches the image by paths each integrator samples a different part
// of, so no two of them estimate the same image: caustic_mirror's point light through the glass
// ball is sampled by bdpt's t = 1 where seen directly (not by pt) and by vcm's merges alone where
// seen in the mirror. tests/test_vcm.cpp compares vcm there with a long vcm render, and bdpt.
const std::vector<std::string> kMergingScenes = {"caustic_mirror"};

}  // namespace

// Each run compares cornell_box (the light tracer's case in every run) and a third of the other scenes,
// drawn per run (tests/points_of_run.hpp).
TEST_CASE("Integrator agreement: BDPT and the light tracer against the path tracer, every scene under its own lights",
          "[render][agreement][opencl][sweep]") {
    const std::vector<Case> cases = own_light_cases();
    REQUIRE(cases[0].name == "cornell_box");
    for (int i : sweep_points_of_run("integrator agreement: scenes under their own lights", int(cases.size()), (int(cases.size()) - 1) / 3, {0}))
        check_case(cases[size_t(i)]);
}

TEST_CASE("Integrator agreement: BDPT against the path tracer under environments", "[render][agreement][opencl][sweep]") {
    std::vector<Case> cases = {
        {"bare plane, constant environment", kBarePlane, "constant:1,1,1", 6, 32, 16, 0, 0.02},
        {"spheres on a plane, courtyard.exr", kSpheresOnPlane, "envmaps/courtyard.exr", 6, 32, 192, 0, 0.02},
        {"shader_ball, courtyard.exr", "scenes/shader_ball.json", "envmaps/courtyard.exr", 6, 32, 32, 0, 0.06},
    };
    for (const Case& c : cases) check_case(c);
}

// An emissive openpbr torus (coated, with fuzz: its emission leaves through both, brdf/emission.h)
// standing among the spheres on the plane. No light sample can find it, so the path tracer finds it
// only where a BSDF-sampled ray hits it, and BDPT only by s = 0; lit by it alone, BDPT has no light
// subpath at all.
const char* kGlowingTorus = R"({"camera": {"type": "pinhole", "position": [0, 1.5, 3.5], "look_at": [0, 0.5, 0], "fov_degrees": 45},
  "materials": {"ground": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}},
                "white": {"albedo": [0.8, 0.8, 0.8], "lobes": {"diffuse": 1}},
                "glossy": {"albedo": [0.8, 0.3, 0.2], "roughness": 0.2, "lobes": {"diffuse": 0.6, "glossy": 0.4}},
                "glow": {"model": "openpbr", "base_color": [0.1, 0.1, 0.1], "coat_weight": 1, "coat_roughness": 0.2, "fuzz_weight": 0.5,
                         "emission_luminance": 6, "emission_color": [1, 0.6, 0.3]}},
  "objects": [{"name": "ground", "material": "ground", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}},
              {"name": "left", "material": "white", "shape": {"type": "translate", "offset": [-0.8, 0.5, 0], "child": {"type": "sphere", "radius": 0.5}}},
              {"name": "right", "material": "glossy", "shape": {"type": "translate", "offset": [0.8, 0.5, -0.3], "child": {"type": "sphere", "radius": 0.5}}},
              {"name": "torus", "material": "glow", "shape": {"type": "translate", "offset": [0, 0.6, -1.2],
               "child": {"type": "rotate", "euler_degrees": [90, 0, 0], "child": {"type": "torus", "major_radius": 0.45, "minor_radius": 0.15}}}}]})";

// Emissive materials (docs/materials.md, Emission): the torus lit by itself alone and under
// courtyard.exr, and the preview's input, the test model with the emissive preset under
// courtyard.exr, against BDPT. Not against bdpt-cache: an emissive surface starts no light subpath
// and is reached by s = 0 alone, whose code (bdpt_strategy_contribution) and camera subpaths the
// cache shares with bdpt; what the cache changes, its t = 1 and s >= 2 strategies under the
// environment, the environment cases above compare. That spares three programs' kernels.
TEST_CASE("Integrator agreement: BDPT against the path tracer with an emissive openpbr material", "[render][agreement][emission][opencl][sweep]") {
    std::vector<Case> cases = {
        {"glowing torus among spheres, its own light alone", kGlowingTorus, "", 6, 32, 160, 0, 0.05, lab::render::LightSampling::mis, false, {}, false},
        {"glowing torus among spheres, courtyard.exr", kGlowingTorus, "envmaps/courtyard.exr", 6, 32, 32, 0, 0.05, lab::render::LightSampling::mis, false,
         {}, false},
        {"preview: glowing_coated_panel on the test model, courtyard.exr", "", "envmaps/courtyard.exr", 6, 32, 32, 0, 0.05,
         lab::render::LightSampling::mis, false, "presets/glowing_coated_panel.json", false},
    };
    for (const Case& c : cases) check_case(c);
}

// The matrix covers every bundled scene: each has a light of its own and is in own_light_cases()
// (or kMergingScenes), or has none and is one of kUnlitScenes (compared under courtyard.exr where the
// budget allows: shader_ball).
TEST_CASE("Integrator agreement: every bundled scene is in the matrix, or has no light of its own", "[render][agreement]") {
    std::vector<std::string> lit;
    for (const Case& c : own_light_cases()) lit.push_back(c.name);
    int scenes = 0;
    for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator("scenes")) {
        if (entry.path().extension() != ".json") continue;
        ++scenes;
        const std::string name = entry.path().stem().string();
        lab::scene::Scene scene = lab::scene::load_scene(entry.path().string());
        const bool has_light = lab::scene::has_own_light(scene);
        INFO(name);
        if (has_light) CHECK(std::count(lit.begin(), lit.end(), name) + std::count(kMergingScenes.begin(), kMergingScenes.end(), name) == 1);
        else CHECK(std::count(kUnlitScenes.begin(), kUnlitScenes.end(), name) == 1);
    }
    CHECK(size_t(scenes) == lit.size() + kUnlitScenes.size() + kMergingScenes.size());
}

// The test's power shown on a case that today's BDPT renders right: spheres on a plane under a
// sphere light. Its comparison passes with every region able to see 2 %; the same batches with one
// region of BDPT's 2 % brighter are rejected there, and only there.
TEST_CASE("Integrator agreement: a 2 % bias in one region is seen, the unchanged batches agree", "[render][agreement][opencl][sweep]") {
    const Case c{"spheres on a plane under a sphere light", kSpheresUnderLight, "", 6, 32, 48, 0, 0.02};
    lab::render::RenderInput input = case_input(c);
    std::vector<ImageRgb> pt = render_batches(input, Integrator::pt, 1, c.batches, c.spp);
    std::vector<ImageRgb> bdpt = render_batches(input, Integrator::bdpt, 1, c.batches, c.spp);
    std::printf("%s: %dx%d, %d batches of %d spp\n", c.name.c_str(), kSize, kSize, c.batches, c.spp);
    Verdict same = compare("bdpt", bdpt, pt, Pairing::paired);
    std::printf("%s: %d of %zu rejected, detectable %.2f %%\n", c.name.c_str(), same.comparison.rejected, same.comparison.regions.size(),
                100.0 * same.power);
    REQUIRE(same.power <= c.power);
    CHECK(same.comparison.rejected == 0);

    // the bottom-left region, pixels [0, kSize / 2) x [kSize / 2, kSize), 2 % brighter in every batch of BDPT's
    for (ImageRgb& image : bdpt)
        for (int y = kSize / 2; y < kSize; ++y)
            for (int x = 0; x < kSize / 2; ++x)
                for (int channel = 0; channel < 3; ++channel) image.pixel(x, y)[channel] *= 1.02f;
    Verdict biased = compare("bdpt x 1.02", bdpt, pt, Pairing::paired);
    std::printf("%s, bottom-left region x 1.02: %d of %zu rejected\n", c.name.c_str(), biased.comparison.rejected,
                biased.comparison.regions.size());
    for (const RegionTest& r : biased.comparison.regions) {
        INFO("region (" << r.x0 << ", " << r.y0 << ") channel " << r.channel << ": t " << r.result.t << ", p " << r.result.p_value);
        CHECK((r.result.p_value < biased.comparison.level) == (r.x0 == 0 && r.y0 == kSize / 2));
    }
}
