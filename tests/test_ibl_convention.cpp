// Conventions of the environments: the cube-map face table (OpenGL's), the lat-long mapping
// (a bright spot painted at the pixel the documented formula names is seen from that direction),
// the rotation about +y and the exposure.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "ibl/environment.hpp"
#include "ibl/ibl.hpp"
#include "validation/uniform_random.hpp"

using single_source::float3;
using lab::ibl::Environment;
using lab::ibl::EnvironmentOptions;
using lab::ibl::LatLongImage;

namespace {

LatLongImage black_image(int width) {
    LatLongImage image;
    image.width = width;
    image.height = width / 2;
    image.rgb.assign(size_t(image.width) * image.height * 3, 0.0f);
    return image;
}

// Lights the pixels whose centres lie within `radius` pixels of image position (x, y) (in pixel
// units, x wrapping around), with radiance `value` in all three channels.
void paint_spot(LatLongImage* image, double x, double y, double radius, float value) {
    for (int py = 0; py < image->height; ++py) {
        for (int px = 0; px < image->width; ++px) {
            double dx = std::fabs(px + 0.5 - x);
            dx = std::fmin(dx, image->width - dx);
            const double dy = py + 0.5 - y;
            if (dx * dx + dy * dy <= radius * radius)
                for (int c = 0; c < 3; ++c) image->rgb[(size_t(py) * image->width + px) * 3 + c] = value;
        }
    }
}

struct Axis {
    const char* name;
    float3 direction;
    double x, y;  // where the convention puts it in a 64 x 32 image, in pixel units
};

// u = atan2(-d.x, d.z) / 2pi + 0.5, v = 0.5 - elevation / pi, written out per axis by hand.
const Axis kAxes[] = {
    {"+x", float3(1, 0, 0), 16.0, 16.0},  // u = 0.25
    {"-x", float3(-1, 0, 0), 48.0, 16.0}, // u = 0.75
    {"+z", float3(0, 0, 1), 32.0, 16.0},  // u = 0.5, the image centre
    {"-z", float3(0, 0, -1), 0.0, 16.0},  // u = 0 = 1, the seam
    {"+y", float3(0, 1, 0), 32.0, 0.0},   // v = 0, the top row
    {"-y", float3(0, -1, 0), 32.0, 32.0}, // v = 1, the bottom row
};

const float kSpot = 1000.0f;

// An image black but for a spot at `axis`; the poles get the whole top or bottom band.
LatLongImage spot_image(const Axis& axis) {
    LatLongImage image = black_image(64);
    if (axis.y == 0.0 || axis.y == 32.0) {
        for (int px = 0; px < 64; ++px) paint_spot(&image, px + 0.5, axis.y, 2.0, kSpot);
    } else {
        paint_spot(&image, axis.x, axis.y, 2.5, kSpot);
    }
    return image;
}

EnvironmentOptions options_with(float rotation, float exposure, int face_size) {
    EnvironmentOptions o;
    o.rotation_degrees = rotation;
    o.exposure_stops = exposure;
    o.face_size = face_size;
    return o;
}

}  // namespace

TEST_CASE("ibl: cube-map faces follow the OpenGL table and round-trip", "[ibl]") {
    struct Case {
        float3 d;
        int face;
        float a, b;
    };
    // sc/|ma|, tc/|ma| of OpenGL 4.6 table 8.19 for a direction with major axis of length 2.
    const Case cases[] = {
        {float3(2, 0.4f, 0.6f), 0, -0.3f, -0.2f}, {float3(-2, 0.4f, 0.6f), 1, 0.3f, -0.2f},
        {float3(0.4f, 2, 0.6f), 2, 0.2f, 0.3f},   {float3(0.4f, -2, 0.6f), 3, 0.2f, -0.3f},
        {float3(0.4f, 0.6f, 2), 4, 0.2f, -0.3f},  {float3(0.4f, 0.6f, -2), 5, -0.2f, -0.3f},
    };
    for (const Case& c : cases) {
        float a = 0, b = 0;
        INFO("face " << c.face);
        CHECK(ibl::cubemap_face(c.d, &a, &b) == c.face);
        CHECK(a == Approx(c.a).margin(1e-7));
        CHECK(b == Approx(c.b).margin(1e-7));
        const float3 back = ibl::cubemap_face_point(c.face, a, b) * 2.0f;
        CHECK(back.x == Approx(c.d.x).margin(1e-6));
        CHECK(back.y == Approx(c.d.y).margin(1e-6));
        CHECK(back.z == Approx(c.d.z).margin(1e-6));
    }
    // Random directions: the face point of (face, a, b) is the direction again.
    lab::validation::UniformRandom rng(7);
    for (int k = 0; k < 10000; ++k) {
        const float3 d = glm::normalize(float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        float a, b;
        const int face = ibl::cubemap_face(d, &a, &b);
        REQUIRE(std::fabs(a) <= 1.0f);
        REQUIRE(std::fabs(b) <= 1.0f);
        const float3 back = glm::normalize(ibl::cubemap_face_point(face, a, b));
        REQUIRE(glm::length(back - d) < 1e-6f);
    }
    // The texel index covers [0, 6 N^2) exactly once per texel centre.
    const int n = 5;
    std::vector<int> hits(6 * n * n, 0);
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const float3 d = ibl::cubemap_face_point(face, -1.0f + (2 * i + 1.0f) / n, -1.0f + (2 * j + 1.0f) / n);
                const int index = ibl::cubemap_texel_index(n, d);
                REQUIRE(index == (face * n + j) * n + i);
                ++hits[index];
            }
    // A zero or NaN direction still reads a valid texel.
    const int zero = ibl::cubemap_texel_index(n, float3(0.0f));
    CHECK((zero >= 0 && zero < 6 * n * n));
    const int nan = ibl::cubemap_texel_index(n, float3(NAN, 0.0f, 0.0f));
    CHECK((nan >= 0 && nan < 6 * n * n));
}

