// The lights' samplers (kernels/lights/) against their densities: chi-square of sphere-light
// samples against sphere_light_pdf from outside (near and far, small and large caps) and inside, of
// rect and disk samples against area_light_pdf (spherical rectangles near, oblique and far; area
// sampling of a parallelogram and of disks) and their power against the flux through a sphere,
// the pdf a sample carries equals light_pdf, the densities integrate to 1, the area sampler, the
// point light, the environment light against ibl's sampler, light selection, and the power of
// every kind of light against hand-computed values (docs/lights.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include "common/input_error.hpp"
#include "common/luminance.hpp"
#include "film/image_output.hpp"
#include "film/tone_map.hpp"
#include "ibl/environment.hpp"
#include "kernels/host.hpp"
#include "render/emitter_images.hpp"
#include "render/light_set.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "validation/chi_square.hpp"
#include "validation/uniform_random.hpp"

using brdf::float3;
namespace validation = lab::validation;

namespace {

constexpr double kPi = 3.14159265358979323846;

kernel::Light sphere_light(float3 center, float radius, float3 radiance) {
    kernel::Light l{};
    l.type = LIGHT_SPHERE;
    kernel::float3_to_array(center, l.position);
    l.radius = radius;
    kernel::float3_to_array(radiance, l.emission);
    l.material_slot = 3;
    return l;
}

// An orthonormal frame around a unit axis, in double: the test's own, not the sampler's.
struct Frame {
    glm::dvec3 t, b, n;
};
Frame frame_around(glm::dvec3 n) {
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

// What every light sample from p promises beyond its point and normal: the pdf it carries is the
// light's pdf of its direction (`pdf`, to 2e-4), distance is |position - p|, wi points at the point,
// radiance is Le and it is no delta; the first broken promise, or empty. `scale` sets the tolerance
// of lengths: the distance from p to the light's far side.
std::string sample_promise_defect(const kernel::Light& l, const kernel::LightSample& ls, float3 p, float pdf, double scale, const std::string& what) {
    const glm::dvec3 to_point = glm::dvec3(ls.position) - glm::dvec3(p);
    if (!(std::fabs(pdf - ls.pdf) <= 2e-4f * ls.pdf)) return "sample pdf " + std::to_string(ls.pdf) + " but " + what + "_pdf " + std::to_string(pdf);
    if (std::fabs(glm::length(to_point) - ls.distance) > 1e-5 * scale) return "distance is not |position - p|";
    if (glm::length(glm::cross(glm::normalize(to_point), glm::dvec3(ls.wi))) * glm::length(to_point) > 1e-5 * scale)
        return "wi does not point at the sampled point";
    if (!(ls.radiance == float3(l.emission[0], l.emission[1], l.emission[2])) || ls.delta != 0)
        return "radiance is not Le, or a " + what + " sample claims to be a delta";
    return "";
}

// The sphere light's sampler as a direction sampler; each sample must keep the promises that
// kernels/lights/light.h makes: the pdf it carries is sphere_light_pdf of its direction, its point
// lies on the sphere with the outward normal, wi points at that point, distance is the distance.
validation::DirectionSampler sphere_sampler(const kernel::Light& l, float3 p, const ConeZoom& zoom) {
    return [&l, p, &zoom](float3 u) {
        validation::DirectionSample s;
        const kernel::LightSample ls = kernel::sphere_light_sample(&l, p, kernel::make_float2(u.x, u.y));
        if (!(ls.pdf > 0.0f)) return s;  // Failed
        s.kind = validation::SampleKind::Continuous;
        s.wi = zoom.forward(ls.wi);
        const glm::dvec3 c(l.position[0], l.position[1], l.position[2]);
        const double scale = glm::length(c - glm::dvec3(p)) + l.radius;
        if (std::fabs(glm::length(glm::dvec3(ls.position) - c) - l.radius) > 1e-5 * scale)
            s.defect = "sampled point off the sphere";
        else if (glm::length(glm::dvec3(ls.normal) - (glm::dvec3(ls.position) - c) / double(l.radius)) > 1e-3)
            s.defect = "normal is not the outward normal at the point";
        else
            s.defect = sample_promise_defect(l, ls, p, kernel::sphere_light_pdf(&l, p, ls.wi), scale, "sphere_light");
        return s;
    };
}

validation::DirectionDensity sphere_density(const kernel::Light& l, float3 p, const ConeZoom& zoom) {
    return [&l, p, &zoom](float3 w) {
        float3 original;
        if (!zoom.backward(w, &original)) return 0.0;
        return double(kernel::sphere_light_pdf(&l, p, original)) * zoom.jacobian();
    };
}

struct SphereCase {
    const char* what;
    float3 p;
};

// One light, seen from near and far, with small and large caps, and from inside.
const kernel::Light kLight = sphere_light(float3(0.3f, 1.2f, -0.4f), 0.5f, float3(4.0f, 3.0f, 2.0f));
const SphereCase kCases[] = {
    {"outside, far: a cap of 0.14 degrees", float3(0.3f, 1.2f, -0.4f) + float3(120.0f, -80.0f, 90.0f)},
    {"outside, tiny: sin theta_max = 2.5e-4 (below pbrt's 1.5-degree switch)", float3(0.3f, 1.2f, -0.4f) + float3(0.0f, 0.0f, 2000.0f)},
    {"outside, medium: 3 radii away", float3(0.3f, 1.2f, -0.4f) + float3(0.9f, -1.0f, 0.6f)},
    {"outside, near: 1.02 radii from the centre", float3(0.3f, 1.2f, -0.4f) + float3(0.0f, 0.51f, 0.0f)},
    {"inside, at the centre", float3(0.3f, 1.2f, -0.4f)},
    {"inside, 0.7 radii off centre", float3(0.3f, 1.2f, -0.4f) + float3(0.2f, -0.25f, 0.1f)},
    {"inside, 0.995 radii off centre (next to the surface)", float3(0.3f, 1.2f, -0.4f) + float3(0.0f, 0.0f, 0.4975f)},
};
constexpr int kCaseCount = sizeof(kCases) / sizeof(kCases[0]);

validation::ChiSquareOptions chi_square_options(long samples) {
    validation::ChiSquareOptions o;
    o.samples = samples;
    o.z_cells = 50;
    o.phi_cells = 100;
    o.seed = 7007;
    o.tests = kCaseCount;
    return o;
}

}  // namespace

TEST_CASE("lights: sphere light samples follow sphere_light_pdf (chi-square, outside and inside)", "[lights]") {
    for (const SphereCase& c : kCases) {
        const ConeZoom zoom(kLight, c.p);
        const validation::ChiSquareResult r =
            validation::chi_square_test(sphere_sampler(kLight, c.p, zoom), sphere_density(kLight, c.p, zoom), chi_square_options(1000000));
        INFO(c.what << ": " << validation::describe(r));
        std::printf("[lights] chi-square sphere light, %s: %s\n", c.what, validation::describe(r).c_str());
        CHECK(r.passed);
        CHECK(r.failed_fraction == 0.0);
        CHECK(r.pdf_integral == Approx(1.0).margin(2e-3));
    }
}

TEST_CASE("lights: the chi-square test rejects a wrong cone sampler and a wrong cone pdf", "[lights]") {
    const float3 p = kCases[2].p;
    const ConeZoom zoom(kLight, p);
    // theta uniform in [0, theta_max] instead of cos theta: the wrong distribution over the cap
    const validation::DirectionSampler theta_uniform = [&](float3 u) {
        validation::DirectionSample s;
        const glm::dvec3 c(kLight.position[0], kLight.position[1], kLight.position[2]);
        const double d = glm::length(c - glm::dvec3(p)), theta = std::asin(kLight.radius / d) * u.x, phi = 2.0 * kPi * u.y;
        const Frame f = frame_around((c - glm::dvec3(p)) / d);
        s.wi = zoom.forward(float3(f.t * (std::sin(theta) * std::cos(phi)) + f.b * (std::sin(theta) * std::sin(phi)) + f.n * std::cos(theta)));
        s.kind = validation::SampleKind::Continuous;
        return s;
    };
    validation::ChiSquareResult wrong_sampler = validation::chi_square_test(theta_uniform, sphere_density(kLight, p, zoom), chi_square_options(200000));
    std::printf("[lights] broken input, theta-uniform cone sampler: %s\n", validation::describe(wrong_sampler).c_str());
    CHECK_FALSE(wrong_sampler.passed);
    // the cone pdf with 1 - cos theta_max taken as sin^2(theta_max) (off by the factor 1 + cos)
    const validation::DirectionDensity wrong_pdf = [&](float3 w) {
        float3 original;
        if (!zoom.backward(w, &original)) return 0.0;
        const double pdf = kernel::sphere_light_pdf(&kLight, p, original);
        const double d2 = glm::dot(glm::dvec3(p) - glm::dvec3(kLight.position[0], kLight.position[1], kLight.position[2]),
                                   glm::dvec3(p) - glm::dvec3(kLight.position[0], kLight.position[1], kLight.position[2]));
        const double s2 = kLight.radius * kLight.radius / d2;
        return pdf > 0.0 ? zoom.jacobian() / (2.0 * kPi * s2) : 0.0;
    };
    const auto sampler = sphere_sampler(kLight, p, zoom);
    validation::ChiSquareResult wrong_density = validation::chi_square_test(sampler, wrong_pdf, chi_square_options(200000));
    std::printf("[lights] broken input, cone pdf 1 / (2 pi sin^2 theta_max): %s\n", validation::describe(wrong_density).c_str());
    CHECK_FALSE(wrong_density.passed);
}

TEST_CASE("lights: sphere_light_pdf integrates to 1 over the sphere and vanishes off the cap", "[lights]") {
    // Midpoint rule over (cos theta, phi) about the axis to the centre, d omega = d cos dphi: the
    // grid is the test's, so the cap's edge falls inside cells (error of the order of one band).
    for (const SphereCase& c : kCases) {
        const glm::dvec3 center(kLight.position[0], kLight.position[1], kLight.position[2]);
        const double d = glm::length(center - glm::dvec3(c.p));
        const Frame f = frame_around(d > 0.0 ? (center - glm::dvec3(c.p)) / d : glm::dvec3(0, 0, 1));
        const bool inside = d <= kLight.radius;
        const double cos_max = inside ? -1.0 : std::sqrt(1.0 - std::pow(kLight.radius / d, 2));
        // the bands cover [cos_max - margin, 1]: outside them the pdf must be 0 (checked below)
        const double lo = inside ? -1.0 : std::fmax(-1.0, cos_max - 0.1 * (1.0 - cos_max));
        const int bands = 4000, sectors = 64;
        double sum = 0.0;
        for (int i = 0; i < bands; ++i) {
            const double z = lo + (i + 0.5) * (1.0 - lo) / bands, s = std::sqrt(1.0 - z * z);
            for (int k = 0; k < sectors; ++k) {
                const double phi = (k + 0.5) * 2.0 * kPi / sectors;
                const float3 w(f.t * (s * std::cos(phi)) + f.b * (s * std::sin(phi)) + f.n * z);
                sum += kernel::sphere_light_pdf(&kLight, c.p, w);
            }
        }
        const double integral = sum * (1.0 - lo) / bands * 2.0 * kPi / sectors;
        INFO(c.what << ": integral " << integral);
        std::printf("[lights] sphere light pdf integral, %s: %.6f\n", c.what, integral);
        // outside, the edge tolerance of kernels/lights/sphere_light.h adds 2e-7 / sin(theta_max)
        CHECK(integral == Approx(1.0).margin(inside ? 1e-3 : 1e-3 + 2e-7 * d / kLight.radius));
        if (!inside) {
            const float3 away(f.t * 0.0 + f.n * -1.0), beside(f.t * std::sqrt(1.0 - std::pow(cos_max - 0.01 * (1.0 - cos_max), 2)) +
                                                               f.n * (cos_max - 0.01 * (1.0 - cos_max)));
            CHECK(kernel::sphere_light_pdf(&kLight, c.p, away) == 0.0f);
            CHECK(kernel::sphere_light_pdf(&kLight, c.p, glm::normalize(beside)) == 0.0f);
        }
    }
}

TEST_CASE("lights: sphere area sampling is uniform by area and matches the pdf from inside", "[lights]") {
    // Normals of area samples are uniform on the unit sphere: chi-square against 1 / (4 pi).
    const validation::DirectionSampler normals = [](float3 u) {
        validation::DirectionSample s;
        float3 n;
        const float3 x = kernel::sphere_light_sample_area(&kLight, kernel::make_float2(u.x, u.y), &n);
        s.kind = validation::SampleKind::Continuous;
        s.wi = n;
        const glm::dvec3 c(kLight.position[0], kLight.position[1], kLight.position[2]);
        if (glm::length(glm::dvec3(x) - c - glm::dvec3(n) * double(kLight.radius)) > 1e-6) s.defect = "point is not centre + r n";
        return s;
    };
    validation::ChiSquareOptions o = chi_square_options(1000000);
    o.tests = 1;
    const validation::ChiSquareResult r = validation::chi_square_test(normals, [](float3) { return 1.0 / (4.0 * kPi); }, o);
    std::printf("[lights] chi-square sphere area sampling (normals against 1 / 4 pi): %s\n", validation::describe(r).c_str());
    INFO(validation::describe(r));
    CHECK(r.passed);
    CHECK(kernel::sphere_light_area_pdf(&kLight) == Approx(1.0 / (4.0 * kPi * 0.25)).epsilon(1e-6));
    // From inside, the area density converted at the point the ray leaves through equals the pdf.
    validation::UniformRandom rng(99);
    const float3 p = kCases[5].p;
    for (int k = 0; k < 1000; ++k) {
        float3 n;
        const float3 x = kernel::sphere_light_sample_area(&kLight, kernel::make_float2(rng.next_float(), rng.next_float()), &n);
        const glm::dvec3 v = glm::dvec3(x) - glm::dvec3(p);
        const double d = glm::length(v), cos_l = std::fabs(glm::dot(glm::dvec3(n), v / d));
        if (cos_l < 1e-2) continue;  // grazing: the conversion is ill-conditioned in float
        const double expected = kernel::sphere_light_area_pdf(&kLight) * d * d / cos_l;
        REQUIRE(kernel::sphere_light_pdf(&kLight, p, float3(v / d)) == Approx(expected).epsilon(1e-4));
    }
}

TEST_CASE("lights: a point light is a delta with radiance I / d^2", "[lights]") {
    kernel::Light l{};
    l.type = LIGHT_POINT;
    kernel::float3_to_array(float3(1.0f, 2.0f, 3.0f), l.position);
    kernel::float3_to_array(float3(5.0f, 6.0f, 7.0f), l.emission);
    l.material_slot = -1;
    const float3 p(1.0f, -1.0f, -1.0f);  // distance 5
    const kernel::LightSample s = kernel::point_light_sample(&l, p);
    CHECK(s.delta == 1);
    CHECK(s.pdf == 1.0f);
    CHECK(s.distance == Approx(5.0f));
    CHECK(glm::length(s.wi - float3(0.0f, 0.6f, 0.8f)) < 1e-6f);
    CHECK(glm::length(s.radiance - float3(5.0f, 6.0f, 7.0f) / 25.0f) < 1e-6f);
    CHECK(s.position == float3(1.0f, 2.0f, 3.0f));
    CHECK(glm::length(s.normal + s.wi) < 1e-6f);
    // no direction finds a delta light: its pdf for MIS is 0, through the dispatcher too
    const lab::ibl::Environment env = lab::ibl::load_environment("constant:1,1,1", {});
    const kernel::EnvironmentBuffers b{env.texels().data(), env.alias().data()};
    CHECK(kernel::light_pdf(&l, &env.map(), b, p, s.wi) == 0.0f);
    const kernel::LightSample d = kernel::sample_light(&l, &env.map(), b, p, kernel::make_float2(0.3f, 0.6f));
    CHECK(d.delta == 1);
    CHECK(d.radiance == s.radiance);
    // at the light itself there is no direction: no sample
    CHECK(kernel::point_light_sample(&l, float3(1.0f, 2.0f, 3.0f)).pdf == 0.0f);
}

TEST_CASE("lights: the environment light is ibl's sampler, radiance and pdf", "[lights]") {
    // turned by 40 degrees, one stop up, faces of 16 texels
    const lab::ibl::Environment env = lab::ibl::load_environment("envmaps/sunset.exr", {40.0f, 1.0f, 16});
    const kernel::EnvironmentBuffers b{env.texels().data(), env.alias().data()};
    kernel::Light l{};
    l.type = LIGHT_ENVIRONMENT;
    l.material_slot = -1;
    validation::UniformRandom rng(4242);
    const float3 p(0.4f, 0.1f, -2.0f);
    for (int k = 0; k < 20000; ++k) {
        const float u1 = rng.next_float(), u2 = rng.next_float();
        float pdf = 0.0f;
        const float3 w = env.sample(u1, u2, &pdf);
        const kernel::LightSample s = kernel::sample_light(&l, &env.map(), b, p, kernel::make_float2(u1, u2));
        REQUIRE(s.wi == w);
        REQUIRE(s.pdf == pdf);
        REQUIRE(s.radiance == env.radiance(w));
        REQUIRE(s.distance == LIGHT_INFINITE_DISTANCE);
        REQUIRE(s.delta == 0);
        REQUIRE(kernel::light_pdf(&l, &env.map(), b, p, s.wi) == pdf);
        const float3 any = glm::normalize(float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        REQUIRE(kernel::environment_light_pdf(&env.map(), b, any) == env.pdf(any));
    }
}

namespace {

// A scene with every kind of light: two spheres (one of them reflecting), two point lights.
const char* kLightScene = R"({
  "camera": {"type": "pinhole", "position": [0, 1, 4], "look_at": [0, 1, 0]},
  "materials": {"white": {"albedo": [0.8, 0.8, 0.8], "lobes": {"diffuse": 1}}},
  "objects": [{"name": "box", "material": "white", "shape": {"type": "box", "half_size": [1, 1, 1]}}],
  "emitters": [
    {"center": [0, 3, 0], "radius": 0.5, "radiance": [2, 2, 2]},
    {"type": "point", "position": [1, 2, 3], "intensity": [1, 1, 1]},
    {"center": [2, 0, 0], "radius": 0.25, "radiance": [10, 0, 0], "material": "white"},
    {"type": "point", "position": [-1, 2, 3], "intensity": [0, 3, 0]}
  ]
})";

}  // namespace

