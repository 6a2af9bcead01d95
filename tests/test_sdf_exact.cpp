// The exact ray intersections (sdf/exact/) against the distance fields they stand for
// (sdf/primitives/): for each primitive, the first root of the field along the ray, found by a
// conservative march and bisection in double precision of t, to 1e-9 (the field itself is the
// float one, evaluated at points rounded once to float). Rays from outside and inside, grazing rays,
// rays along the axes and rays from 1e4 units away; misses must be misses.
//
// Tolerances come from float rounding, not from the code under test: the hit point's position is
// good to a few ulps of its coordinates' scale, kPositionUlps * 2^-24 * (|o| + t + size), and t to
// that divided by the cosine between the ray and the surface's normal at the root (a grazing ray's
// t is ill-conditioned: a small move of the surface moves it far along the ray).
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "sdf/sdf.hpp"

namespace {

using Vec3 = glm::vec3;
using DVec3 = glm::dvec3;

constexpr double kPositionUlps = 64.0;

struct Primitive {
    std::string name;
    float size;  // the primitive's extent, for tolerances and ray placement
    std::function<float(Vec3)> field;
    std::function<Vec3(Vec3)> normal;
    std::function<float(Vec3, Vec3, float)> hit;
};

std::vector<Primitive> primitives() {
    const Vec3 half(0.8f, 0.5f, 0.3f);
    const Vec3 n = glm::normalize(Vec3(0.3f, 1.0f, -0.2f));
    return {
        {"sphere", 1.0f, [](Vec3 p) { return sdf::fSphere(p, 1.0f); }, [](Vec3 p) { return sdf::nSphere(p, 1.0f); },
         [](Vec3 o, Vec3 v, float t) { return sdf::xSphere(o, v, 1.0f, t); }},
        {"plane", 1.0f, [n](Vec3 p) { return sdf::fPlane(p, n, 0.25f); }, [n](Vec3 p) { return sdf::nPlane(p, n, 0.25f); },
         [n](Vec3 o, Vec3 v, float t) { return sdf::xPlane(o, v, n, 0.25f, t); }},
        {"box", 0.8f, [half](Vec3 p) { return sdf::fBox(p, half); }, [half](Vec3 p) { return sdf::nBox(p, half); },
         [half](Vec3 o, Vec3 v, float t) { return sdf::xBox(o, v, half, t); }},
        {"round_box", 0.8f, [half](Vec3 p) { return sdf::fRoundBox(p, half, 0.2f); }, [half](Vec3 p) { return sdf::nRoundBox(p, half, 0.2f); },
         [half](Vec3 o, Vec3 v, float t) { return sdf::xRoundBox(o, v, half, 0.2f, t); }},
        {"torus", 1.3f, [](Vec3 p) { return sdf::fTorus(p, 1.0f, 0.3f); }, [](Vec3 p) { return sdf::nTorus(p, 1.0f, 0.3f); },
         [](Vec3 o, Vec3 v, float t) { return sdf::xTorus(o, v, 1.0f, 0.3f, t); }},
        {"cylinder", 0.7f, [](Vec3 p) { return sdf::fCylinder(p, 0.5f, 0.7f); }, [](Vec3 p) { return sdf::nCylinder(p, 0.5f, 0.7f); },
         [](Vec3 o, Vec3 v, float t) { return sdf::xCylinder(o, v, 0.5f, 0.7f, t); }},
        {"capsule", 1.0f, [](Vec3 p) { return sdf::fCapsule(p, 0.4f, 0.6f); }, [](Vec3 p) { return sdf::nCapsule(p, 0.4f, 0.6f); },
         [](Vec3 o, Vec3 v, float t) { return sdf::xCapsule(o, v, 0.4f, 0.6f, t); }},
        {"cone", 1.2f, [](Vec3 p) { return sdf::fCone(p, 0.6f, 1.2f); }, [](Vec3 p) { return sdf::nCone(p, 0.6f, 1.2f); },
         [](Vec3 o, Vec3 v, float t) { return sdf::xCone(o, v, 0.6f, 1.2f, t); }},
    };
}

// The field at o + t v, the point computed in double and rounded once to float.
float field_at(const Primitive& p, Vec3 o, Vec3 v, double t) { return p.field(Vec3(DVec3(o) + t * DVec3(v))); }

// The first sign change of the field along the ray in (0, t_max]: a march that steps by |f| (safe:
// the fields are exact distances) but at least `floor`, then bisection of the bracket to 1e-9.
// Returns INFINITY when there is none (a touch narrower than `floor` counts as none).
double reference_root(const Primitive& p, Vec3 o, Vec3 v, double t_max) {
    const double floor = 1e-6 * p.size;
    double t0 = 0.0;
    float f0 = field_at(p, o, v, 0.0);
    if (f0 == 0.0f) f0 = field_at(p, o, v, floor);
    for (int i = 0; i < 2000000; ++i) {
        double t1 = t0 + std::fmax(std::fabs(double(f0)), floor);
        if (t1 > t_max) return INFINITY;
        float f1 = field_at(p, o, v, t1);
        if (f1 == 0.0f) {  // on the surface: a crossing only if the far side has the other sign
            t0 = t1;
            continue;
        }
        if ((f0 > 0.0f) != (f1 > 0.0f)) {
            double lo = t0, hi = t1;
            while (hi - lo > 1e-9 * std::fmax(1.0, lo)) {
                double mid = 0.5 * (lo + hi);
                if ((field_at(p, o, v, mid) > 0.0f) == (f0 > 0.0f)) lo = mid;
                else hi = mid;
            }
            return 0.5 * (lo + hi);
        }
        t0 = t1;
        f0 = f1;
    }
    return INFINITY;
}

struct Ray {
    Vec3 o, v;
    const char* kind;
};

Vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        Vec3 d(g(rng), g(rng), g(rng));
        if (glm::length(d) > 1e-3f) return glm::normalize(d);
    }
}

