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
#include <optional>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "fuzz/fuzz_check.hpp"
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

// The integral of the pdf over the sphere, written in face coordinates: d(omega) = dA / J with
// J(a, b) = (1 + a^2 + b^2)^(3/2), computed here. Inside a texel the pdf is its probability over
// the texel's area times J, so pdf / J is constant there, and a 2 x 2 point rule per texel (points
// off the centre, so the pdf is probed across the texel) integrates it exactly up to rounding.
double pdf_integral(const lab::ibl::Environment& env) {
    const int n = env.face_size();
    const double cell = 2.0 / n, offsets[2] = {0.21, 0.79};
    double total = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (double oa : offsets)
                    for (double ob : offsets) {
                        const double a = -1.0 + cell * (i + oa), b = -1.0 + cell * (j + ob);
                        const single_source::float3 local = single_source::normalize(::ibl::cubemap_face_point(face, float(a), float(b)));
                        const float pdf = env.pdf(::ibl::environment_to_world(&env.map(), local));
                        FUZZ_REQUIRE(std::isfinite(pdf) && pdf > 0.0f, "the pdf is not finite and positive");
                        const double jacobian = std::pow(1.0 + a * a + b * b, 1.5);
                        total += double(pdf) / jacobian * cell * cell / 4.0;
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
    options.face_size = 1 + in.byte() % 4;  // 1 .. 4: small, so a million inputs run in minutes
    options.rotation_degrees = float(int(in.byte()) * 3 - 360);
    options.exposure_stops = float(int(in.byte() % 129) - 64);
    std::vector<float> pixels(size_t(width) * height * channels);
    for (float& p : pixels) p = in.number();
    const std::vector<std::string> names = channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};

    std::optional<lab::ibl::Environment> loaded;
    try {
        loaded.emplace(lab::ibl::Environment::from_image(lab::ibl::latlong_from_pixels("fuzz.exr", width, height, pixels, names),
                                                         "fuzz.exr", options));
    } catch (const lab::InputError&) {
        return 0;
    }
    const lab::ibl::Environment& env = *loaded;
    for (const single_source::float4& t : env.texels())
        FUZZ_REQUIRE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && t.x >= 0.0f && t.y >= 0.0f && t.z >= 0.0f,
                     "a texel is negative or not finite");
    // float rounding only: the pdf and the cdf are floats (2^-24 each), summed over 6 n^2 texels
    const double integral = pdf_integral(env);
    if (!(std::fabs(integral - 1.0) < 1e-4)) std::fprintf(stderr, "the pdf integrates to %.9g\n", integral);
    FUZZ_REQUIRE(std::fabs(integral - 1.0) < 1e-4, "the pdf does not integrate to 1 over the sphere");
    for (int k = 0; k < 16; ++k) {
        const float u1 = (k + 0.5f) / 16.0f, u2 = std::fmod(0.618034f * (k + 1), 1.0f);
        float pdf = 0.0f;
        const single_source::float3 d = env.sample(u1, u2, &pdf);
        FUZZ_REQUIRE(std::isfinite(pdf) && pdf > 0.0f, "a sample's pdf is not finite and positive");
        FUZZ_REQUIRE(std::fabs(single_source::length(d) - 1.0f) < 1e-4f, "a sampled direction is not a unit vector");
        const single_source::float3 l = env.radiance(d);
        FUZZ_REQUIRE(std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z), "the radiance of a sampled direction is not finite");
    }
    return 0;
}
