// BDPT's MIS weights (kernels/bdpt_mis.h) on constructed paths: for every path, the weights of all
// the strategies that can make it sum to 1, with the balance and the power heuristic, over every
// strategy mask (bdpt, the path tracer's s <= 1, the light tracer's t = 1, ...). The paths start on
// each kind of light (a sphere, a point light: delta in position, the environment: at infinity)
// and pass Lambert walls and a mirror (a delta lobe). Each subpath's densities are filled in as
// kernels/bdpt_walk.h records them (forward along its own direction, reverse from the other side,
// 0 next to a delta lobe), except that the connection's endpoints and their neighbours carry a
// walk's stale reverse densities, which the weight must replace; a strategy "can make" the path when neither connection endpoint is a
// delta lobe and, for s = 0, the path starts on an emitter. Host only, no device.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "kernels/host.hpp"
#include "ibl/environment.hpp"
#include "render/camera_setup.hpp"
#include "tests/lobe_material.hpp"

namespace bdpt_mis_test {
using namespace ::kernel;
// The MIS code never marches; path.h only needs the scene's functions declared.
inline float scene_distance(float3) { return 1.0f; }
inline float scene_distance_material(float3, int* material) {
    *material = 0;
    return 1.0f;
}
inline int scene_analytic_normal(float3, float3*) { return 0; }
#include "sdf/march.h"
#include "sdf/normals.h"
#include "kernels/bdpt_mis.h"
}  // namespace bdpt_mis_test

namespace {

using namespace bdpt_mis_test;
using brdf::float3;

constexpr int kLambert = 0, kMirror = 1, kSphereSlot = 2;
constexpr int kEnvironment = 0, kSphere = 1, kPoint = 2;

struct Fixture {
    std::vector<brdf::Material> materials;
    std::vector<brdf::float4> emission{brdf::float4(0.0f), brdf::float4(0.0f), brdf::float4(1.0f, 1.0f, 1.0f, EMISSION_ABSORBS)};
    std::vector<kernel::Light> lights;
    std::vector<float> cdf{0.0f, 0.3f, 0.7f, 1.0f};
    std::vector<int> light_of_slot{-1, -1, kSphere};
    lab::ibl::Environment env = lab::ibl::Environment::constant(float3(1.0f), "constant", lab::ibl::EnvironmentOptions{});
    RenderScene scene{};
    RenderKernelSettings k{};
    kernel::Camera camera{};

