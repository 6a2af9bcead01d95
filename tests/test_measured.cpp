// Measured materials (brdf/measured.h): a preset naming a MERL file, made at test time by tabulating a
// lab material (brdf::tabulate_merl) and writing it (brdf::write_merl_file); one table serves the
// whole file. Checks: the preset's errors, the feature switch, reciprocity, the chi-square test of the
// tabulated sampler, the OpenCL build against the C++ build, and a render of a sphere against the
// render of the lab material it was tabulated from.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/features.hpp"
#include "brdf/host/measured_registry.hpp"
#include "brdf/host/merl_file.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "kernels/host/brdf_batch.hpp"
#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/lobe_material.hpp"
#include "tests/render_inputs.hpp"
#include "validation/chi_square.hpp"
#include "validation/reciprocity.hpp"
#include "validation/sampling_efficiency.hpp"
#include "validation/region_t_test.hpp"

namespace fs = std::filesystem;
using brdf::float3;

namespace {

// Diffuse under a rough GGX coat, coloured: smooth enough for the tables' resolution to matter, and
// nothing a MERL table cannot hold (isotropic, no delta, no transmission).
brdf::Material lab_material() {
    brdf::Material m = lobe_material(0.6f, 0.4f, 0.0f, 0.0f);
    m.albedo[0] = 0.7f, m.albedo[1] = 0.45f, m.albedo[2] = 0.25f;
    m.roughness = 0.45f;
    return m;
}

struct Fixture {
    fs::path dir;
    std::string preset;  // a preset naming table.binary
    brdf::Material lab, measured;
};

fs::path write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

const Fixture& fixture() {
    static const Fixture f = [] {
        Fixture x;
        x.dir = fs::temp_directory_path() / ("dtoadq_measured_" + std::to_string(::getpid()));
        fs::create_directories(x.dir);
        // removed at exit: the table is 33 MB
        static struct Cleanup {
            fs::path dir;
            ~Cleanup() {
                std::error_code ec;
                fs::remove_all(dir, ec);
            }
        } cleanup{x.dir};
        x.lab = lab_material();
        const brdf::Material lab = x.lab;
        brdf::write_merl_file((x.dir / "table.binary").string(),
                              brdf::tabulate_merl([&](float3 wo, float3 wi) { return brdf::bsdf_eval(&lab, wo, wi); }, "lab"));
        x.preset = write_text(x.dir / "measured.json", R"({"name": "tabulated", "measured": "table.binary"})").string();
        x.measured = brdf::load_preset(x.preset).material;
        return x;
    }();
    return f;
}

std::string load_error(const std::string& path) {
    try {
        brdf::load_preset(path);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a measured preset reads its table once and evaluates it", "[measured]") {
    const Fixture& f = fixture();
    CHECK(f.measured.model == BRDF_MODEL_MEASURED);
    // a second preset naming the same file shares its block
    fs::path again = write_text(f.dir / "again.json", R"({"measured": "table.binary"})");
    CHECK(brdf::load_preset(again.string()).material.measured_offset == f.measured.measured_offset);
    const float* block = brdf::bsdf_table_data().data() + f.measured.measured_offset;
    // at a bin centre the table holds the lab material's value
    brdf::HalfDiffAngles a = brdf::merl_bin_center(40, 30, 50);
    float3 wo, wi;
    brdf::directions_from_half_diff(a, &wo, &wi);
    float3 lab = brdf::bsdf_eval(&f.lab, wo, wi), measured = brdf::bsdf_eval(&f.measured, wo, wi);
    CHECK(measured.x == Approx(lab.x).epsilon(1e-3));
    CHECK(measured.z == Approx(lab.z).epsilon(1e-3));
    CHECK(measured == brdf::merl_eval(block, wo, wi));
    // at the pole the azimuth is 0 whatever the signs of the zeros (atan2(0, -0) is pi): the sampler
    // may return (0, -0, 1) after its rotation, and its pdf must be the one bsdf_pdf gives there
    const float3 oblique = brdf::direction_from_degrees(47.0f, 200.0f);
    CHECK(brdf::bsdf_pdf(&f.measured, oblique, float3(0.0f, -0.0f, 1.0f)) == brdf::bsdf_pdf(&f.measured, oblique, float3(0.0f, 0.0f, 1.0f)));
    CHECK(brdf::bsdf_pdf(&f.measured, oblique, float3(-0.0f, -0.0f, 1.0f)) == brdf::bsdf_pdf(&f.measured, oblique, float3(0.0f, 0.0f, 1.0f)));
    // below the horizon: nothing
    CHECK(brdf::bsdf_eval(&f.measured, wo, float3(wi.x, wi.y, -wi.z)) == float3(0.0f));
    CHECK(brdf::bsdf_pdf(&f.measured, wo, float3(wi.x, wi.y, -wi.z)) == 0.0f);
}

TEST_CASE("a measured preset's problems name the preset and the field", "[measured]") {
    // its own small files: no table needed
    const fs::path dir = fs::temp_directory_path() / ("dtoadq_measured_errors_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string missing = write_text(dir / "missing.json", R"({"measured": "nowhere.binary"})").string();
    std::string e = load_error(missing);
    CHECK(e.rfind(missing + ": measured: MERL file \"nowhere.binary\" not found", 0) == 0);

    // a truncated table (the header alone): the MERL reader's line after the preset's field
    const int header[3] = {90, 90, 180};
    std::ofstream(dir / "header.binary", std::ios::binary).write(reinterpret_cast<const char*>(header), sizeof header);
    const std::string truncated = write_text(dir / "truncated.json", R"({"measured": "header.binary"})").string();
    e = load_error(truncated);
    INFO(e);
    CHECK(e.rfind(truncated + ": measured: ", 0) == 0);
    CHECK(e.find("header.binary: data: truncated") != std::string::npos);
    CHECK(e.find('\n') == std::string::npos);

    const std::string number = write_text(dir / "number.json", R"({"measured": 3})").string();
    CHECK(load_error(number).rfind(number + ": measured: expected a file path", 0) == 0);
    const std::string both = write_text(dir / "both.json", R"({"model": "lab", "measured": "header.binary"})").string();
    CHECK(load_error(both).rfind(both + ": model: ", 0) == 0);
    std::error_code ec;
    fs::remove_all(dir, ec);
}

TEST_CASE("a measured material switches on its feature only", "[measured][features]") {
    brdf::Material measured = brdf::default_material();
    measured.model = BRDF_MODEL_MEASURED;
    for (const auto& [name, on] : brdf::used_features({measured})) CHECK(on == (name == "BRDF_FEATURE_MEASURED"));
    for (const auto& [name, on] : brdf::used_features({lab_material()}))
        if (name == "BRDF_FEATURE_MEASURED") CHECK_FALSE(on);
}

TEST_CASE("a measured material is reciprocal", "[measured][reciprocity]") {
    // float rounding of the half/difference angles only (the [merl] lookup test's tolerance)
    lab::validation::ReciprocityResult r = lab::validation::reciprocity_error(fixture().measured, 20000, 7);
    INFO("worst " << r.max_relative_error);
    CHECK(r.max_relative_error <= 2e-4);
}

// [sweep]: a ctest test of its own (docs/testing.md).
TEST_CASE("the measured sampler's pdf matches its samples (chi-square)", "[measured][chi_square][sweep]") {
    const Fixture& f = fixture();
    // normal incidence (where wo has no azimuth of its own), middle, grazing
    const float thetas[3] = {0.0f, 47.0f, 84.0f}, phis[3] = {0.0f, 200.0f, 115.0f};
    for (int d = 0; d < 3; ++d) {
        lab::validation::ChiSquareOptions options;
        options.tests = 3;
        options.seed = uint64_t(d) + 31;
        lab::validation::ChiSquareResult r = lab::validation::chi_square_bsdf(f.measured, brdf::direction_from_degrees(thetas[d], phis[d]), options);
        INFO("theta " << thetas[d] << ": " << lab::validation::describe(r));
        CHECK(r.passed);
        CHECK(r.pdf_integral == Approx(1.0).margin(1e-3));
    }
}

TEST_CASE("measured eval, pdf and sample: the OpenCL build agrees with the C++ build", "[measured][opencl]") {
    const Fixture& f = fixture();
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    auto direction = [&] {
        float z = uniform(rng), phi = 2.0f * SS_PI * uniform(rng), r = std::sqrt(std::fmax(0.0f, 1.0f - z * z));
        return float3(r * std::cos(phi), r * std::sin(phi), z);
    };
    const int n = 20000;
    std::vector<int> index(n, 0);
    std::vector<float3> wo(n), wi(n), u(n);
    for (int i = 0; i < n; ++i) wo[i] = direction(), wi[i] = direction(), u[i] = float3(uniform(rng), uniform(rng), uniform(rng));
    lab::opencl::Runtime runtime;
    lab::kernels::BrdfBatch batch(runtime);
    batch.set_materials({f.measured});
    std::vector<float3> f_cl = batch.eval(index, wo, wi);
    std::vector<float> pdf_cl = batch.pdf(index, wo, wi);
    std::vector<brdf::BsdfSample> s_cl = batch.sample(index, wo, u);
    // The two builds' sin, cos, atan2 and sqrt differ in the last bit; the lookup's sqrt-spaced theta_h
    // coordinate and the interpolation between bins amplify that, and a direction on a bin's edge may
    // fall on either side. Every value within 1e-4 relative, at most 1 % of the items beyond 1e-5 (the
    // lab's agreement level, tests/test_opencl_agreement.cpp).
    double worst = 0.0;
    int beyond = 0, samples = 0;
    auto relative = [](double a, double b) { return a == b ? 0.0 : std::fabs(a - b) / std::fmax(std::fabs(a), std::fabs(b)); };
    for (int i = 0; i < n; ++i) {
        float3 fh = brdf::bsdf_eval(&f.measured, wo[i], wi[i]);
        float ph = brdf::bsdf_pdf(&f.measured, wo[i], wi[i]);
        brdf::BsdfSample sh = brdf::bsdf_sample(&f.measured, wo[i], u[i]);
        samples += sh.flags != 0;
        double d = 0.0;
        for (int c = 0; c < 3; ++c) d = std::fmax(d, relative(fh[c], f_cl[i][c]));
        d = std::fmax(d, relative(ph, pdf_cl[i]));
        if (sh.flags != s_cl[i].flags) d = INFINITY;
        for (int c = 0; c < 3; ++c) d = std::fmax(d, std::fabs(double(sh.wi[c]) - s_cl[i].wi[c]));
        for (int c = 0; c < 3; ++c) d = std::fmax(d, relative(sh.f[c], s_cl[i].f[c]));
        d = std::fmax(d, relative(sh.pdf, s_cl[i].pdf));
        worst = std::fmax(worst, d);
        beyond += d > 1e-5;
    }
    std::printf("measured OpenCL agreement: %d items, %d samples; worst relative difference %.3g, %d items beyond 1e-5\n", n, samples, worst,
                beyond);
    CHECK(worst <= 1e-4);
    CHECK(beyond <= n / 100);
    CHECK(samples > n / 3);
}

TEST_CASE("a sphere of the tabulated material renders as the lab material does (region t-test)", "[measured][render][welch][opencl]") {
    const Fixture& f = fixture();
    const std::string sphere = R"({
  "camera": {"type": "pinhole", "position": [0, 0, 3.2], "look_at": [0, 0, 0], "fov_degrees": 40},
  "materials": {"sample": {"lobes": {"diffuse": 1}}},
  "objects": [{"name": "ball", "material": "sample", "shape": {"type": "sphere", "radius": 1}}]
})";
    lab::opencl::Runtime runtime("");
    // independent renders: one renderer, each render from other sample indices
    auto renders = [&](const brdf::Material& m, uint64_t seed) {
        lab::render::RenderInput input = render_input(m, "envmaps/studio.exr", 24, lab::render::LightSampling::mis, seed, sphere);
        input.settings.max_depth = 4;
        lab::render::OpenClRenderer renderer(runtime, input);
        std::vector<lab::film::ImageRgb> out;
        for (int k = 0; k < 6; ++k) {
            renderer.set_first_sample(32 * k);
            out.push_back(render_samples(renderer, 32).image);
        }
        return out;
    };
    std::vector<lab::film::ImageRgb> lab = renders(f.lab, 100), measured = renders(f.measured, 200);
    lab::validation::RegionComparison same = lab::validation::compare_by_region(lab, measured, 2, 2, 0.01);
    const lab::validation::RegionTest* w = same.worst();
    std::printf("region t-test, lab vs tabulated sphere: %d of %zu rejected at %.2g; worst p %.3g (means %.4g vs %.4g)\n", same.rejected,
                same.regions.size(), same.level, w->result.p_value, w->result.mean_a, w->result.mean_b);
    CHECK(same.rejected == 0);
    // the test sees a 10 % difference at this budget
    for (lab::film::ImageRgb& image : measured)
        for (float& v : image.rgb) v *= 1.10f;
    CHECK(lab::validation::compare_by_region(lab, measured, 2, 2, 0.01).rejected > 0);
}

TEST_CASE("the tabulated sampler beats cosine sampling as the lab's own sampler does", "[measured][sampling]") {
    // Variance of the directional-albedo estimator against cosine-weighted sampling (> 1: better);
    // the tabulated density follows f cos, so it must gain where the coat's highlight is.
    const Fixture& f = fixture();
    for (float theta : {0.0f, 47.0f, 75.0f}) {
        float3 wo = brdf::direction_from_degrees(theta, 30.0f);
        lab::validation::SamplingEfficiency lab = lab::validation::sampling_efficiency(f.lab, wo, 200000, 3);
        lab::validation::SamplingEfficiency measured = lab::validation::sampling_efficiency(f.measured, wo, 200000, 3);
        std::printf("sampling efficiency at theta %.0f: variance ratio over cosine sampling, lab sampler %.2f, tabulated %.2f\n", theta,
                    lab.ratio, measured.ratio);
        CHECK(measured.ratio > 1.0);
    }
}
