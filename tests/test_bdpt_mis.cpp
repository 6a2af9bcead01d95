// BDPT's MIS weights (kernels/bdpt_mis.h) on paths the real walks made (kernels/bdpt_walk.h, on the
// host build of the kernels over a real scene): for every path, the weights of all the strategies
// that can make it sum to 1, with the balance and the power heuristic, over every strategy mask,
// and with the light-vertex cache's sample counts (kernels/bdpt_cache.h: N_L / N_pixels light
// subpaths per camera subpath for t = 1, M / (connectable vertices per light subpath) connections
// to a given light vertex for s >= 2, t >= 2) as render/light_cache.cpp sets them, and with vertex
// merging (vcm, kernels/vcm.h): the merges at every vertex that can merge join the sum, each weighed
// by vcm_merge_weight from the light subpath and camera subpath that meet there.
//
// The paths come from the walks themselves, with the densities the walks recorded:
//  - camera subpaths that reach a light (an emissive sphere or the environment): the path is the
//    subpath; each other strategy (s, t) keeps its first t camera vertices, and its light subpath is
//    the rest of the path read backwards, whose forward densities are the ones the camera walk
//    recorded as reverse densities and the other way round;
//  - light subpaths (from a sphere, a point light, the environment) joined to the lens: the same,
//    with the roles swapped.
// Only the two densities at the far end of the path that the other walk would have recorded (a
// light's origin and emission densities, the camera's) come from the kernel's own vertex_pdf_*.
// The scene has an endless Lambert floor, a Lambert ball, a mirror ball (delta lobes) and every
// kind of light, so that the environment's light disk misses part of the floor: strategies that
// start there cannot make those paths and must take none of their weight.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/host.hpp"
#include "render/camera_setup.hpp"
#include "render/host_kernels.hpp"
#include "render/host_renderer.hpp"
#include "render/light_cache.hpp"
#include "render/light_set.hpp"
#include "render/vcm.hpp"
#include "tests/render_inputs.hpp"


// A named namespace keeps the using-directive to this file in its unity group (tests/CMakeLists.txt).
namespace bdpt_mis_test {
namespace {

using namespace lab::render::host_kernels;
using brdf::float3;

const char* kScene = R"({
  "camera": {"type": "pinhole", "position": [0.3, 1.4, 4.5], "look_at": [0, 0.6, 0], "fov_degrees": 50},
  "materials": {
    "floor": {"albedo": [0.7, 0.7, 0.7], "lobes": {"diffuse": 1}},
    "ball": {"albedo": [0.8, 0.5, 0.3], "lobes": {"diffuse": 1}},
    "mirror": {"albedo": [0.9, 0.9, 0.9], "metallic": 1, "roughness": 0, "lobes": {"specular": 1}}
  },
  "objects": [
    {"name": "floor", "material": "floor", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}},
    {"name": "ball", "material": "ball", "shape": {"type": "translate", "offset": [-0.7, 0.5, 0], "child": {"type": "sphere", "radius": 0.5}}},
    {"name": "mirror", "material": "mirror", "shape": {"type": "translate", "offset": [0.7, 0.45, 0.2], "child": {"type": "sphere", "radius": 0.45}}}
  ],
  "emitters": [
    {"center": [0.1, 2.0, 0.3], "radius": 0.3, "radiance": [6, 6, 6], "material": "ball"},
    {"type": "point", "position": [-1.2, 1.6, 1.2], "intensity": [3, 3, 3]}
  ]
})";

struct Fixture {
    lab::render::RenderInput input = render_input(std::nullopt, "constant:0.6,0.7,0.8", 32, lab::render::LightSampling::mis, 0, kScene);
    lab::render::HostSceneScope scene_scope{input.scene};  // the kernels' distance field is this scene's
    lab::scene::CompiledScene compiled;
    lab::render::LightSet lights;
    std::vector<brdf::float4> emission;
    RenderScene scene{};
    RenderKernelSettings settings{};
    kernel::Camera camera{};
    MarchSettings march{};