    Fixture() {
        materials.push_back(lobe_material(1, 0, 0, 0));
        brdf::Material mirror = lobe_material(0, 0, 1, 0);
        mirror.roughness = 0.0f;
        materials.push_back(mirror);
        materials.push_back(lobe_material(1, 0, 0, 0));
        kernel::Light e{}, s{}, p{};
        e.type = LIGHT_ENVIRONMENT;
        e.material_slot = -1;
        s.type = LIGHT_SPHERE;
        float3_to_array(float3(0.0f, 3.0f, 0.0f), s.position);
        s.radius = 0.5f;
        float3_to_array(float3(1.0f), s.emission);
        s.material_slot = kSphereSlot;
        p.type = LIGHT_POINT;
        float3_to_array(float3(0.3f, 2.5f, 0.2f), p.position);
        float3_to_array(float3(1.0f), p.emission);
        p.material_slot = -1;
        lights = {e, s, p};
        scene = render_scene_make(materials.data(), brdf::measured_tables(), emission.data(), lights.data(), cdf.data(), light_of_slot.data(), env.map(),
                                  env.texels().data(), env.alias().data());
        k.light_count = 3;
        k.scene_radius = 5.0f;
        k.max_distance = 100.0f;
        lab::scene::Camera c;
        c.type = lab::scene::CameraType::pinhole;
        c.position = float3(0.2f, 1.0f, 5.0f);
        c.look_at = float3(0.0f, 1.0f, 0.0f);
        c.fov_degrees = 90.0f;
        camera = lab::render::make_camera(c, 64, 64, "test");
    }
};

// A point of a constructed path.
struct Point {
    int type;  // VERTEX_*
    float3 p, n;
    int index;  // slot of a surface, light index of a light
};

PathVertex make_vertex(const Point& q) {
    PathVertex v{};
    v.type = q.type;
    v.p = q.p;
    v.index = q.index;
    v.on_surface = q.type == VERTEX_SURFACE || (q.type == VERTEX_LIGHT && q.index == kSphere);
    v.frame = frame_from_normal(q.type == VERTEX_ENVIRONMENT ? -q.p : q.n);
    return v;
}

bool is_delta(const Point& q) { return q.type == VERTEX_SURFACE && q.index == kMirror; }

// The path x_0 (light) .. x_{n-1} (camera) as both subpaths record it. x_0 is on the light side a
// light vertex; on the camera side the sphere is an emissive surface.
struct Subpaths {
    std::vector<PathVertex> light, cam;
};

Subpaths record(const Fixture& f, const std::vector<Point>& x) {
    int n = int(x.size());
    std::vector<PathVertex> lv(n), cv(n);
    for (int i = 0; i < n; ++i) {
        lv[i] = make_vertex(x[i]);
        Point c = x[i];
        if (i == 0 && c.type == VERTEX_LIGHT && c.index == kSphere) {
            c.type = VERTEX_SURFACE;
            c.index = kSphereSlot;
        }
        cv[i] = make_vertex(c);
        lv[i].delta = cv[i].delta = is_delta(x[i]);
        if (lv[i].type == VERTEX_SURFACE) {  // wo: towards the light side on the light subpath, the camera side on the camera's
            if (i > 0) lv[i].wo = frame_to_local(lv[i].frame, vertex_direction(&lv[i], &lv[i - 1]));
            if (i + 1 < n) cv[i].wo = frame_to_local(cv[i].frame, vertex_direction(&cv[i], &cv[i + 1]));
        }
    }
    const RenderKernelSettings* k = &f.k;
    std::vector<float> fwd_light(n), fwd_cam(n);
    for (int i = 0; i < n; ++i) {
        if (i == 0) fwd_light[i] = vertex_pdf_light_origin(k, &f.scene, &lv[0]);
        else if (i == 1) fwd_light[i] = vertex_pdf_light(k, &f.scene, &lv[0], &lv[1]);
        else fwd_light[i] = is_delta(x[i - 1]) ? 0.0f : vertex_pdf(k, &f.camera, &f.scene, &lv[i - 2], &lv[i - 1], &lv[i]);
        if (i == n - 1) fwd_cam[i] = 0.0f;
        else if (i + 1 < n && is_delta(x[i + 1])) fwd_cam[i] = 0.0f;
        else fwd_cam[i] = vertex_pdf(k, &f.camera, &f.scene, i + 2 < n ? &cv[i + 2] : nullptr, &cv[i + 1], &cv[i]);
    }
    Subpaths sp;
    for (int i = 0; i < n; ++i) {
        lv[i].pdf_fwd = fwd_light[i];
        lv[i].pdf_rev = fwd_cam[i];
        sp.light.push_back(lv[i]);
    }
    for (int m = 0; m < n; ++m) {
        PathVertex v = cv[n - 1 - m];
        v.pdf_fwd = fwd_cam[n - 1 - m];
        v.pdf_rev = fwd_light[n - 1 - m];
        sp.cam.push_back(v);
    }
    return sp;
}

bool can_make(const std::vector<Point>& x, int s, int t) {
    if (s == 1 && t == 1) return false;  // bdpt leaves (1, 1) to (0, 2); these paths are longer
    if (s == 0) return !(x[0].type == VERTEX_LIGHT && x[0].index == kPoint);
    if (t == 1) return !is_delta(x[s - 1]) && x[s - 1].type != VERTEX_ENVIRONMENT;
    return !is_delta(x[s - 1]) && !is_delta(x[s]);
}

// The sum of the weights of the enabled strategies that can make path x; -1 when none can.
double weight_sum(Fixture& f, const std::vector<Point>& x) {
    Subpaths sp = record(f, x);
    int n = int(x.size());
    double sum = 0.0;
    bool any = false;
    for (int s = 0; s < n; ++s) {
        int t = n - s;
        if (!can_make(x, s, t) || !bdpt_strategy_enabled(f.k.strategies, s, t)) continue;
        // A walk leaves in the endpoints and their neighbours the reverse densities of its own
        // continuation, not of this connection: the weight must not read them.
        Subpaths walked = sp;
        for (int i = std::max(0, s - 2); i < s; ++i) walked.light[i].pdf_rev = 123.0f;
        for (int i = std::max(0, t - 2); i < t; ++i) walked.cam[i].pdf_rev = 321.0f;
        PathVertex sampled = s == 1 ? walked.light[0] : walked.cam[0];
        sum += bdpt_mis_weight(&f.k, &f.camera, &f.scene, walked.light.data(), walked.cam.data(), &sampled, s, t);
        any = true;
    }
    return any ? sum : -1.0;
}

}  // namespace

