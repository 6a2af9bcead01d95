// Rect and disk emitters (kernels/lights/area_light.h) against closed forms, with the path tracer
// and the light tracer on the OpenCL device and BDPT on the host C++ build.
//
// The scene: an endless Lambert plane (reflectance rho = 0.5) under a rect of 1 x 0.6 and a disk of
// radius 0.4, both 1 above it, facing down, 3 apart. A camera between each light and the plane, on
// its axis and looking straight down, sees a square of the plane around the light's foot. Light
// reaches the plane from the lights alone and leaves it for the lights' black backs or nowhere, so
// a pixel is (rho / pi) times the irradiance E averaged over its footprint, which a plane at right
// angles to the view maps onto the film with one scale. E at a point of the plane:
//  - from a rect: pi L times the form factor of the parallel rect, the four rects that share a corner
//    above the point with signs (Howell's catalogue, B-3), each
//        F(a, b) = 1 / (2 pi) [ X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2)) + Y / sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2)) ],
//    X = a / h, Y = b / h (odd in each, so the signed corner offsets add up);
//  - from a disk of radius r whose axis is rho_p from the point (Howell, B-13):
//        F = 1/2 [ 1 - (h^2 + rho_p^2 - r^2) / sqrt((h^2 + rho_p^2 + r^2)^2 - 4 rho_p^2 r^2) ],
//    r^2 / (h^2 + r^2) on the axis.
// Each pixel's expected value is that formula averaged over its footprint (a 6 x 6 midpoint rule,
// within 1e-5 of the integral here); the test checks the image mean against the mean of those
// within 1 %, and first requires the mean's standard error (from the spread of the pixels about
// their expected values: noise alone) to be at most a quarter of that, as tests/closed_form_scenes.hpp
// does. Each light is checked with the other's radiance 0 (a black disk or rect beside it, which
// shades nothing there), so all runs share one compiled scene.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "opencl/runtime.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/closed_form_scenes.hpp"

namespace {

using lab::render::Integrator;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRho = 0.5;      // the plane's reflectance
constexpr double kHeight = 1.0;   // of both lights above the plane
constexpr double kRectA = 1.0, kRectB = 0.6, kRectX = -1.5;  // the rect's edges along x and z, its centre's x
constexpr double kDiskR = 0.4, kDiskX = 1.5;                 // the disk's radius and centre's x
constexpr double kCameraHeight = 0.5;
constexpr double kHalfView = 0.4;  // half the side of the square of the plane the camera sees
constexpr double kRadiance = 2.0;

// The scene with the rect's and the disk's radiance, and a camera at (x, camera_y, z) looking along
// `look` (JSON) with up `up`, vertical field of view `fov` degrees.
std::string area_light_scene(double rect_le, double disk_le, double x, double camera_y, double z, const std::string& look, const std::string& up,
                             double fov) {
    auto n = [](double v) { return std::to_string(v); };
    auto gray = [&](double v) { return "[" + n(v) + ", " + n(v) + ", " + n(v) + "]"; };
    return R"({"camera": {"type": "pinhole", "position": [)" + n(x) + ", " + n(camera_y) + ", " + n(z) + R"(], "look_at": )" + look +
           R"(, "up": )" + up + R"(, "fov_degrees": )" + n(fov) + R"(},
      "materials": {"wall": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}, "retroreflection": 0, "subsurface": 0}},
      "objects": [{"name": "ground", "material": "wall", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}}],
      "emitters": [{"type": "rect", "center": [)" + n(kRectX) + ", " + n(kHeight) + R"(, 0], "edge_u": [)" + n(kRectA) + R"(, 0, 0], "edge_v": [0, 0, )" +
           n(kRectB) + R"(], "radiance": )" + gray(rect_le) + R"(},
                   {"type": "disk", "center": [)" + n(kDiskX) + ", " + n(kHeight) + R"(, 0], "normal": [0, -1, 0], "radius": )" + n(kDiskR) +
           R"(, "radiance": )" + gray(disk_le) + R"(}]})";
}

// The camera on the light's axis looking straight down at the square of half side kHalfView.
std::string plane_view_scene(bool rect) {
    const double x = rect ? kRectX : kDiskX;
    const double fov = 2.0 * std::atan(kHalfView / kCameraHeight) * 180.0 / kPi;
    return area_light_scene(rect ? kRadiance : 0.0, rect ? 0.0 : kRadiance, x, kCameraHeight, 0.0, "[" + std::to_string(x) + ", 0, 0]", "[0, 0, -1]", fov);
}

// The form factor from a point to the parallel rect with a corner above it, edges a, b at height h.
double corner_form_factor(double a, double b, double h) {
    const double x = a / h, y = b / h, sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * kPi);
}

