// The OpenPBR Surface lobes of the BRDF module against closed forms and independent computations.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "tests/chi_square_suite.hpp"

using brdf::float3;

namespace {

using LobeFunction = float3 (*)(float3 rho, float sigma, float3 wo, float3 wi);

// Directional albedo of a lobe by the midpoint rule, in double: n cells in mu_i on each side of
// mu_o and 2n in phi_i from phi_o, so that the lobe's kinks (at mu_i = mu_o, where t switches, and at
// phi_i - phi_o = +-90 degrees, where s changes sign) lie on cell edges and it is smooth in each cell.
double eon_albedo_midpoint(LobeFunction f, float sigma, float3 wo, int n) {
    double phi_o = std::atan2(double(wo.y), double(wo.x)), sum = 0.0;
    double edges[3] = {0.0, double(wo.z), 1.0};
    for (int piece = 0; piece < 2; ++piece) {
        double lo = edges[piece], width = (edges[piece + 1] - lo) / n;
        for (int i = 0; i < n; ++i) {
            double mu = lo + (i + 0.5) * width, sin_t = std::sqrt(1.0 - mu * mu);
            for (int j = 0; j < 2 * n; ++j) {
                double phi = phi_o + M_PI * (j + 0.5) / n;
                float3 wi(float(sin_t * std::cos(phi)), float(sin_t * std::sin(phi)), float(mu));
                sum += double(f(float3(1.0f), sigma, wo, wi).x) * mu * width * (M_PI / n);
            }
        }
    }
    return sum;
}

// The albedo with n = 128, and its error bound: the midpoint rule's error is O(h^2) for an
// integrand smooth in each cell, so the estimate with n = 64 is four times as far off and their
// difference bounds the finer one's error (3x over).
struct EonQuadrature {
    double albedo, error;
};
EonQuadrature eon_albedo_quadrature(LobeFunction f, float sigma, float3 wo) {
    double coarse = eon_albedo_midpoint(f, sigma, wo, 64), fine = eon_albedo_midpoint(f, sigma, wo, 128);
    return {fine, std::fabs(fine - coarse) + 1e-6};  // + float rounding of the lobe's values, summed in double
}

// The textbook reflectance of a film on a substrate (Born and Wolf, 1.6.4), for one wavelength, in
// complex double: per polarisation r = (r12 + r23 e^{i delta}) / (1 + r12 r23 e^{i delta}),
// delta = 4 pi n2 d cos theta2 / lambda, with complex cosines past a critical angle and a complex
// index n3 for a conductor (principal roots throughout); unpolarised R.
double thin_film_textbook(double cos1, double n1, double n2, std::complex<double> n3, double d_um, double lambda_um) {
    using C = std::complex<double>;
    double sin2_1 = 1.0 - cos1 * cos1;
    C cos2 = std::sqrt(C(1.0 - (n1 / n2) * (n1 / n2) * sin2_1)), cos3 = std::sqrt(C(1.0 - (n1 / n3) * (n1 / n3) * sin2_1));
    C phase = std::exp(C(0.0, 1.0) * (4.0 * M_PI * n2 * d_um / lambda_um) * cos2);
    auto amplitude = [](C a, C b, C ci, C ct) { return (a * ci - b * ct) / (a * ci + b * ct); };
    double r = 0.0;
    for (int p = 0; p < 2; ++p) {
        C r12 = p == 0 ? amplitude(n1, n2, cos1, cos2) : amplitude(n2, n1, cos1, cos2);
        C r23 = p == 0 ? amplitude(n2, n3, cos2, cos3) : amplitude(n3, n2, cos2, cos3);
        r += 0.5 * std::norm((r12 + r23 * phase) / (1.0 + r12 * r23 * phase));
    }
    return r;
}

struct FilmCase {
    double n1, n2, n3, theta_deg;
};

}  // namespace