TEST_CASE("BDPT: the MIS weights of all strategies that can make a path sum to 1", "[render][bdpt][mis]") {
    Fixture f;
    const float3 up(0.0f, 1.0f, 0.0f);
    Point sphere{VERTEX_LIGHT, float3(0.0f, 2.5f, 0.0f), -up, kSphere};
    Point point{VERTEX_LIGHT, float3(0.3f, 2.5f, 0.2f), float3(0.0f), kPoint};
    Point environment{VERTEX_ENVIRONMENT, glm::normalize(float3(0.2f, 1.0f, 0.1f)), float3(0.0f), kEnvironment};
    Point floor{VERTEX_SURFACE, float3(0.0f, 0.0f, 0.0f), up, kLambert};
    Point wall{VERTEX_SURFACE, float3(1.5f, 1.0f, 0.0f), float3(-1.0f, 0.0f, 0.0f), kLambert};
    Point mirror{VERTEX_SURFACE, float3(1.5f, 1.0f, 0.0f), float3(-1.0f, 0.0f, 0.0f), kMirror};
    Point other{VERTEX_SURFACE, float3(-1.0f, 0.8f, 0.5f), float3(1.0f, 0.0f, 0.0f), kLambert};
    Point camera{VERTEX_CAMERA, float3(0.2f, 1.0f, 5.0f), float3(0.0f), 0};
    std::vector<std::vector<Point>> paths = {
        {sphere, floor, camera},
        {sphere, floor, wall, camera},
        {sphere, floor, wall, other, floor, camera},
        {sphere, mirror, floor, camera},
        {sphere, floor, mirror, camera},
        {point, floor, camera},
        {point, floor, wall, other, camera},
        {point, mirror, floor, camera},
        {point, floor, mirror, other, camera},
        {environment, floor, camera},
        {environment, floor, wall, camera},
        {environment, mirror, floor, camera},
        {environment, floor, mirror, camera},
    };
    int checked = 0;
    for (int heuristic : {MIS_BALANCE, MIS_POWER})
        for (int mask : {STRATEGY_ALL, STRATEGY_S0 | STRATEGY_S1, STRATEGY_T1, STRATEGY_S1 | STRATEGY_S2 | STRATEGY_T1, STRATEGY_S0 | STRATEGY_S2})
            for (size_t p = 0; p < paths.size(); ++p) {
                f.k.mis_heuristic = heuristic;
                f.k.strategies = mask;
                double sum = weight_sum(f, paths[p]);
                if (sum < 0.0) continue;
                INFO("path " << p << ", heuristic " << heuristic << ", mask " << mask);
                CHECK(sum == Approx(1.0).epsilon(1e-5));
                ++checked;
            }
    CHECK(checked > 100);
}
