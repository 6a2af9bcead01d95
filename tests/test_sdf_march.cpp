// Sphere tracing (sdf/march.h) on host test scenes: hits at the analytic distance, misses,
// running out of steps, marching from inside a solid, over-relaxation (same hits, fewer steps,
// no tunnelling through a thin slab), and dividing by a Lipschitz bound above 1.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "sdf/sdf.hpp"

// The scene the marcher traces: whatever the test case installs.
namespace sdf_test_march {
using namespace sdf;
static std::function<float(float3)> current_distance;
inline float scene_distance(float3 p) { return current_distance(p); }
inline float scene_march_distance(float3 p) { return scene_distance(p); }
inline int scene_analytic_normal(float3, float3*) { return 0; }
#include "sdf/march.h"
#include "sdf/normals.h"
}  // namespace sdf_test_march

using sdf::float3;
namespace scene = sdf_test_march;

namespace {

float epsilon_at(const scene::MarchSettings& s, float t) { return std::fmax(s.epsilon_min, s.epsilon_relative * t); }

// Nearest t >= 0 where the ray meets the sphere |p - c| = r from outside or inside; -1 if none.
double ray_sphere(float3 o, float3 d, float3 c, float r) {
    double ox = double(o.x) - c.x, oy = double(o.y) - c.y, oz = double(o.z) - c.z;
    double b = ox * d.x + oy * d.y + oz * d.z;
    double cc = ox * ox + oy * oy + oz * oz - double(r) * r;
    double disc = b * b - cc;
    if (disc < 0.0) return -1.0;
    double s = std::sqrt(disc);
    if (-b - s >= 0.0) return -b - s;
    if (-b + s >= 0.0) return -b + s;
    return -1.0;
}

float3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> g(0.0f, 1.0f);
    for (;;) {
        float3 v(g(rng), g(rng), g(rng));
        float l = glm::length(v);
        if (l > 1e-6f) return v / l;
    }
}

// A camera's rays: a w x h grid over a 60-degree vertical field of view.
std::vector<float3> camera_rays(float3 eye, float3 target, int w, int h) {
    float3 forward = glm::normalize(target - eye);
    float3 right = glm::normalize(glm::cross(forward, float3(0, 1, 0)));
    float3 up = glm::cross(right, forward);
    float half = std::tan(0.5f * 60.0f * 3.14159265f / 180.0f);
    std::vector<float3> rays;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            float x = (2.0f * (i + 0.5f) / w - 1.0f) * half * float(w) / float(h);
            float y = (1.0f - 2.0f * (j + 0.5f) / h) * half;
            rays.push_back(glm::normalize(forward + right * x + up * y));
        }
    return rays;
}

}  // namespace