TEST_CASE("F82 tint: white is Schlick exactly, 1/7 reaches tint times Schlick, values stay in [0, 1]", "[brdf][openpbr]") {
    const float f0s[] = {0.0f, 0.04f, 0.3f, 0.7f, 0.95f, 1.0f};
    const float tints[] = {0.0f, 0.2f, 0.5f, 0.9f, 1.0f};
    for (float f0 : f0s) {
        float3 f0v(f0, 0.5f * f0, 1.0f - f0);
        for (int i = 0; i <= 200; ++i) {
            float mu = i / 200.0f;
            float3 schlick = brdf::fresnel_schlick(f0v, mu), f82 = brdf::fresnel_f82_tint(f0v, float3(1.0f), mu);
            CHECK(f82.x == schlick.x);  // b = 0 exactly: the same bits
            CHECK(f82.y == schlick.y);
            CHECK(f82.z == schlick.z);
        }
        for (float tint : tints) {
            // OpenPBR 1.1: at mu_bar = 1/7 the curve equals tint x F_Schlick(mu_bar), in double here
            double mu_bar = 1.0 / 7.0, expected = tint * (f0 + (1.0 - f0) * std::pow(1.0 - mu_bar, 5));
            float3 at_bar = brdf::fresnel_f82_tint(float3(f0), float3(tint), 1.0f / 7.0f);
            INFO("F0 " << f0 << ", tint " << tint);
            CHECK(at_bar.x == Approx(expected).margin(1e-6));  // float rounding of a few operations on values <= 1
            // normal incidence is F0, grazing incidence 1, whatever the tint
            CHECK(brdf::fresnel_f82_tint(float3(f0), float3(tint), 1.0f).x == f0);
            CHECK(brdf::fresnel_f82_tint(float3(f0), float3(tint), 0.0f).x == Approx(1.0f).margin(1e-7));
            for (int i = 0; i <= 1000; ++i) {
                float f = brdf::fresnel_f82_tint(float3(f0), float3(tint), i / 1000.0f).x;
                INFO("mu " << i / 1000.0f << ": " << f);
                CHECK((f >= 0.0f && f <= 1.0f));
            }
        }
    }
}

TEST_CASE("EON: roughness 0 is Lambert exactly, and the lobe is reciprocal", "[brdf][openpbr]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    float3 rho(0.8f, 0.35f, 0.05f);
    float3 lambert = rho * brdf::lambert_brdf();
    double worst = 0.0;
    for (int k = 0; k < 20000; ++k) {
        float3 wo = brdf::square_to_cosine_hemisphere(u(rng), u(rng)), wi = brdf::square_to_uniform_sphere(u(rng), u(rng));
        wi.z = std::fabs(wi.z);
        float3 f = brdf::eon_brdf(rho, 0.0f, wo, wi);
        CHECK(f.x == lambert.x);  // the same bits
        CHECK(f.y == lambert.y);
        CHECK(f.z == lambert.z);
        for (float sigma : {0.1f, 0.5f, 1.0f}) {
            float3 a = brdf::eon_brdf(rho, sigma, wo, wi), b = brdf::eon_brdf(rho, sigma, wi, wo);
            for (int c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs(a[c] - b[c]) / std::fmax(a[c], b[c]));
        }
    }
    std::printf("EON reciprocity: largest relative difference %.2e\n", worst);
    CHECK(worst <= 1e-6);  // float rounding: the same terms multiplied in another order, a few ulps
    CHECK(brdf::eon_brdf(rho, 0.5f, float3(0, 0.6f, 0.8f), float3(0, 0.6f, -0.8f)).x == 0.0f);
    CHECK(brdf::eon_brdf(rho, 0.5f, float3(0, 0.6f, -0.8f), float3(0, 0.6f, 0.8f)).x == 0.0f);
}