TEST_CASE("ibl: a spot painted where the lat-long convention says is seen in that direction", "[ibl]") {
    for (const Axis& axis : kAxes) {
        INFO("spot at " << axis.name);
        const Environment env = Environment::from_image(spot_image(axis), "spot", options_with(0, 0, 16));
        CHECK(env.radiance(axis.direction).x > 0.5f * kSpot);
        for (const Axis& other : kAxes) {
            if (&other == &axis) continue;
            INFO("looking at " << other.name);
            CHECK(env.radiance(other.direction) == float3(0.0f));
        }
        // The helper functions state the same convention.
        double u, v;
        lab::ibl::latlong_coordinates(axis.direction, &u, &v);
        const double expected_u = axis.x / 64.0, expected_v = axis.y / 32.0;
        if (axis.y != 0.0 && axis.y != 32.0)  // u is arbitrary at the poles
            CHECK(std::fmod(u - expected_u + 1.0, 1.0) == Approx(0.0).margin(1e-7));
        CHECK(v == Approx(expected_v).margin(1e-7));
        const float3 back = lab::ibl::latlong_direction(expected_u, expected_v);
        CHECK(glm::length(back - axis.direction) < 1e-6f);
    }
}

TEST_CASE("ibl: rotation turns the environment about +y as documented, exposure scales it", "[ibl]") {
    const Axis& plus_x = kAxes[0];
    const Axis& plus_z = kAxes[2];
    // 90 degrees: the image's +x is seen from world -z, its +z from world +x.
    const Environment from_x = Environment::from_image(spot_image(plus_x), "spot", options_with(90, 0, 16));
    CHECK(from_x.radiance(float3(0, 0, -1)).x > 0.5f * kSpot);
    CHECK(from_x.radiance(float3(1, 0, 0)) == float3(0.0f));
    const Environment from_z = Environment::from_image(spot_image(plus_z), "spot", options_with(90, 0, 16));
    CHECK(from_z.radiance(float3(1, 0, 0)).x > 0.5f * kSpot);
    CHECK(from_z.radiance(float3(0, 0, 1)) == float3(0.0f));
    // -90 = 270 degrees turns the other way; 450 = 90.
    const Environment back = Environment::from_image(spot_image(plus_x), "spot", options_with(-90, 0, 16));
    CHECK(back.radiance(float3(0, 0, 1)).x > 0.5f * kSpot);
    const Environment wrapped = Environment::from_image(spot_image(plus_x), "spot", options_with(450, 0, 16));
    CHECK(wrapped.map().rotation_cos == 0.0f);
    CHECK(wrapped.map().rotation_sin == 1.0f);

    // Any angle: radiance(R e) of the rotated environment equals radiance(e) of the unrotated one.
    const Environment plain = Environment::from_image(spot_image(plus_x), "spot", options_with(0, 0, 16));
    const Environment turned = Environment::from_image(spot_image(plus_x), "spot", options_with(37, 0, 16));
    const double t = 37.0 * 3.14159265358979323846 / 180.0;
    lab::validation::UniformRandom rng(3);
    int agree = 0;
    for (int k = 0; k < 1000; ++k) {
        const float3 e = glm::normalize(float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        const float3 w(float(std::cos(t) * e.x + std::sin(t) * e.z), e.y, float(-std::sin(t) * e.x + std::cos(t) * e.z));
        agree += turned.radiance(w) == plain.radiance(e);
    }
    CHECK(agree >= 995);  // a few land across a texel edge through rounding

    // Exposure multiplies radiance by 2^stops and leaves the sampling alone.
    const Environment brighter = Environment::from_image(spot_image(plus_x), "spot", options_with(0, 1.5f, 16));
    const float3 base = plain.radiance(plus_x.direction), scaled = brighter.radiance(plus_x.direction);
    CHECK(scaled.x == Approx(base.x * std::pow(2.0, 1.5)).epsilon(1e-6));
    CHECK(brighter.pdf(plus_x.direction) == plain.pdf(plus_x.direction));
    const Environment darker = lab::ibl::load_environment("constant:1,2,4", options_with(0, -2, 0));
    CHECK(darker.radiance(float3(0, 1, 0)) == float3(0.25f, 0.5f, 1.0f));
}
