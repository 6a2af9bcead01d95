// MERL measured-BRDF tables: the file reader against a file written byte by byte here, the writer's
// round trip, the lookup's parameterisation (exact at bin centres, reciprocal, continuous), and one
// clear error per kind of bad file.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "brdf/host/merl_file.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"

namespace fs = std::filesystem;
// A named namespace keeps the using-directive to this file in its unity group (tests/CMakeLists.txt).
namespace merl_file_test {
using namespace brdf;  // the single-source names (float3, HalfDiffAngles, merl_*) live in namespace brdf

namespace {

std::string temp_path(const std::string& name) { return (fs::temp_directory_path() / ("dtoadq_merl_" + name)).string(); }

// Entry e of channel c in file units: a pattern with no symmetry the reader could fake.
double known_file_value(int c, int e) { return double(c + 1) * 1000.0 + double(e % 977) + 0.25 * double(e % 3); }

// A MERL file written field by field, independently of write_merl_file; `edit` may spoil it.
void write_raw(const std::string& path, std::int32_t d0, std::int32_t d1, std::int32_t d2, std::size_t doubles,
               double poison = 0.0, std::size_t poison_at = std::size_t(-1), std::size_t extra_bytes = 0) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    const std::int32_t dims[3] = {d0, d1, d2};
    out.write(reinterpret_cast<const char*>(dims), sizeof dims);
    for (std::size_t i = 0; i < doubles; ++i) {
        const int c = int(i / MERL_ENTRY_COUNT), e = int(i % MERL_ENTRY_COUNT);
        const double v = i == poison_at ? poison : known_file_value(c, e);
        out.write(reinterpret_cast<const char*>(&v), sizeof v);
    }
    for (std::size_t i = 0; i < extra_bytes; ++i) out.put('x');
}

std::string read_error(const std::string& path) {
    try {
        brdf::read_merl_file(path);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "";
}

float3 random_direction_above(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float z = 0.02f + 0.98f * u(rng), phi = 2.0f * SS_PI * u(rng), r = std::sqrt(1.0f - z * z);
    return float3(r * std::cos(phi), r * std::sin(phi), z);
}

}  // namespace

TEST_CASE("the MERL reader returns a hand-written file's entries times MERL's channel scales", "[merl]") {
    const std::string path = temp_path("known.binary");
    write_raw(path, 90, 90, 180, std::size_t(3) * MERL_ENTRY_COUNT);
    const brdf::MeasuredTable t = brdf::read_merl_file(path);
    REQUIRE(t.rgb.size() == std::size_t(3) * MERL_ENTRY_COUNT);
    // MERL's BRDFRead.cpp: red 1/1500, green 1.15/1500, blue 1.66/1500.
    const double scale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};
    for (int e : {0, 1, 179, 180, 16199, 16200, 777777, MERL_ENTRY_COUNT - 1})
        for (int c = 0; c < 3; ++c) {
            INFO("entry " << e << " channel " << c);
            CHECK(t.rgb[std::size_t(3) * e + c] == float(known_file_value(c, e) * scale[c]));
        }
    // Entry order: phi_d fastest, then theta_d, then theta_h (MERL's lookup_brdf_val).
    CHECK(merl_entry_index(0, 0, 1) == 1);
    CHECK(merl_entry_index(0, 1, 0) == 180);
    CHECK(merl_entry_index(1, 0, 0) == 16200);
    fs::remove(path);
}

