TEST_CASE("OpenCL: a runtime gives its recent programs again for the same source and options, and builds the rest", "[opencl]") {
    auto source = [](int value) {
        const std::string text = "__kernel void k(__global int* x) { x[0] = " + std::to_string(value) + "; }\n";
        return lab::opencl::assemble_source("kernels/k.cl", [&](const std::string&) -> std::string_view { return text; });
    };
    auto run = [](const lab::opencl::Runtime& runtime, const lab::opencl::Program& program) {
        lab::opencl::BufferHandle out = runtime.buffer(sizeof(cl_int), CL_MEM_READ_WRITE);
        lab::opencl::KernelHandle kernel = program.kernel("k");
        lab::opencl::set_kernel_args(kernel, out);
        runtime.launch_1d(kernel, 1, 1);
        cl_int value = 0;
        runtime.read(out, &value, sizeof(value));
        return value;
    };
    lab::opencl::Runtime runtime;
    const lab::opencl::Program first = runtime.build(source(1), "-cl-std=CL1.2");
    CHECK(runtime.build(source(1), "-cl-std=CL1.2").get() == first.get());
    // another source or other options: a program of its own, which runs its own code
    const lab::opencl::Program other = runtime.build(source(2), "-cl-std=CL1.2");
    CHECK(other.get() != first.get());
    CHECK(runtime.build(source(1), "-cl-std=CL1.2 -DUNUSED").get() != first.get());
    CHECK(run(runtime, runtime.build(source(2), "-cl-std=CL1.2")) == 2);
    CHECK(run(runtime, runtime.build(source(1), "-cl-std=CL1.2")) == 1);
    // the most recent kBuiltPrograms are kept: one used again stays, the least recent is built anew
    for (int i = 0; i < int(lab::opencl::Runtime::kBuiltPrograms) - 1; ++i) runtime.build(source(100 + i), "-cl-std=CL1.2");
    CHECK(runtime.build(source(1), "-cl-std=CL1.2").get() == first.get());
    runtime.build(source(99), "-cl-std=CL1.2");
    CHECK(runtime.build(source(2), "-cl-std=CL1.2").get() != other.get());
    // a program outlives the runtime's keeping it
    CHECK(run(runtime, other) == 2);
}

// The OpenCL build of the BRDF module (kernels/brdf_batch.cl on PoCL) against its C++ build: the
// same materials (every preset, 990 random ones), directions (grazing ones included) and random
// numbers give bsdf_eval, bsdf_pdf and bsdf_sample results equal to 1e-5 relative. Where an item is
// so ill-conditioned that the C++ build itself moves by more than that when its inputs move by
// two ulps, the OpenCL result must stay within 8 times that movement instead (kSensitivityFactor);
// fewer than 2 % of the items may need this. A non-delta sample's f and pdf that stray further are
// held to the C++ evaluation at the OpenCL sample's own direction, by the same rule
// (ratio_at_own_direction): near the horizon they follow the last bits of wi.z. Also the runtime's device selection and its mapping of compiler errors
// back to the original file and line. PoCL is a required dependency: no device fails, not skips.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "kernels/host/brdf_batch.hpp"
#include "opencl/device.hpp"
#include "opencl/kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "validation/random_inputs.hpp"
#include "validation/uniform_random.hpp"

namespace fs = std::filesystem;
namespace validation = lab::validation;
using brdf::float3;

