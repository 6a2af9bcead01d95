// environment_pdf() reads a texel's probability from its w (ibl/environment.h), filled on the host
// from the alias tables. It must give, bit for bit, the density of the probability with which the
// tables draw the texel (cubemap_texel_probabilities(), which tests/test_ibl_alias.cpp checks
// against every number of the generator): at every texel, on texel edges and cube edges, on all six
// faces, for rotated environments, for the sampler's own *pdf, and after a new transform.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "ibl/distribution.hpp"
#include "ibl/environment.hpp"
#include "ibl/ibl.hpp"
#include "tests/float_bits.hpp"
#include "validation/uniform_random.hpp"

using single_source::float3;
using lab::ibl::Environment;
using lab::ibl::EnvironmentOptions;

namespace {

// The density of `direction` from the tables' probabilities, found from the same single-source
// pieces as environment_pdf but without the texel's w.
float pdf_from_tables(const Environment& env, const std::vector<float>& probability, float3 direction) {
    const int n = env.face_size();
    float a, b;
    const int face = ibl::cubemap_face(ibl::environment_to_local(&env.map(), direction), &a, &b);
    const int i = ibl::cubemap_texel_coordinate(n, a), j = ibl::cubemap_texel_coordinate(n, b);
    return ibl::environment_texel_density(n, probability[size_t(face * n + j) * n + i], a, b);
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

// Every texel's w against the tables' probability, then the pdf of edge, random and sampled
// directions against pdf_from_tables(); counts the mismatches and reports the first.
long mismatches(const Environment& env, std::string* first) {
    const int n = env.face_size();
    const std::vector<float> probability = lab::ibl::cubemap_texel_probabilities(env.alias(), n);
    auto pdf_of = [&](float3 d) { return pdf_from_tables(env, probability, d); };
    long bad = 0;
    auto fail = [&](const std::string& what) {
        if (bad++ == 0) *first = what;
    };
    for (int r = 0; r < CUBEMAP_FACES * n; ++r)
        for (int i = 0; i < n; ++i) {
            const float stored = env.texels()[size_t(r) * n + i].w;
            const float p = probability[size_t(r) * n + i];
            if (float_bits(stored) != float_bits(p))
                fail("texel row " + std::to_string(r) + " column " + std::to_string(i) + ": w " + std::to_string(stored) +
                     " but probability " + std::to_string(p));
        }
    auto check = [&](float3 d, const char* kind) {
        const float got = env.pdf(d), expected = pdf_of(d);
        if (float_bits(got) != float_bits(expected))
            fail(std::string(kind) + " direction (" + std::to_string(d.x) + ", " + std::to_string(d.y) + ", " +
                 std::to_string(d.z) + "): pdf " + std::to_string(got) + " but " + std::to_string(expected) + " from the tables");
    };
    for (const float3& d : edge_directions(env)) check(d, "edge");
    lab::validation::UniformRandom rng(77);
    for (int k = 0; k < 20000; ++k) check(float3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)), "random");
    for (int k = 0; k < 20000; ++k) {
        float pdf = 0.0f;
        const float3 d = env.sample(rng.next_float(), rng.next_float(), &pdf);
        if (float_bits(pdf) != float_bits(pdf_of(d)))
            fail("sampled direction: *pdf " + std::to_string(pdf) + " but " + std::to_string(pdf_of(d)) + " from the tables");
    }
    return bad;
}

}  // namespace

TEST_CASE("ibl: environment_pdf from the texel's w equals the density of the alias tables, bit for bit", "[ibl][ibl-texel-pdf]") {
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