TEST_CASE("SDF march: a sphere is hit at the analytic distance, missed, or the steps run out", "[sdf]") {
    scene::current_distance = [](float3 p) { return sdf::fSphere(p, 1.0f); };
    const scene::MarchSettings s = scene::march_settings_default(1.0f);
    CHECK(s.over_relaxation == 1.0f);
    CHECK(s.max_steps == 256);
    CHECK(scene::march_epsilon(s, 0.01f) == 1e-5f);
    CHECK(scene::march_epsilon(s, 4.0f) == epsilon_at(s, 4.0f));

    // head on: t = 4, within the hit threshold
    scene::MarchResult head_on = scene::march(float3(0, 0, -5), float3(0, 0, 1), 0.0f, s);
    CHECK(head_on.status == MARCH_HIT);
    CHECK(std::fabs(head_on.t - 4.0f) <= epsilon_at(s, 4.0f));
    CHECK(head_on.steps <= 3);

    // oblique rays: never past the surface, short of it by at most epsilon along the normal
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 0.9f);
    double worst_depth = 0.0;
    int oblique = 0;
    for (int i = 0; i < 500; ++i) {
        float3 o = random_direction(rng) * 5.0f;
        float3 target = random_direction(rng) * u(rng);
        float3 d = glm::normalize(target - o);
        double t_exact = ray_sphere(o, d, float3(0), 1.0f);
        REQUIRE(t_exact > 0.0);
        float3 hit = o + d * float(t_exact);
        double cos_theta = std::fabs(glm::dot(d, glm::normalize(hit)));
        scene::MarchResult r = scene::march(o, d, 0.0f, s);
        INFO("ray " << i << ": t " << r.t << ", exact " << t_exact << ", status " << r.status);
        REQUIRE(r.status == MARCH_HIT);
        CHECK(r.t <= t_exact + 1e-5);
        double depth = (t_exact - r.t) * cos_theta;  // how far short of the surface, along its normal
        CHECK(depth <= epsilon_at(s, r.t));
        worst_depth = std::fmax(worst_depth, depth / epsilon_at(s, r.t));
        ++oblique;
    }
    std::printf("SDF march: %d oblique rays hit the unit sphere, worst shortfall along the normal %.3f epsilon\n", oblique, worst_depth);

    // misses: pointing away, and passing at distance 0.5 from the surface
    scene::MarchResult away = scene::march(float3(0, 0, -5), float3(0, 0, -1), 0.0f, s);
    CHECK(away.status == MARCH_MISS);
    CHECK(away.t > s.max_distance);
    scene::MarchResult past = scene::march(float3(0, 1.5f, -5), float3(0, 0, 1), 0.0f, s);
    CHECK(past.status == MARCH_MISS);
    CHECK(past.steps < 20);
    scene::MarchResult beyond = scene::march(float3(0, 0, -5), float3(0, 0, 1), 200.0f, s);
    CHECK(beyond.status == MARCH_MISS);
    CHECK(beyond.steps == 0);

    // grazing: passes 2e-4 above the sphere, so steps shrink near the tangent point
    scene::MarchSettings few = s;
    few.max_steps = 8;
    scene::MarchResult grazing = scene::march(float3(0, 1.0002f, -5), float3(0, 0, 1), 0.0f, few);
    CHECK(grazing.status == MARCH_OUT_OF_STEPS);
    CHECK(grazing.steps == 8);
    CHECK(grazing.t > 4.0f);
    CHECK(grazing.t < 5.0f);
}

TEST_CASE("SDF march: from inside a solid the ray finds the inner surface", "[sdf]") {
    scene::current_distance = [](float3 p) { return sdf::fSphere(p, 1.0f); };
    std::mt19937 rng(11);
    for (float omega : {1.0f, 1.5f}) {
        scene::MarchSettings s = scene::march_settings_default(1.0f);
        s.over_relaxation = omega;
        for (int i = 0; i < 200; ++i) {
            float3 o = i < 100 ? float3(0.0f) : float3(0.3f, 0.2f, -0.1f);
            float3 d = random_direction(rng);
            double t_exact = ray_sphere(o, d, float3(0), 1.0f);
            scene::MarchResult r = scene::march(o, d, 0.0f, s);
            INFO("omega " << omega << ", ray " << i << ": t " << r.t << ", exact " << t_exact);
            REQUIRE(r.status == MARCH_HIT);
            CHECK(r.t <= t_exact + 1e-5);
            CHECK(t_exact - r.t <= 2.0 * epsilon_at(s, r.t));
        }
    }
}