// Irradiance at (px, pz) on the plane per unit radiance of the light.
double rect_irradiance(double px, double pz) {
    const double x0 = kRectX - 0.5 * kRectA - px, x1 = kRectX + 0.5 * kRectA - px, z0 = -0.5 * kRectB - pz, z1 = 0.5 * kRectB - pz;
    const double f = corner_form_factor(x1, z1, kHeight) - corner_form_factor(x0, z1, kHeight) - corner_form_factor(x1, z0, kHeight) +
                     corner_form_factor(x0, z0, kHeight);
    return kPi * f;
}

double disk_irradiance(double px, double pz) {
    const double h2 = kHeight * kHeight, r2 = kDiskR * kDiskR, p2 = (px - kDiskX) * (px - kDiskX) + pz * pz;
    const double f = 0.5 * (1.0 - (h2 + p2 - r2) / std::sqrt((h2 + p2 + r2) * (h2 + p2 + r2) - 4.0 * p2 * r2));
    return kPi * f;
}

// Each pixel's expected value: (rho / pi) L E averaged over its footprint, a square of the plane
// (x to the right, z down the image, about the camera's foot).
std::vector<double> expected_pixels(bool rect, int size) {
    const double cx = rect ? kRectX : kDiskX, pixel = 2.0 * kHalfView / size;
    constexpr int kRule = 6;
    std::vector<double> out(size_t(size) * size_t(size));
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            double sum = 0.0;
            for (int b = 0; b < kRule; ++b)
                for (int a = 0; a < kRule; ++a) {
                    const double x = cx - kHalfView + pixel * (i + (a + 0.5) / kRule), z = -kHalfView + pixel * (j + (b + 0.5) / kRule);
                    sum += rect ? rect_irradiance(x, z) : disk_irradiance(x, z);
                }
            out[size_t(j) * size_t(size) + size_t(i)] = kRho / kPi * kRadiance * sum / (kRule * kRule);
        }
    return out;
}

// The image's mean against the mean of the expected pixels, the standard error from the residuals.
void check_plane(const std::string& what, bool rect, lab::render::Renderer& renderer, int size, int plain_spp) {
    const int spp = plain_spp / closed_forms::kPathDivisor;  // the sanitized build's quarter (tests/closed_form_scenes.hpp)
    RenderResult r = render_samples(renderer, spp);
    const std::vector<double> expected = expected_pixels(rect, size);
    double sum = 0.0, sum_expected = 0.0, sum2 = 0.0;
    const size_t n = expected.size();
    for (size_t p = 0; p < n; ++p) {
        const double v = r.image.rgb[3 * p + 1], residual = v - expected[p];
        sum += v;
        sum_expected += expected[p];
        sum2 += residual * residual;
    }
    const double mean = sum / double(n), exact = sum_expected / double(n);
    const double residual_mean = mean - exact;
    const double standard_error = std::sqrt(std::max(0.0, sum2 / double(n) - residual_mean * residual_mean) / double(n - 1));
    INFO(what << (rect ? ", rect" : ", disk") << " (" << renderer.device_description() << "): mean " << mean << " +- " << standard_error
              << ", exact " << exact << " (" << 100.0 * residual_mean / exact << " %), " << spp << " spp");
    std::printf("area lights, %s, %s: mean %.6f +- %.6f, exact %.6f, error %+.3f %%\n", what.c_str(), rect ? "rect" : "disk", mean, standard_error,
                exact, 100.0 * residual_mean / exact);
    CHECK(r.stats.nonfinite_samples == 0);
    REQUIRE(standard_error < closed_forms::bound(0.0025) * exact);
    CHECK(std::fabs(residual_mean) < closed_forms::bound(0.01) * exact);
}

lab::render::RenderInput area_input(const std::string& scene, Integrator integrator, int size) {
    lab::render::RenderInput input = render_input(std::nullopt, "", size, lab::render::LightSampling::mis, 5, scene);
    input.settings.integrator = integrator;
    input.settings.max_depth = 4;  // the plane sees only the lights' backs: one bounce is all there is
    return input;
}