    Fixture() {
        input.settings.integrator = lab::render::Integrator::bdpt;
        input.settings.max_depth = 6;
        input.settings.roulette_depth = 64;  // long paths survive
        settings = lab::render::HostRenderer(input, 1).kernel_settings(0, 1);
        compiled = lab::scene::compile_scene(input.scene, lab::scene::CompileOptions{});
        for (brdf::Material& m : compiled.materials) m = brdf::material_clamped(&m);
        lights = lab::render::build_light_set(compiled, &*input.environment, lab::render::LightSelection::uniform);
        emission = lab::render::emission_table(compiled);
        const lab::ibl::Environment& env = *input.environment;
        scene = render_scene_make(compiled.materials.data(), brdf::bsdf_tables(), emission.data(), lights.lights.data(),
                                  lights.selection_cdf.data(), lights.light_of_slot.data(), env.map(), env.texels().data(), env.alias().data());
        camera = lab::render::make_camera(compiled.camera, 32, 32, "test");
        march = render_march_settings(&settings);
    }
};

// Whether the environment's light disk (bdpt_light_subpath: radius R about the scene's centre c,
// facing the scene from c + R w, rays running along -w up to the march's max distance) reaches p:
// written out here from the disk's geometry, not taken from the kernel.
bool disk_reaches(const RenderKernelSettings& settings, float3 w, float3 p) {
    glm::dvec3 d = glm::dvec3(p) - glm::dvec3(settings.bdpt.scene_center[0], settings.bdpt.scene_center[1], settings.bdpt.scene_center[2]);
    double along = glm::dot(d, glm::dvec3(w));
    double across = glm::length(d - along * glm::dvec3(w));
    return across <= settings.bdpt.scene_radius && along <= settings.bdpt.scene_radius && settings.bdpt.scene_radius - along <= settings.max_distance;
}

// A path x_0 (on a light) .. x_{n-1} (the lens) as strategy (s, t) sees it: light[0..s-1] and
// cam[0..t-1], each with the densities its own walk records.
struct Split {
    std::vector<PathVertex> light, cam;
};

// x_0 of a camera subpath, an emissive surface, as the light vertex a light subpath starts on.
PathVertex as_light_vertex(const Fixture& f, PathVertex v) {
    if (v.type == VERTEX_SURFACE) {
        v.index = f.scene.light_of_slot[v.index];
        v.type = VERTEX_LIGHT;
    }
    v.delta = 0;
    return v;
}

// A light vertex on a sphere light as the emissive surface a camera subpath hits.
PathVertex as_surface_vertex(const Fixture& f, PathVertex v) {
    if (v.type == VERTEX_LIGHT) {
        v.type = VERTEX_SURFACE;
        v.index = f.scene.lights[v.index].material_slot;
    }
    return v;
}

// `walked`: a subpath as its walk recorded it, its first `keep` vertices kept for the own side; the
// rest, read backwards, becomes the other side. Its first vertices get the densities the other walk
// would have recorded there, from the kernel's vertex_pdf_*: a light's origin and emission
// densities, or the camera's density and (a light walk's last vertex having been joined to the lens,
// not continued) the next one's.
void split_off(const Fixture& f, const std::vector<PathVertex>& walked, int keep, bool walked_is_camera, Split* out) {
    const int n = int(walked.size());
    std::vector<PathVertex>& own = walked_is_camera ? out->cam : out->light;
    std::vector<PathVertex>& other = walked_is_camera ? out->light : out->cam;
    own.assign(walked.begin(), walked.begin() + keep);
    other.clear();
    for (int j = n - 1; j >= keep; --j) {
        PathVertex v = walked[size_t(j)];
        const int i = int(other.size());
        if (i == 0) v = walked_is_camera ? as_light_vertex(f, v) : camera_vertex(&f.camera, v.p, float3(1.0f));
        std::swap(v.pdf_fwd, v.pdf_rev);  // what the other walk records forward, this one recorded in reverse
        other.push_back(v);
    }
    // the far end's own densities: the other walk's start
    if (walked_is_camera) {
        if (!other.empty()) other[0].pdf_fwd = vertex_pdf_light_origin(&f.settings, &f.scene, &other[0]);
        if (other.size() > 1) other[1].pdf_fwd = vertex_pdf_light(&f.settings, &f.scene, &other[0], &other[1]);
    } else {
        if (other.size() > 1) other[1].pdf_fwd = vertex_pdf(&f.settings, &f.camera, &f.scene, nullptr, &other[0], &other[1]);
        // the light walk recorded the one before its last vertex for its own continuation, not the lens
        if (other.size() > 2) other[2].pdf_fwd = vertex_pdf(&f.settings, &f.camera, &f.scene, &other[0], &other[1], &other[2]);
        if (!other.empty()) other[0].pdf_fwd = 0.0f;
        // a light vertex the camera subpath reaches is the emissive surface it hits
        if (!other.empty() && other.back().type == VERTEX_LIGHT) other.back() = as_surface_vertex(f, other.back());
    }
}

