// White-furnace tests of the preview (the path tracer, kernels/path_tracer.cl, on PoCL): the test model without its
// ground under a constant environment of radiance 1. A white Lambert surface then reflects exactly
// what it receives, however many bounces a path takes, so every pixel must be 1. Conductors of
// albedo 1 lose what their microfacet model loses (single scattering); on a convex sphere, where no
// reflected ray returns, every pixel lies between the material's smallest directional albedo and 1. A dark pixel would be a path that
// leaked, self-shadowed or got stuck; a bright one a pdf or weight that does not match its sampler.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "film/image_stats.hpp"
#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/lobe_material.hpp"
#include "tests/render_inputs.hpp"
#include "validation/albedo.hpp"

namespace {

using lab::film::ImageRgb;
using IblSampling = lab::render::LightSampling;

brdf::Material white_lambert() {
    brdf::Material m = lobe_material(1, 0, 0, 0);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    return m;
}

// A conductor whose Fresnel is 1 at every angle: all the energy it loses is the microfacet model's.
brdf::Material white_conductor(int distribution, float roughness) {
    brdf::Material m = lobe_material(0, 1, 0, 0);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    m.metallic = 1.0f;
    m.roughness = roughness;
    m.distribution = distribution;
    m.hc_shape = 3.0f;
    m.energy_compensation = 0;  // single scattering: the loss these tests check (compensation: tests/test_energy_compensation.cpp)
    return m;
}

using Render = RenderResult;

// A lone sphere filling most of the image: convex, so every reflected ray escapes and a pixel
// shows exactly the single-scattering albedo at its view angle.
const char* kSphereScene = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 3.2], "look_at": [0, 0, 0], "fov_degrees": 40},
  "materials": {"sample": {"albedo": [1, 1, 1], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "ball", "material": "sample", "shape": {"type": "sphere", "radius": 1}}]
})";

Render furnace(const lab::opencl::Runtime& runtime, const brdf::Material& material, IblSampling sampling, int spp, uint64_t seed = 1,
               bool convex = false) {
    // The sphere scene has no ground to switch off.
    lab::render::RenderInput input = render_input(material, "constant:1,1,1", 48, sampling, seed, convex ? kSphereScene : "", convex);
    // A white furnace never ends a path by roulette, only by depth; between the core and the shell a
    // path of albedo 1 can bounce hundreds of times before it finds the window.
    input.settings.max_depth = 512;
    lab::render::OpenClRenderer renderer(runtime, input);
    return render_samples(renderer, spp);
}

struct Range {
    float lo = INFINITY, hi = -INFINITY;
};

Range pixel_range(const ImageRgb& image) {
    Range r;
    for (float v : image.rgb) {
        r.lo = std::min(r.lo, v);
        r.hi = std::max(r.hi, v);
    }
    return r;
}

// Typical per-pixel noise of one render: two renders with different seeds differ by sqrt(2) sigma.
double pixel_noise(const ImageRgb& a, const ImageRgb& b) { return lab::film::image_error(a, b).rmse_mean / std::sqrt(2.0); }

// ---- the lone sphere, seen by kSphereScene's camera -------------------------------------------------
// The camera is at (0, 0, 3.2) looking down -z with a vertical field of view of 40 degrees on a
// square image (kernels/camera.h). The cosine of the view angle where the ray through the
// image point (x, y), in pixels, meets the unit sphere; 0 where it misses.
double sphere_view_cosine(double x, double y, int size) {
    const double t = std::tan(20.0 * M_PI / 180.0), eye = 3.2;
    const double sx = (2.0 * x / size - 1.0) * t, sy = (1.0 - 2.0 * y / size) * t;
    const double norm = std::sqrt(sx * sx + sy * sy + 1.0);
    const double dx = sx / norm, dy = sy / norm, dz = -1.0 / norm;
    // |o + s d|^2 = 1 with o = (0, 0, eye): s^2 + 2 s eye dz + eye^2 - 1 = 0
    const double b = eye * dz, disc = b * b - (eye * eye - 1.0);
    if (disc <= 0.0) return 0.0;
    const double s = -b - std::sqrt(disc);
    const double nx = s * dx, ny = s * dy, nz = eye + s * dz;  // the hit point is its own normal
    return -(dx * nx + dy * ny + dz * nz);
}

// Pixels whose whole square sees the sphere (all four corners and the centre hit it): the only ones
// whose value is the material's, not a blend with the backdrop. Their view cosines' range.
struct SpherePixel {
    size_t index;
    double cos_min, cos_max, cos_centre;
};
std::vector<SpherePixel> sphere_pixels(int size) {
    std::vector<SpherePixel> out;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double c[5] = {sphere_view_cosine(x, y, size), sphere_view_cosine(x + 1, y, size), sphere_view_cosine(x, y + 1, size),
                           sphere_view_cosine(x + 1, y + 1, size), sphere_view_cosine(x + 0.5, y + 0.5, size)};
            if (*std::min_element(c, c + 5) <= 0.0) continue;
            out.push_back({size_t(y) * size + x, *std::min_element(c, c + 4), *std::max_element(c, c + 4), c[4]});
        }
    return out;
}

