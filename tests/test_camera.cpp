// The camera (kernels/camera.h, render/camera_setup): the thin lens against thin-lens optics (a point
// on the plane of focus images to a point, one off it to the circle of confusion), camera rays and
// lens connections invert each other, the importance W_e and its pdf are normalised as documented,
// and points behind the camera or outside the film are not visible.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "common/input_error.hpp"
#include "kernels/host.hpp"
#include "render/camera_setup.hpp"
#include "validation/uniform_random.hpp"

using brdf::float3;

namespace {

constexpr double kPi = 3.14159265358979323846;

lab::scene::Camera scene_camera(float aperture, float focus) {
    lab::scene::Camera c;
    c.type = aperture > 0.0f ? lab::scene::CameraType::thin_lens : lab::scene::CameraType::pinhole;
    c.position = float3(0.5f, 1.5f, 6.0f);
    c.look_at = float3(0.0f, 0.8f, 0.0f);
    c.fov_degrees = 35.0f;
    c.aperture_radius = aperture;
    c.focus_distance = focus;
    return c;
}

// The point at depth z along the view direction, offset on the plane at that depth (in units of
// the film's half extents there, so (sx, sy) is where the pinhole images it).
float3 point_at_depth(const kernel::Camera& c, double z, double sx, double sy) {
    const glm::dvec3 o(c.position[0], c.position[1], c.position[2]), f(c.forward[0], c.forward[1], c.forward[2]);
    const glm::dvec3 r(c.right[0], c.right[1], c.right[2]), u(c.up[0], c.up[1], c.up[2]);
    return float3(o + z * (f + sx * r + sy * u));
}

// A lens sample grid of n x n, plus numbers next to 1 so the rim of the disk is reached.
kernel::float2 lens_u(int i, int j, int n) {
    auto at = [n](int k) { return k == n - 1 ? 0x1.fffffep-1f : (float(k) + 0.5f) / float(n); };
    return kernel::make_float2(at(i), at(j));
}

}  // namespace

TEST_CASE("camera: a point on the plane of focus images to one spot, off it to the circle of confusion", "[camera]") {
    const int width = 160, height = 120;
    const float aperture = 0.12f, focus = 5.0f;
    const kernel::Camera c = lab::render::make_camera(scene_camera(aperture, focus), width, height, "scenes/x.json");
    const double sx = 0.3, sy = -0.2;  // off axis
    // the pinhole image of (sx, sy): raster ((sx + 1) w / 2, (1 - sy) h / 2)
    const double cx = (sx + 1.0) * 0.5 * width, cy = (1.0 - sy) * 0.5 * height;
    // pixels per unit of film at distance 1 (|right| is the half width there)
    const double pixels_per_unit = 0.5 * width / glm::length(float3(c.right[0], c.right[1], c.right[2]));
    for (double z : {double(focus), 2.0, 3.5, 9.0, 40.0}) {
        const float3 p = point_at_depth(c, z, sx, sy);
        // thin-lens optics: blur circle radius R |1/F - 1/z| on the film at distance 1
        const double expected = aperture * std::fabs(1.0 / focus - 1.0 / z) * pixels_per_unit;
        const int n = 200;
        double max_r = 0.0, sum_r2 = 0.0, mean_x = 0.0, mean_y = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const kernel::CameraSample s = kernel::camera_sample_wi(&c, p, lens_u(i, j, n));
                REQUIRE(s.visible == 1);
                const double dx = s.raster.x - cx, dy = s.raster.y - cy;
                max_r = std::fmax(max_r, std::sqrt(dx * dx + dy * dy));
                sum_r2 += dx * dx + dy * dy;
                mean_x += dx;
                mean_y += dy;
            }
        const double count = double(n) * n, rms = std::sqrt(sum_r2 / count);
        mean_x /= count;
        mean_y /= count;
        std::printf("[camera] thin lens R = %.2f, F = %.1f: point at depth %.1f: blur radius %.5f px (thin-lens optics %.5f), "
                    "rms %.5f (R/sqrt 2: %.5f), centre offset (%.2g, %.2g) px\n",
                    aperture, focus, z, max_r, expected, rms, expected / std::sqrt(2.0), mean_x, mean_y);
        if (z == double(focus)) {
            // in focus: every lens point lands on the pinhole image, to float rounding (1e-3 px)
            CHECK(max_r < 1e-3);
        } else {
            // the rim is reached (the grid's last row maps to radius 1 - 2^-24) and not exceeded;
            // the float rounding of the raster is about 1e-5 px
            CHECK(max_r == Approx(expected).epsilon(1e-4).margin(1e-3));
            // uniform over the disk: E[r^2] = R^2 / 2; the midpoint rule over the area-preserving
            // concentric map errs by O(1 / n^2), the rim row adds about as much: 1e-3 is ample
            CHECK(rms == Approx(expected / std::sqrt(2.0)).epsilon(1e-3));
            CHECK(std::fabs(mean_x) < 1e-3 * expected + 1e-3);
            CHECK(std::fabs(mean_y) < 1e-3 * expected + 1e-3);
        }
    }
}