TEST_CASE("lights: the light set's power formulas, order, slots and selection", "[lights]") {
    const lab::scene::CompiledScene scene = lab::scene::compile_scene(lab::scene::parse_scene(kLightScene, "scenes/lights.json"));
    const lab::ibl::Environment env = lab::ibl::load_environment("constant:0.5,0.5,0.5", {});
    const lab::render::LightSet set = lab::render::build_light_set(scene, &env, lab::render::LightSelection::power);
    REQUIRE(set.lights.size() == 5);
    CHECK(set.lights[0].type == LIGHT_ENVIRONMENT);
    CHECK(set.lights[1].type == LIGHT_SPHERE);
    CHECK(set.lights[2].type == LIGHT_SPHERE);
    CHECK(set.lights[3].type == LIGHT_POINT);
    CHECK(set.lights[4].type == LIGHT_POINT);
    // slots: "white" 0, emitters[0] 1, emitters[2] 2
    REQUIRE(set.light_of_slot == std::vector<int>{-1, 1, 2});
    CHECK(set.lights[1].material_slot == 1);
    CHECK(set.lights[2].material_slot == 2);
    CHECK(scene.materials[2].weight_diffuse == 1.0f);  // the reflecting emitter scatters with "white"
    CHECK(scene.materials[1].weight_diffuse == 0.0f);  // the plain one is black
    // hand-computed: sphere pi Le 4 pi r^2 (luminance of grey = the grey; of red = 0.2126 red)
    CHECK(set.power[1] == Approx(kPi * 2.0 * 4.0 * kPi * 0.25).epsilon(1e-6));
    CHECK(set.power[2] == Approx(kPi * 0.2126 * 10.0 * 4.0 * kPi * 0.0625).epsilon(1e-6));
    CHECK(set.power[3] == Approx(4.0 * kPi).epsilon(1e-6));
    CHECK(set.power[4] == Approx(4.0 * kPi * 0.7152 * 3.0).epsilon(1e-6));
    // environment: pi R^2 * 4 pi L, R the radius of the box around camera (0, 1, 4), the box
    // [-1, 1]^3, the spheres and the points: x in [-1, 2.25], y in [-1, 3.5], z in [-1, 4]
    const double radius = 0.5 * std::sqrt(3.25 * 3.25 + 4.5 * 4.5 + 5.0 * 5.0);
    CHECK(scene.bounds_radius == Approx(radius).epsilon(1e-6));
    CHECK(set.power[0] == Approx(kPi * radius * radius * 4.0 * kPi * 0.5).epsilon(1e-5));
    // selection in proportion to power; the pmf sums to 1 and the sampler's frequencies match it
    double total = 0.0, sum = 0.0;
    for (double p : set.power) total += p;
    REQUIRE(set.selection_cdf.size() == 6);
    for (int k = 0; k < 5; ++k) {
        const float pmf = kernel::light_selection_pmf(set.selection_cdf.data(), 5, k);
        CHECK(pmf == Approx(set.power[size_t(k)] / total).epsilon(1e-5));
        sum += pmf;
    }
    CHECK(sum == Approx(1.0).epsilon(1e-6));
    std::vector<long> counts(5, 0);
    const long n = 1000000;
    validation::UniformRandom rng(31);
    for (long i = 0; i < n; ++i) {
        float pmf = 0.0f;
        const int k = kernel::select_light(set.selection_cdf.data(), 5, rng.next_float(), &pmf);
        REQUIRE(pmf == kernel::light_selection_pmf(set.selection_cdf.data(), 5, k));
        ++counts[size_t(k)];
    }
    for (int k = 0; k < 5; ++k) {
        const double p = kernel::light_selection_pmf(set.selection_cdf.data(), 5, k);
        const double sigma = std::sqrt(n * p * (1.0 - p));
        INFO("light " << k << ": " << counts[size_t(k)] << " draws, expected " << n * p);
        CHECK(std::fabs(counts[size_t(k)] - n * p) < 5.0 * sigma);  // 5 sigma: a false alarm 1 in 1.7 million
    }
    // uniform selection
    const lab::render::LightSet uniform = lab::render::build_light_set(scene, &env, lab::render::LightSelection::uniform);
    for (int k = 0; k < 5; ++k) CHECK(kernel::light_selection_pmf(uniform.selection_cdf.data(), 5, k) == Approx(0.2).epsilon(1e-6));
    // without an environment the spheres come first; no lights: no cdf, select_light says -1
    const lab::render::LightSet no_env = lab::render::build_light_set(scene, nullptr, lab::render::LightSelection::power);
    CHECK(no_env.lights.size() == 4);
    CHECK(no_env.light_of_slot == std::vector<int>{-1, 0, 1});
    // the kinds a scene's kernel is built for (-DSCENE_LIGHT_TYPES), a bit (1 << LIGHT_*) each
    CHECK(lab::render::light_type_mask(set) == ((1 << LIGHT_ENVIRONMENT) | (1 << LIGHT_SPHERE) | (1 << LIGHT_POINT)));
    CHECK(lab::render::light_type_mask(no_env) == ((1 << LIGHT_SPHERE) | (1 << LIGHT_POINT)));
    CHECK(lab::render::light_type_mask(lab::render::LightSet{}) == 0);
    float pmf = 1.0f;
    CHECK(kernel::select_light(nullptr, 0, 0.5f, &pmf) == -1);
    CHECK(pmf == 0.0f);
    CHECK(lab::render::parse_light_selection("uniform") == lab::render::LightSelection::uniform);
    CHECK_THROWS_WITH(lab::render::parse_light_selection("flux"), "--light-selection: unknown value \"flux\" (power, uniform)");
}

