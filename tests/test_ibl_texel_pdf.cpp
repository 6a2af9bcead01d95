// environment_pdf() reads a texel's probability from its w (ibl/environment.h), filled on the host
// from the cdfs. It must give, bit for bit, the density that distribution2d_probability() of the
// cdfs gives, the probability the sampler realises: at every texel, on texel edges and cube edges,
// on all six faces, for rotated environments, for the sampler's own *pdf, and after a new transform.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "ibl/environment.hpp"
#include "ibl/ibl.hpp"
#include "tests/float_bits.hpp"
#include "validation/uniform_random.hpp"

using brdf::float3;
using lab::ibl::Environment;
using lab::ibl::EnvironmentOptions;

namespace {

// The density of `direction` from the cdfs: what environment_pdf computed before the texels held
// their probabilities, from the same single-source pieces.
float pdf_from_cdfs(const Environment& env, float3 direction) {
    const int n = env.face_size();
    float a, b;
    const int face = ibl::cubemap_face(ibl::environment_to_local(&env.map(), direction), &a, &b);
    const int i = ibl::cubemap_texel_coordinate(n, a), j = ibl::cubemap_texel_coordinate(n, b);
    const float p = ibl::distribution2d_probability(env.marginal_cdf().data(), env.conditional_cdf().data(), n, face * n + j, i);
    return ibl::environment_texel_density(n, p, a, b);
}

// Face coordinates on and beside every texel edge (k / N steps and the floats next to them) and
// the texel centres: a grid of directions on each face, in the environment's frame, turned to the world.
std::vector<float3> edge_directions(const Environment& env) {
    const int n = env.face_size();
    std::vector<float> coordinates;
    for (int k = 0; k <= n; ++k) {
        const float edge = -1.0f + 2.0f * float(k) / float(n);
        coordinates.push_back(edge);
        coordinates.push_back(std::nextafter(edge, -2.0f));
        coordinates.push_back(std::nextafter(edge, 2.0f));
        if (k < n) coordinates.push_back(-1.0f + (2.0f * float(k) + 1.0f) / float(n));
    }
    std::vector<float3> directions;
    for (int face = 0; face < CUBEMAP_FACES; ++face)
        for (float a : coordinates)
            for (float b : coordinates)
                directions.push_back(ibl::environment_to_world(&env.map(), glm::normalize(ibl::cubemap_face_point(face, a, b))));
    return directions;
}

// Every texel's w against distribution2d_probability(), then the pdf of edge, random and sampled
// directions against pdf_from_cdfs(); counts the mismatches and reports the first.
long mismatches(const Environment& env, std::string* first) {
    const int n = env.face_size();
    long bad = 0;
    auto fail = [&](const std::string& what) {
        if (bad++ == 0) *first = what;
    };
    for (int r = 0; r < CUBEMAP_FACES * n; ++r)
        for (int i = 0; i < n; ++i) {
            const float stored = env.texels()[size_t(r) * n + i].w;
            const float p = ibl::distribution2d_probability(env.marginal_cdf().data(), env.conditional_cdf().data(), n, r, i);
            if (float_bits(stored) != float_bits(p))
                fail("texel row " + std::to_string(r) + " column " + std::to_string(i) + ": w " + std::to_string(stored) +
                     " but probability " + std::to_string(p));
        }
    auto check = [&](float3 d, const char* kind) {
        const float got = env.pdf(d), expected = pdf_from_cdfs(env, d);
        if (float_bits(got) != float_bits(expected))
            fail(std::string(kind) + " direction (" + std::to_string(d.x) + ", " + std::to_string(d.y) + ", " +
                 std::to_string(d.z) + "): pdf " + std::to_string(got) + " but " + std::to_string(expected) + " from the cdfs");
    };
    for (const float3& d : edge_directions(env)) check(d, "edge");
    lab::validation::UniformRandom rng(77);
    for (int k = 0; k < 20000; ++k) check(float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)), "random");
    for (int k = 0; k < 20000; ++k) {
        float pdf = 0.0f;
        const float3 d = env.sample(rng.next_float(), rng.next_float(), &pdf);
        if (float_bits(pdf) != float_bits(pdf_from_cdfs(env, d)))
            fail("sampled direction: *pdf " + std::to_string(pdf) + " but " + std::to_string(pdf_from_cdfs(env, d)) + " from the cdfs");
    }
    return bad;
}

}  // namespace

TEST_CASE("ibl: environment_pdf from the texel's w equals the density of the cdfs, bit for bit", "[ibl][ibl-texel-pdf]") {
    struct Case {
        const char* spec;
        float rotation;
        int face_size;
    };
    // Rotations: none, a quarter turn (exact), and an oblique one; face sizes even and odd.
    const Case cases[] = {{"envmaps/courtyard.exr", 0.0f, 32},  {"envmaps/courtyard.exr", 33.0f, 17},
                          {"envmaps/sunset.exr", 90.0f, 24},    {"envmaps/studio.exr", -71.5f, 16},
                          {"constant:0.2,0.5,1", 12.0f, 8},     {"constant:0,0,0", 0.0f, 8}};
    for (const Case& c : cases) {
        EnvironmentOptions options;
        options.rotation_degrees = c.rotation;
        options.face_size = c.face_size;
        Environment env = lab::ibl::load_environment(c.spec, options);
        std::string first;
        long bad = mismatches(env, &first);
        INFO(c.spec << " rotated " << c.rotation << " at face " << c.face_size << ": " << bad << " mismatches, first " << first);
        CHECK(bad == 0);
        // A new rotation and exposure keep the texels, their distribution and so w.
        env.set_transform(c.rotation + 50.0f, 1.5f);
        bad = mismatches(env, &first);
        INFO("after set_transform: " << bad << " mismatches, first " << first);
        CHECK(bad == 0);
    }
}