TEST_CASE("half/difference angles invert, and bin centres follow MERL's sqrt spacing of theta_h", "[merl]") {
    std::mt19937 rng(7);
    for (int i = 0; i < 2000; ++i) {
        const float3 wo = random_direction_above(rng), wi = random_direction_above(rng);
        const HalfDiffAngles a = half_diff_from_directions(wo, wi);
        // Rotating phi_h away (isotropy) keeps every angle between the pair and the normal.
        float3 wo2, wi2;
        directions_from_half_diff(a, &wo2, &wi2);
        CHECK(wo2.z == Approx(wo.z).margin(2e-5));
        CHECK(wi2.z == Approx(wi.z).margin(2e-5));
        CHECK(glm::dot(wo2, wi2) == Approx(glm::dot(wo, wi)).margin(2e-5));
        // Swapping the pair moves phi_d by pi: the table coordinate is the same (reciprocity).
        const HalfDiffAngles b = half_diff_from_directions(wi, wo);
        CHECK(b.theta_h == Approx(a.theta_h).margin(1e-5));
        CHECK(b.theta_d == Approx(a.theta_d).margin(1e-5));
        const float du = std::fabs(merl_phi_d_coordinate(a.phi_d) - merl_phi_d_coordinate(b.phi_d));
        CHECK(std::fmin(du, float(MERL_PHI_D_BINS) - du) < 2e-3f);
    }
    // MERL's theta_half_index: floor(sqrt(theta_h in degrees * 90)); the centre of bin i lies inside bin i.
    for (int ih : {0, 1, 10, 45, 89}) {
        const HalfDiffAngles c = merl_bin_center(ih, 3, 5);
        const double degrees = double(c.theta_h) * 180.0 / M_PI;
        CHECK(int(std::floor(std::sqrt(degrees * 90.0))) == ih);
        CHECK(merl_theta_h_coordinate(c.theta_h) == Approx(ih + 0.5).margin(1e-3));
    }
}

TEST_CASE("a tabulated lab material survives writing and reading, and the lookup is exact at bin centres", "[merl]") {
    const Material m = load_preset("presets/glossy_plastic.json").material;
    const brdf::MeasuredTable t = brdf::tabulate_merl(
        [&](float3 wo, float3 wi) { return bsdf_eval(&m, wo, wi); }, "glossy_plastic");
    const std::string path = temp_path("roundtrip.binary");
    brdf::write_merl_file(path, t);
    const brdf::MeasuredTable back = brdf::read_merl_file(path);
    REQUIRE(back.rgb.size() == t.rgb.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < t.rgb.size(); ++i)
        worst = std::fmax(worst, std::fabs(double(back.rgb[i]) - t.rgb[i]) / std::fmax(1e-30, std::fabs(double(t.rgb[i]))));
    CHECK(worst <= 2.0 * std::numeric_limits<float>::epsilon());  // float -> double / scale -> * scale -> float
    fs::remove(path);

    // At a bin centre the interpolated lookup is the entry itself.
    for (int ih : {0, 7, 40, 80})
        for (int id : {0, 20, 60})
            for (int ip : {0, 90, 179}) {
                float3 wo, wi;
                directions_from_half_diff(merl_bin_center(ih, id, ip), &wo, &wi);
                if (wo.z <= 0.0f || wi.z <= 0.0f) continue;
                const float3 v = merl_eval(back.rgb.data(), wo, wi);
                const float3 e = merl_entry(back.rgb.data(), merl_entry_index(ih, id, ip));
                INFO(ih << " " << id << " " << ip);
                CHECK(v.x == Approx(e.x).epsilon(1e-4));
                CHECK(v.z == Approx(e.z).epsilon(1e-4));
            }
}

TEST_CASE("the measured lookup is reciprocal, never negative, and continuous across the phi_d seam", "[merl]") {
    const Material m = load_preset("presets/rubber.json").material;
    const brdf::MeasuredTable t = brdf::tabulate_merl(
        [&](float3 wo, float3 wi) { return bsdf_eval(&m, wo, wi); }, "rubber");
    std::mt19937 rng(11);
    for (int i = 0; i < 5000; ++i) {
        const float3 wo = random_direction_above(rng), wi = random_direction_above(rng);
        const float3 a = merl_eval(t.rgb.data(), wo, wi), b = merl_eval(t.rgb.data(), wi, wo);
        CHECK(a.x >= 0.0f);
        CHECK(a.x == Approx(b.x).epsilon(2e-4));
        CHECK(a.y == Approx(b.y).epsilon(2e-4));
    }
    // phi_d = 0 and phi_d = pi are the same point of the table.
    HalfDiffAngles p = merl_bin_center(30, 30, 0);
    p.phi_d = 1e-6f;
    const float3 lo = merl_lookup(t.rgb.data(), p);
    p.phi_d = SS_PI - 1e-6f;
    const float3 hi = merl_lookup(t.rgb.data(), p);
    CHECK(lo.x == Approx(hi.x).epsilon(1e-4));
    // Below the horizon there is nothing.
    CHECK(merl_eval(t.rgb.data(), float3(0, 0, 1), float3(0.6f, 0, -0.8f)).x == 0.0f);
}