TEST_CASE("EON: a white lobe reflects everything; Fujii's lobe alone matches its closed-form albedo and fails that", "[brdf][openpbr]") {
    for (float sigma : {0.25f, 0.5f, 1.0f}) {
        for (float theta : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
            float3 wo = brdf::direction_from_degrees(theta, 40.0f);
            EonQuadrature eon = eon_albedo_quadrature(brdf::eon_brdf, sigma, wo);
            EonQuadrature fujii = eon_albedo_quadrature(brdf::eon_single_scattering_brdf, sigma, wo);
            double a = 1.0 / (1.0 + (0.5 - 2.0 / (3.0 * M_PI)) * sigma);  // the paper's A, in double
            double closed_form = a + sigma * a / M_PI * brdf::eon_albedo_g(wo.z);
            std::printf("EON sigma %.2f theta %4.1f: albedo %.7f +- %.1e (Fujii alone %.6f, closed form %.6f)\n", sigma,
                        theta, eon.albedo, eon.error, fujii.albedo, closed_form);
            INFO("sigma " << sigma << ", theta " << theta);
            CHECK(std::fabs(eon.albedo - 1.0) <= eon.error);
            CHECK(std::fabs(fujii.albedo - closed_form) <= fujii.error);
            if (theta < 89.0f) CHECK(std::fabs(fujii.albedo - 1.0) > 100.0 * fujii.error);  // the check has power
        }
    }
}

TEST_CASE("EON: its cosine sampler passes the chi-square suite's test, and a wrong pdf fails it", "[brdf][openpbr][chi_square]") {
    using namespace lab::validation;
    ChiSquareOptions options = chi_square_suite_options();
    options.tests = 2;  // Sidak over the true pdf and the wrong one
    DirectionSampler sampler = [](float3 u) {
        DirectionSample s;
        s.kind = SampleKind::Continuous;
        s.wi = brdf::eon_sample(u.x, u.y);
        return s;
    };
    // the sampler and its pdf do not depend on wo or sigma (cosine-weighted): one direction tests them
    float3 wo = brdf::direction_from_degrees(60.0f, 30.0f);
    ChiSquareResult r = chi_square_test(sampler, [wo](float3 wi) { return double(brdf::eon_pdf(wo, wi)); }, options);
    std::printf("EON chi-square: %s\n", describe(r).c_str());
    INFO(describe(r));
    CHECK(r.passed);
    // uniform over the hemisphere: integrates to 1 as the true pdf does, and must be rejected
    ChiSquareResult wrong = chi_square_test(sampler, [](float3 wi) { return wi.z > 0.0f ? 0.5 / M_PI : 0.0; }, options);
    std::printf("EON chi-square against a uniform pdf (must be rejected): %s\n", describe(wrong).c_str());
    INFO(describe(wrong));
    CHECK_FALSE(wrong.passed);
}

