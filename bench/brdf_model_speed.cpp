#include "bench/brdf_model_speed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/brdf_workload.hpp"
#include "bench/timed_runs.hpp"
#include "brdf/host/parameters.hpp"
#include "cli/render_job.hpp"
#include "report/convergence.hpp"
#include "render/opencl_renderer.hpp"

namespace lab::cli {

brdf::Material lab_on_same_base(const brdf::Material& o) {
    brdf::Material m = brdf::default_material(BRDF_MODEL_LAB);
    for (int c = 0; c < 3; ++c) m.albedo[c] = o.albedo[c] * o.base_weight;
    m.roughness = o.roughness;
    m.anisotropic = o.anisotropic;
    m.tangent_rotation = o.tangent_rotation;
    m.metallic = o.metallic;
    float r = (o.ior - 1.0f) / (o.ior + 1.0f);
    m.fresnel = r * r * o.specular_weight;
    m.subsurface = o.subsurface;
    m.subsurface_asymmetry = o.subsurface_asymmetry;
    // the lab mixes its lobes by normalised weights: the diffuse at nearly its full albedo under a glossy
    // lobe of the dielectric's F0, as openpbr's diffuse under its specular (a darker lab base would
    // end its paths sooner and give more paths per second for less work per ray)
    m.weight_diffuse = 1.0f - o.weight_transmission;
    m.weight_glossy = o.metallic > 0.0f ? 1.0f : m.fresnel;
    m.weight_specular = 0.0f;
    m.weight_transmission = o.weight_transmission;
    m.ior = o.ior;
    m.distribution = BRDF_DISTRIBUTION_GGX;
    m.energy_compensation = o.energy_compensation;
    return m;
}

brdf::Material openpbr_base_only(const brdf::Material& openpbr) {
    brdf::Material m = openpbr;
    m.coat_weight = 0.0f;
    m.fuzz_weight = 0.0f;
    m.thin_film_weight = 0.0f;
    return m;
}

namespace {

using Clock = std::chrono::steady_clock;

// The four rates of one material set: C++ eval, C++ sample, OpenCL eval, OpenCL sample (items/s,
// the OpenCL ones kernel time only).
constexpr int kRates = 4;
const char* const kRateNames[kRates] = {"C++ eval", "C++ sample", "OpenCL eval", "OpenCL sample"};

std::vector<double> measure_rates(const Workload& w, kernels::BrdfBatch& batch) {
    std::vector<double> rates(kRates);
    double n = double(w.index.size());
    for (int k = 0; k < 2; ++k) {
        Operation op = k == 0 ? Operation::eval : Operation::sample;
        Clock::time_point start = Clock::now();
        g_sink = g_sink + run_cpp(w, op, 0, long(w.index.size()));
        rates[size_t(k)] = n / std::chrono::duration<double>(Clock::now() - start).count();
        if (k == 0) g_sink = g_sink + batch.eval(w.index, w.wo, w.wi)[0].x;
        else g_sink = g_sink + batch.sample(w.index, w.wo, w.u)[0].pdf;
        rates[size_t(2 + k)] = n / batch.last_timing().kernel;
    }
    return rates;
}

// Ratios gathered over the repeats, one list per (row, column).
struct RatioTable {
    std::map<std::pair<std::string, int>, std::vector<double>> ratios, rates;
    void add(const std::string& row, int column, double rate, double baseline) {
        rates[{row, column}].push_back(rate);
        ratios[{row, column}].push_back(rate / baseline);
    }
    std::string cell(const std::string& row, int column) const {
        auto it = ratios.find({row, column});
        if (it == ratios.end() || it->second.empty()) return "-";
        const std::vector<double>& v = it->second;
        char text[64];
        std::snprintf(text, sizeof text, "%.2fx [%.2f, %.2f]", median(v), *std::min_element(v.begin(), v.end()),
                      *std::max_element(v.begin(), v.end()));
        return text;
    }
    double median_rate(const std::string& row, int column) const {
        auto it = rates.find({row, column});
        return it == rates.end() ? 0.0 : median(it->second);
    }
};

// The preview (test model, no ground, every slot the material under test) of each material, on
// the runtime's device; kernels built once, each compiling the features of its one material.
class PreviewRates {
public:
    PreviewRates(const opencl::Runtime& runtime, const ModelSpeedOptions& options)
        : runtime_(runtime), seconds_(options.preview_seconds) {
        RenderJobOptions o;
        o.size = options.preview_size;
        o.ground = "off";
        o.env = options.preview_env;
        job_input_ = prepare_render_job(o).input;
    }
    int add(const brdf::Material& material) {
        render::RenderInput input = job_input_;
        for (scene::MaterialSlot& slot : input.scene.materials)
            if (slot.source != "emitter") slot.material = material;
        renderers_.push_back(std::make_unique<render::OpenClRenderer>(runtime_, input));
        renderers_.back()->add_samples(1);  // PoCL compiles the work-group function at the first launch
        return int(renderers_.size()) - 1;
    }
    // Paths and rays per second of one run.
    std::pair<double, double> rates(int id) {
        render::Renderer& r = *renderers_[size_t(id)];
        r.reset();
        report::render_for(r, seconds_, [](double) {});
        render::RenderStatistics stats = r.statistics();
        return {stats.paths_per_second(), stats.rays_per_second()};
    }

private:
    const opencl::Runtime& runtime_;
    double seconds_;
    render::RenderInput job_input_;
    std::vector<std::unique_ptr<render::Renderer>> renderers_;
};

}  // namespace

void print_model_speed(const std::vector<brdf::Preset>& presets, const opencl::Runtime& runtime, kernels::BrdfBatch& batch,
                       const ModelSpeedOptions& o) {
    // Materials: the presets, then for each openpbr preset its base alone and the lab on that base.
    std::vector<brdf::Material> materials;
    std::vector<int> lab_presets, openpbr_presets;
    for (size_t i = 0; i < presets.size(); ++i) {
        materials.push_back(presets[i].material);
        if (presets[i].material.model == BRDF_MODEL_LAB) lab_presets.push_back(int(i));
        if (presets[i].material.model == BRDF_MODEL_OPENPBR) openpbr_presets.push_back(int(i));
    }
    if (lab_presets.empty() || openpbr_presets.empty()) {
        std::printf("\nopenpbr against lab: needs presets of both models in the folder\n");
        return;
    }
    std::vector<int> base_only, lab_base;
    for (int p : openpbr_presets) {
        base_only.push_back(int(materials.size()));
        materials.push_back(openpbr_base_only(presets[size_t(p)].material));
        lab_base.push_back(int(materials.size()));
        materials.push_back(lab_on_same_base(presets[size_t(p)].material));
    }
    Workload w = make_workload(materials, o.samples, false);
    batch.set_materials(materials);
    auto use = [&](const std::vector<int>& ids) {
        for (size_t i = 0; i < w.index.size(); ++i) w.index[i] = ids[i % ids.size()];
    };

    bool preview = o.preview_seconds > 0.0;
    std::unique_ptr<PreviewRates> previews;
    std::vector<int> preview_lab, preview_base, preview_whole;
    if (preview) {
        std::printf("\nbuilding the preview kernels (%zu openpbr presets: lab on the same base, the base alone, the whole preset)\n",
                    openpbr_presets.size());
        std::fflush(stdout);
        previews = std::make_unique<PreviewRates>(runtime, o);
        for (size_t k = 0; k < openpbr_presets.size(); ++k) {
            preview_lab.push_back(previews->add(materials[size_t(lab_base[k])]));
            preview_base.push_back(previews->add(materials[size_t(base_only[k])]));
            preview_whole.push_back(previews->add(materials[size_t(openpbr_presets[k])]));
        }
    }

    RatioTable every, pairs;
    for (int r = 0; r < o.repeats; ++r) {
        std::vector<std::vector<double>> rates;
        for (size_t i = 0; i < presets.size(); ++i) {
            use({int(i)});
            rates.push_back(measure_rates(w, batch));
        }
        for (int c = 0; c < kRates; ++c) {
            double log_sum = 0.0;  // the lab presets' geometric mean: the baseline of this repeat
            for (int i : lab_presets) log_sum += std::log(rates[size_t(i)][size_t(c)]);
            double lab = std::exp(log_sum / double(lab_presets.size()));
            for (size_t i = 0; i < presets.size(); ++i) every.add(presets[i].name, c, rates[i][size_t(c)], lab);
        }
        for (size_t k = 0; k < openpbr_presets.size(); ++k) {
            const std::string& name = presets[size_t(openpbr_presets[k])].name;
            use({lab_base[k]});
            std::vector<double> same = measure_rates(w, batch);
            use({base_only[k]});
            std::vector<double> base = measure_rates(w, batch);
            for (int c = 0; c < kRates; ++c) pairs.add(name, c, base[size_t(c)], same[size_t(c)]);
            if (preview) {
                std::pair<double, double> lab_rates = previews->rates(preview_lab[k]), base_rates = previews->rates(preview_base[k]),
                                          whole_rates = previews->rates(preview_whole[k]);
                pairs.add(name, kRates, base_rates.first, lab_rates.first);
                pairs.add(name, kRates + 1, base_rates.second, lab_rates.second);
                pairs.add(name, kRates + 2, whole_rates.first, lab_rates.first);
            }
        }
        std::printf("  repeat %d of %d done\n", r + 1, o.repeats);
        std::fflush(stdout);
    }

    size_t width = 6;
    for (const brdf::Preset& p : presets) width = std::max(width, p.name.size());
    std::printf("\nevery preset against the lab model: %ld items of one material per batch, C++ one thread and OpenCL kernel time;\n"
                "the rate is the median in millions per second; the ratio is to the geometric mean of the %zu lab presets' rates\n"
                "measured in the same repeat, the median of %d repeats [lowest, highest]\n",
                o.samples, lab_presets.size(), o.repeats);
    std::printf("  %-*s %-10s", int(width), "preset", "model");
    for (int c = 0; c < kRates; ++c) std::printf(" %28s", kRateNames[c]);
    std::printf("\n");
    auto row_cells = [&](const RatioTable& t, const std::string& row, int columns) {
        for (int c = 0; c < columns; ++c) {
            char rate[16];
            std::snprintf(rate, sizeof rate, "%.2f", t.median_rate(row, c) * 1e-6);
            std::printf(" %7s %20s", rate, t.cell(row, c).c_str());
        }
    };
    for (const brdf::Preset& p : presets) {
        std::printf("  %-*s %-10s", int(width), p.name.c_str(), brdf::model_name(p.material.model));
        row_cells(every, p.name, kRates);
        std::printf("\n");
    }

    std::printf("\neach openpbr preset's base (coat, fuzz and thin film off) against the lab model on the same base (colour, metalness,\n"
                "roughness, anisotropy, index; Lambert for the diffuse under a glossy lobe of the dielectric's F0): ratio openpbr / lab, median of %d paired repeats [lowest, highest]",
                o.repeats);
    if (preview)
        std::printf(";\npreview: the test model without ground under %s, %s, %.1f s per figure, pt with MIS, each kernel compiled\n"
                    "for its one material (rays/s: camera, bounce and shadow rays, less tied to how long the paths are); 'whole'\n"
                    "is the preset with its layers against the same lab base",
                    o.preview_env.c_str(), o.preview_size.c_str(), o.preview_seconds);
    std::printf("\n  %-*s", int(width), "preset");
    for (int c = 0; c < kRates; ++c) std::printf(" %20s", kRateNames[c]);
    if (preview) std::printf(" %20s %20s %20s %14s", "preview paths/s", "preview rays/s", "whole, paths/s", "lab paths/s");
    std::printf("\n");
    for (int p : openpbr_presets) {
        const std::string& name = presets[size_t(p)].name;
        std::printf("  %-*s", int(width), name.c_str());
        for (int c = 0; c < kRates + (preview ? 3 : 0); ++c) std::printf(" %20s", pairs.cell(name, c).c_str());
        if (preview) {
            const std::vector<double>& v = pairs.rates.at({name, kRates});
            const std::vector<double>& ratio = pairs.ratios.at({name, kRates});
            std::vector<double> lab_paths;
            for (size_t i = 0; i < v.size(); ++i) lab_paths.push_back(v[i] / ratio[i]);
            std::printf(" %14.3g", median(lab_paths));
        }
        std::printf("\n");
    }
}

}  // namespace lab::cli