// Whether strategy (s, t) can make path x (x_0 on the light; light[0] of the s = n split).
bool can_make(const Fixture& f, const std::vector<PathVertex>& x, int s, int t) {
    const PathVertex& x0 = x[0];
    const bool point_light = x0.type == VERTEX_LIGHT && f.scene.lights[x0.index].type == LIGHT_POINT;
    // (1, 1): a light subpath's first vertex joined to the lens, a light seen directly, which
    // (0, 2) makes too; neither can at infinity, and no camera ray hits a point light
    if (s == 1 && t == 1) return x0.type == VERTEX_LIGHT && !point_light;
    if (s == 0) return !point_light;
    if (s >= 2 && x0.type == VERTEX_ENVIRONMENT && !disk_reaches(f.settings, x0.p, x[1].p)) return false;
    if (t == 1) return !x[size_t(s - 1)].delta && x[size_t(s - 1)].type != VERTEX_ENVIRONMENT;
    return !(s >= 2 && x[size_t(s - 1)].delta) && !x[size_t(s)].delta;
}

// Whether merging at x_m can make path x: its light subpath reaches x_m (the environment's disk
// reaches x_1), x_m is neither the light's vertex nor the lens, and it scatters by a lobe no delta.
bool can_merge(const Fixture& f, const std::vector<PathVertex>& x, int m) {
    if (m < 1 || m > int(x.size()) - 2) return false;
    if (x[0].type == VERTEX_ENVIRONMENT && !disk_reaches(f.settings, x[0].p, x[1].p)) return false;
    const PathVertex& v = x[size_t(m)];
    return v.type == VERTEX_SURFACE && vertex_scatters(&f.scene, &v) && !v.delta;
}

// How far the weights may sum from 1 on this path, from its geometry. A walk records each density
// for the direction it sampled, and the weight computes the connection's from the stored points;
// the two directions differ by the ray origin's offset off the surface (2 epsilon) and the march's
// hit threshold (epsilon) across the segment, which changes a density by that angle over the cosine
// at each end. The weights' sum moves by at most about twice the sum of the densities' relative
// changes, and the power heuristic doubles that again.
double geometric_slack(const std::vector<PathVertex>& x) {
    double slack = 0.0;
    for (size_t i = 0; i + 1 < x.size(); ++i) {
        const PathVertex &a = x[i], &b = x[i + 1];
        if (a.type == VERTEX_ENVIRONMENT || b.type == VERTEX_ENVIRONMENT) continue;
        const float3 w = b.p - a.p;
        const double d = glm::length(w);
        if (!(d > 0.0)) return 1.0;
        const double angle = 3.0 * std::max(a.epsilon, b.epsilon) / d;
        for (const PathVertex* v : {&a, &b})
            if (v->on_surface && !v->delta) slack += angle / std::max(1e-6, std::fabs(double(glm::dot(v->frame.n, w)) / d));
    }
    return 4.0 * slack;
}

struct Totals {
    int paths = 0, environment_unreached = 0, delta = 0, point = 0, sphere = 0, environment = 0, merges = 0;
};

