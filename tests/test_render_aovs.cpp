// The first-hit AOVs (kernels/first_hit.h, Renderer::first_hit_aovs) of a Lambert sphere against
// closed forms. Each pixel's AOV is the mean over its samples of what the sample's camera ray
// finds; the test draws the same camera rays (the kernels' camera and random streams, which the
// AOVs share with the radiance) and intersects them with the sphere analytically, in double.
//  - albedo: a Lambert surface's BSDF-sample weight f cos / pdf = (rho / pi) cos / (cos / pi) is
//    rho for every sample, so a pixel whose samples all hit is rho to float rounding (a few
//    operations of relative error 2^-24 each, summed over the samples: bound 1e-6);
//  - normal and depth: the sphere is hit exactly (sdf/exact), so the only error is float
//    rounding in t = -b - sqrt(b^2 - c), b = o.d, c = |o|^2 - R^2, whose condition grows as
//    1 / sqrt(disc) toward the silhouette: |dt| <~ k eps |o|^2 / sqrt(disc) (k = 16 covers the
//    dozen roundings of the quadratic and of the ray), and the unit normal (p - centre) / R moves
//    by dt / R. Pixels whose rays come within disc < 0.01 of grazing are left out, as are pixels
//    only some of whose samples hit.
//  - slot: the first sample's, 0 where its ray meets the sphere and -1 where it misses.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/camera_setup.hpp"
#include "opencl/runtime.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/render_inputs.hpp"

namespace {

const char* const kTintedSphereScene = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 3.2], "look_at": [0, 0, 0], "fov_degrees": 40},
  "materials": {"sample": {"albedo": [0.25, 0.5, 0.75], "lobes": {"diffuse": 1}, "retroreflection": 0, "subsurface": 0}},
  "objects": [{"name": "ball", "material": "sample", "shape": {"type": "sphere", "radius": 1}}]
})";
constexpr double kAlbedo[3] = {0.25, 0.5, 0.75};
constexpr int size = 24, spp = 2;

lab::render::RenderInput sphere_input() {
    return render_input(std::nullopt, "", size, lab::render::LightSampling::bsdf, 7, kTintedSphereScene);
}

void check_sphere_aovs(lab::render::Renderer& renderer) {
    renderer.set_samples_per_launch(spp);
    renderer.add_samples(spp);
    const lab::render::FirstHitAovs aovs = renderer.first_hit_aovs();
    const kernel::Camera camera = lab::render::make_camera(renderer.compiled_scene().camera, size, size, "test");
    const kernel::RenderKernelSettings settings = renderer.kernel_settings(0, spp);
    const double eps = std::ldexp(1.0, -24);

    int checked = 0, background = 0, slot_wrong = 0;
    double albedo_error = 0.0, normal_excess = 0.0, depth_excess = 0.0;
    for (int pixel = 0; pixel < size * size; ++pixel) {
        double normal[3] = {0, 0, 0}, depth = 0.0, bound = 0.0;
        int hits = 0, misses = 0;
        for (int s = 0; s < spp; ++s) {
            kernel::Rng rng = kernel::rng_make(unsigned(pixel), unsigned(s), settings.seed_lo, settings.seed_hi);
            brdf::float3 o, d;
            kernel::camera_pixel_ray(&camera, pixel, &rng, &o, &d);
            const double b = double(o.x) * d.x + double(o.y) * d.y + double(o.z) * d.z;
            const double c = double(o.x) * o.x + double(o.y) * o.y + double(o.z) * o.z - 1.0;
            const double disc = b * b - c;
            // the slot is the first sample's: the sphere's (0) or none (-1); grazing rays left out
            if (s == 0 && (disc < -0.01 || disc > 0.01)) slot_wrong += aovs.slot[size_t(pixel)] != (disc > 0.0 ? 0 : -1);
            if (disc < 0.0) ++misses;
            if (disc < 0.01) continue;
            const double t = -b - std::sqrt(disc);
            normal[0] += (o.x + t * d.x) / spp;
            normal[1] += (o.y + t * d.y) / spp;
            normal[2] += (o.z + t * d.z) / spp;
            depth += t / spp;
            bound = std::max(bound, 16.0 * eps * (c + 1.0) / std::sqrt(disc));
            ++hits;
        }
        const float* a = aovs.albedo.rgb.data() + 3 * pixel;
        const float* n = aovs.normal.rgb.data() + 3 * pixel;
        if (misses == spp) {  // the background: zeros
            ++background;
            CHECK((a[0] == 0.0f && a[1] == 0.0f && a[2] == 0.0f && n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f && aovs.depth[pixel] == 0.0f));
        }
        if (hits < spp) continue;
        ++checked;
        for (int k = 0; k < 3; ++k) {
            albedo_error = std::max(albedo_error, std::abs(a[k] - kAlbedo[k]));
            normal_excess = std::max(normal_excess, std::abs(n[k] - normal[k]) / bound);
        }
        depth_excess = std::max(depth_excess, std::abs(aovs.depth[pixel] - depth) / bound);
    }
    INFO(checked << " pixels checked, " << background << " background; albedo error " << albedo_error
                 << ", normal and depth errors over their bounds " << normal_excess << ", " << depth_excess);
    CHECK(checked > size * size / 4);
    CHECK(background > size * size / 4);
    CHECK(albedo_error <= 1e-6);
    CHECK(normal_excess <= 1.0);
    CHECK(depth_excess <= 1.0);
    CHECK(slot_wrong == 0);
}

}  // namespace

TEST_CASE("First-hit AOVs of a Lambert sphere: its albedo, its analytic normal and distance, its slot (host)", "[render][aov]") {
    lab::render::HostRenderer renderer(sphere_input(), 2);
    check_sphere_aovs(renderer);
}

TEST_CASE("First-hit AOVs of a Lambert sphere: its albedo, its analytic normal and distance, its slot (OpenCL)", "[render][aov][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::render::OpenClRenderer renderer(runtime, sphere_input());
    check_sphere_aovs(renderer);
}