namespace {

// Rect and disk lights (kernels/lights/area_light.h): a rect of 1 x 0.6 and a disk of radius 0.4 at
// c, tilted (normal t x b of the test's own frame about a slanted axis), and a parallelogram of the
// rect's edges 60 degrees apart, which has no spherical rectangle and is sampled by area.
const glm::dvec3 kAreaCenter(0.3, 1.2, -0.4);
const Frame kAreaFrame = frame_around(glm::normalize(glm::dvec3(0.3, -1.0, 0.2)));

kernel::Light area_light(int type, glm::dvec3 u, glm::dvec3 v, float radius) {
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

const kernel::Light kRect = area_light(LIGHT_RECT, kAreaFrame.t * 1.0, kAreaFrame.b * 0.6, 0.0f);
const kernel::Light kParallelogram = area_light(LIGHT_RECT, kAreaFrame.t * 1.0, (kAreaFrame.t * 0.5 + kAreaFrame.b * std::sqrt(0.75)) * 0.6, 0.0f);
const kernel::Light kDisk = area_light(LIGHT_DISK, kAreaFrame.t * 0.4, kAreaFrame.b * 0.4, 0.4f);

// The radius of a ball about the centre that holds the light with a margin of 10 %: the zoom's cone
// around it keeps the light's corners and rim off the cone's edge, where the zoom's stretch is
// steepest and the cells' quadrature misses slivers of the light.
double area_light_reach(const kernel::Light& l) {
    const glm::dvec3 u(l.edge_u[0], l.edge_u[1], l.edge_u[2]), v(l.edge_v[0], l.edge_v[1], l.edge_v[2]);
    if (l.type == LIGHT_DISK) return 1.1 * l.radius;
    return 0.55 * std::max(glm::length(u + v), glm::length(u - v));
}

struct AreaCase {
    const char* what;
    const kernel::Light* light;
    glm::dvec3 offset;  // of p from the centre, in the light's frame (t, b, n)
};

const AreaCase kAreaCases[] = {
    {"rect, near: 0.3 above its centre (3.0 sr, spherical rectangle)", &kRect, {0.0, 0.0, 0.3}},
    {"rect, oblique: beside a corner, 65 degrees off its normal (spherical rectangle)", &kRect, {1.4, 0.9, 0.8}},
    {"rect, far: 11 away, 25 degrees off its normal (5e-3 sr, spherical rectangle)", &kRect, {4.0, 2.0, 10.0}},
    {"parallelogram, edges 60 degrees apart (by area)", &kParallelogram, {0.2, -0.3, 0.5}},
    {"disk, near: 0.25 above its rim (by area)", &kDisk, {0.4, 0.0, 0.25}},
    {"disk, oblique: 2 away, 70 degrees off its normal (by area)", &kDisk, {1.3, 1.3, 0.7}},
};
constexpr int kAreaCaseCount = sizeof(kAreaCases) / sizeof(kAreaCases[0]);

float3 area_case_point(const AreaCase& c) { return float3(kAreaCenter + kAreaFrame.t * c.offset.x + kAreaFrame.b * c.offset.y + kAreaFrame.n * c.offset.z); }

// The area light's sampler as a direction sampler, each sample keeping kernels/lights/light.h's
// promises: its pdf is area_light_pdf of its direction, its point lies on the light with the
// emitting side's normal, wi points at it, distance is the distance, radiance is Le.
validation::DirectionSampler area_sampler(const kernel::Light& l, float3 p, const ConeZoom& zoom) {
    return [&l, p, &zoom](float3 u) {
        validation::DirectionSample s;
        const kernel::LightSample ls = kernel::area_light_sample(&l, p, kernel::make_float2(u.x, u.y));
        if (!(ls.pdf > 0.0f)) return s;  // Failed
        s.kind = validation::SampleKind::Continuous;
        s.wi = zoom.forward(ls.wi);
        const double scale = glm::length(kAreaCenter - glm::dvec3(p)) + area_light_reach(l);
        const glm::dvec3 u_edge(l.edge_u[0], l.edge_u[1], l.edge_u[2]), v_edge(l.edge_v[0], l.edge_v[1], l.edge_v[2]);
        const glm::dvec3 n = glm::normalize(glm::cross(u_edge, v_edge));
        if (std::fabs(glm::dot(glm::dvec3(ls.position) - kAreaCenter, n)) > 1e-5 * scale || !kernel::area_light_contains(&l, ls.position))
            s.defect = "sampled point off the light";
        else if (glm::length(glm::dvec3(ls.normal) - n) > 1e-5)
            s.defect = "normal is not the emitting side's";
        else
            s.defect = sample_promise_defect(l, ls, p, kernel::area_light_pdf(&l, p, ls.wi), scale, "area_light");
        return s;
    };
}

validation::DirectionDensity area_density(const kernel::Light& l, float3 p, const ConeZoom& zoom, double factor = 1.0) {
    return [&l, p, &zoom, factor](float3 w) {
        float3 original;
        if (!zoom.backward(w, &original)) return 0.0;
        return factor * double(kernel::area_light_pdf(&l, p, original)) * zoom.jacobian();
    };
}

validation::ChiSquareOptions area_chi_square_options(long samples) {
    validation::ChiSquareOptions o = chi_square_options(samples);
    o.tests = kAreaCaseCount;
    return o;
}

}  // namespace

TEST_CASE("lights: rect and disk light samples follow area_light_pdf (chi-square)", "[lights][area]") {
    for (const AreaCase& c : kAreaCases) {
        const float3 p = area_case_point(c);
        const ConeZoom zoom(kAreaCenter, area_light_reach(*c.light), p);
        const validation::ChiSquareResult r =
            validation::chi_square_test(area_sampler(*c.light, p, zoom), area_density(*c.light, p, zoom), area_chi_square_options(1000000));
        INFO(c.what << ": " << validation::describe(r));
        std::printf("[lights] chi-square area light, %s: %s\n", c.what, validation::describe(r).c_str());
        CHECK(r.passed);
        CHECK(r.failed_fraction == 0.0);
        CHECK(r.pdf_integral == Approx(1.0).margin(2e-3));
        // behind it (the mirror image of p through its plane) the light sends nothing and has no density
        const glm::dvec3 behind = glm::dvec3(p) - 2.0 * kAreaFrame.n * c.offset.z;
        CHECK(kernel::area_light_sample(c.light, float3(behind), kernel::make_float2(0.3f, 0.6f)).pdf == 0.0f);
        CHECK(kernel::area_light_pdf(c.light, float3(behind), float3(glm::normalize(kAreaCenter - behind))) == 0.0f);
    }
    // the densities each case states: solid angle where it says so, area elsewhere
    const kernel::SphericalRect near = kernel::spherical_rect_make(&kRect, area_case_point(kAreaCases[0]));
    const kernel::SphericalRect close = kernel::spherical_rect_make(&kRect, float3(kAreaCenter + kAreaFrame.n * 0.002));  // 6.25 sr
    const kernel::SphericalRect far = kernel::spherical_rect_make(&kRect, float3(kAreaCenter + kAreaFrame.n * 50.0));     // 2.4e-4 sr
    CHECK(kernel::rect_light_uses_solid_angle(&kRect, &near));
    const kernel::SphericalRect zoomed = kernel::spherical_rect_make(&kRect, area_case_point(kAreaCases[2]));
    CHECK(kernel::rect_light_uses_solid_angle(&kRect, &zoomed));
    CHECK_FALSE(kernel::rect_light_uses_solid_angle(&kRect, &close));
    CHECK_FALSE(kernel::rect_light_uses_solid_angle(&kRect, &far));
    CHECK_FALSE(kernel::rect_light_is_rectangle(&kParallelogram));
    // the solid angle of the rect from above its centre: 4 asin(a b / sqrt((a^2 + 4 h^2)(b^2 + 4 h^2)))
    CHECK(near.solid_angle == Approx(4.0 * std::asin(0.6 / std::sqrt((1.0 + 0.36) * (0.36 + 0.36)))).epsilon(1e-5));
}

TEST_CASE("lights: the chi-square test rejects a rect pdf off by 3 % either way and a disk sampled uniformly in radius", "[lights][area]") {
    const AreaCase& c = kAreaCases[1];
    const float3 p = area_case_point(c);
    const ConeZoom zoom(kAreaCenter, area_light_reach(kRect), p);
    const validation::ChiSquareResult off =
        validation::chi_square_test(area_sampler(kRect, p, zoom), area_density(kRect, p, zoom, 1.03), area_chi_square_options(300000));
    std::printf("[lights] broken input, spherical rectangle pdf times 1.03: %s\n", validation::describe(off).c_str());
    CHECK_FALSE(off.passed);
    const validation::ChiSquareResult low =
        validation::chi_square_test(area_sampler(kRect, p, zoom), area_density(kRect, p, zoom, 0.97), area_chi_square_options(300000));
    std::printf("[lights] broken input, spherical rectangle pdf times 0.97: %s\n", validation::describe(low).c_str());
    CHECK_FALSE(low.passed);
    // a disk point at radius r u instead of r sqrt(u): too many samples near the centre
    const float3 q = area_case_point(kAreaCases[4]);
    const ConeZoom disk_zoom(kAreaCenter, 0.4, q);
    const validation::DirectionSampler radius_uniform = [&](float3 u) {
        validation::DirectionSample s;
        const double r = 0.4 * u.x, phi = 2.0 * kPi * u.y;
        const glm::dvec3 x = kAreaCenter + kAreaFrame.t * (r * std::cos(phi)) + kAreaFrame.b * (r * std::sin(phi));
        s.wi = disk_zoom.forward(float3(glm::normalize(x - glm::dvec3(q))));
        s.kind = validation::SampleKind::Continuous;
        return s;
    };
    const validation::ChiSquareResult wrong = validation::chi_square_test(radius_uniform, area_density(kDisk, q, disk_zoom), area_chi_square_options(300000));
    std::printf("[lights] broken input, disk sampled uniformly in radius: %s\n", validation::describe(wrong).c_str());
    CHECK_FALSE(wrong.passed);
}

namespace {

// The flux light l sends through a sphere of radius 2 about (0.5, 1, -0.2) against `power`: the
// irradiance its samples estimate at points spread evenly over the sphere, E(x) = L cos / pdf per
// sample with cos against the outward normal, integrated over the sphere's area. 400 x 800 strata
// of (cos theta, phi), one point and one light sample each: the standard error of the integral, from
// the spread of the strata's estimates (an over-estimate for strata), is required at most 0.25 % and
// the integral within 1 %.
void check_flux_through_sphere(const kernel::Light& l, kernel::EnvironmentBuffers b, double power, uint64_t seed, const std::string& what) {
    const glm::dvec3 center(0.5, 1.0, -0.2);
    const double radius = 2.0;
    validation::UniformRandom rng(seed);
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

}  // namespace

// The power the light set gives a rect or disk, pi A L (luminance), is the flux it sends through any
// sphere around it (check_flux_through_sphere: an off-centre one of radius 2).
TEST_CASE("lights: a rect's and a disk's power is the flux through a sphere around them", "[lights][area]") {
    const char* scene_text = R"({"camera": {"type": "pinhole", "position": [0, 0, 5], "look_at": [0, 0, 0], "fov_degrees": 40},
      "emitters": [{"type": "rect", "center": [0.3, 1.2, -0.4], "edge_u": [1, 0, 0], "edge_v": [0, 0.3, 0.52], "radiance": [2, 2, 2]},
                   {"type": "disk", "center": [0.3, 1.2, -0.4], "normal": [0.3, -1, 0.2], "radius": 0.4, "radiance": [1, 2, 3]}]})";
    const lab::scene::CompiledScene scene = lab::scene::compile_scene(lab::scene::parse_scene(scene_text, "scenes/area.json"));
    const lab::render::LightSet set = lab::render::build_light_set(scene, nullptr, lab::render::LightSelection::power);
    REQUIRE(set.lights.size() == 2);
    CHECK(set.lights[0].type == LIGHT_RECT);
    CHECK(set.lights[1].type == LIGHT_DISK);
    CHECK(set.light_of_slot == std::vector<int>{0, 1});
    // hand-computed: pi L |U x V| and pi L pi r^2 (the luminance of (1, 2, 3): 0.2126 + 1.4304 + 0.2166)
    CHECK(set.power[0] == Approx(kPi * 2.0 * std::sqrt(0.09 + 0.2704)).epsilon(1e-5));
    CHECK(set.power[1] == Approx(kPi * (0.2126 + 2.0 * 0.7152 + 3.0 * 0.0722) * kPi * 0.16).epsilon(1e-5));
    for (size_t k = 0; k < set.lights.size(); ++k) check_flux_through_sphere(set.lights[k], kernel::EnvironmentBuffers{}, set.power[k], 17 + k, k == 0 ? "rect" : "disk");
}

