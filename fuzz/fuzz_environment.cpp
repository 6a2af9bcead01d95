// Fuzzes the environment loader on arbitrary float images: any width and height (most not 2:1),
// one or three channels, and pixels from raw bits, so NaN, infinities, negatives, denormals, huge
// and tiny values all occur; plus the cube face size, rotation and exposure. Invariants: every
// input is refused with lab::InputError or gives an environment whose texels are finite and
// non-negative, whose pdf is finite everywhere and integrates to 1 over the sphere, and whose
// samples have a finite positive pdf and finite radiance.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "fuzz/fuzz_check.hpp"
#include "ibl/distribution.hpp"
#include "ibl/environment.hpp"

namespace {

// Reads the input front to back; past its end, zeros.
struct Bytes {
    const uint8_t* data;
    size_t size, at = 0;
    uint8_t byte() { return at < size ? data[at++] : 0; }
    float number() {
        uint32_t bits = 0;
        for (int k = 0; k < 4; ++k) bits |= uint32_t(byte()) << (8 * k);
        float v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
};

// The integral of the pdf over the sphere by the midpoint rule on a grid of `m` x `m` cells per
// face (m a multiple of the face size, so no cell straddles two texels), each weighted by its exact
// solid angle. Inside a texel the pdf varies only through the cube's Jacobian
// (1 + a^2 + b^2)^(3/2); with cells 2/m <= 1/32 wide the rule's relative error is below 2e-4
// (h^2/24 times the Jacobian's relative second derivative, at most 9, per axis).
double pdf_integral(const lab::ibl::Environment& env, int m) {
    double total = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const double a0 = -1.0 + 2.0 * i / m, a1 = -1.0 + 2.0 * (i + 1) / m;
                const double b0 = -1.0 + 2.0 * j / m, b1 = -1.0 + 2.0 * (j + 1) / m;
                const brdf::float3 local =
                    brdf::normalize(::ibl::cubemap_face_point(face, float(0.5 * (a0 + a1)), float(0.5 * (b0 + b1))));
                const float pdf = env.pdf(::ibl::environment_to_world(&env.map(), local));
                FUZZ_REQUIRE(std::isfinite(pdf) && pdf > 0.0f, "the pdf is not finite and positive");
                total += double(pdf) * lab::ibl::face_rectangle_solid_angle(a0, a1, b0, b1);
            }
    return total;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Bytes in{data, size};
    const int height = in.byte() % 12;      // 0 .. 11: zero and odd sizes too
    const int width = in.byte() % 24;       // mostly not 2:1
    const int channels = in.byte() % 2 ? 3 : 1;
    lab::ibl::EnvironmentOptions options;
    options.face_size = in.byte() % 9;      // 0: automatic (16), else 1 .. 8
    options.rotation_degrees = float(int(in.byte()) * 3 - 360);
    options.exposure_stops = float(int(in.byte() % 129) - 64);
    std::vector<float> pixels(size_t(width) * height * channels);
    for (float& p : pixels) p = in.number();
    const std::vector<std::string> names = channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};

    lab::ibl::Environment env = lab::ibl::Environment::constant(brdf::float3(1.0f), "unused", {});
    try {
        lab::ibl::LatLongImage image = lab::ibl::latlong_from_pixels("fuzz.exr", width, height, pixels, names);
        env = lab::ibl::Environment::from_image(image, "fuzz.exr", options);
    } catch (const lab::InputError&) {
        return 0;
    }
    for (const brdf::float4& t : env.texels())
        FUZZ_REQUIRE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && t.x >= 0.0f && t.y >= 0.0f && t.z >= 0.0f,
                     "a texel is negative or not finite");
    const int n = env.face_size();
    const double integral = pdf_integral(env, n * ((64 + n - 1) / n));
    if (!(std::fabs(integral - 1.0) < 1e-3)) std::fprintf(stderr, "the pdf integrates to %.9g\n", integral);
    FUZZ_REQUIRE(std::fabs(integral - 1.0) < 1e-3, "the pdf does not integrate to 1 over the sphere");
    for (int k = 0; k < 16; ++k) {
        const float u1 = (k + 0.5f) / 16.0f, u2 = std::fmod(0.618034f * (k + 1), 1.0f);
        float pdf = 0.0f;
        const brdf::float3 d = env.sample(u1, u2, &pdf);
        FUZZ_REQUIRE(std::isfinite(pdf) && pdf > 0.0f, "a sample's pdf is not finite and positive");
        FUZZ_REQUIRE(std::fabs(brdf::length(d) - 1.0f) < 1e-4f, "a sampled direction is not a unit vector");
        const brdf::float3 l = env.radiance(d);
        FUZZ_REQUIRE(std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z), "the radiance of a sampled direction is not finite");
    }
    return 0;
}