TEST_CASE("SDF march: over-relaxation hits the same surfaces in fewer steps and never tunnels", "[sdf]") {
    // ground, sphere, box, torus: the usual mix of head-on and grazing rays
    scene::current_distance = [](float3 p) {
        float d = sdf::fPlane(p, float3(0, 1, 0), 1.0f);
        d = sdf::fOpUnion(d, sdf::fSphere(p, 1.0f));
        d = sdf::fOpUnion(d, sdf::fBox(p - float3(2.5f, -0.5f, 1.0f), float3(0.5f, 0.5f, 0.8f)));
        d = sdf::fOpUnion(d, sdf::fTorus(p - float3(-2.5f, -0.6f, 0.5f), 0.8f, 0.3f));
        return d;
    };
    const float3 eye(0.0f, 1.5f, -6.0f);
    std::vector<float3> rays = camera_rays(eye, float3(0.0f, -0.3f, 0.0f), 96, 64);
    scene::MarchSettings plain = scene::march_settings_default(1.0f);
    scene::MarchSettings relaxed = plain;
    relaxed.over_relaxation = 1.5f;
    long steps_plain = 0, steps_relaxed = 0;
    int hits = 0, same = 0, grazing_differences = 0;
    double worst_depth = 0.0;
    for (const float3& d : rays) {
        scene::MarchResult a = scene::march(eye, d, 0.0f, plain);
        scene::MarchResult b = scene::march(eye, d, 0.0f, relaxed);
        steps_plain += a.steps;
        steps_relaxed += b.steps;
        if (a.status != MARCH_HIT) {
            if (b.status == a.status) ++same;
            continue;
        }
        ++hits;
        // the difference of the two hit points measured along the surface normal: both lie within
        // epsilon of the surface, in front of it
        float3 n = scene::normal_central(eye + d * a.t, 1e-3f);
        double depth = std::fabs(double(b.t) - a.t) * std::fabs(glm::dot(n, d));
        if (b.status == MARCH_HIT && depth <= 2.0 * epsilon_at(plain, a.t)) {
            ++same;
            worst_depth = std::fmax(worst_depth, depth / epsilon_at(plain, a.t));
        } else {
            // a ray that passes within epsilon of a silhouette: plain tracing stops there, the
            // larger steps may sample past that near-miss and go on to the surface behind
            ++grazing_differences;
            CHECK(b.t >= a.t);  // never in front of the first surface
        }
    }
    const int n = int(rays.size());
    double avg_plain = double(steps_plain) / n, avg_relaxed = double(steps_relaxed) / n;
    std::printf("SDF march over %d camera rays (%d hits): average steps %.2f plain, %.2f with omega = 1.5 (%.1f%% fewer); "
                "%d grazing differences, worst hit-depth difference %.3f epsilon\n",
                n, hits, avg_plain, avg_relaxed, 100.0 * (1.0 - avg_relaxed / avg_plain), grazing_differences, worst_depth);
    CHECK(hits > n / 2);
    CHECK(same + grazing_differences == n);
    CHECK(grazing_differences <= n / 100);
    CHECK(avg_relaxed <= avg_plain);
}