TEST_CASE("thin film: the Airy series equals the textbook film reflectance; thickness 0 is no film", "[brdf][openpbr]") {
    const FilmCase cases[] = {
        {1.0, 1.33, 1.0, 0.0},  {1.0, 1.33, 1.0, 50.0}, {1.0, 1.33, 1.5, 30.0},  // soap film in air, water on glass
        {1.0, 2.0, 1.5, 0.0},   {1.0, 2.0, 1.5, 70.0},                           // TiO2-like film on glass
        {1.0, 1.4, 2.4, 45.0},                                                   // film below the base's index
        {1.6, 2.0, 1.3, 60.0},  // under a coat: total reflection inside the film at the base (1.6 sin 60 > 1.3)
    };
    double worst = 0.0;
    for (const FilmCase& c : cases) {
        float cos1 = float(std::cos(c.theta_deg * M_PI / 180.0));
        for (double d : {0.05, 0.25, 0.5, 1.2}) {
            for (double lambda : {0.42, 0.55, 0.68}) {
                double expected = thin_film_textbook(cos1, c.n1, c.n2, c.n3, d, lambda);
                float r = brdf::thin_film_reflectance(cos1, float(c.n1), float(c.n2), float(c.n3), float(d), float(1.0 / lambda), 0.0f);
                INFO("n " << c.n1 << " " << c.n2 << " " << c.n3 << ", theta " << c.theta_deg << ", d " << d << " um, lambda " << lambda);
                // float rounding: the phase (up to 75 rad) is good to ~1e-5 rad, and dR/dphase <= 2 sum m C_m < 0.2 here
                CHECK(std::fabs(r - expected) <= 1e-5);
                worst = std::fmax(worst, std::fabs(r - expected));
            }
        }
        // thickness 0 is the base's own Fresnel reflectance, bit for bit; a film 1e-6 um thin is within rounding of it
        float bare = brdf::fresnel_dielectric(cos1, float(c.n3 / c.n1));
        CHECK(brdf::thin_film_reflectance(cos1, float(c.n1), float(c.n2), float(c.n3), 0.0f, 1.8f, 0.1f) == bare);
        CHECK(brdf::thin_film_reflectance(cos1, float(c.n1), float(c.n2), float(c.n3), 1e-6f, 1.8f, 0.0f) == Approx(bare).margin(1e-6));
        float3 rgb = brdf::thin_film_reflectance_rgb(cos1, float(c.n1), float(c.n2), float(c.n3), 0.0f);
        CHECK((rgb.x == bare && rgb.y == bare && rgb.z == bare));
    }
    std::printf("thin film against the textbook: largest difference %.2e\n", worst);
    // a film of the base's index, or of the outside's, is no film at any thickness
    for (double d : {0.1, 0.37, 0.9}) {
        CHECK(brdf::thin_film_reflectance(0.8f, 1.0f, 1.5f, 1.5f, float(d), 2.0f, 0.0f) == Approx(brdf::fresnel_dielectric(0.8f, 1.5f)).margin(1e-6));
        CHECK(brdf::thin_film_reflectance(0.8f, 1.0f, 1.0f, 1.5f, float(d), 2.0f, 0.0f) == Approx(brdf::fresnel_dielectric(0.8f, 1.5f)).margin(1e-6));
    }
}

TEST_CASE("thin film: the series over a Gaussian in wavenumber equals the textbook reflectance averaged over it", "[brdf][openpbr]") {
    double worst = 0.0;
    for (double d : {0.2, 0.6, 2.0}) {
        for (double theta : {0.0, 60.0}) {
            float cos1 = float(std::cos(theta * M_PI / 180.0));
            const double nu = 1.0 / 0.55, sigma = 0.1;
            // midpoint rule over +-6 sigma (the Gaussian's mass outside: 2e-9), 4000 cells for a few periods
            const int n = 4000;
            double average = 0.0;
            for (int i = 0; i < n; ++i) {
                double x = -6.0 + 12.0 * (i + 0.5) / n;
                average += std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI) * (12.0 / n) *
                           thin_film_textbook(cos1, 1.0, 1.33, 1.5, d, 1.0 / (nu + sigma * x));
            }
            float r = brdf::thin_film_reflectance(cos1, 1.0f, 1.33f, 1.5f, float(d), float(nu), float(sigma));
            INFO("d " << d << ", theta " << theta);
            CHECK(std::fabs(r - average) <= 1e-5);
            worst = std::fmax(worst, std::fabs(r - average));
        }
    }
    std::printf("thin film over a Gaussian in wavenumber: largest difference %.2e\n", worst);
}

