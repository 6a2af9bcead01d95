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
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include "film/image_output.hpp"
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
                             double fov, const std::string& rect_image = "", const std::string& disk_image = "") {
    auto image = [](const std::string& path) { return path.empty() ? std::string() : R"(, "image": ")" + path + "\""; };
    auto n = [](double v) { return std::to_string(v); };
    auto gray = [&](double v) { return "[" + n(v) + ", " + n(v) + ", " + n(v) + "]"; };
    return R"({"camera": {"type": "pinhole", "position": [)" + n(x) + ", " + n(camera_y) + ", " + n(z) + R"(], "look_at": )" + look +
           R"(, "up": )" + up + R"(, "fov_degrees": )" + n(fov) + R"(},
      "materials": {"wall": {"albedo": [0.5, 0.5, 0.5], "lobes": {"diffuse": 1}, "retroreflection": 0, "subsurface": 0}},
      "objects": [{"name": "ground", "material": "wall", "shape": {"type": "plane", "normal": [0, 1, 0], "offset": 0}}],
      "emitters": [{"type": "rect", "center": [)" + n(kRectX) + ", " + n(kHeight) + R"(, 0], "edge_u": [)" + n(kRectA) + R"(, 0, 0], "edge_v": [0, 0, )" +
           n(kRectB) + R"(], "radiance": )" + gray(rect_le) + image(rect_image) + R"(},
                   {"type": "disk", "center": [)" + n(kDiskX) + ", " + n(kHeight) + R"(, 0], "normal": [0, -1, 0], "radius": )" + n(kDiskR) +
           R"(, "radiance": )" + gray(disk_le) + image(disk_image) + R"(}]})";
}

// The camera on the light's axis looking straight down at the square of half side kHalfView; the
// lights show the images at those paths when given (their radiance then a scale of 1).
std::string plane_view_scene(bool rect, const std::string& rect_image = "", const std::string& disk_image = "") {
    const double x = rect ? kRectX : kDiskX;
    const double fov = 2.0 * std::atan(kHalfView / kCameraHeight) * 180.0 / kPi;
    const double le = rect_image.empty() ? kRadiance : 1.0;
    return area_light_scene(rect ? le : 0.0, rect ? 0.0 : le, x, kCameraHeight, 0.0, "[" + std::to_string(x) + ", 0, 0]", "[0, 0, -1]", fov,
                            rect_image, disk_image);
}

// The form factor from a point to the parallel rect with a corner above it, edges a, b at height h.
double corner_form_factor(double a, double b, double h) {
    const double x = a / h, y = b / h, sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * kPi);
}

// Irradiance at (px, pz) on the plane per unit radiance of the part [x0, x1] x [z0, z1] of the rect
// (the whole rect by default).
double rect_irradiance(double px, double pz, double xa = kRectX - 0.5 * kRectA, double xb = kRectX + 0.5 * kRectA, double za = -0.5 * kRectB,
                       double zb = 0.5 * kRectB) {
    const double x0 = xa - px, x1 = xb - px, z0 = za - pz, z1 = zb - pz;
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
// (x to the right, z down the image, about the camera's foot), E(x, z) per unit radiance given.
std::vector<double> expected_pixels(bool rect, int size, const std::function<double(double, double)>& irradiance, int rule = 6) {
    const double cx = rect ? kRectX : kDiskX, pixel = 2.0 * kHalfView / size;
    const int kRule = rule;
    std::vector<double> out(size_t(size) * size_t(size));
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            double sum = 0.0;
            for (int b = 0; b < kRule; ++b)
                for (int a = 0; a < kRule; ++a) {
                    const double x = cx - kHalfView + pixel * (i + (a + 0.5) / kRule), z = -kHalfView + pixel * (j + (b + 0.5) / kRule);
                    sum += irradiance(x, z);
                }
            out[size_t(j) * size_t(size) + size_t(i)] = kRho / kPi * kRadiance * sum / (kRule * kRule);
        }
    return out;
}

std::vector<double> expected_pixels(bool rect, int size) {
    return expected_pixels(rect, size, [rect](double x, double z) { return rect ? rect_irradiance(x, z) : disk_irradiance(x, z); });
}