namespace {

// Image emitters (kernels/lights/image_emitter.h): an 8 x 4 image with a dark row (the file's row 1,
// all 0), a bright texel (20 at column 5 of row 2) and a gradient elsewhere, shown by the rect and
// the disk of the cases above with a scale of (1, 0.5, 2), bound after one alias entry of its own
// (offset 0 means no image).
constexpr int kImageWidth = 8, kImageHeight = 4;
std::vector<float> test_image_pixels() {
    std::vector<float> rgb(size_t(kImageWidth) * kImageHeight * 3);
    for (int y = 0; y < kImageHeight; ++y)
        for (int x = 0; x < kImageWidth; ++x) {
            const float v = y == 1 ? 0.0f : (x == 5 && y == 2 ? 20.0f : 0.2f + 0.1f * float(x + 3 * y));
            float* p = &rgb[3 * (size_t(y) * kImageWidth + size_t(x))];
            p[0] = v;
            p[1] = 0.5f * v + 0.05f;
            p[2] = y == 1 ? 0.0f : 0.3f;
        }
    return rgb;
}

struct ImageLights {
    lab::render::LightSet set;
    std::vector<brdf::float4> texels;
    std::vector<kernel::AliasEntry> alias{kernel::AliasEntry{1.0f, 0}};
    ImageLights() {
        const lab::render::EmitterImage image = lab::render::emitter_image_from_pixels("test.exr", kImageWidth, kImageHeight, test_image_pixels());
        for (const kernel::Light* l : {&kRect, &kDisk}) {
            kernel::Light copy = *l;
            kernel::float3_to_array(float3(1.0f, 0.5f, 2.0f), copy.emission);
            set.lights.push_back(copy);
        }
        bind_emitter_images({image, image}, &set, &texels, &alias);
    }
    kernel::EnvironmentBuffers buffers() const { return kernel::EnvironmentBuffers{texels.data(), alias.data()}; }
};

// Whether st lies within `margin` of a line between two texels.
bool near_texel_edge(kernel::float2 st, double margin) {
    const double x = st.x * kImageWidth, y = st.y * kImageHeight;
    return std::fabs(x - std::round(x)) < margin * kImageWidth || std::fabs(y - std::round(y)) < margin * kImageHeight;
}

// The image emitter's sampler as a direction sampler, each sample keeping kernels/lights/light.h's
// promises: its point lies on the light, its pdf is image_emitter_pdf of its direction and its
// radiance image_emitter_radiance at its point (the texel the direction finds again may be the
// neighbour only for a point within float rounding, 1e-5, of a texel edge).
validation::DirectionSampler image_sampler(const kernel::Light& l, kernel::EnvironmentBuffers b, float3 p, const ConeZoom& zoom) {
    return [&l, b, p, &zoom](float3 u) {
        validation::DirectionSample s;
        const kernel::LightSample ls = kernel::image_emitter_sample(&l, b, p, kernel::make_float2(u.x, u.y));
        if (!(ls.pdf > 0.0f)) return s;  // Failed
        s.kind = validation::SampleKind::Continuous;
        s.wi = zoom.forward(ls.wi);
        const float pdf = kernel::image_emitter_pdf(&l, b, p, ls.wi);
        const float3 radiance = kernel::image_emitter_radiance(&l, b, ls.position, -ls.wi);
        if (!kernel::area_light_contains(&l, ls.position))
            s.defect = "sampled point off the light";
        else if (!(radiance == ls.radiance))
            s.defect = "radiance is not the texel's at the sampled point";
        else if (!(std::fabs(pdf - ls.pdf) <= 2e-4f * ls.pdf) && !near_texel_edge(kernel::area_light_st(&l, ls.position), 1e-5))
            s.defect = "sample pdf " + std::to_string(ls.pdf) + " but image_emitter_pdf " + std::to_string(pdf);
        return s;
    };
}

// image_emitter_pdf through the zoom, or a broken density: `broken` 1 reads the texel one column to
// the right of the direction's (wrapping), 2 ignores the texels (the uniform area density).
validation::DirectionDensity image_density(const kernel::Light& l, kernel::EnvironmentBuffers b, float3 p, const ConeZoom& zoom, int broken = 0) {
    return [&l, b, p, &zoom, broken](float3 w) {
        float3 original;
        if (!zoom.backward(w, &original)) return 0.0;
        if (broken == 0) return double(kernel::image_emitter_pdf(&l, b, p, original)) * zoom.jacobian();
        float t, cos_l;
        if (!kernel::area_light_ray_hit(&l, p, original, &t, &cos_l)) return 0.0;
        double pdf_area = 1.0 / double(kernel::area_light_area(&l));
        if (broken == 1) {
            const kernel::float2 st = kernel::area_light_st(&l, p + original * t);
            const int column = (std::min(int(st.x * kImageWidth), kImageWidth - 1) + 1) % kImageWidth;
            const int row = std::min(int(st.y * kImageHeight), kImageHeight - 1);
            const kernel::EmitterImage im = kernel::emitter_image(&l, b);
            pdf_area *= double(b.texels[im.texels + row * kImageWidth + column].w) * kImageWidth * kImageHeight;
        }
        return pdf_area * double(t) * t / cos_l * zoom.jacobian();
    };
}

}  // namespace