TEST_CASE("thin film over a conductor: the Airy series equals the textbook reflectance; thickness 0 is the bare conductor", "[brdf][openpbr]") {
    // complex indices of gold, copper and aluminium near 550 nm, held fixed over wavelength (no dispersion)
    const std::complex<double> metals[] = {{0.43, 2.45}, {0.94, 2.6}, {0.96, 6.69}};
    double worst = 0.0, worst_bare = 0.0;
    for (std::complex<double> n3 : metals) {
        brdf::float2 base(float(n3.real()), float(n3.imag()));
        for (double n2 : {1.33, 2.0}) {
            for (double theta : {0.0, 45.0, 75.0, 88.0}) {  // at 88 degrees |r12 r23| reaches 0.96: the series past 64 terms
                float cos1 = float(std::cos(theta * M_PI / 180.0));
                for (double d : {0.05, 0.3, 0.9}) {
                    for (double lambda : {0.42, 0.55, 0.68}) {
                        double expected = thin_film_textbook(cos1, 1.0, n2, n3, d, lambda);
                        float r = brdf::thin_film_conductor_reflectance(cos1, 1.0f, float(n2), base, float(d), float(1.0 / lambda), 0.0f);
                        INFO("n3 " << n3 << ", film " << n2 << ", theta " << theta << ", d " << d << ", lambda " << lambda);
                        CHECK(std::fabs(r - expected) <= 1e-5);  // float rounding, as for the dielectric base
                        worst = std::fmax(worst, std::fabs(r - expected));
                    }
                }
                // thickness 0: the bare conductor, |r13|^2 of the textbook with no film; a film 1e-9 um thin within rounding of it
                double bare = thin_film_textbook(cos1, 1.0, 1.0, n3, 0.0, 0.55);
                float r0 = brdf::thin_film_conductor_reflectance(cos1, 1.0f, float(n2), base, 0.0f, 1.8f, 0.1f);
                CHECK(std::fabs(r0 - bare) <= 1e-6);
                CHECK(std::fabs(brdf::thin_film_conductor_reflectance(cos1, 1.0f, float(n2), base, 1e-9f, 1.8f, 0.0f) - bare) <= 2e-6);
                worst_bare = std::fmax(worst_bare, std::fabs(r0 - bare));
            }
        }
    }
    std::printf("thin film over a conductor against the textbook: largest difference %.2e, bare conductor %.2e\n", worst, worst_bare);
    // kappa = 0 is the dielectric base
    for (double d : {0.1, 0.5}) {
        float a = brdf::thin_film_conductor_reflectance(0.7f, 1.0f, 1.4f, brdf::float2(1.6f, 0.0f), float(d), 1.7f, 0.1f);
        CHECK(a == Approx(brdf::thin_film_reflectance(0.7f, 1.0f, 1.4f, 1.6f, float(d), 1.7f, 0.1f)).margin(1e-7));
    }
}

namespace {

// Gulbrandsen 2014's conductor of normal reflectance r and edge tint g, in double, for the test only.
std::complex<double> gulbrandsen_textbook(double r, double g) {
    r = std::min(r, 0.99);
    double n_min = (1.0 - r) / (1.0 + r), n_max = (1.0 + std::sqrt(r)) / (1.0 - std::sqrt(r));
    double n = g * n_min + (1.0 - g) * n_max;
    return {n, std::sqrt(std::max(0.0, ((n + 1.0) * (n + 1.0) * r - (n - 1.0) * (n - 1.0)) / (1.0 - r)))};
}

// OpenPBR's F82 tint (Kutz et al.'s notation) in double.
double f82_textbook(double f0, double tint, double mu) {
    auto schlick = [f0](double m) { return f0 + (1.0 - f0) * std::pow(1.0 - m, 5.0); };
    const double mu_bar = 1.0 / 7.0;
    double b = schlick(mu_bar) * (1.0 - tint) / (mu_bar * std::pow(1.0 - mu_bar, 6.0));
    return std::max(0.0, schlick(mu) - b * mu * std::pow(1.0 - mu, 6.0));
}

}  // namespace

