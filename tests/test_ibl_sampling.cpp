// Importance sampling of environments: environment_sample() draws directions with exactly the
// density environment_pdf() states (chi-square over the sphere), returns that density with each
// sample, the density integrates to 1, and it beats uniform sampling on real environments.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ibl/distribution.hpp"
#include "ibl/environment.hpp"
#include "ibl/ibl.hpp"
#include "validation/chi_square.hpp"
#include "validation/uniform_random.hpp"

using single_source::float3;
using lab::ibl::Environment;
using lab::ibl::EnvironmentOptions;
using lab::ibl::LatLongImage;
namespace validation = lab::validation;

namespace {

constexpr double kPi = 3.14159265358979323846;

EnvironmentOptions options_with(float rotation, int face_size) {
    EnvironmentOptions o;
    o.rotation_degrees = rotation;
    o.face_size = face_size;
    return o;
}

// Strong contrast: a sun 10^5 times the sky, a bright band, and a black lower hemisphere (whole
// rows of the -y face without light: the fallback and the floor of the distribution).
LatLongImage contrast_image() {
    LatLongImage image;
    image.width = 64;
    image.height = 32;
    image.rgb.assign(size_t(64) * 32 * 3, 0.0f);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 64; ++x) {
            float* p = &image.rgb[(size_t(y) * 64 + x) * 3];
            const double dx = x + 0.5 - 20.0, dy = y + 0.5 - 9.0;
            float value = 0.1f;
            if (dx * dx + dy * dy < 2.0) value = 10000.0f;
            if (x >= 40 && x < 48) value = 5.0f;
            p[0] = value;
            p[1] = 0.5f * value;
            p[2] = 0.2f * value;
        }
    return image;
}

// The environment's sampler for the chi-square test; each sample must carry pdf ==
// environment_pdf(direction), the density the estimator radiance / pdf needs.
validation::DirectionSampler checked_sampler(const Environment& env) {
    return [&env](float3 u) {
        validation::DirectionSample s;
        float pdf = 0.0f;
        s.wi = env.sample(u.x, u.y, &pdf);
        s.kind = validation::SampleKind::Continuous;
        if (!(pdf > 0.0f) || pdf != env.pdf(s.wi))
            s.defect = "sample pdf " + std::to_string(pdf) + " but environment_pdf " + std::to_string(env.pdf(s.wi));
        return s;
    };
}

// Midpoint rule over (z, phi), where d(omega) = dz dphi: independent of the cube's texels.
double pdf_sphere_integral(const Environment& env, int z_cells, int phi_cells) {
    double sum = 0.0;
    for (int i = 0; i < z_cells; ++i) {
        const double z = -1.0 + (i + 0.5) * 2.0 / z_cells, r = std::sqrt(1.0 - z * z);
        double row = 0.0;
        for (int k = 0; k < phi_cells; ++k) {
            const double phi = (k + 0.5) * 2.0 * kPi / phi_cells;
            row += env.pdf(float3(float(r * std::cos(phi)), float(z), float(r * std::sin(phi))));
        }
        sum += row;
    }
    return sum * (2.0 / z_cells) * (2.0 * kPi / phi_cells);
}

// The same over the environment's own cube, d(omega) = dA / J(a, b): a 4 x 4 midpoint rule inside
// every texel, each point turned to the world direction it stands for. The pdf is P / area x J on
// a texel, so this sums P over the texels up to rounding: a check of the cube and pdf plumbing.
double pdf_cube_integral(const Environment& env) {
    const int n = env.face_size();
    const double cell = 2.0 / (4 * n);
    double sum = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < 4 * n; ++y)
            for (int x = 0; x < 4 * n; ++x) {
                const float a = float(-1.0 + (x + 0.5) * cell), b = float(-1.0 + (y + 0.5) * cell);
                const float3 w = ibl::environment_to_world(&env.map(), glm::normalize(ibl::cubemap_face_point(face, a, b)));
                sum += double(env.pdf(w)) / ibl::cubemap_area_per_solid_angle(a, b) * cell * cell;
            }
    return sum;
}