TEST_CASE("bad MERL files give one line naming the file and what is wrong", "[merl]") {
    const std::size_t full = std::size_t(3) * MERL_ENTRY_COUNT;
    const std::string path = temp_path("bad.binary");

    CHECK_THAT(read_error(temp_path("missing.binary")), Catch::Contains("missing.binary: cannot open"));

    write_raw(path, 90, 90, 180, full - 1);
    CHECK_THAT(read_error(path), Catch::Contains("bad.binary: data: truncated"));

    write_raw(path, 90, 90, 0, 0);  // header only, with a wrong dimension
    CHECK_THAT(read_error(path), Catch::Contains("dimensions: 90 x 90 x 0, but a MERL table is 90 x 90 x 180"));

    write_raw(path, 90, 90, 360, full);  // the anisotropic-looking variant is not MERL's isotropic table
    CHECK_THAT(read_error(path), Catch::Contains("dimensions: 90 x 90 x 360"));

    write_raw(path, 90, 90, 180, full, std::nan(""), MERL_ENTRY_COUNT + 181);
    CHECK_THAT(read_error(path), Catch::Contains("green entry 181 (theta_h bin 0, theta_d bin 1, phi_d bin 1): not a finite number"));

    write_raw(path, 90, 90, 180, full, -1.0, 5);  // negative in red only: not MERL's unmeasured marker
    CHECK_THAT(read_error(path), Catch::Contains("red entry 5 (theta_h bin 0, theta_d bin 0, phi_d bin 5): negative (-1.000000) while other channels are measured"));

    write_raw(path, 90, 90, 180, full, 0.0, std::size_t(-1), 8);
    CHECK_THAT(read_error(path), Catch::Contains("8 bytes after the last entry"));

    std::ofstream(path, std::ios::binary | std::ios::trunc) << "MERL";
    CHECK_THAT(read_error(path), Catch::Contains("dimensions: truncated"));
    fs::remove(path);
}

TEST_CASE("entries MERL marks unmeasured (-1 in every channel) are masked and filled from smaller theta_d", "[merl]") {
    const Material m = load_preset("presets/rubber.json").material;
    MeasuredTable t = tabulate_merl([&](float3 wo, float3 wi) { return bsdf_eval(&m, wo, wi); }, "rubber");
    const int hole = merl_entry_index(10, 70, 33), below = merl_entry_index(10, 69, 33);
    const int column_start = merl_entry_index(20, 0, 3);  // a hole with nothing below: filled from above
    t.unmeasured.assign(MERL_ENTRY_COUNT, false);
    t.unmeasured[std::size_t(hole)] = t.unmeasured[std::size_t(column_start)] = true;
    const std::string path = temp_path("holes.binary");
    write_merl_file(path, t);  // writes -1 in all three channels there
    const MeasuredTable back = read_merl_file(path);
    REQUIRE(back.unmeasured.size() == std::size_t(MERL_ENTRY_COUNT));
    int holes = 0;
    for (bool u : back.unmeasured) holes += u;
    CHECK(holes == 2);
    CHECK(is_unmeasured(back, hole));
    CHECK(!is_unmeasured(back, below));
    for (int c = 0; c < 3; ++c) {
        CHECK(back.rgb[std::size_t(3) * hole + c] == back.rgb[std::size_t(3) * below + c]);
        CHECK(back.rgb[std::size_t(3) * column_start + c] == back.rgb[std::size_t(3) * merl_entry_index(20, 1, 3) + c]);
    }
    fs::remove(path);
}

}  // namespace merl_file_test