TEST_CASE("thin film on the metal: F82 plus the film's change of the equivalent conductor's two-interface reflectance", "[brdf][openpbr]") {
    struct MetalCase {
        double f0, tint;
    };
    // gold-, copper- and aluminium-like channels, a dark metal with a dark tint, a white one (F0 above Gulbrandsen's 0.99)
    const MetalCase metals[] = {{0.95, 0.9}, {0.55, 0.5}, {0.91, 0.98}, {0.05, 0.2}, {1.0, 1.0}};
    brdf::Material m = brdf::default_material(BRDF_MODEL_OPENPBR);
    double worst = 0.0, dielectric_miss = 0.0;
    for (const MetalCase& c : metals) {
        // the index in float against Gulbrandsen's in double: eta = n_max + g (n_min - n_max) cancels
        // towards g = 1, good to a few ulps of n_max; kappa^2 is a difference over 1 - r, and moves with eta
        brdf::float2 index = brdf::conductor_index_from_tint(float(c.f0), float(c.tint));
        std::complex<double> exact = gulbrandsen_textbook(c.f0, c.tint);
        const double eps = std::ldexp(1.0, -24), r = std::min(c.f0, 0.99), n = exact.real();
        double eta_bound = 8.0 * eps * (1.0 + std::sqrt(r)) / (1.0 - std::sqrt(r));
        double kappa2_bound = 8.0 * eps * ((n + 1.0) * (n + 1.0) * r + (n - 1.0) * (n - 1.0)) / (1.0 - r) +
                              std::fabs(2.0 * (n + 1.0) * r - 2.0 * (n - 1.0)) / (1.0 - r) * eta_bound;
        CHECK(std::fabs(index.x - n) <= eta_bound);
        CHECK(std::fabs(double(index.y) * index.y - std::norm(exact.imag())) <= kappa2_bound);
        // the film's part against the textbook over the float index
        std::complex<double> n3(index.x, index.y);
        for (double film_ior : {1.33, 1.8}) {
            for (double weight : {1.0, 0.6}) {
                m.thin_film_ior = float(film_ior), m.thin_film_weight = float(weight);
                for (double theta : {0.0, 45.0, 75.0}) {
                    float cos1 = float(std::cos(theta * M_PI / 180.0));
                    double f82 = f82_textbook(c.f0, c.tint, cos1);
                    for (double d : {0.1, 0.35, 0.9}) {
                        m.thin_film_thickness = float(d);
                        for (double lambda : {0.45, 0.55, 0.65}) {
                            double change = thin_film_textbook(cos1, 1.0, film_ior, n3, d, lambda) - thin_film_textbook(cos1, 1.0, 1.0, n3, 0.0, lambda);
                            double expected = std::min(1.0, std::max(0.0, f82 + weight * change));
                            float r = brdf::openpbr_metal_film_channel(&m, float(f82), float(c.f0), float(c.tint), cos1, float(1.0 / lambda), 0.0f);
                            INFO("F0 " << c.f0 << ", tint " << c.tint << ", film " << film_ior << " x " << weight << ", theta " << theta << ", d " << d
                                       << ", lambda " << lambda);
                            // the Airy series' float rounding (1e-5, the conductor test above) and the bare conductor's (1e-6)
                            CHECK(std::fabs(r - expected) <= 1.1e-5);
                            worst = std::fmax(worst, std::fabs(r - expected));
                            // the check sees the base: the same film over a dielectric of the same F0 is far off
                            double eta = (1.0 + std::sqrt(std::min(c.f0, 0.99))) / (1.0 - std::sqrt(std::min(c.f0, 0.99)));
                            double over_dielectric = f82 + weight * (thin_film_textbook(cos1, 1.0, film_ior, eta, d, lambda) -
                                                                     thin_film_textbook(cos1, 1.0, 1.0, eta, 0.0, lambda));
                            dielectric_miss = std::fmax(dielectric_miss, std::fabs(std::min(1.0, std::max(0.0, over_dielectric)) - r));
                        }
                    }
                }
            }
        }
    }
    CHECK(dielectric_miss > 100 * 1.1e-5);
    std::printf("thin film on the metal against the two-interface reflectance: largest difference %.2e (over a dielectric base instead: %.2f)\n",
                worst, dielectric_miss);
    // the equivalent conductor reflects F0 at normal incidence, so there the film is the two-interface reflectance itself
    for (const MetalCase& c : metals) {
        if (c.f0 > 0.99) continue;
        m.thin_film_weight = 1.0f, m.thin_film_ior = 1.5f, m.thin_film_thickness = 0.3f;
        brdf::float2 index = brdf::conductor_index_from_tint(float(c.f0), float(c.tint));
        float r = brdf::openpbr_metal_film_channel(&m, float(c.f0), float(c.f0), float(c.tint), 1.0f, 1.0f / 0.55f, 0.0f);
        CHECK(std::fabs(r - thin_film_textbook(1.0, 1.0, 1.5, std::complex<double>(index.x, index.y), 0.3, 0.55)) <= 1.1e-5);
    }
}