void check_chi_square(const Environment& env, const char* what, long samples) {
    validation::ChiSquareOptions options;
    options.samples = samples;
    options.z_cells = 50;
    options.phi_cells = 100;
    options.seed = 20240;
    options.tests = 3;
    const validation::ChiSquareResult r = validation::chi_square_test(
        checked_sampler(env), [&env](float3 w) { return double(env.pdf(w)); }, options);
    INFO(what << ": " << validation::describe(r));
    std::printf("[ibl] chi-square %s: %s\n", what, validation::describe(r).c_str());
    CHECK(r.passed);
    CHECK(r.pdf_integral == Approx(1.0).margin(1e-3));
}

}  // namespace

TEST_CASE("ibl: environment_sample follows environment_pdf (chi-square)", "[ibl]") {
    const Environment contrast = Environment::from_image(contrast_image(), "contrast", options_with(30, 8));
    check_chi_square(contrast, "contrast 64x32, face 8, rotated 30 deg", 1000000);
    const Environment courtyard = lab::ibl::load_environment("envmaps/courtyard.exr", options_with(-75, 16));
    check_chi_square(courtyard, "courtyard.exr, face 16, rotated -75 deg", 1000000);
    const Environment black = lab::ibl::load_environment("constant:0,0,0", options_with(0, 4));
    check_chi_square(black, "black constant, face 4 (uniform fallback)", 200000);
}

TEST_CASE("ibl: the environment pdf integrates to 1 and follows the texel weights", "[ibl]") {
    const Environment contrast = Environment::from_image(contrast_image(), "contrast", options_with(30, 8));
    const Environment courtyard = lab::ibl::load_environment("envmaps/courtyard.exr", options_with(0, 16));
    const Environment black = lab::ibl::load_environment("constant:0,0,0", options_with(0, 16));
    for (const Environment* env : {&contrast, &courtyard, &black}) {
        const double on_cube = pdf_cube_integral(*env);
        INFO(env->source() << ": pdf integral over the cube " << on_cube);
        CHECK(on_cube == Approx(1.0).margin(1e-5));
        std::printf("[ibl] %s: pdf integral over the cube (4x4 per texel) %.7f\n", env->source().c_str(), on_cube);
    }
    // Without a sun, a plain grid over the sphere resolves the texel edges well enough.
    const double on_sphere = pdf_sphere_integral(courtyard, 1000, 2000);
    std::printf("[ibl] courtyard: pdf integral over the sphere (1000 x 2000 midpoint in z, phi) %.6f\n", on_sphere);
    CHECK(on_sphere == Approx(1.0).margin(1e-3));
    // Texel probabilities: luminance x solid angle over the total, up to the floor.
    const int n = courtyard.face_size();
    double total = 0.0;
    for (int t = 0; t < 6 * n * n; ++t) {
        const single_source::float4 x = courtyard.texels()[t];
        total += lab::ibl::luminance(x.x, x.y, x.z) * lab::ibl::texel_solid_angle(n, t % n, (t / n) % n);
    }
    double worst = 0.0;
    for (int t = 0; t < 6 * n * n; ++t) {
        const single_source::float4 x = courtyard.texels()[t];
        const double expected = lab::ibl::luminance(x.x, x.y, x.z) * lab::ibl::texel_solid_angle(n, t % n, (t / n) % n) / total;
        const double p = courtyard.texels()[t].w;  // the probability the alias tables draw the texel with
        // Texels far below the mean may sit on the floor; compare those on an absolute scale.
        worst = std::fmax(worst, std::fabs(p - expected) / std::fmax(expected, 1e-3 / (6.0 * n * n)));
    }
    INFO("worst relative difference of a texel probability " << worst);
    CHECK(worst < 2e-3);
    // A black environment falls back to uniform: 4 pi pdf = 1 up to the variation of the
    // area-to-solid-angle factor inside a texel.
    validation::UniformRandom rng(5);
    for (int k = 0; k < 1000; ++k) {
        const float3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        REQUIRE(4.0 * kPi * black.pdf(d) == Approx(1.0).margin(0.15));
    }
}