// The rect seen straight on from 0.8 below through a 90 degree view of 32 x 32 pixels: pixels of
// 0.05 on its plane, so its 1 x 0.6 cover 20 x 12 pixels, the camera a quarter pixel off its axis in
// both directions so that its edges cross pixels at a quarter (no edge on a pixel boundary, where
// rounding decides). A pixel is L times the share of its camera rays that hit the rect: exactly L
// inside, exactly 0 outside, and the image sums to L times the rect's 240 pixels up to the noise of
// the edge pixels' shares, sigma^2 = sum c (1 - c) / spp over their covered fractions c.
void check_rect_edges(const lab::opencl::Runtime& runtime) {
    constexpr int kSize = 32, kSpp = 1024;
    constexpr double kDistance = 0.8, kPixel = 2.0 * kDistance / kSize, kShift = 0.25 * kPixel;
    const double x = kRectX + kShift, z = kShift;
    const std::string look = "[" + std::to_string(x) + ", " + std::to_string(kHeight) + ", " + std::to_string(z) + "]";
    lab::render::OpenClRenderer pt(runtime, area_input(area_light_scene(kRadiance, 0.0, x, kHeight - kDistance, z, look, "[0, 0, 1]", 90.0),
                                                       Integrator::pt, kSize));
    RenderResult r = render_samples(pt, kSpp);
    // the covered share of each pixel along one axis: the rect's pixel interval against the pixel's
    auto share = [](int i, double lo, double hi) { return std::max(0.0, std::min(double(i + 1), hi) - std::max(double(i), lo)); };
    const double x_lo = 0.5 * kSize - 0.5 * kRectA / kPixel, y_lo = 0.5 * kSize - 0.5 * kRectB / kPixel;
    double area = 0.0, variance = 0.0, worst_inside = 0.0, worst_outside = 0.0, expected_area = 0.0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            const double v = r.image.rgb[3 * (size_t(j) * kSize + size_t(i)) + 1] / kRadiance;
            area += v;
            // the image's x may run along +x or -x of the world, its y along +z or -z: the shares are
            // those of the interval shifted by a quarter pixel one way or the other, and the image says
            // which; both cover the same area
            double c = 0.0;
            for (double sx : {-0.25, 0.25})
                for (double sy : {-0.25, 0.25}) {
                    const double cand = share(i, x_lo + sx, x_lo + sx + kRectA / kPixel) * share(j, y_lo + sy, y_lo + sy + kRectB / kPixel);
                    if (std::fabs(cand - v) < std::fabs(c - v) || (sx == -0.25 && sy == -0.25)) c = cand;
                }
            expected_area += c;
            variance += c * (1.0 - c) / kSpp;
            if (c == 1.0) worst_inside = std::max(worst_inside, std::fabs(v - 1.0));
            if (c == 0.0) worst_outside = std::max(worst_outside, std::fabs(v));
        }
    const double sigma = std::sqrt(variance);
    std::printf("area lights, rect edges: %.3f pixels covered, exact %.1f (sigma %.3f); inside off by %g, outside %g\n", area,
                kRectA * kRectB / (kPixel * kPixel), sigma, worst_inside, worst_outside);
    INFO("covered " << area << " pixels, exact " << kRectA * kRectB / (kPixel * kPixel) << ", sigma " << sigma);
    CHECK(std::fabs(expected_area - kRectA * kRectB / (kPixel * kPixel)) < 1e-9);
    CHECK(worst_inside < 1e-6);
    CHECK(worst_outside == 0.0);
    CHECK(std::fabs(area - kRectA * kRectB / (kPixel * kPixel)) < 4.0 * sigma);
}

}  // namespace

TEST_CASE("Area lights: irradiance under a rect and a disk on their axes: pt and lt on the OpenCL device", "[render][closed-form][area][opencl]") {
    lab::opencl::Runtime runtime("");
    for (bool rect : {true, false}) {
        lab::render::OpenClRenderer pt(runtime, area_input(plane_view_scene(rect), Integrator::pt, 16));
        check_plane("pt", rect, pt, 16, 64);
        lab::render::OpenClRenderer lt(runtime, area_input(plane_view_scene(rect), Integrator::lt, 16));
        check_plane("lt", rect, lt, 16, 6400);
    }
    // the same compiled scene, the camera under the rect
    check_rect_edges(runtime);
}

TEST_CASE("Area lights: irradiance under a rect and a disk on their axes: BDPT on the host", "[render][closed-form][area][bdpt][host]") {
    for (bool rect : {true, false}) {
        lab::render::HostRenderer bdpt(area_input(plane_view_scene(rect), Integrator::bdpt, 12));
        check_plane("bdpt", rect, bdpt, 12, 320);
    }
}