// The per-sample standard deviation of a white Lambert sphere's pixels under a constant sky of 1,
// in closed form: one vertex, the sphere hides exactly the lower hemisphere, so with c the cosine
// of a direction to the normal,
//   env sampling (uniform over the sphere, c uniform in [-1, 1]): X = 4 c [c > 0], variance 5/3;
//   MIS (power heuristic, one env and one cosine-weighted BSDF sample, independent):
//     X = 4 c_e / (1 + 16 c_e^2) [c_e > 0] + 16 c_b^2 / (1 + 16 c_b^2), c_b with density 2 c_b;
// their variances by quadrature (mean 1 - ln 17 / 16 + ln 17 / 16 = 1).
double lambert_sphere_sample_sigma(IblSampling sampling) {
    if (sampling == IblSampling::lights) return std::sqrt(5.0 / 3.0);
    const int n = 200000;
    double e1 = 0.0, e1_sq = 0.0, e2 = 0.0, e2_sq = 0.0;
    for (int k = 0; k < n; ++k) {
        const double c = (k + 0.5) / n;
        const double env = 4.0 * c / (1.0 + 16.0 * c * c), bsdf = 16.0 * c * c / (1.0 + 16.0 * c * c);
        e1 += 0.5 * env / n;  // c_e uniform on [-1, 1]: density 1/2, and 0 below
        e1_sq += 0.5 * env * env / n;
        e2 += 2.0 * c * bsdf / n;
        e2_sq += 2.0 * c * bsdf * bsdf / n;
    }
    REQUIRE(e1 + e2 == Approx(1.0).margin(1e-6));
    return std::sqrt(e1_sq - e1 * e1 + e2_sq - e2 * e2);
}

}  // namespace

TEST_CASE("Furnace: a white Lambert test model is 1 in every pixel (BSDF sampling, no noise)", "[furnace][preview][opencl]") {
    lab::opencl::Runtime runtime("");
    Render r = furnace(runtime, white_lambert(), IblSampling::bsdf, 4);
    Range range = pixel_range(r.image);
    INFO("pixels in [" << range.lo << ", " << range.hi << "], lost rays " << r.stats.lost_rays << " of " << r.stats.rays);
    CHECK(r.stats.nonfinite_samples == 0);
    CHECK(range.lo > 0.99f);
    CHECK(range.hi < 1.01f);
}

TEST_CASE("Furnace: environment sampling and MIS give 1 on a white Lambert sphere, within their closed-form noise", "[furnace][preview][opencl]") {
    // The tolerance comes from the estimator's variance in closed form, not from the image: a bug
    // that adds variance fails the noise check instead of widening its own tolerance. Means are
    // over the pixels that see the sphere, not over the backdrop (exactly 1 by construction).
    lab::opencl::Runtime runtime("");
    const int spp = 64;
    const std::vector<SpherePixel> pixels = sphere_pixels(48);
    REQUIRE(pixels.size() > 600);
    for (IblSampling sampling : {IblSampling::lights, IblSampling::mis}) {
        const double sigma = lambert_sphere_sample_sigma(sampling) / std::sqrt(double(spp));  // per pixel
        Render r = furnace(runtime, white_lambert(), sampling, spp, 1, true);
        double sum = 0.0, sum_sq = 0.0;
        float lo = INFINITY, hi = -INFINITY;
        for (const SpherePixel& p : pixels) {
            const double v = r.image.rgb[p.index * 3];
            sum += v;
            sum_sq += (v - 1.0) * (v - 1.0);
            lo = std::min(lo, float(v));
            hi = std::max(hi, float(v));
        }
        const double n = double(pixels.size()), mean = sum / n, rms = std::sqrt(sum_sq / n);
        INFO(lab::render::light_sampling_name(sampling) << ": mean over " << pixels.size() << " sphere pixels " << mean << ", rms deviation "
                                                  << rms << ", closed-form sigma " << sigma << ", pixels in [" << lo << ", " << hi << "]");
        CHECK(r.stats.nonfinite_samples == 0);
        CHECK(std::fabs(mean - 1.0) < 4.0 * sigma / std::sqrt(n));
        // the pixels' spread is the closed-form one (its own estimate is good to about 1 / sqrt(2 n))
        CHECK(rms < sigma * (1.0 + 4.0 / std::sqrt(2.0 * n)));
        CHECK(rms > sigma * (1.0 - 4.0 / std::sqrt(2.0 * n)));
        CHECK(lo > 1.0 - 6.0 * sigma);
        CHECK(hi < 1.0 + 6.0 * sigma);
    }
}