TEST_CASE("ibl: environment sampling beats uniform sampling", "[ibl]") {
    // Estimators of the sphere integral I of luminance: Y(w) / pdf(w) with environment sampling,
    // 4 pi Y(w) with uniform sampling. Exact variances from the texels (the radiance is constant
    // on each): uniform 4 pi sum(Y^2 omega) - I^2; environment sum over texels of
    // Y^2 (area / P) integral(J^-2 dA) - I^2, J = dA/d(omega) = (1 + a^2 + b^2)^(3/2).
    for (const char* name : {"courtyard", "sunset", "studio"}) {
        const std::string path = std::string("envmaps/") + name + ".exr";
        const Environment env = lab::ibl::load_environment(path, EnvironmentOptions{});
        const int n = env.face_size();
        const double area = (2.0 / n) * (2.0 / n);
        // Integral of J^-2 over each texel of a face (8 x 8 midpoint rule; J is smooth).
        std::vector<double> inverse_j2(size_t(n) * n, 0.0);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (int q = 0; q < 64; ++q) {
                    const double a = -1.0 + (i + (q % 8 + 0.5) / 8.0) * 2.0 / n, b = -1.0 + (j + (q / 8 + 0.5) / 8.0) * 2.0 / n;
                    const double jacobian = std::pow(1.0 + a * a + b * b, 1.5);
                    inverse_j2[size_t(j) * n + i] += area / 64.0 / (jacobian * jacobian);
                }
        double integral = 0.0, uniform_second = 0.0, env_second = 0.0;
        for (int t = 0; t < 6 * n * n; ++t) {
            const int i = t % n, j = (t / n) % n;
            const single_source::float4 x = env.texels()[t];
            const double y = lab::ibl::luminance(x.x, x.y, x.z), omega = lab::ibl::texel_solid_angle(n, i, j);
            const double p = x.w;
            integral += y * omega;
            uniform_second += 4.0 * kPi * y * y * omega;
            env_second += y * y * area / p * inverse_j2[size_t(j) * n + i];
        }
        const double uniform_variance = uniform_second - integral * integral;
        const double env_variance = env_second - integral * integral;

        // Monte Carlo through the public API: both estimators are unbiased, their sample
        // variances match the exact ones. Also the upward irradiance of luminance,
        // E = integral of Y(w) max(w.y, 0): environment sampling Y cos / pdf, uniform 4 pi Y cos,
        // and cosine-weighted sampling of the upper hemisphere (a diffuse BSDF's) pi Y.
        validation::UniformRandom rng(99);
        const long m = 1 << 19;
        struct Moments {
            double sum = 0.0, sum2 = 0.0;
            void add(double x) { sum += x, sum2 += x * x; }
            double mean(long m) const { return sum / m; }
            double variance(long m) const { return sum2 / m - mean(m) * mean(m); }
        } env_i, uni_i, env_e, uni_e, cos_e;
        auto luminance = [&env](float3 w) {
            const float3 l = env.radiance(w);
            return lab::ibl::luminance(l.x, l.y, l.z);
        };
        for (long k = 0; k < m; ++k) {
            float pdf;
            const float3 w = env.sample(rng.next_float(), rng.next_float(), &pdf);
            env_i.add(luminance(w) / pdf);
            env_e.add(luminance(w) * std::fmax(w.y, 0.0f) / pdf);
            const double z = 1.0 - 2.0 * rng.next_double(), phi = 2.0 * kPi * rng.next_double(), r = std::sqrt(1.0 - z * z);
            const float3 wu(float(r * std::cos(phi)), float(z), float(r * std::sin(phi)));
            uni_i.add(4.0 * kPi * luminance(wu));
            uni_e.add(4.0 * kPi * luminance(wu) * std::fmax(wu.y, 0.0f));
            // Malley: a uniform point of the unit disk lifted to the hemisphere around +y.
            const double rd = std::sqrt(rng.next_double()), pd = 2.0 * kPi * rng.next_double();
            const float3 wc(float(rd * std::cos(pd)), float(std::sqrt(std::fmax(0.0, 1.0 - rd * rd))), float(rd * std::sin(pd)));
            cos_e.add(kPi * luminance(wc));
        }
        const double env_mean = env_i.mean(m), env_mc_variance = env_i.variance(m);
        const double uni_mean = uni_i.mean(m), uni_mc_variance = uni_i.variance(m);
        std::printf("[ibl] %s: integral of luminance %.5g; per-sample variance uniform %.4g (MC %.4g), environment %.4g "
                    "(MC %.4g): ratio %.4g (MC %.4g)\n",
                    path.c_str(), integral, uniform_variance, uni_mc_variance, env_variance, env_mc_variance,
                    uniform_variance / env_variance, uni_mc_variance / env_mc_variance);
        std::printf("[ibl] %s: upward irradiance of luminance %.5g (env) %.5g (uniform) %.5g (cosine); MC variance "
                    "uniform / environment %.4g, cosine / environment %.4g\n",
                    path.c_str(), env_e.mean(m), uni_e.mean(m), cos_e.mean(m), uni_e.variance(m) / env_e.variance(m),
                    cos_e.variance(m) / env_e.variance(m));
        const double e_sigma = std::sqrt(uni_e.variance(m) / m) + std::sqrt(env_e.variance(m) / m);
        CHECK(env_e.mean(m) == Approx(uni_e.mean(m)).margin(5.0 * e_sigma));
        CHECK(uni_e.variance(m) > env_e.variance(m));
        INFO(path);
        CHECK(env_mean == Approx(integral).margin(5.0 * std::sqrt(env_variance / m)));
        CHECK(uni_mean == Approx(integral).margin(5.0 * std::sqrt(uniform_variance / m)));
        CHECK(env_mc_variance == Approx(env_variance).epsilon(0.1));
        CHECK(uniform_variance / env_variance > 5.0);
    }
}