// The weights of every strategy of the mask that can make the path `walked` (one walk's subpath that
// is a whole path) sum to 1, with bdpt's sample counts (one of each strategy) and the light-vertex
// cache's: a pool of a quarter of the pixels with 3 connections, and of 4 times the pixels with 1,
// over pilots of 0.6 and 2.5 connectable vertices per light subpath; and vcm's, the first pool with
// its merges at two radii (N_L pi r^2 of 0.03 and 7: merges weighed from far below to far above
// the connections on this scene's densities).
void check_path(Fixture& f, const std::vector<PathVertex>& walked, bool walked_is_camera, Totals* totals) {
    kernel::RenderKernelSettings counts[5] = {f.settings, f.settings, f.settings, f.settings, f.settings};
    const struct {
        float light_paths;
        int connections;
        double vertices_per_path;
    } kCaches[2] = {{0.25f, 3, 0.6}, {4.0f, 1, 2.5}};
    for (int c = 0; c < 2; ++c) {
        lab::render::RenderSettings cache = f.input.settings;
        cache.integrator = lab::render::Integrator::bdpt_cache;
        cache.bdpt.light_paths = kCaches[c].light_paths;
        cache.bdpt.connections = kCaches[c].connections;
        const double paths = lab::render::light_cache_paths(cache);
        lab::render::set_light_cache_weights(cache, uint64_t(kCaches[c].vertices_per_path * paths), &counts[c + 1]);
    }
    for (int c = 0; c < 2; ++c) {
        counts[c + 3] = counts[1];
        counts[c + 3].bdpt.merge_samples = c == 0 ? 0.03f : 7.0f;
    }
    const int n = int(walked.size());
    Split whole;
    split_off(f, walked, walked_is_camera ? 0 : n, walked_is_camera, &whole);
    const std::vector<PathVertex>& x = whole.light;  // x_0 .. x_{n-1}, x_{n-1} the lens
    const double slack = geometric_slack(x);
    bool any_delta = false;
    for (const PathVertex& v : x) any_delta = any_delta || v.delta;
    for (const kernel::RenderKernelSettings& with_counts : counts) {
        for (int heuristic : {MIS_BALANCE, MIS_POWER})
            for (int mask : {STRATEGY_ALL, STRATEGY_S0 | STRATEGY_S1, STRATEGY_T1, STRATEGY_S1 | STRATEGY_S2 | STRATEGY_T1, STRATEGY_S0 | STRATEGY_S2}) {
                f.settings.bdpt.mis_heuristic = heuristic;
                f.settings.bdpt.strategies = mask;
                f.settings.bdpt.light_tracing_samples = with_counts.bdpt.light_tracing_samples;
                f.settings.bdpt.connection_samples = with_counts.bdpt.connection_samples;
                f.settings.bdpt.merge_samples = with_counts.bdpt.merge_samples;
                double sum = 0.0;
                bool any = false;
                for (int s = 0; s < n; ++s) {
                    const int t = n - s;
                    if (!can_make(f, x, s, t) || !bdpt_strategy_enabled(mask, s, t)) continue;
                    Split split;
                    split_off(f, walked, walked_is_camera ? t : s, walked_is_camera, &split);
                    // the connection's endpoints and their neighbours carry densities of their walk's own
                    // continuation, not of this connection: the weight must not read them
                    for (int i = std::max(0, s - 2); i < s; ++i) split.light[size_t(i)].pdf_rev = 123.0f;
                    for (int i = std::max(0, t - 2); i < t; ++i) split.cam[size_t(i)].pdf_rev = 321.0f;
                    PathVertex sampled = s == 1 && t > 1 ? split.light[0] : split.cam[0];
                    sum += bdpt_mis_weight(&f.settings, &f.camera, &f.scene, split.light.data(), split.cam.data(), &sampled, s, t);
                    any = true;
                }
                // the merges: x_0 .. x_m walked from the light, x_m .. x_{n-1} from the lens
                for (int m = 1; f.settings.bdpt.merge_samples > 0.0f && m < n - 1; ++m) {
                    if (!can_merge(f, x, m)) continue;
                    const int s = m + 1, t = n - m;
                    Split from_light, from_camera;
                    split_off(f, walked, walked_is_camera ? t - 1 : s, walked_is_camera, &from_light);
                    split_off(f, walked, walked_is_camera ? t : s - 1, walked_is_camera, &from_camera);
                    std::vector<PathVertex>& light = from_light.light;
                    std::vector<PathVertex>& cam = from_camera.cam;
                    for (int i = std::max(0, s - 2); i < s; ++i) light[size_t(i)].pdf_rev = 123.0f;
                    for (int i = std::max(0, t - 3); i < t; ++i) cam[size_t(i)].pdf_rev = 321.0f;
                    sum += vcm_merge_weight(&f.settings, &f.camera, &f.scene, light.data(), cam.data(), s, t);
                    totals->merges += 1;
                    any = true;
                }
                if (!any) continue;
                INFO((walked_is_camera ? "camera" : "light") << " subpath of " << n << " vertices, light type " << x[0].type
                                                              << ", heuristic " << heuristic << ", mask " << mask << ", samples of t = 1 "
                                                              << f.settings.bdpt.light_tracing_samples << " and of s >= 2 "
                                                              << f.settings.bdpt.connection_samples << ": sum " << sum << ", slack " << slack);
                // float rounding of the ratios' running products, plus what the recorded directions allow
                CHECK(std::fabs(sum - 1.0) <= 1e-4 + slack);
            }
    }
    totals->paths += 1;
    totals->delta += any_delta ? 1 : 0;
    if (x[0].type == VERTEX_ENVIRONMENT) {
        totals->environment += 1;
        if (!disk_reaches(f.settings, x[0].p, x[1].p)) totals->environment_unreached += 1;
    } else if (x[0].type == VERTEX_LIGHT && f.scene.lights[x[0].index].type == LIGHT_POINT) {
        totals->point += 1;
    } else {
        totals->sphere += 1;
    }
}

}  // namespace