TEST_CASE("lights: image emitter samples follow image_emitter_pdf on a rect and a disk (chi-square)", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    for (int k = 0; k < 2; ++k) {
        const kernel::Light& l = lights.set.lights[size_t(k)];
        const AreaCase& c = kAreaCases[k == 0 ? 0 : 4];  // near the rect's centre, near the disk's rim
        const float3 p = area_case_point(c);
        const ConeZoom zoom(kAreaCenter, area_light_reach(l), p);
        validation::ChiSquareOptions options = chi_square_options(1000000);
        options.tests = 2;
        const validation::ChiSquareResult r = validation::chi_square_test(image_sampler(l, b, p, zoom), image_density(l, b, p, zoom), options);
        INFO((k == 0 ? "rect" : "disk") << ": " << validation::describe(r));
        std::printf("[lights] chi-square image emitter, %s, %s: %s\n", k == 0 ? "rect" : "disk", c.what, validation::describe(r).c_str());
        CHECK(r.passed);
        CHECK(r.failed_fraction == 0.0);
        CHECK(r.pdf_integral == Approx(1.0).margin(2e-3));
        // a light subpath's origin: drawn by image_emitter_sample_point, its density light_area_pdf
        const float3 q = kernel::image_emitter_sample_point(&l, b, kernel::make_float2(0.3f, 0.7f));
        float3 n;
        const float3 q2 = kernel::light_sample_area(&l, b, kernel::make_float2(0.3f, 0.7f), &n);
        CHECK(q == q2);
        CHECK(kernel::light_area_pdf(&l, b, q) == kernel::image_emitter_area_pdf(&l, b, q));
        // behind it: nothing
        const glm::dvec3 behind = glm::dvec3(p) - 2.0 * kAreaFrame.n * c.offset.z;
        CHECK(kernel::image_emitter_sample(&l, b, float3(behind), kernel::make_float2(0.3f, 0.6f)).pdf == 0.0f);
        CHECK(kernel::image_emitter_pdf(&l, b, float3(behind), float3(glm::normalize(kAreaCenter - behind))) == 0.0f);
    }
}

