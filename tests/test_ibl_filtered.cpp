// The filtered environment lookup (what the camera sees directly): equal to the texel at texel
// centres, continuous across texel edges inside a face, exact on a constant environment.
#include <catch2/catch.hpp>

#include <cmath>

#include "ibl/environment.hpp"

using single_source::float3;

namespace {

// A face-size-8 environment whose texels differ from their neighbours: radiance = texel index.
lab::ibl::Environment ramp_environment() {
    const int n = 8;
    lab::ibl::LatLongImage image;
    image.width = 64;
    image.height = 32;
    image.rgb.assign(size_t(image.width * image.height * 3), 0.0f);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) image.rgb[size_t((y * image.width + x) * 3 + c)] = float(x + 3 * y + c);
    lab::ibl::EnvironmentOptions options;
    options.face_size = n;
    return lab::ibl::Environment::from_image(image, "ramp", options);
}

// The direction through face +z's point (a, b) (ibl/cubemap.h: (a, -b, 1)).
float3 on_positive_z(float a, float b) { return glm::normalize(float3(a, -b, 1.0f)); }

}  // namespace

TEST_CASE("filtered environment: texel centres give the texel, edges are continuous", "[ibl]") {
    lab::ibl::Environment env = ramp_environment();
    const int n = env.face_size();
    for (int i = 1; i < n - 1; ++i) {
        float a = -1.0f + (2.0f * float(i) + 1.0f) / float(n), b = -1.0f + 3.0f / float(n);
        float3 d = on_positive_z(a, b);
        float3 nearest = env.radiance(d), filtered = env.radiance_filtered(d);
        CHECK(filtered.x == Approx(nearest.x).epsilon(1e-5));
        CHECK(filtered.z == Approx(nearest.z).epsilon(1e-5));
        // across the edge between texels i and i + 1 the nearest lookup jumps, the filter does not
        float edge = -1.0f + 2.0f * float(i + 1) / float(n);
        float3 left = env.radiance_filtered(on_positive_z(edge - 1e-4f, b)), right = env.radiance_filtered(on_positive_z(edge + 1e-4f, b));
        float3 jump_nearest = env.radiance(on_positive_z(edge + 1e-4f, b)) - env.radiance(on_positive_z(edge - 1e-4f, b));
        if (std::fabs(jump_nearest.x) > 0.1f) CHECK(std::fabs(right.x - left.x) < 0.01f * std::fabs(jump_nearest.x));
    }
}

TEST_CASE("filtered environment: a constant environment stays exactly constant", "[ibl]") {
    lab::ibl::Environment env = lab::ibl::load_environment("constant:0.25,0.5,2");
    for (float3 d : {float3(1, 0, 0), float3(0.3f, -0.8f, 0.1f), float3(-0.577f, 0.577f, 0.577f), float3(0, 0, -1)}) {
        float3 l = env.radiance_filtered(d);
        CHECK(l.x == 0.25f);
        CHECK(l.y == 0.5f);
        CHECK(l.z == 2.0f);
    }
}
