// Resampling lat-long images onto the cube keeps the integral of radiance over the sphere (each
// texel is the mean over its solid angle), and a constant stays exactly constant.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "ibl/distribution.hpp"
#include "ibl/environment.hpp"
#include "validation/uniform_random.hpp"

using single_source::float3;
using lab::ibl::Environment;
using lab::ibl::EnvironmentOptions;
using lab::ibl::LatLongImage;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Integral of the image's radiance (per channel) over the sphere, each pixel constant over its
// solid angle: (2 pi / W) (sin(elevation_top) - sin(elevation_bottom)).
std::vector<double> latlong_integral(const LatLongImage& image) {
    std::vector<double> sum(3, 0.0);
    for (int y = 0; y < image.height; ++y) {
        const double top = (0.5 - double(y) / image.height) * kPi, bottom = (0.5 - double(y + 1) / image.height) * kPi;
        const double solid_angle = 2.0 * kPi / image.width * (std::sin(top) - std::sin(bottom));
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) sum[c] += solid_angle * image.rgb[(size_t(y) * image.width + x) * 3 + c];
    }
    return sum;
}

// The same over the cube: texel radiance times its exact solid angle.
std::vector<double> cubemap_integral(const Environment& env) {
    const int n = env.face_size();
    std::vector<double> sum(3, 0.0);
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const single_source::float4 t = env.texels()[(size_t(face) * n + j) * n + i];
                const double omega = lab::ibl::texel_solid_angle(n, i, j);
                sum[0] += omega * t.x;
                sum[1] += omega * t.y;
                sum[2] += omega * t.z;
            }
    return sum;
}

double worst_relative_error(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) worst = std::fmax(worst, std::fabs(a[c] - b[c]) / b[c]);
    return worst;
}

// Smooth variation, a narrow bright spot and a sharp-edged band: 512 x 256.
LatLongImage synthetic_image() {
    LatLongImage image;
    image.width = 512;
    image.height = 256;
    image.rgb.resize(size_t(image.width) * image.height * 3);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double u = (x + 0.5) / image.width, v = (y + 0.5) / image.height;
            const double smooth = 1.0 + 0.5 * std::sin(6.0 * kPi * u) * std::sin(kPi * v);
            const double du = std::fmin(std::fabs(u - 0.3), 1.0 - std::fabs(u - 0.3)), dv = v - 0.35;
            const double spot = 5000.0 * std::exp(-(du * du + dv * dv) / (2.0 * 0.004 * 0.004));
            const double band = (v > 0.6 && v < 0.62) ? 20.0 : 0.0;
            float* p = &image.rgb[(size_t(y) * image.width + x) * 3];
            p[0] = float(smooth + spot);
            p[1] = float(smooth + band);
            p[2] = float(0.1 * smooth);
        }
    return image;
}

EnvironmentOptions face_size(int n) {
    EnvironmentOptions o;
    o.face_size = n;
    return o;
}

}  // namespace

// What docs/environments.md promises of the conversion: the sphere integral of radiance within
// 3e-4 on the six envmaps, 1.1e-4 on the synthetic spot image.
constexpr double kEnvmapTolerance = 3e-4;
constexpr double kSyntheticTolerance = 1.5e-4;

TEST_CASE("ibl: texel solid angles sum to 4 pi", "[ibl]") {
    for (int n : {1, 3, 16, 512}) {
        double sum = 0.0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) sum += lab::ibl::texel_solid_angle(n, i, j);
        CHECK(6.0 * sum == Approx(4.0 * kPi).epsilon(1e-12));
    }
    // One face is a sixth of the sphere; its centre texel of a 1-texel face likewise.
    CHECK(lab::ibl::face_rectangle_solid_angle(-1, 1, -1, 1) == Approx(4.0 * kPi / 6.0).epsilon(1e-14));
}

TEST_CASE("ibl: conversion keeps the sphere integral of a synthetic image", "[ibl]") {
    const LatLongImage image = synthetic_image();
    const std::vector<double> reference = latlong_integral(image);
    for (int n : {16, 64, 128}) {
        const Environment env = Environment::from_image(image, "synthetic", face_size(n));
        const double error = worst_relative_error(cubemap_integral(env), reference);
        INFO("face size " << n << ": relative error of the sphere integral " << error);
        CHECK(error < kSyntheticTolerance);
        std::printf("[ibl] synthetic 512x256, face %d: sphere integral relative error %.2e\n", n, error);
    }
}

