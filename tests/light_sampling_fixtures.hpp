// What the lights' sampler tests share (tests/test_light_sampling.cpp, tests/test_image_emitter_sampling.cpp):
// the test's own frames, the cone zoom that stretches a light's directions over the hemisphere for
// the chi-square grid, the rect and disk lights seen from fixed points, and the check of a light's
// power against the flux through a sphere around it.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "common/luminance.hpp"
#include "kernels/host.hpp"
#include "validation/chi_square.hpp"
#include "validation/uniform_random.hpp"

namespace light_fixtures {

using brdf::float3;

inline constexpr double kPi = 3.14159265358979323846;

// An orthonormal frame around a unit axis, in double: the test's own, not the sampler's.
struct Frame {
    glm::dvec3 t, b, n;
};
inline Frame frame_around(glm::dvec3 n) {
    glm::dvec3 helper = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    glm::dvec3 t = glm::normalize(glm::cross(helper, n));
    return {t, glm::cross(n, t), n};
}

// From outside, the visible cap is a cone of directions that may cover a tiny fraction of the
// sphere, too small for a grid over the whole sphere. The test therefore looks at the samples
// through a fixed change of variables that stretches the cone onto the upper hemisphere,
// 1 - cos theta' = (1 - cos theta) / (1 - cos theta_max), phi' = phi (about the axis from p to the
// centre, in the test's own frame, computed in double). Its Jacobian is the constant
// d omega' / d omega = 1 / (1 - cos theta_max), so the stretched samples have density
// pdf(w) (1 - cos theta_max): any error of the sampler or of the pdf shows there unchanged.
struct ConeZoom {
    Frame frame;
    double one_minus_cos_max = 2.0;  // 2: no zoom (from inside, the samples cover the sphere)
    bool active = false;