// A point on the surface near q: q moved along the normal by the distance.
Vec3 onto_surface(const Primitive& p, Vec3 q) {
    for (int i = 0; i < 4; ++i) q -= p.normal(q) * p.field(q);
    return q;
}

std::vector<Ray> rays_for(const Primitive& p, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto inside_box = [&] { return Vec3(u(rng), u(rng), u(rng)) * (1.2f * p.size); };
    std::vector<Ray> rays;
    for (int i = 0; i < 60; ++i) {  // outside, aimed at a point of the bounding region (hits and misses)
        Vec3 o = random_unit(rng) * (4.0f * p.size);
        rays.push_back({o, glm::normalize(inside_box() - o), "outside"});
    }
    for (int i = 0; i < 40; ++i) {  // inside the solid (for the plane, below it)
        Vec3 q = inside_box();
        if (p.field(q) < -1e-3f * p.size) rays.push_back({q, random_unit(rng), "inside"});
    }
    for (int i = 0; i < 40; ++i) {  // grazing: nearly tangent where they enter, 1-2 degrees in
        Vec3 s = onto_surface(p, inside_box());
        Vec3 n = p.normal(s);
        Vec3 tangent = glm::normalize(glm::cross(n, random_unit(rng)));
        Vec3 v = glm::normalize(tangent - n * (0.02f + 0.015f * std::fabs(u(rng))));
        rays.push_back({s - v * (2.0f * p.size), v, "grazing"});
    }
    for (int axis = 0; axis < 3; ++axis)  // along the axes, through the centre and off it
        for (float sign : {-1.0f, 1.0f})
            for (float offset : {0.0f, 0.25f}) {
                Vec3 v(0.0f);
                v[axis] = sign;
                Vec3 o = -v * (3.0f * p.size);
                o[(axis + 1) % 3] += offset * p.size;
                rays.push_back({o, v, "axis"});
            }
    for (int i = 0; i < 20; ++i) {  // from 1e4 units away
        Vec3 o = random_unit(rng) * 1e4f;
        rays.push_back({o, glm::normalize(inside_box() * 0.5f - o), "far"});
    }
    return rays;
}

}  // namespace

TEST_CASE("Exact intersection: each primitive's closed form hits where its distance field's root is", "[sdf][exact]") {
    std::mt19937 rng(35);
    for (const Primitive& p : primitives()) {
        int hits = 0, misses = 0;
        for (const Ray& ray : rays_for(p, rng)) {
            const float t_max = 3e4f;
            const double reference = reference_root(p, ray.o, ray.v, t_max);
            const float t = p.hit(ray.o, ray.v, t_max);
            INFO(p.name << " " << ray.kind << " ray o = (" << ray.o.x << ", " << ray.o.y << ", " << ray.o.z << "), v = (" << ray.v.x << ", "
                        << ray.v.y << ", " << ray.v.z << "): exact " << t << ", field root " << reference);
            // a root where the field has the same sign a little before and after it is a touch (a
            // ray along an edge or a rim, within float rounding): either answer is right there
            const double delta = 1e-4 * p.size;
            const bool touch = std::isfinite(reference) && (field_at(p, ray.o, ray.v, reference - delta) > 0.0f) ==
                                                              (field_at(p, ray.o, ray.v, reference + delta) > 0.0f);
            if (!std::isfinite(reference) || touch) {
                // a touch of the surface within float rounding may count as a hit
                if (std::isfinite(t)) CHECK(std::fabs(field_at(p, ray.o, ray.v, t)) <= 1e-5f * p.size);
                else ++misses;
                continue;
            }
            REQUIRE(std::isfinite(t));
            ++hits;
            const double scale = glm::length(ray.o) + reference + p.size;
            const double position_tolerance = kPositionUlps * std::ldexp(1.0, -24) * scale;
            const Vec3 root = Vec3(DVec3(ray.o) + reference * DVec3(ray.v));
            const double cosine = std::fmax(std::fabs(double(glm::dot(p.normal(root), ray.v))), 1e-3);
            CHECK(std::fabs(double(t) - reference) <= position_tolerance / cosine + 1e-9 * reference);
        }
        INFO(p.name);
        CHECK(hits >= 40);  // the ray sets exercise both outcomes
        CHECK(misses >= 5);
    }
}

TEST_CASE("Exact intersection: t_max cuts the hit, and a ray leaving a convex solid's surface does not hit it again", "[sdf][exact]") {
    const Vec3 o(0.0f, 0.0f, 5.0f), v(0.0f, 0.0f, -1.0f);
    CHECK(sdf::xSphere(o, v, 1.0f, 4.0f) == 4.0f);
    CHECK(std::isinf(sdf::xSphere(o, v, 1.0f, 3.999f)));
    CHECK(sdf::xBox(o, v, Vec3(1.0f), 100.0f) == 4.0f);
    // a reflected ray from a point just off the sphere's surface: both roots behind it
    const Vec3 p(0.0f, 0.0f, 1.0f + 2e-5f);
    CHECK(std::isinf(sdf::xSphere(p, glm::normalize(Vec3(0.3f, 0.0f, 1.0f)), 1.0f, 100.0f)));
    CHECK(std::isinf(sdf::xBox(p, glm::normalize(Vec3(0.3f, 0.0f, 1.0f)), Vec3(1.0f), 100.0f)));
}