TEST_CASE("camera: camera rays and lens connections invert each other", "[camera]") {
    for (float aperture : {0.0f, 0.2f}) {
        const kernel::Camera c = lab::render::make_camera(scene_camera(aperture, 4.0f), 96, 64, "scenes/x.json");
        lab::validation::UniformRandom rng(17);
        int tested = 0;
        for (int k = 0; k < 20000; ++k) {
            const float3 p = point_at_depth(c, rng.uniform(0.5f, 30.0f), rng.uniform(-1.1f, 1.1f), rng.uniform(-1.1f, 1.1f));
            const kernel::float2 u = kernel::make_float2(rng.next_float(), rng.next_float());
            const kernel::CameraSample s = kernel::camera_sample_wi(&c, p, u);
            if (!s.visible) continue;
            ++tested;
            float3 origin, direction;
            kernel::camera_generate_ray(&c, s.raster.x, s.raster.y, u, &origin, &direction);
            REQUIRE(glm::length(origin - s.lens_point) < 1e-5f);
            // the ray from the lens point through raster passes through p
            const float3 to_p = p - origin;
            REQUIRE(glm::length(glm::cross(direction, to_p)) < 2e-6f * glm::length(to_p) + 1e-6f);
            REQUIRE(glm::dot(direction, to_p) > 0.0f);
            REQUIRE(glm::length(s.wi + direction) < 1e-5f);
            REQUIRE(s.distance == Approx(glm::length(to_p)).epsilon(1e-5));
            // the importance of that ray and its raster
            kernel::float2 raster(0.0f);
            REQUIRE(kernel::camera_importance(&c, origin, direction, &raster) == Approx(s.importance).epsilon(1e-4));
            REQUIRE(std::fabs(raster.x - s.raster.x) < 2e-3f);
            REQUIRE(std::fabs(raster.y - s.raster.y) < 2e-3f);
        }
        INFO("lens radius " << aperture << ": " << tested << " visible points");
        CHECK(tested > 10000);
    }
}

TEST_CASE("camera: W_e and its pdf are normalised over the film's directions", "[camera]") {
    // Identity checked (docs in kernels/camera.h): for a fixed lens point,
    //   integral over all directions of W_e(w) cos theta d omega = 1 / lens_area   (1 for the pinhole),
    //   integral of pdf_direction(w) d omega = 1.
    // The integral runs over a (theta, phi) grid about forward, the test's own parametrisation, so
    // the film's edges cut cells: the error is of the order of one grid step of theta (1e-3).
    for (float aperture : {0.0f, 0.25f}) {
        const int width = 90, height = 60;
        const kernel::Camera c = lab::render::make_camera(scene_camera(aperture, 3.0f), width, height, "scenes/x.json");
        const float3 lens = kernel::camera_lens_point(&c, kernel::make_float2(0.8f, 0.3f));
        const glm::dvec3 f(c.forward[0], c.forward[1], c.forward[2]);
        const glm::dvec3 r = glm::normalize(glm::dvec3(c.right[0], c.right[1], c.right[2]));
        const glm::dvec3 u = glm::cross(r, f);
        const double half_diagonal = std::atan(glm::length(glm::dvec3(c.right[0], c.right[1], c.right[2]) +
                                                            glm::dvec3(c.up[0], c.up[1], c.up[2])) * 1.2);
        const int thetas = 3000, phis = 3000;
        double we = 0.0, pdf = 0.0;
        // pbrt's relation at every direction the film sees: pdf_direction = W_e lens_area cos theta,
        // pdf_position = 1 / lens_area. Checked with the same Approx as a REQUIRE would, counted here and
        // asserted once after the loop (a REQUIRE per direction costs 4/5 of the test under the sanitizers);
        // the first direction that breaks it is reported.
        long broken = 0;
        std::string first_broken;
        for (int i = 0; i < thetas; ++i) {
            const double theta = (i + 0.5) * half_diagonal / thetas;
            const double cell = std::sin(theta) * (half_diagonal / thetas) * (2.0 * kPi / phis);
            for (int k = 0; k < phis; ++k) {
                const double phi = (k + 0.5) * 2.0 * kPi / phis;
                const float3 w(f * std::cos(theta) + (r * std::cos(phi) + u * std::sin(phi)) * std::sin(theta));
                kernel::float2 raster(0.0f);
                const float importance = kernel::camera_importance(&c, lens, w, &raster);
                we += importance * std::cos(theta) * cell;
                float pdf_pos, pdf_dir;
                kernel::camera_pdf_we(&c, lens, w, &pdf_pos, &pdf_dir);
                pdf += pdf_dir * cell;
                if (pdf_dir > 0.0f) {
                    const double expected_dir = importance * kernel::camera_lens_area(&c) * std::cos(theta);
                    const double expected_pos = 1.0 / kernel::camera_lens_area(&c);
                    if (!(pdf_dir == Approx(expected_dir).epsilon(1e-5)) || !(pdf_pos == Approx(expected_pos).epsilon(1e-6))) {
                        if (broken++ == 0)
                            first_broken = "theta " + std::to_string(theta) + " phi " + std::to_string(phi) + ": pdf_dir " +
                                           std::to_string(pdf_dir) + " (W_e area cos " + std::to_string(expected_dir) + "), pdf_pos " +
                                           std::to_string(pdf_pos) + " (1 / area " + std::to_string(expected_pos) + ")";
                    }
                }
            }
        }
        INFO("lens radius " << aperture << ": " << broken << " directions break pdf = W_e area cos; the first at " << first_broken);
        REQUIRE(broken == 0);
        const double lens_area = aperture > 0.0f ? kPi * aperture * aperture : 1.0;
        std::printf("[camera] lens radius %.2f: integral of W_e cos = %.6f (1 / lens area = %.6f), integral of pdf_dir = %.6f\n",
                    aperture, we, 1.0 / lens_area, pdf);
        CHECK(we * lens_area == Approx(1.0).margin(2e-3));
        CHECK(pdf == Approx(1.0).margin(2e-3));
    }
}