TEST_CASE("lights: the chi-square test rejects an image pdf off by one texel or ignoring the texels", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    for (int k = 0; k < 2; ++k) {
        const kernel::Light& l = lights.set.lights[size_t(k)];
        const float3 p = area_case_point(kAreaCases[k == 0 ? 0 : 4]);
        const ConeZoom zoom(kAreaCenter, area_light_reach(l), p);
        for (int broken : {1, 2}) {
            validation::ChiSquareOptions options = chi_square_options(100000);
            options.tests = 4;
            const validation::ChiSquareResult r = validation::chi_square_test(image_sampler(l, b, p, zoom), image_density(l, b, p, zoom, broken), options);
            std::printf("[lights] broken input, image emitter %s, %s: %s\n", k == 0 ? "rect" : "disk",
                        broken == 1 ? "pdf of the texel one column over" : "pdf uniform by area", validation::describe(r).c_str());
            CHECK_FALSE(r.passed);
        }
    }
}

TEST_CASE("lights: an image emitter shows its image unmirrored from the emitting side, and its inverse map is exact", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    const std::vector<float> rgb = test_image_pixels();
    const kernel::Light& rect = lights.set.lights[0];
    const glm::dvec3 u(rect.edge_u[0], rect.edge_u[1], rect.edge_u[2]), v(rect.edge_v[0], rect.edge_v[1], rect.edge_v[2]);
    // the file's pixel (x, y), rows from the top, at c + ((x + 1/2) / W - 1/2) U + (1/2 - (y + 1/2) / H) V: seen from the
    // emitting side (looking along -n, n = U x V) with U to the right, V is up, so the file's first row is at the top
    for (int y = 0; y < kImageHeight; ++y)
        for (int x = 0; x < kImageWidth; ++x) {
            const glm::dvec3 q = kAreaCenter + u * ((x + 0.5) / kImageWidth - 0.5) + v * (0.5 - (y + 0.5) / kImageHeight);
            const float3 le = kernel::image_emitter_radiance(&rect, b, float3(q), kernel::area_light_normal(&rect));
            const float* pixel = &rgb[3 * (size_t(y) * kImageWidth + size_t(x))];
            CHECK(le == float3(pixel[0] * 1.0f, pixel[1] * 0.5f, pixel[2] * 2.0f));
            CHECK(kernel::image_emitter_radiance(&rect, b, float3(q), -kernel::area_light_normal(&rect)) == float3(0.0f));
        }
    // the inverse concentric map undoes the map over the square
    validation::UniformRandom rng(5);
    double worst = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const float s = rng.next_float(), t = rng.next_float();
        const kernel::float2 d = kernel::square_to_concentric_disk(s, t);
        const kernel::float2 back = kernel::concentric_disk_to_square(d.x, d.y);
        worst = std::max(worst, double(std::max(std::fabs(back.x - s), std::fabs(back.y - t))));
    }
    CHECK(worst < 2e-6);
}

