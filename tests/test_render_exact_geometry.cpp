// Images whose geometry has a closed form, rendered on the OpenCL device with the plain primitives
// intersected exactly: an emissive sphere covers exactly its projected area (the march's hit
// threshold would inflate it), and a box's edge lies where the camera projects it.
//
// Both measure coverage: a pixel's value is the fraction of its samples (uniform over the pixel)
// that see the surface, times a known radiance. The tolerances are the coverage's own sampling
// noise, a Bernoulli variance p (1 - p) / spp <= 1 / (4 spp) in each pixel the outline crosses, at 5
// standard deviations. At these sizes the sphere's noise (0.013 % of its area) is well below the
// inflation of the march's relative hit threshold (1e-4 t: +0.10 % here, which fails the test).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/render_inputs.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFovDegrees = 40.0;

lab::film::ImageRgb render(const lab::opencl::Runtime& runtime, const char* scene, const std::string& env, int size, int spp) {
    lab::render::RenderInput input = render_input(std::nullopt, env, size, lab::render::LightSampling::mis, 35, scene);
    input.settings.max_depth = 1;
    lab::render::OpenClRenderer renderer(runtime, input);
    return render_samples(renderer, spp).image;
}

}  // namespace

TEST_CASE("Exact geometry: an emissive sphere's image has its exact projected area", "[render][exact][opencl]") {
    lab::opencl::Runtime runtime;
    // radiance 1 on a black background: the image's sum is the sphere's area in pixels
    const char* scene = R"({
      "camera": {"type": "pinhole", "position": [0, 0, 0], "look_at": [0, 0, -1], "fov_degrees": 40},
      "materials": {},
      "objects": [],
      "emitters": [{"center": [0, 0, -5], "radius": 1, "radiance": [1, 1, 1]}]
    })";
    const int size = 128, spp = 256;
    const lab::film::ImageRgb image = render(runtime, scene, "", size, spp);
    double area = 0.0;
    for (size_t i = 0; i < image.rgb.size(); i += 3) area += image.rgb[i + 1];
    // the silhouette is the cone of half-angle asin(R / D) about the axis: on the film at distance 1
    // a circle of radius tan(asin(R / D)), in pixels scaled by (size / 2) / tan(fov / 2)
    const double tan_alpha = 1.0 / std::sqrt(25.0 - 1.0);
    const double radius = tan_alpha * (size / 2.0) / std::tan(kFovDegrees / 2.0 * kPi / 180.0);
    const double expected = kPi * radius * radius;
    // the outline crosses at most 4 (2 radius + 1) pixels (each row and column of the circle twice)
    const double sigma = std::sqrt(4.0 * (2.0 * radius + 1.0) / (4.0 * spp));
    std::printf("emissive sphere: area %.3f px^2, closed form %.3f (%+.3f %%), noise sigma %.3f px^2\n", area, expected,
                100.0 * (area / expected - 1.0), sigma);
    CHECK(std::fabs(area - expected) <= 5.0 * sigma);
}

TEST_CASE("Exact geometry: a box's edge lies where the camera projects it", "[render][exact][opencl]") {
    lab::opencl::Runtime runtime;
    // a black box against a constant sky of 1: a pixel's value is the fraction of it the box leaves
    // uncovered. The box covers the image right of its left edge, x = -0.3 on its face at z = -4
    // (its left side faces away from the camera, so that edge is the silhouette).
    const char* scene = R"({
      "camera": {"type": "pinhole", "position": [0, 0, 0], "look_at": [0, 0, -1], "fov_degrees": 40},
      "materials": {"black": {"albedo": [0, 0, 0], "lobes": {"diffuse": 1}}},
      "objects": [{"name": "box", "material": "black", "shape": {"type": "translate", "offset": [4.85, 0, -4.5],
        "child": {"type": "box", "half_size": [5.15, 10, 0.5]}}}]
    })";
    const int size = 32, spp = 256;
    const lab::film::ImageRgb image = render(runtime, scene, "constant:1,1,1", size, spp);
    double covered = 0.0;
    for (size_t i = 0; i < image.rgb.size(); i += 3) covered += 1.0 - image.rgb[i + 1];
    const double edge = size - covered / size;  // the raster column where the box starts, averaged over the rows
    const double expected = (-0.3 / 4.0 / std::tan(kFovDegrees / 2.0 * kPi / 180.0) + 1.0) * 0.5 * size;
    // one crossed pixel per row: the mean over the rows of sigma <= 1 / (2 sqrt(spp))
    const double sigma = 1.0 / (2.0 * std::sqrt(double(spp) * size));
    std::printf("box edge: column %.4f, closed form %.4f (%+.4f px), noise sigma %.4f px\n", edge, expected, edge - expected, sigma);
    CHECK(std::fabs(edge - expected) <= 5.0 * sigma);
}