TEST_CASE("Furnace: a white GGX conductor sphere shows in each pixel the albedo at that pixel's view angle", "[furnace][preview][opencl]") {
    // Each pixel against the directional albedo at its own view angle (over the range of angles its
    // square spans), not one band for all. Noise bound: with visible-normal sampling the BSDF
    // sample's weight G2 / G1 is at most 1 and the power-heuristic light sample's at most half of
    // it, so a sample lies in [0, 1.5]: standard deviation at most 0.75 (Popoviciu).
    lab::opencl::Runtime runtime("");
    const brdf::Material material = white_conductor(BRDF_DISTRIBUTION_GGX, 0.6f);
    const int spp = 64;
    const double sigma = 0.75 / std::sqrt(double(spp));
    // the albedo against the cosine of the view angle, tabulated finely (standard error < 1e-4)
    const int table = 256;
    std::vector<double> albedo(table + 1);
    for (int k = 0; k <= table; ++k) {
        const double c = std::max(1e-3, double(k) / table), sin_t = std::sqrt(1.0 - c * c);
        albedo[size_t(k)] = lab::validation::directional_albedo(material, brdf::float3(float(sin_t), 0.0f, float(c)), 64).value.x;
    }
    auto albedo_at = [&](double c) { return albedo[size_t(std::lround(c * table))]; };
    Render r = furnace(runtime, material, IblSampling::mis, spp, 1, true);
    CHECK(r.stats.nonfinite_samples == 0);
    double deviation = 0.0;
    int outside = 0;
    const std::vector<SpherePixel> pixels = sphere_pixels(48);
    for (const SpherePixel& p : pixels) {
        double lo = 1.0, hi = 0.0;
        for (int k = int(std::floor(p.cos_min * table)); k <= int(std::ceil(p.cos_max * table)) && k <= table; ++k) {
            lo = std::min(lo, albedo[size_t(k)]);
            hi = std::max(hi, albedo[size_t(k)]);
        }
        const double v = r.image.rgb[p.index * 3];
        deviation += v - albedo_at(p.cos_centre);
        if (v < lo - 5.0 * sigma || v > hi + 5.0 * sigma) ++outside;
    }
    const double n = double(pixels.size());
    INFO("mean deviation from each pixel's own albedo " << deviation / n << " over " << pixels.size() << " pixels, " << outside
                                                        << " outside 5 sigma (" << 5.0 * sigma << ") of their albedo range");
    CHECK(std::fabs(albedo_at(1.0) - albedo_at(0.1)) > 5.0 * sigma / std::sqrt(n));  // the angle matters here
    CHECK(std::fabs(deviation / n) < 4.0 * sigma / std::sqrt(n) + 2e-3);  // + the pixel squares' angle spread
    CHECK(outside == 0);
}

TEST_CASE("Furnace: a white Hyper-Cauchy conductor sphere loses only its single-scattering energy", "[furnace][preview][opencl]") {
    // Hyper-Cauchy normals are sampled from D cos, whose weights have no bound, so the noise figure
    // is measured - on two other seeds than the image checked.
    lab::opencl::Runtime runtime("");
    const brdf::Material material = white_conductor(BRDF_DISTRIBUTION_HYPER_CAUCHY, 0.6f);
    double smallest = 1.0;
    for (float theta = 0.0f; theta <= 88.0f; theta += 4.0f)
        smallest = std::min(smallest, double(lab::validation::directional_albedo(material, brdf::direction_from_degrees(theta, 0.0f), 64).value.x));
    Render checked = furnace(runtime, material, IblSampling::mis, 32, 1, true);
    Render a = furnace(runtime, material, IblSampling::mis, 32, 2, true), b = furnace(runtime, material, IblSampling::mis, 32, 3, true);
    const double noise = pixel_noise(a.image, b.image);
    float lo = INFINITY, hi = -INFINITY;
    for (const SpherePixel& p : sphere_pixels(48)) {
        lo = std::min(lo, checked.image.rgb[p.index * 3]);
        hi = std::max(hi, checked.image.rgb[p.index * 3]);
    }
    INFO("smallest albedo " << smallest << ", sphere pixels in [" << lo << ", " << hi << "], pixel noise " << noise);
    CHECK(checked.stats.nonfinite_samples == 0);
    CHECK(smallest < 0.999);
    CHECK(lo > smallest - 0.01 - 5.0 * noise);
    CHECK(hi < 1.0 + 0.01 + 5.0 * noise);
}