// An image emitter's power, pi A times the luminance of scale x the image's mean RGB, is the flux its
// samples send through a sphere around it (as for the constant rect and disk above).
TEST_CASE("lights: an image emitter's power is the flux through a sphere around it", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    const lab::render::EmitterImage image = lab::render::emitter_image_from_pixels("test.exr", kImageWidth, kImageHeight, test_image_pixels());
    for (size_t k = 0; k < 2; ++k) {
        const kernel::Light& l = lights.set.lights[k];
        const double power = lab::render::image_light_power(l, image.mean_rgb);
        // by hand: the mean over the texels of scale x texel, its luminance
        double r = 0.0, g = 0.0, bl = 0.0;
        const std::vector<float> rgb = test_image_pixels();
        for (size_t p = 0; p < rgb.size() / 3; ++p) {
            r += rgb[3 * p];
            g += 0.5 * rgb[3 * p + 1];
            bl += 2.0 * rgb[3 * p + 2];
        }
        const double n_texels = double(kImageWidth * kImageHeight);
        CHECK(power == Approx(kPi * lab::luminance(r / n_texels, g / n_texels, bl / n_texels) * kernel::area_light_area(&l)).epsilon(1e-6));
        check_flux_through_sphere(l, b, power, 29 + k, k == 0 ? "image rect" : "image disk");
    }
}