TEST_CASE("BDPT: the MIS weights of all strategies that can make a walked path sum to 1", "[render][bdpt][mis]") {
    Fixture f;
    PathCounters counters{};
    const int max_vertices = f.settings.bdpt.max_vertices;
    std::vector<PathVertex> cam(static_cast<size_t>(max_vertices)), light(static_cast<size_t>(max_vertices));
    Totals totals;
    for (int sample = 0; sample < 3000; ++sample) {
        const int pixel = (sample * 37) % (32 * 32);
        Rng rng = rng_make(uint(pixel), uint(sample), 5u, 0u);
        const int n_cam = bdpt_camera_subpath(&f.settings, f.march, &f.camera, &f.scene, pixel, &rng, cam.data(), max_vertices, &counters);
        const int n_light = bdpt_light_subpath(&f.settings, f.march, &f.scene, &rng, light.data(), max_vertices - 1, &counters);
        // camera subpaths that end on a light: every prefix that does
        for (int t = 2; t <= n_cam; ++t)
            if (vertex_emits(&f.scene, &cam[size_t(t - 1)])) check_path(f, std::vector<PathVertex>(cam.begin(), cam.begin() + t), true, &totals);
        // light subpaths joined to the lens where it sees them
        Rng lens_rng = rng_make(uint(pixel), uint(sample), 6u, 0u);
        for (int s = 2; s <= n_light; ++s) {
            const PathVertex& qs = light[size_t(s - 1)];
            if (qs.type == VERTEX_ENVIRONMENT) continue;
            float4 u = rng_next4(&lens_rng);
            CameraSample cs = camera_sample_wi(&f.camera, qs.p, make_float2(u.x, u.y));
            // a path t = 1 can make: the lens sees the vertex, whose BSDF (not a mirror's) sends light there
            if (!cs.visible || !(max_component(vertex_f(&f.scene, &qs, cs.wi, TRANSPORT_IMPORTANCE)) > 0.0f)) continue;
            if (!segment_unoccluded(bdpt_ray_origin(&qs, cs.wi), cs.wi, cs.distance, -1, f.march, &counters)) continue;
            std::vector<PathVertex> walked(light.begin(), light.begin() + s);
            walked.push_back(camera_vertex(&f.camera, cs.lens_point, float3(1.0f)));
            walked.back().pdf_fwd = walked.back().pdf_rev = 0.0f;
            check_path(f, walked, false, &totals);
        }
    }
    INFO("paths " << totals.paths << ": from a sphere " << totals.sphere << ", a point light " << totals.point << ", the environment "
                  << totals.environment << " (" << totals.environment_unreached << " where its disk does not reach), through a mirror "
                  << totals.delta << "; merges weighed " << totals.merges);
    CHECK(totals.sphere > 100);
    CHECK(totals.point > 100);
    CHECK(totals.environment > 100);
    CHECK(totals.environment_unreached > 20);
    CHECK(totals.delta > 50);
    CHECK(totals.merges > 1000);
}

}  // namespace bdpt_mis_test

TEST_CASE("BDPT: every strategy a path can have gets a code of its own (its --strategies image and random stream)", "[render][bdpt][mis]") {
    std::vector<int> codes;
    for (int s = 0; s <= BDPT_VERTEX_LIMIT; ++s)
        for (int t = 1; s + t <= BDPT_VERTEX_LIMIT; ++t) codes.push_back(kernel::bdpt_strategy_code(s, t));
    std::sort(codes.begin(), codes.end());
    CHECK(std::adjacent_find(codes.begin(), codes.end()) == codes.end());
}