// The image's mean against the mean of the expected pixels, the standard error from the residuals;
// returns the image's mean.
double check_pixels(const std::string& what, bool rect, lab::render::Renderer& renderer, int plain_spp, const std::vector<double>& expected) {
    const int spp = plain_spp / closed_forms::kPathDivisor;  // the sanitized build's quarter (tests/closed_form_scenes.hpp)
    RenderResult r = render_samples(renderer, spp);
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
    return mean;
}

void check_plane(const std::string& what, bool rect, lab::render::Renderer& renderer, int size, int plain_spp) {
    check_pixels(what, rect, renderer, plain_spp, expected_pixels(rect, size));
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

namespace {

// Image emitters (kernels/lights/image_emitter.h) on the same plane, each light at a scale of 1:
//  - the rect shows an 8 x 4 grey image with a dark row (the file's row 1), a bright texel (20 at
//    column 5 of row 2) and a ramp along x elsewhere. Its texels are rects parallel to the plane,
//    so E is exact: the sum over texels of their value times the form factor of their part of the
//    rect (the file's row y at t in [(H - 1 - y) / H, (H - y) / H] along V = +z, column i at s in
//    [i / W, (i + 1) / W] along U = +x);
//  - the disk shows a 2 x 1 image of 1 and 3, whose mean is the constant disk's radiance 2: half
//    disks (the concentric map takes the square's left half onto the disk's half x < 0 along U). E
//    from a host quadrature over the square, 64 x 64 midpoints mapped onto the disk (equal areas:
//    the map keeps them), checked against the closed form with a uniform image; by the symmetry of
//    the square view under a half turn about the axis, which swaps the halves, the mean over the
//    view is the constant disk's.
constexpr int kImageW = 8, kImageH = 4;
double rect_texel(int x, int y) { return y == 1 ? 0.0 : (x == 5 && y == 2 ? 20.0 : 0.5 + 0.25 * x); }
constexpr double kDiskTexels[2] = {1.0, 3.0};

std::filesystem::path emitter_test_folder() {
    return std::filesystem::temp_directory_path() / ("dtoadq-image-emitters-" + std::to_string(::getpid()));
}

std::string write_emitter_test_image(const std::string& name, int width, int height, const std::function<double(int, int)>& value) {
    const std::filesystem::path folder = emitter_test_folder();
    std::filesystem::create_directories(folder);
    lab::film::ImageRgb image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) image.rgb[3 * (size_t(y) * size_t(width) + size_t(x)) + size_t(c)] = float(value(x, y));
    const std::string path = (folder / name).string();
    lab::film::write_exr(path, image, lab::film::ImageMetadata{});
    return path;
}

double rect_image_irradiance(double px, double pz) {
    double e = 0.0;
    for (int y = 0; y < kImageH; ++y)
        for (int x = 0; x < kImageW; ++x) {
            const double t0 = double(kImageH - 1 - y) / kImageH, t1 = double(kImageH - y) / kImageH;
            const double xa = kRectX - 0.5 * kRectA + kRectA * x / kImageW, xb = kRectX - 0.5 * kRectA + kRectA * (x + 1) / kImageW;
            e += rect_texel(x, y) * rect_irradiance(px, pz, xa, xb, -0.5 * kRectB + kRectB * t0, -0.5 * kRectB + kRectB * t1);
        }
    return e;
}

// The disk's quadrature points (x, z on the light's plane) and their texel values: U and V as the
// scene gives them.
struct DiskQuadrature {
    std::vector<glm::dvec3> points;  // x, z, value
    DiskQuadrature(const lab::scene::Emitter& disk, bool uniform) {
        constexpr int kN = 64;
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                const double s = (i + 0.5) / kN, t = (j + 0.5) / kN;
                const kernel::float2 d = kernel::square_to_concentric_disk(float(s), float(t));
                const glm::dvec3 q = glm::dvec3(disk.center) + glm::dvec3(disk.edge_u) * double(d.x) + glm::dvec3(disk.edge_v) * double(d.y);
                points.emplace_back(q.x, q.z, uniform ? 1.0 : kDiskTexels[s < 0.5 ? 0 : 1]);
            }
    }
    // E = integral of L cos cos / d^2 dA, both cosines h / d
    double operator()(double px, double pz) const {
        double sum = 0.0;
        for (const glm::dvec3& p : points) {
            const double d2 = (p.x - px) * (p.x - px) + (p.y - pz) * (p.y - pz) + kHeight * kHeight;
            sum += p.z * kHeight * kHeight / (d2 * d2);
        }
        return sum * kPi * kDiskR * kDiskR / double(points.size());
    }
};