namespace {

// A scene whose rect shows the image at `path` (absolute), compiled.
lab::scene::CompiledScene emitter_image_scene(const std::string& path, const std::string& radiance = "") {
    const std::string text = R"({"camera": {"type": "pinhole", "position": [0, 0, 5], "look_at": [0, 0, 0], "fov_degrees": 40},
      "emitters": [{"type": "sphere", "center": [3, 0, 0], "radius": 0.5, "radiance": [1, 1, 1]},
                   {"type": "point", "position": [0, 3, 0], "intensity": [1, 1, 1]},
                   {"type": "rect", "center": [0, 1, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "image": ")" + path + "\"" + radiance + "}]}";
    return lab::scene::compile_scene(lab::scene::parse_scene(text, "scenes/screen.json"));
}

std::string emitter_image_error(const std::string& path) {
    try {
        lab::render::load_emitter_images(emitter_image_scene(path), 0.0);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "";
}

std::string emitter_temp_file(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("dtoadq-emitter-images-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    return (folder / name).string();
}

}  // namespace

TEST_CASE("lights: an emitter's image is read as environments are, and bad images give one line naming the scene's field and the file", "[lights][image]") {
    // a 3 x 2 PNG: sRGB-decoded to linear; rows from the top of the file land at t = 1 first
    const std::string png = emitter_temp_file("screen.png");
    const std::vector<uint8_t> bytes = {0, 0, 0, 64, 64, 64, 128, 128, 128, 255, 255, 255, 10, 20, 30, 200, 100, 50};
    lab::film::write_srgb8_png(png, 3, 2, bytes, lab::film::ImageMetadata{});
    const std::vector<std::optional<lab::render::EmitterImage>> images = lab::render::load_emitter_images(emitter_image_scene(png), 0.0);
    REQUIRE(images.size() == 2);  // the sphere and the rect; the point light is no emitter
    CHECK_FALSE(images[0].has_value());
    REQUIRE(images[1].has_value());
    CHECK(images[1]->width == 3);
    CHECK(images[1]->height == 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c) {
                const brdf::float4 t = images[1]->texels[size_t(1 - y) * 3 + size_t(x)];
                CHECK(t[c] == Approx(lab::film::srgb_decode(float(bytes[size_t(3 * (3 * y + x) + c)]) / 255.0f)).epsilon(1e-6));
            }
    // the scale defaults to 1 with an image
    CHECK(emitter_image_scene(png).emitters[1].radiance == brdf::float3(1.0f));
    CHECK(emitter_image_scene(png, R"(, "radiance": [2, 1, 0.5])").emitters[1].radiance == brdf::float3(2.0f, 1.0f, 0.5f));

    const std::string missing = emitter_temp_file("none.exr");
    CHECK(emitter_image_error(missing) == "scenes/screen.json: emitters[2].image: " + missing + ": no such file");
    const std::string corrupt = emitter_temp_file("corrupt.exr");
    { std::FILE* f = std::fopen(corrupt.c_str(), "wb"); std::fputs("not an image", f); std::fclose(f); }
    CHECK(emitter_image_error(corrupt) == "scenes/screen.json: emitters[2].image: " + corrupt + ": cannot be read as an OpenEXR, Radiance HDR or PNG image");
    const std::string text = emitter_temp_file("screen.txt");
    { std::FILE* f = std::fopen(text.c_str(), "wb"); std::fputs("x", f); std::fclose(f); }
    CHECK(emitter_image_error(text) == "scenes/screen.json: emitters[2].image: " + text + ": unsupported image format \".txt\" (expected .exr, .hdr or .png)");
    for (float bad : {std::nanf(""), -0.5f, std::numeric_limits<float>::infinity()}) {
        lab::film::ImageRgb image(2, 2);
        image.rgb[3 * 1 + 2] = bad;  // pixel (1, 0), B
        const std::string path = emitter_temp_file("bad.exr");
        lab::film::write_exr(path, image, lab::film::ImageMetadata{});
        const std::string what = std::isnan(bad) ? "NaN" : (bad < 0.0f ? "negative" : "infinite");
        CHECK(emitter_image_error(path) == "scenes/screen.json: emitters[2].image: " + path + ": pixel (1, 0): B is " + what + " (radiance must be finite and >= 0)");
    }
    // a header that claims more than the file can hold is refused before anything is allocated
    // (common/image_claim.hpp), and sizes past the limit by their own line
    CHECK_THROWS_WITH(lab::render::emitter_image_from_pixels("big.exr", lab::render::kMaxEmitterImageSide + 1, 1, {}),
                      "big.exr: size: 4097 x 1 (an emitter's image has 1 to 4096 texels a side)");
    std::error_code ec;
    std::filesystem::remove_all(std::filesystem::path(png).parent_path(), ec);
}