    ConeZoom(const kernel::Light& l, float3 p) : ConeZoom(glm::dvec3(l.position[0], l.position[1], l.position[2]), l.radius, p) {}
    // The cone from p that holds the ball of radius r about c (no zoom from inside it).
    ConeZoom(glm::dvec3 c, double r, float3 p) {
        const glm::dvec3 q(p);
        const double d = glm::length(c - q);
        frame = frame_around(d > 0.0 ? (c - q) / d : glm::dvec3(0, 0, 1));
        if (d > r) {
            const double s2 = (r / d) * (r / d);
            one_minus_cos_max = s2 / (1.0 + std::sqrt(1.0 - s2));
            active = true;
        }
    }
    // A direction from p -> the stretched direction (or itself without zoom).
    float3 forward(float3 w) const {
        if (!active) return w;
        const glm::dvec3 v = glm::normalize(glm::dvec3(w));
        const double x = glm::dot(v, frame.t), y = glm::dot(v, frame.b), z = glm::dot(v, frame.n);
        const double sin_t = std::sqrt(x * x + y * y);
        // 1 - cos theta = 2 sin^2(theta / 2), without cancellation
        const double theta = std::atan2(sin_t, z);
        const double u = std::fmin(2.0 * std::pow(std::sin(0.5 * theta), 2) / one_minus_cos_max, 1.0);
        const double cos_p = 1.0 - u, sin_p = std::sqrt(std::fmax(0.0, u * (2.0 - u)));
        const double phi = std::atan2(y, x);
        const glm::dvec3 out = frame.t * (sin_p * std::cos(phi)) + frame.b * (sin_p * std::sin(phi)) + frame.n * cos_p;
        return float3(out);
    }
    // A stretched direction -> the direction from p it stands for; false below the horizon.
    bool backward(float3 w, float3* original) const {
        if (!active) {
            *original = w;
            return true;
        }
        const glm::dvec3 v(w);
        const double x = glm::dot(v, frame.t), y = glm::dot(v, frame.b), z = glm::dot(v, frame.n);
        if (!(z > 0.0)) return false;
        const double u = (1.0 - z) * one_minus_cos_max;  // 1 - cos theta
        const double theta = 2.0 * std::asin(std::sqrt(0.5 * u));
        const double phi = std::atan2(y, x);
        const glm::dvec3 out = frame.t * (std::sin(theta) * std::cos(phi)) + frame.b * (std::sin(theta) * std::sin(phi)) +
                               frame.n * std::cos(theta);
        *original = float3(out);
        return true;
    }
    double jacobian() const { return active ? one_minus_cos_max : 1.0; }
};

// The chi-square grid of the lights' tests over `tests` tests (the family they split the
// significance over), with `samples` samples.
inline lab::validation::ChiSquareOptions light_chi_square_options(long samples, int tests) {
    lab::validation::ChiSquareOptions o;
    o.samples = samples;
    o.z_cells = 50;
    o.phi_cells = 100;
    o.seed = 7007;
    o.tests = tests;
    return o;
}

// Rect and disk lights (kernels/lights/area_light.h): a rect of 1 x 0.6 and a disk of radius 0.4 at
// c, tilted (normal t x b of the test's own frame about a slanted axis), and a parallelogram of the
// rect's edges 60 degrees apart, which has no spherical rectangle and is sampled by area.
inline const glm::dvec3 kAreaCenter(0.3, 1.2, -0.4);
inline const Frame kAreaFrame = frame_around(glm::normalize(glm::dvec3(0.3, -1.0, 0.2)));

inline kernel::Light area_light(int type, glm::dvec3 u, glm::dvec3 v, float radius) {
    kernel::Light l{};
    l.type = type;
    kernel::float3_to_array(float3(kAreaCenter), l.position);
    kernel::float3_to_array(float3(u), l.edge_u);
    kernel::float3_to_array(float3(v), l.edge_v);
    l.radius = radius;
    kernel::float3_to_array(float3(2.0f, 2.0f, 2.0f), l.emission);
    l.material_slot = 4;
    return l;
}

inline const kernel::Light kRect = area_light(LIGHT_RECT, kAreaFrame.t * 1.0, kAreaFrame.b * 0.6, 0.0f);
inline const kernel::Light kParallelogram = area_light(LIGHT_RECT, kAreaFrame.t * 1.0, (kAreaFrame.t * 0.5 + kAreaFrame.b * std::sqrt(0.75)) * 0.6, 0.0f);
inline const kernel::Light kDisk = area_light(LIGHT_DISK, kAreaFrame.t * 0.4, kAreaFrame.b * 0.4, 0.4f);

// The radius of a ball about the centre that holds the light with a margin of 10 %: the zoom's cone
// around it keeps the light's corners and rim off the cone's edge, where the zoom's stretch is
// steepest and the cells' quadrature misses slivers of the light.
inline double area_light_reach(const kernel::Light& l) {
    const glm::dvec3 u(l.edge_u[0], l.edge_u[1], l.edge_u[2]), v(l.edge_v[0], l.edge_v[1], l.edge_v[2]);
    if (l.type == LIGHT_DISK) return 1.1 * l.radius;
    return 0.55 * std::max(glm::length(u + v), glm::length(u - v));
}

struct AreaCase {
    const char* what;
    const kernel::Light* light;
    glm::dvec3 offset;  // of p from the centre, in the light's frame (t, b, n)
};

inline const AreaCase kAreaCases[] = {
    {"rect, near: 0.3 above its centre (3.0 sr, spherical rectangle)", &kRect, {0.0, 0.0, 0.3}},
    {"rect, oblique: beside a corner, 65 degrees off its normal (spherical rectangle)", &kRect, {1.4, 0.9, 0.8}},
    {"rect, far: 11 away, 25 degrees off its normal (5e-3 sr, spherical rectangle)", &kRect, {4.0, 2.0, 10.0}},
    {"parallelogram, edges 60 degrees apart (by area)", &kParallelogram, {0.2, -0.3, 0.5}},
    {"disk, near: 0.25 above its rim (by area)", &kDisk, {0.4, 0.0, 0.25}},
    {"disk, oblique: 2 away, 70 degrees off its normal (by area)", &kDisk, {1.3, 1.3, 0.7}},
};
inline constexpr int kAreaCaseCount = sizeof(kAreaCases) / sizeof(kAreaCases[0]);

inline float3 area_case_point(const AreaCase& c) { return float3(kAreaCenter + kAreaFrame.t * c.offset.x + kAreaFrame.b * c.offset.y + kAreaFrame.n * c.offset.z); }

// The flux light l sends through a sphere of radius 2 about (0.5, 1, -0.2) against `power`: the
// irradiance its samples estimate at points spread evenly over the sphere, E(x) = L cos / pdf per
// sample with cos against the outward normal, integrated over the sphere's area. 400 x 800 strata
// of (cos theta, phi), one point and one light sample each: the standard error of the integral, from
// the spread of the strata's estimates (an over-estimate for strata), is required at most 0.25 % and
// the integral within 1 %.
inline void check_flux_through_sphere(const kernel::Light& l, kernel::EnvironmentBuffers b, double power, uint64_t seed, const std::string& what) {
    const glm::dvec3 center(0.5, 1.0, -0.2);
    const double radius = 2.0;
    lab::validation::UniformRandom rng(seed);
    constexpr int kBands = 400, kSectors = 800;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < kBands; ++i)
        for (int j = 0; j < kSectors; ++j) {
            const double z = -1.0 + 2.0 * (i + rng.next_double()) / kBands, phi = 2.0 * kPi * (j + rng.next_double()) / kSectors;
            const double s = std::sqrt(1.0 - z * z);
            const glm::dvec3 outward(s * std::cos(phi), s * std::sin(phi), z);
            const float3 x(center + radius * outward);
            const kernel::LightSample ls = kernel::sample_light(&l, nullptr, b, x, kernel::make_float2(rng.next_float(), rng.next_float()));
            double e = 0.0;
            if (ls.pdf > 0.0f)
                e = lab::luminance(double(ls.radiance.x), double(ls.radiance.y), double(ls.radiance.z)) *
                    std::max(0.0, -glm::dot(glm::dvec3(ls.wi), outward)) / double(ls.pdf);
            sum += e;
            sum2 += e * e;
        }
    const double n = double(kBands) * kSectors, mean = sum / n;
    const double area = 4.0 * kPi * radius * radius, flux = area * mean;
    const double standard_error = area * std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1.0));
    std::printf("[lights] %s: flux through the sphere %.5f +- %.5f, power %.5f (%+.3f %%)\n", what.c_str(), flux, standard_error, power,
                100.0 * (flux / power - 1.0));
    INFO(what << ": flux " << flux << " +- " << standard_error << ", power " << power);
    REQUIRE(standard_error < 0.0025 * power);
    CHECK(flux == Approx(power).epsilon(0.01));
}

}  // namespace light_fixtures