TEST_CASE("SDF march: over-relaxation does not tunnel through a thin slab", "[sdf]") {
    // a slab 0.01 thick: y in [-0.005, 0.005]
    scene::current_distance = [](float3 p) { return sdf::fBox(p, float3(20.0f, 0.005f, 20.0f)); };
    // Over-relaxation without Keinert's overlap test, to show the rays below can tunnel.
    auto naive = [](float3 o, float3 d, float omega, float max_distance) {
        float t = 0.0f;
        for (int i = 0; i < 256 && t <= max_distance; ++i) {
            float r = std::fabs(scene::scene_distance(o + d * t));
            if (r < 1e-4f * t + 1e-5f) return t;
            t += omega * r;
        }
        return INFINITY;
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int naive_tunnels = 0;
    const int kRays = 2000;
    for (float omega : {1.5f, 1.9f}) {
        scene::MarchSettings plain = scene::march_settings_default(1.0f);
        scene::MarchSettings relaxed = plain;
        relaxed.over_relaxation = omega;
        for (int i = 0; i < kRays; ++i) {
            // from 2 above the slab, elevations from 0.5 to 89 degrees
            float elevation = (0.5f + 88.5f * u(rng)) * 3.14159265f / 180.0f;
            float azimuth = 6.2831853f * u(rng);
            float3 o(0.0f, 2.0f, 0.0f);
            float3 d(std::cos(elevation) * std::cos(azimuth), -std::sin(elevation), std::cos(elevation) * std::sin(azimuth));
            double t_top = (2.0 - 0.005) / std::sin(double(elevation));
            if (t_top * std::cos(double(elevation)) > 19.5) continue;  // past the slab's edge
            scene::MarchResult a = scene::march(o, d, 0.0f, plain);
            scene::MarchResult b = scene::march(o, d, 0.0f, relaxed);
            INFO("omega " << omega << ", elevation " << elevation << ": plain t " << a.t << ", relaxed t " << b.t << ", top at " << t_top);
            REQUIRE(a.status == MARCH_HIT);
            REQUIRE(b.status == MARCH_HIT);
            CHECK(b.t <= t_top + 1e-4);
            CHECK(std::fabs(b.t - a.t) * std::sin(elevation) <= 2.0f * epsilon_at(plain, a.t));
            naive_tunnels += naive(o, d, omega, 100.0f) > t_top + 0.01;
        }
    }
    std::printf("SDF march: thin slab, %d rays at omega 1.5 and 1.9: no tunnelling; naive over-relaxation tunnels on %d\n", 2 * kRays,
                naive_tunnels);
    CHECK(naive_tunnels > 0);
}

TEST_CASE("SDF march: dividing by the Lipschitz bound keeps a displaced sphere from being overshot", "[sdf]") {
    const float amplitude = 0.25f, frequency = 10.0f;
    auto f = [=](float3 p) { return sdf::fOpDisplaceSine(sdf::fSphere(p, 1.2f), p, amplitude, frequency); };
    scene::current_distance = f;
    const float lipschitz = sdf::lipschitz_displace_sine(1.0f, amplitude, frequency);  // 3.5
    // the first crossing along the ray, by dense sampling and bisection
    auto first_crossing = [&](float3 o, float3 d) {
        const double dt = 1e-3;
        double t0 = 0.0;
        float f0 = f(o);
        for (double t = dt; t < 8.0; t += dt) {
            float f1 = f(o + d * float(t));
            if ((f0 > 0.0f) != (f1 > 0.0f)) {
                double lo = t0, hi = t;
                for (int k = 0; k < 40; ++k) {
                    double mid = 0.5 * (lo + hi);
                    if ((f(o + d * float(mid)) > 0.0f) == (f0 > 0.0f)) lo = mid;
                    else hi = mid;
                }
                return lo;
            }
            t0 = t;
            f0 = f1;
        }
        return -1.0;
    };
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.3f, 1.3f);
    int rays = 0, overshoot_bounded = 0, overshoot_unbounded = 0;
    long steps_bounded = 0;
    for (int i = 0; i < 400; ++i) {
        float3 o = random_direction(rng) * 4.0f;
        float3 d = glm::normalize(float3(u(rng), u(rng), u(rng)) - o);
        double t_ref = first_crossing(o, d);
        if (t_ref < 0.0) continue;
        ++rays;
        scene::MarchSettings bounded = scene::march_settings_default(lipschitz);
        scene::MarchResult a = scene::march(o, d, 0.0f, bounded);
        steps_bounded += a.steps;
        INFO("ray " << i << ": t " << a.t << ", first crossing " << t_ref << ", status " << a.status);
        CHECK(a.status == MARCH_HIT);
        CHECK(a.t <= t_ref + 1e-4);
        overshoot_bounded += a.t > t_ref + 1e-4;
        scene::MarchResult b = scene::march(o, d, 0.0f, scene::march_settings_default(1.0f));
        overshoot_unbounded += b.status != MARCH_HIT || b.t > t_ref + 1e-3;
    }
    std::printf("SDF march: displaced sphere (bound %.2f), %d rays: %d overshoot dividing by %.2f (%.1f steps on average), "
                "%d overshoot dividing by 1\n",
                lipschitz, rays, overshoot_bounded, lipschitz, double(steps_bounded) / rays, overshoot_unbounded);
    CHECK(rays > 200);
    CHECK(overshoot_bounded == 0);
    CHECK(overshoot_unbounded > 0);  // the bound matters: taking the field for a distance overshoots
}