namespace {

constexpr float kRelative = 1e-5f;
// Both values below this count as zero. Only reached by underflowing tails (pow/exp of a large
// negative exponent, a D or G of 1e-38); whether such a value is denormal, flushed or exactly 0
// depends on the math library, and it is 30 orders of magnitude below anything a renderer sums.
constexpr float kBothZero = 1e-30f;

// Relative difference |a - b| / max(|a|, |b|); 0 for equal values (infinities, both NaN) and for
// two essentially-zero values; infinity when exactly one is NaN.
double relative_difference(float a, float b) {
    if (a == b || (std::isnan(a) && std::isnan(b))) return 0.0;
    if (std::isnan(a) || std::isnan(b)) return INFINITY;
    double scale = std::fmax(std::fabs(double(a)), std::fabs(double(b)));
    if (scale <= kBothZero) return 0.0;
    return std::fabs(double(a) - double(b)) / scale;
}

// A direction is compared as one vector, relative to its length: a component near 0 of a unit
// vector (x = sin(theta) cos(phi) near phi = pi/2) carries no relative precision of its own, so a
// one-ulp difference in phi would look like a large per-component error.
double direction_difference(float3 a, float3 b) {
    if (!brdf::finite3(a) || !brdf::finite3(b)) return a == b ? 0.0 : INFINITY;
    double scale = std::fmax(std::fmax(std::fabs(a.x), std::fabs(a.y)), std::fmax(std::fabs(a.z), std::fmax(std::fabs(b.x), std::fmax(std::fabs(b.y), std::fabs(b.z)))));
    if (scale == 0.0) return 0.0;
    double d = std::fmax(std::fabs(double(a.x) - b.x), std::fmax(std::fabs(double(a.y) - b.y), std::fabs(double(a.z) - b.z)));
    return d / scale;
}

std::string describe(const brdf::Material& m) {
    std::ostringstream s;
    s.precision(9);
    s << "model " << m.model << " distribution " << m.distribution << " albedo " << m.albedo[0] << "," << m.albedo[1] << ","
      << m.albedo[2] << " roughness " << m.roughness << " metallic " << m.metallic << " fresnel " << m.fresnel << " subsurface "
      << m.subsurface << " asymmetry " << m.subsurface_asymmetry << " retro " << m.retroreflection << " anisotropic "
      << m.anisotropic << " rotation " << m.tangent_rotation << " hc_shape " << m.hc_shape << " lobes " << m.weight_diffuse << ","
      << m.weight_glossy << "," << m.weight_specular << "," << m.weight_transmission << " ior " << m.ior;
    return s.str();
}

std::string describe(float3 v) {
    char text[96];
    std::snprintf(text, sizeof(text), "(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
    return text;
}

// Uniform on the sphere, or grazing (|cos theta| from 1e-2 down to 1e-6), or along the normal.
float3 random_direction(validation::UniformRandom& rng) {
    float kind = rng.next_float();
    if (kind < 0.6f) return validation::uniform_sphere_direction(rng);
    if (kind < 0.95f) {
        float z = std::pow(10.0f, rng.uniform(-6.0f, -2.0f)) * (rng.next_float() < 0.8f ? 1.0f : -1.0f);
        float phi = rng.uniform(0.0f, 2.0f * float(M_PI)), r = std::sqrt(1.0f - z * z);
        return float3(r * std::cos(phi), r * std::sin(phi), z);
    }
    return float3(0.0f, 0.0f, rng.next_float() < 0.8f ? 1.0f : -1.0f);
}

struct Inputs {
    size_t presets = 0;  // the first materials
    std::vector<brdf::Material> materials;
    std::vector<int> index;
    std::vector<float3> wo, wi, u;
};

// Items found while investigating disagreements, kept because random draws rarely land on them.
void add_known_hard_items(Inputs* in) {
    // A grazing wo (cos 1.9e-5) whose glossy sample comes from the rim of the visible-normal disk
    // (u.y = 1 - 2^-24): wi is almost the mirror of wo, and the sign of the computed wo.h, which
    // the glossy pdf tests and the glossy eval does not, is rounding noise there.
    brdf::Material m = brdf::default_material();
    const float albedo[3] = {0.446940809f, 0.915117919f, 0.53556788f};
    for (int c = 0; c < 3; ++c) m.albedo[c] = albedo[c];
    m.roughness = 0.359879166f;
    m.metallic = 0.325471222f;
    m.fresnel = 0.653886795f;
    m.subsurface = 0.230815277f;
    m.subsurface_asymmetry = -0.784431338f;
    m.retroreflection = 0.667388558f;
    m.anisotropic = 0.283476502f;
    m.tangent_rotation = -6.02843666f;
    m.hc_shape = 1.77259445f;
    m.weight_diffuse = 0.7826612f;
    m.weight_glossy = 0.648122966f;
    m.weight_specular = 0.643078029f;
    m.weight_transmission = 0.918977678f;
    m.ior = 1.0f;
    in->materials.push_back(m);
    in->index.push_back(int(in->materials.size()) - 1);
    in->wo.push_back(float3(-0.989639819f, 0.143572181f, 1.90087503e-05f));
    in->wi.push_back(float3(0.989635766f, -0.143600002f, 0.000163204066f));
    in->u.push_back(float3(0.462388128f, 0.99999994f, 0.102388531f));
}

// Every preset, then random materials with every parameter in its range and 30 % of the draws at
// an end of the range (smooth, metallic, zero weights, shape and ior limits), a fifth of them the
// 2017 model. Per material: random and grazing pairs, mirror pairs (the glossy peak) and near
// mirrors, and u with some components at 0 or 1 - 2^-24. Each material's pairs come from a stream
// of their own, seeded by the preset's file name or the random material's number, so that a preset
// added or removed changes no other material's items.
Inputs make_inputs(int random_materials, int pairs_per_material, uint64_t seed) {
    Inputs in;
    std::vector<fs::path> preset_files;
    for (const auto& entry : fs::directory_iterator("presets"))
        if (entry.path().extension() == ".json") preset_files.push_back(entry.path());
    std::sort(preset_files.begin(), preset_files.end());
    std::vector<uint64_t> streams;
    for (const fs::path& file : preset_files) {
        in.materials.push_back(brdf::load_preset(file.string()).material);
        uint64_t name_hash = 14695981039346656037ull;  // FNV-1a of the file name
        for (unsigned char c : file.filename().string()) name_hash = (name_hash ^ c) * 1099511628211ull;
        streams.push_back(seed ^ name_hash);
    }
    in.presets = in.materials.size();
    REQUIRE(in.presets >= 10);
    validation::UniformRandom rng(seed);
    for (int k = 0; k < random_materials; ++k) {
        int model = rng.next_float() < 0.2f ? BRDF_MODEL_DTOADQ2017 : BRDF_MODEL_LAB;
        in.materials.push_back(validation::random_edge_material(rng, model, 0.3f));
        streams.push_back(seed + 1 + uint64_t(k));
    }
    for (int m = 0; m < int(in.materials.size()); ++m) {
        validation::UniformRandom rng(streams[size_t(m)]);
        for (int k = 0; k < pairs_per_material; ++k) {
            float3 wo = random_direction(rng), wi = random_direction(rng);
            float kind = rng.next_float();
            if (kind < 0.1f) wi = float3(-wo.x, -wo.y, wo.z);
            else if (kind < 0.15f) wi = glm::normalize(float3(-wo.x, -wo.y, wo.z) + 0.01f * validation::uniform_sphere_direction(rng));
            float3 u = rng.next_float3();
            for (int c = 0; c < 3; ++c)
                if (rng.next_float() < 0.03f) u[c] = rng.next_float() < 0.5f ? 0.0f : 0.99999994f;
            in.index.push_back(m);
            in.wo.push_back(wo);
            in.wi.push_back(wi);
            in.u.push_back(u);
        }
    }
    add_known_hard_items(&in);
    return in;
}

// The compared outputs of one item, flattened: eval f (3), pdf, sample wi (3), sample f (3), sample pdf.
constexpr int kValues = 11;
const char* const kValueNames[kValues] = {"eval f.r", "eval f.g", "eval f.b", "pdf",      "sample wi.x", "sample wi.y",
                                          "sample wi.z", "sample f.r", "sample f.g", "sample f.b", "sample pdf"};
constexpr int kFirstSampleValue = 4;

struct Outputs {
    float v[kValues];
    int flags;
};

Outputs outputs_of(float3 f, float pdf, const brdf::BsdfSample& s) {
    return {{f.x, f.y, f.z, pdf, s.wi.x, s.wi.y, s.wi.z, s.f.x, s.f.y, s.f.z, s.pdf}, s.flags};
}

Outputs evaluate_cpp(const brdf::Material& m, float3 wo, float3 wi, float3 u) {
    return outputs_of(brdf::bsdf_eval(&m, wo, wi), brdf::bsdf_pdf(&m, wo, wi), brdf::bsdf_sample(&m, wo, u));
}

// Difference of value k in its own metric: sampled directions as vectors, everything else relative.
double difference(int k, const Outputs& a, const Outputs& b) {
    if (k >= 4 && k <= 6) return direction_difference(float3(a.v[4], a.v[5], a.v[6]), float3(b.v[4], b.v[5], b.v[6]));
    return relative_difference(a.v[k], b.v[k]);
}

// Where the plain 1e-5 check fails, how far the C++ build itself moves when its inputs move by a
// couple of ulps. The two builds' sin, cos, pow, exp, lgamma differ (measured over 2^20 arguments:
// in 10 to 25 % of them, by up to 1.5 ulp; both within 2 ulp of the exact value), so where a result amplifies
// last-bit changes beyond 1e-5 (grazing angles with a rotated tangent, a Henyey-Greenstein peak at
// g = 0.95, a disk sample at its rim for u near 1) no float implementation can agree to 1e-5 and
// the builds are held to that sensitivity instead.
struct Sensitivity {
    double value[kValues] = {};
    bool flags_reachable = false;  // some perturbed C++ sample had the OpenCL sample's flags
};

float ulp(float x) {
    x = std::fabs(x);
    return std::nextafter(x, INFINITY) - x;
}

Sensitivity sensitivity(const brdf::Material& m, float3 wo, float3 wi, float3 u, const Outputs& base, int other_flags, uint64_t seed) {
    validation::UniformRandom rng(seed);
    auto steps = [&](int most) { return float(std::min(int(rng.next_float() * float(2 * most + 1)), 2 * most) - most); };
    auto perturb_direction = [&](float3 w) {
        // x and y carry the rotation's error, at the scale of the larger one; z is never recomputed
        float xy = ulp(std::fmax(std::fabs(w.x), std::fabs(w.y)));
        return float3(w.x + steps(2) * xy, w.y + steps(2) * xy, w.z + steps(2) * ulp(w.z));
    };
    // u on the grid of a 24-bit generator, kept in [0, 1); the ends of the range move further, since
    // there a disk sample sits on its rim, where z = sqrt(1 - x^2 - y^2) keeps about half the bits
    auto perturb_u = [&](float x) {
        float k = x == 0.0f || x == 0.99999994f ? steps(8) : steps(2);
        return std::fmin(std::fmax(x + k * 0x1p-24f, 0.0f), 0.99999994f);
    };
    Sensitivity s;
    for (int draw = 0; draw < 64; ++draw) {
        brdf::Material p = m;
        for (const brdf::ScalarParameter& param : brdf::scalar_parameters()) {
            if (param.field) p.*(param.field) += steps(2) * ulp(p.*(param.field));
            else
                for (float& a : p.albedo) a += steps(2) * ulp(a);
        }
        Outputs o = evaluate_cpp(p, perturb_direction(wo), perturb_direction(wi),
                                 float3(perturb_u(u.x), perturb_u(u.y), perturb_u(u.z)));
        s.flags_reachable = s.flags_reachable || o.flags == other_flags;
        for (int k = 0; k < kValues; ++k) {
            if (k >= kFirstSampleValue && o.flags != base.flags) continue;  // a different event: no spread of values
            s.value[k] = std::max(s.value[k], difference(k, o, base));
        }
    }
    return s;
}

// How many ulp-level sensitivities the OpenCL result may stray. The perturbation moves the inputs
// by 2 ulp; the OpenCL built-ins may themselves be off by more: pow by up to 16 ulp (OpenCL 1.2,
// section 7.4), against glibc's correctly rounded or 1-ulp results. The Hyper-Cauchy visible-normal
// sampler inverts its slope CDFs (incomplete beta functions) by Newton iteration on pow, exp and
// log, so those built-in differences reach the sampled direction: 16 ulp / 2 ulp = 8.
constexpr double kSensitivityFactor = 8.0;
// A sampled direction may differ between the builds by what the direction check accepts; near the
// horizon f and pdf change with the last bits of a small wi.z (f and the pdf carry 1 / |wi.z|), far
// beyond what the inputs' 2-ulp perturbation moves the C++ build's own sample. So a non-delta
// sample's f or pdf (value k) that strays more is held instead to the C++ evaluation at the OpenCL
// sample's own direction, by the eval's rule: what the sampler promises, f and pdf of its wi.
double ratio_at_own_direction(const brdf::Material& m, float3 wo, float3 u, const Outputs& cl, int k, uint64_t seed) {
    const float3 wi(cl.v[4], cl.v[5], cl.v[6]);
    const Outputs at = evaluate_cpp(m, wo, wi, u);
    const int eval_k = k < 10 ? k - 7 : 3;  // eval f.r, f.g, f.b or pdf
    const double d = relative_difference(cl.v[k], at.v[eval_k]);
    if (d <= kRelative) return 0.0;
    const Sensitivity s = sensitivity(m, wo, wi, u, at, cl.flags, seed);
    return s.value[eval_k] > 0.0 ? (d - kRelative) / s.value[eval_k] : INFINITY;
}

// A flag difference is also accepted where the successful sample lies this close to the horizon:
// whether a direction at cos 1e-4 survives the checks for a positive cosine and pdf depends on the
// last bits of a sqrt(1 - x^2 - y^2), and its contribution f |cos| / pdf is nearly nothing.
constexpr float kHorizon = 1e-3f;

// Per value: the worst difference, how many needed the sensitivity allowance, the worst ratio of
// difference to sensitivity, and the failures with a few examples.
struct Tally {
    double worst_plain = 0.0;  // among items within 1e-5
    size_t above_1e6 = 0;
    size_t conditioned = 0;
    double worst_ratio = 0.0;
    size_t failures = 0;
    std::vector<std::string> examples;

    void fail(const std::string& where) {
        ++failures;
        if (examples.size() < 3) examples.push_back(where);
    }
};

std::string at(const Inputs& in, size_t i) {
    return "wo " + describe(in.wo[i]) + " wi " + describe(in.wi[i]) + " u " + describe(in.u[i]) + " | " +
           describe(in.materials[size_t(in.index[i])]);
}

}  // namespace

TEST_CASE("OpenCL: PoCL provides a device and selectors pick it", "[opencl]") {
    std::vector<lab::opencl::DeviceInfo> devices = lab::opencl::list_devices();
    REQUIRE_FALSE(devices.empty());  // PoCL is required: no device is a failure
    lab::opencl::DeviceInfo chosen = lab::opencl::select_device("");
    CHECK(chosen.device != nullptr);
    CHECK(lab::opencl::select_device(devices.front().id()).device == devices.front().device);
    CHECK(lab::opencl::select_device("cpu").type == "cpu");
    // part of a name, in any case: the chosen device's own name, upper-cased (PoCL's CPU device is
    // "pthread-..." in older releases and "cpu-..." in newer ones)
    std::string upper = chosen.device_name;
    for (char& ch : upper) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    CHECK(lab::opencl::select_device(upper).device == chosen.device);
    try {
        lab::opencl::select_device("no such device");
        FAIL("an unknown selector was accepted");
    } catch (const lab::opencl::DeviceNotFound& e) {
        std::string message = e.what();
        CHECK(message.find("\"no such device\"") != std::string::npos);
        CHECK(message.find(devices.front().id()) != std::string::npos);  // lists what is available
        CHECK(message.find('\n') == std::string::npos);
    }
    CHECK_THROWS_AS(lab::opencl::select_device("7:3"), lab::opencl::DeviceNotFound);
}

TEST_CASE("OpenCL: a kernel build error names the original file and line", "[opencl]") {
    // kernels/broken.cl includes lib/a.h, which includes its sibling b.h; line 3 of b.h is wrong.
    std::vector<std::pair<std::string, std::string>> files = {
        {"kernels/broken.cl", "// entry\n#include \"lib/a.h\"\n__kernel void k(__global float* x) { x[0] = a(); }\n"},
        {"lib/a.h", "#ifndef A_H\n#define A_H\n#include \"b.h\"\nfloat a(void) { return b(); }\n#endif\n"},
        {"lib/b.h", "#ifndef B_H\n#define B_H\nfloat b(void) { return undeclared_name; }\n#endif\n"},
    };
    auto lookup = [&](const std::string& path) -> std::string_view {
        for (const auto& f : files)
            if (f.first == path) return f.second;
        return {};
    };
    lab::opencl::AssembledSource source = lab::opencl::assemble_source("kernels/broken.cl", lookup);
    REQUIRE(source.origin.size() == 10);
    CHECK(source.locate(6).file == "lib/b.h");
    CHECK(source.locate(6).line == 3);

    lab::opencl::Runtime runtime;
    try {
        runtime.build(source, "-cl-std=CL1.2");
        FAIL("a broken kernel built");
    } catch (const lab::opencl::KernelBuildError& e) {
        std::string message = e.what();
        std::string first_line = message.substr(0, message.find('\n'));
        INFO(message);
        CHECK(first_line.find("lib/b.h:3:") != std::string::npos);
        CHECK(first_line.find("undeclared_name") != std::string::npos);
        CHECK(first_line.find("generated line 6") != std::string::npos);
        CHECK(message.find("at lib/b.h:3 (generated line 6)") != std::string::npos);
    }

    files[1].second = "#include \"missing.h\"\n";
    try {
        lab::opencl::assemble_source("kernels/broken.cl", lookup);
        FAIL("an include of a missing file was accepted");
    } catch (const lab::opencl::OpenClError& e) {
        CHECK(std::string(e.what()).find("lib/a.h:1: #include \"missing.h\"") != std::string::npos);
    }
}

TEST_CASE("OpenCL: bsdf_eval, bsdf_pdf and bsdf_sample agree with the C++ build", "[opencl][agreement]") {
    Inputs in = make_inputs(990, 500, 20240607u);
    const size_t n = in.index.size();

    lab::opencl::Runtime runtime;
    lab::kernels::BrdfBatch batch(runtime);
    batch.set_materials(in.materials);
    std::vector<float3> f_cl = batch.eval(in.index, in.wo, in.wi);
    std::vector<float> pdf_cl = batch.pdf(in.index, in.wo, in.wi);
    std::vector<brdf::BsdfSample> s_cl = batch.sample(in.index, in.wo, in.u);

    Tally tally[kValues];
    Tally flags;
    size_t nonzero_eval = 0, successful_samples = 0, delta_samples = 0, conditioned_items = 0;
    for (size_t i = 0; i < n; ++i) {
        const brdf::Material& m = in.materials[size_t(in.index[i])];
        Outputs cpp = evaluate_cpp(m, in.wo[i], in.wi[i], in.u[i]);
        Outputs cl = outputs_of(f_cl[i], pdf_cl[i], s_cl[i]);
        nonzero_eval += std::fmax(cpp.v[0], std::fmax(cpp.v[1], cpp.v[2])) > 0.0f;
        successful_samples += cpp.flags != 0;
        delta_samples += (cpp.flags & BSDF_DELTA) != 0;

        bool same_event = cpp.flags == cl.flags;
        double d[kValues];
        bool plain = same_event;
        for (int k = 0; k < kValues; ++k) {
            d[k] = k < kFirstSampleValue || same_event ? difference(k, cpp, cl) : 0.0;
            plain = plain && d[k] <= kRelative;
        }
        if (plain) {
            for (int k = 0; k < kValues; ++k) {
                tally[k].worst_plain = std::max(tally[k].worst_plain, d[k]);
                tally[k].above_1e6 += d[k] > 1e-6;
            }
            continue;
        }

        ++conditioned_items;
        Sensitivity s = sensitivity(m, in.wo[i], in.wi[i], in.u[i], cpp, cl.flags, i);
        if (!same_event) {
            const Outputs& succeeded = cpp.flags ? cpp : cl;
            bool grazing = (cpp.flags == 0 || cl.flags == 0) && std::fabs(succeeded.v[6]) < kHorizon;
            ++flags.conditioned;
            if (!s.flags_reachable && !grazing)
                flags.fail("flags " + std::to_string(cpp.flags) + " vs " + std::to_string(cl.flags) + " | " + at(in, i));
        }
        for (int k = 0; k < kValues; ++k) {
            if (d[k] <= kRelative) {
                tally[k].worst_plain = std::max(tally[k].worst_plain, d[k]);
                tally[k].above_1e6 += d[k] > 1e-6;
                continue;
            }
            ++tally[k].conditioned;
            double ratio = s.value[k] > 0.0 ? (d[k] - kRelative) / s.value[k] : INFINITY;
            if (ratio > kSensitivityFactor && k > 6 && same_event && !(cl.flags & BSDF_DELTA))
                ratio = ratio_at_own_direction(m, in.wo[i], in.u[i], cl, k, i);
            tally[k].worst_ratio = std::max(tally[k].worst_ratio, ratio);
            if (ratio > kSensitivityFactor) {
                char text[160];
                std::snprintf(text, sizeof(text), "C++ %.9g, OpenCL %.9g, difference %.3g, C++ sensitivity %.3g | ", cpp.v[k], cl.v[k],
                              d[k], s.value[k]);
                tally[k].fail(text + at(in, i));
            }
        }
    }

    std::printf("OpenCL agreement on %s: %zu materials (%zu presets), %zu items: %zu nonzero evals, %zu samples (%zu delta)\n",
                runtime.device().device_name.c_str(), in.materials.size(), in.presets, n, nonzero_eval,
                successful_samples, delta_samples);
    std::printf("  %zu items (%.2f%%) exceed 1e-5 somewhere and are held to %.0fx the C++ build's own sensitivity to 2-ulp input changes\n",
                conditioned_items, 100.0 * double(conditioned_items) / double(n), kSensitivityFactor);
    std::printf("  %-12s %12s %10s %12s %14s %9s\n", "value", "worst<=1e-5", ">1e-6", "conditioned", "worst d/sens", "failures");
    for (int k = 0; k < kValues; ++k)
        std::printf("  %-12s %12.3g %10zu %12zu %14.3g %9zu\n", kValueNames[k], tally[k].worst_plain, tally[k].above_1e6, tally[k].conditioned,
                    tally[k].worst_ratio, tally[k].failures);
    std::printf("  %-12s %12s %10s %12zu %14s %9zu\n", "sample flags", "-", "-", flags.conditioned, "-", flags.failures);

    // the inputs exercise what they claim to, and the allowance stays an exception
    CHECK(nonzero_eval > n / 4);
    CHECK(successful_samples > n / 2);
    CHECK(delta_samples > n / 100);
    CHECK(conditioned_items < n / 50);
    for (int k = 0; k < kValues; ++k) {
        INFO(kValueNames[k] << ": " << tally[k].failures << " disagreements, e.g. " << (tally[k].examples.empty() ? "" : tally[k].examples.front()));
        CHECK(tally[k].failures == 0);
    }
    INFO("sample flags: " << flags.failures << " disagreements, e.g. " << (flags.examples.empty() ? "" : flags.examples.front()));
    CHECK(flags.failures == 0);
}