// The path tracer's shortcuts through the environment (ibl/environment.h): the radiance and the
// density of a direction from one lookup of its texel, the sample with its radiance, and the texel a
// sample draws, found before the sample for a prefetch. The first two must be the separate
// lookups' very bits; the drawn texel may differ from the sample's only where rounding moves the
// sample's direction over a texel's edge, a band some ulps wide: fewer than 1 in 10^4 of the
// samples, where a wrong texel index (row and column swapped, a face off) misses nearly all. The entry
// of the row's alias table asked for before that must be the one the sample reads, every time.
TEST_CASE("ibl: one lookup gives the radiance and the density, and the texel a sample draws and its alias entry are known before it", "[ibl]") {
    const Environment contrast = Environment::from_image(contrast_image(), "contrast", options_with(30, 8));
    const Environment courtyard = lab::ibl::load_environment("envmaps/courtyard.exr", options_with(-75, 16));
    for (const Environment* env : {&contrast, &courtyard}) {
        const ::ibl::EnvironmentMap& map = env->map();
        const single_source::float4* texels = env->texels().data();
        validation::UniformRandom random(7);
        long radiance_pdf_differs = 0, sample_differs = 0, texel_differs = 0, entry_differs = 0;
        const long n = 200000;
        for (long i = 0; i < n; ++i) {
            const float3 w = glm::normalize(random.next_float3() * 2.0f - float3(1.0f));
            float pdf = -1.0f;
            const float3 l = ::ibl::environment_radiance_pdf(&map, texels, w, &pdf);
            if (l != ::ibl::environment_radiance(&map, texels, w) || pdf != ::ibl::environment_pdf(&map, texels, w)) ++radiance_pdf_differs;

            const float u1 = random.next_float(), u2 = random.next_float();
            float sample_pdf = -1.0f, plain_pdf = -2.0f;
            float3 radiance(-1.0f);
            const float3 d = ::ibl::environment_sample_radiance(&map, texels, env->alias().data(), u1, u2, &sample_pdf, &radiance);
            const float3 plain = ::ibl::environment_sample(&map, texels, env->alias().data(), u1, u2, &plain_pdf);
            if (d != plain || sample_pdf != plain_pdf || radiance != ::ibl::environment_radiance(&map, texels, d)) ++sample_differs;
            float a, b;
            const int drawn = ::ibl::environment_sample_texel(&map, env->alias().data(), u1, u2);
            if (drawn != ::ibl::environment_texel(&map, d, &a, &b)) ++texel_differs;
            // the entry of the drawn row's table the peek asks for: in that row's table, and naming
            // the drawn column as its own cell or as its alias
            const int m = map.face_size, entry = ::ibl::environment_sample_column_entry(&map, env->alias().data(), u1, u2);
            const int in_rows = entry - CUBEMAP_FACES * m, column = drawn % m;
            if (in_rows < 0 || in_rows / m != drawn / m ||
                (in_rows % m != column && env->alias()[size_t(entry)].alias != column))
                ++entry_differs;
        }
        INFO(env->source() << ": " << texel_differs << " of " << n << " drawn texels differ from the sample's");
        std::printf("[ibl] %s: %ld of %ld drawn texels differ from the sample's\n", env->source().c_str(), texel_differs, n);
        CHECK(radiance_pdf_differs == 0);
        CHECK(sample_differs == 0);
        CHECK(texel_differs * 10000 < n);
        CHECK(entry_differs == 0);
    }
}
