// The lights' samplers (kernels/lights/) against their densities: chi-square of sphere-light
// samples against sphere_light_pdf from outside (near and far, small and large caps) and inside, of
// rect and disk samples against area_light_pdf (spherical rectangles near, oblique and far; area
// sampling of a parallelogram and of disks) and their power against the flux through a sphere,
// the pdf a sample carries equals light_pdf, the densities integrate to 1, the area sampler, the
// point light, the environment light against ibl's sampler, light selection, and the power of
// every kind of light against hand-computed values (docs/lights.md). Image emitters:
// tests/test_image_emitter_sampling.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ibl/environment.hpp"
#include "kernels/host.hpp"
#include "render/light_set.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "validation/chi_square.hpp"
#include "validation/uniform_random.hpp"

#include "tests/light_sampling_fixtures.hpp"

using brdf::float3;
namespace validation = lab::validation;
using light_fixtures::area_case_point;
using light_fixtures::area_light_reach;
using light_fixtures::AreaCase;
using light_fixtures::check_flux_through_sphere;
using light_fixtures::ConeZoom;
using light_fixtures::Frame;
using light_fixtures::frame_around;
using light_fixtures::kAreaCaseCount;
using light_fixtures::kAreaCases;
using light_fixtures::kAreaCenter;
using light_fixtures::kAreaFrame;
using light_fixtures::kDisk;
using light_fixtures::kParallelogram;
using light_fixtures::kPi;
using light_fixtures::kRect;
using light_fixtures::light_chi_square_options;

namespace {

kernel::Light sphere_light(float3 center, float radius, float3 radiance) {
    kernel::Light l{};
    l.type = LIGHT_SPHERE;
    kernel::float3_to_array(center, l.position);
    l.radius = radius;
    kernel::float3_to_array(radiance, l.emission);
    l.material_slot = 3;
    return l;
}

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

validation::ChiSquareOptions chi_square_options(long samples) { return light_chi_square_options(samples, kCaseCount); }

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

validation::ChiSquareOptions area_chi_square_options(long samples) { return light_chi_square_options(samples, kAreaCaseCount); }

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