TEST_CASE("camera: points behind the camera, outside the film or on the lens are not visible", "[camera]") {
    for (float aperture : {0.0f, 0.1f}) {
        const kernel::Camera c = lab::render::make_camera(scene_camera(aperture, 5.0f), 64, 48, "scenes/x.json");
        const kernel::float2 u = kernel::make_float2(0.5f, 0.5f);  // the lens centre
        CHECK(kernel::camera_sample_wi(&c, point_at_depth(c, 3.0, 0.2, 0.1), u).visible == 1);
        CHECK(kernel::camera_sample_wi(&c, point_at_depth(c, -3.0, 0.2, 0.1), u).visible == 0);  // behind
        CHECK(kernel::camera_sample_wi(&c, point_at_depth(c, 3.0, 1.05, 0.0), u).visible == 0);  // right of the film
        CHECK(kernel::camera_sample_wi(&c, point_at_depth(c, 3.0, 0.0, -1.05), u).visible == 0); // below it
        const kernel::CameraSample on_lens = kernel::camera_sample_wi(&c, kernel::camera_lens_point(&c, u), u);
        CHECK(on_lens.visible == 0);
        CHECK(on_lens.importance == 0.0f);
        CHECK(on_lens.pdf == 0.0f);
        kernel::float2 raster;
        CHECK(kernel::camera_importance(&c, kernel::camera_lens_point(&c, u), -float3(c.forward[0], c.forward[1], c.forward[2]), &raster) == 0.0f);
    }
}

TEST_CASE("camera: make_camera rejects a thin lens it cannot use, naming the field", "[camera]") {
    lab::scene::Camera bad = scene_camera(0.1f, 5.0f);
    bad.focus_distance = 0.0f;
    CHECK_THROWS_WITH(lab::render::make_camera(bad, 64, 48, "scenes/x.json"),
                      "scenes/x.json: camera.focus_distance: a thin lens needs a finite focus distance > 0");
    bad = scene_camera(0.1f, 5.0f);
    bad.aperture_radius = -1.0f;
    CHECK_THROWS_WITH(lab::render::make_camera(bad, 64, 48, "scenes/x.json"),
                      "scenes/x.json: camera.aperture_radius: a thin lens needs a finite aperture radius > 0");
    const kernel::Camera pinhole = lab::render::make_camera(scene_camera(0.0f, 0.0f), 64, 48, "scenes/x.json");
    CHECK(pinhole.lens_radius == 0.0f);
    // right and up span the film's half extents at distance 1: tan(fov / 2) vertically, times the aspect
    CHECK(glm::length(float3(pinhole.up[0], pinhole.up[1], pinhole.up[2])) == Approx(std::tan(17.5 * kPi / 180.0)).epsilon(1e-6));
    CHECK(glm::length(float3(pinhole.right[0], pinhole.right[1], pinhole.right[2])) ==
          Approx(std::tan(17.5 * kPi / 180.0) * 64.0 / 48.0).epsilon(1e-6));
}