TEST_CASE("ibl: conversion keeps the sphere integral of the envmaps", "[ibl]") {
    for (const char* name : {"courtyard", "city", "forest", "interior", "studio", "sunset"}) {
        const std::string path = std::string("envmaps/") + name + ".exr";
        const auto start = std::chrono::steady_clock::now();
        const LatLongImage image = lab::ibl::read_latlong_image(path);
        const Environment env = Environment::from_image(image, path, EnvironmentOptions{});
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        CHECK(env.face_size() == 256);
        const double error = worst_relative_error(cubemap_integral(env), latlong_integral(image));
        INFO(path << ": relative error of the sphere integral " << error);
        CHECK(error < kEnvmapTolerance);
        std::printf("[ibl] %s: 1024x512 -> 6x256^2 in %.3f s (read + convert + cdfs), sphere integral error %.2e\n",
                    path.c_str(), seconds, error);
    }
    // A small face averages many pixels per texel.
    const LatLongImage courtyard = lab::ibl::read_latlong_image("envmaps/courtyard.exr");
    const Environment small = Environment::from_image(courtyard, "courtyard", face_size(16));
    CHECK(worst_relative_error(cubemap_integral(small), latlong_integral(courtyard)) < kEnvmapTolerance);
}

TEST_CASE("ibl: a constant environment is exactly constant", "[ibl]") {
    const Environment spec = lab::ibl::load_environment("constant:0.25,0.5,3", EnvironmentOptions{});
    CHECK(spec.face_size() == 16);
    CHECK(spec.source() == "constant:0.25,0.5,3");
    lab::validation::UniformRandom rng(11);
    for (int k = 0; k < 10000; ++k) {
        const float3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        REQUIRE(spec.radiance(d) == float3(0.25f, 0.5f, 3.0f));
    }
    // A constant image through the resampling: every texel's radiance is that constant to the last
    // bit (its w holds the texel's probability, ibl/environment.h).
    LatLongImage image;
    image.width = 96;
    image.height = 48;
    image.rgb.resize(size_t(96) * 48 * 3);
    for (size_t p = 0; p < image.rgb.size(); p += 3) {
        image.rgb[p] = 0.7f;
        image.rgb[p + 1] = 0.3f;
        image.rgb[p + 2] = 1e-3f;
    }
    const Environment converted = Environment::from_image(image, "constant image", face_size(24));
    for (const single_source::float4& t : converted.texels()) REQUIRE(single_source::float3(t.x, t.y, t.z) == single_source::float3(0.7f, 0.3f, 1e-3f));
}

TEST_CASE("ibl: the conversion shares work between points and threads without changing a bit", "[ibl]") {
    // equirect_to_cubemap computes once what its points share (docs/environments.md). Each texel is
    // checked against the same average computed whole at every point, through the public lookups,
    // on every face (the four around y share rows, the two on it do not), and the result against
    // other thread counts. Face size 37: rows split unevenly between threads.
    const LatLongImage image = synthetic_image();
    const int n = 37, s = lab::ibl::cubemap_supersampling(image.width, n);
    const std::vector<single_source::float4> texels = lab::ibl::equirect_to_cubemap(image, n, 1);
    int differ = 0, checked = 0;
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < n; j += 3)
            for (int i = 0; i < n; i += 2) {
                double sum[3] = {0.0, 0.0, 0.0}, weight_sum = 0.0;
                for (int sj = 0; sj < s; ++sj)
                    for (int si = 0; si < s; ++si) {
                        const float a = float(-1.0 + 2.0 * (i + (si + 0.5) / s) / n), b = float(-1.0 + 2.0 * (j + (sj + 0.5) / s) / n);
                        const double weight = 1.0 / double(::ibl::cubemap_area_per_solid_angle(a, b));
                        double u, v;
                        lab::ibl::latlong_coordinates(::ibl::cubemap_face_point(face, a, b), &u, &v);
                        const float3 l = lab::ibl::latlong_bilinear(image, u, v);
                        sum[0] += weight * l.x;
                        sum[1] += weight * l.y;
                        sum[2] += weight * l.z;
                        weight_sum += weight;
                    }
                const single_source::float4 t = texels[(size_t(face) * n + j) * n + i];
                const bool same = t.x == float(sum[0] / weight_sum) && t.y == float(sum[1] / weight_sum) && t.z == float(sum[2] / weight_sum);
                INFO("face " << face << " texel (" << i << ", " << j << ")");
                CHECK(same);
                differ += same ? 0 : 1;
                ++checked;
            }
    std::printf("[ibl] conversion against the whole computation at every point: %d of %d texels differ\n", differ, checked);
    for (int threads : {2, 3, 8}) {
        const std::vector<single_source::float4> other = lab::ibl::equirect_to_cubemap(image, n, threads);
        INFO(threads << " threads");
        CHECK(std::memcmp(other.data(), texels.data(), texels.size() * sizeof(texels[0])) == 0);
    }
}