double pixel_mean(const std::vector<double>& v) {
    double sum = 0.0;
    for (double x : v) sum += x;
    return sum / double(v.size());
}

struct ImageScenes {
    ImageScenes() = default;
    ImageScenes(const ImageScenes&) = delete;
    ImageScenes& operator=(const ImageScenes&) = delete;
    ~ImageScenes() {  // the renderers have read the images by now
        std::error_code ec;
        std::filesystem::remove_all(emitter_test_folder(), ec);
    }
    std::string rect_image = write_emitter_test_image("rect.exr", kImageW, kImageH, rect_texel);
    std::string disk_image = write_emitter_test_image("disk.exr", 2, 1, [](int x, int) { return kDiskTexels[x]; });
    std::string scene(bool rect) const { return plane_view_scene(rect, rect_image, disk_image); }
    // the expected pixels (per unit scale: pixels of (rho / pi) E with radiance kRadiance, so divided by it)
    std::vector<double> expected(bool rect, int size, const lab::render::Renderer& renderer) const {
        std::vector<double> e;
        if (rect) e = expected_pixels(true, size, rect_image_irradiance);
        else e = expected_pixels(false, size, DiskQuadrature(renderer.compiled_scene().emitters[1], false), 3);
        for (double& v : e) v /= kRadiance;
        return e;
    }
};

}  // namespace

TEST_CASE("Image emitters: the disk's quadrature matches its closed form, and its 2-texel image the constant disk's mean", "[render][closed-form][area][image][host]") {
    const ImageScenes scenes;
    lab::render::HostRenderer probe(area_input(scenes.scene(false), Integrator::pt, 8));
    const lab::scene::Emitter& disk = probe.compiled_scene().emitters[1];
    const DiskQuadrature uniform(disk, true), halves(disk, false);
    double worst = 0.0;
    for (double x : {0.0, 0.2, 0.4})
        for (double z : {0.0, 0.3, -0.4}) worst = std::max(worst, std::fabs(uniform(kDiskX + x, z) / disk_irradiance(kDiskX + x, z) - 1.0));
    std::printf("area lights, image disk: quadrature against the closed form, worst %.2e\n", worst);
    CHECK(worst < 1e-3);
    const double constant = pixel_mean(expected_pixels(false, 16));  // radiance kRadiance, the image's mean
    const double image = pixel_mean(expected_pixels(false, 16, halves, 3)) / kRadiance;
    std::printf("area lights, image disk: mean over the view %.6f, constant disk of the same mean %.6f\n", image, constant);
    CHECK(image == Approx(constant).epsilon(1e-3));
    // and the quadrature tells the halves apart: 0.3 off the axis along +U and -U, 0.824 and 0.696 (a
    // 200 x 200 grid over the half disks)
    const glm::dvec3 u = glm::normalize(glm::dvec3(disk.edge_u));
    CHECK(halves(kDiskX + 0.3 * u.x, 0.3 * u.z) == Approx(0.8240).epsilon(1e-3));
    CHECK(halves(kDiskX - 0.3 * u.x, -0.3 * u.z) == Approx(0.6964).epsilon(1e-3));
}

TEST_CASE("Image emitters: irradiance under a rect and a disk showing images: pt and lt on the OpenCL device", "[render][closed-form][area][image][opencl]") {
    lab::opencl::Runtime runtime("");
    const ImageScenes scenes;
    for (bool rect : {true, false}) {
        lab::render::OpenClRenderer pt(runtime, area_input(scenes.scene(rect), Integrator::pt, 16));
        const std::vector<double> expected = scenes.expected(rect, 16, pt);
        check_pixels("image, pt", rect, pt, 64, expected);
        lab::render::OpenClRenderer lt(runtime, area_input(scenes.scene(rect), Integrator::lt, 16));
        check_pixels("image, lt", rect, lt, 6400, expected);
    }
}

TEST_CASE("Image emitters: irradiance under a rect and a disk showing images: BDPT on the host", "[render][closed-form][area][image][bdpt][host]") {
    const ImageScenes scenes;
    for (bool rect : {true, false}) {
        lab::render::HostRenderer bdpt(area_input(scenes.scene(rect), Integrator::bdpt, 12));
        check_pixels("image, bdpt", rect, bdpt, 320, scenes.expected(rect, 12, bdpt));
    }
}
