// dtoadq bench: performance figures (each subcommand in a file of bench/, registered here). `bench brdf` times bsdf_eval, bsdf_pdf and bsdf_sample in the
// C++ build (one thread and all threads) and in the OpenCL build, the openpbr model against the lab
// model per preset and on the same base (bench/brdf_model_speed.hpp), and prints how much each
// preset's own sampler reduces variance against cosine-weighted sampling.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/preset.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "common/input_error.hpp"
#include "bench/brdf_model_speed.hpp"
#include "bench/brdf_workload.hpp"
#include "kernels/host/brdf_batch.hpp"
#include "common/parallel_for.hpp"
#include "validation/sampling_efficiency.hpp"

namespace lab::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct BenchBrdfOptions {
    long samples = 1000000;
    std::string device;
    std::string presets = "presets";
    long efficiency_samples = 200000;
    int threads = hardware_threads();
    int repeats = 3;
    bool sorted = false;
    ModelSpeedOptions models;
};

// Best of `repeats` wall-clock runs: the figure least disturbed by the rest of the machine.
double best_seconds(int repeats, const std::function<void()>& run) {
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
        Clock::time_point start = Clock::now();
        run();
        best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return best;
}

double cpp_rate(const Workload& w, Operation op, int threads, int repeats) {
    long n = long(w.index.size());
    double seconds = best_seconds(repeats, [&] {
        std::vector<float> partial(size_t(threads), 0.0f);
        lab::parallel_for(threads, threads, [&](int t) {
            partial[size_t(t)] = run_cpp(w, op, n * t / threads, n * (t + 1) / threads);
        });
        for (float p : partial) g_sink = g_sink + p;
    });
    return double(n) / seconds;
}

struct OpenClRates {
    double kernel[3] = {0, 0, 0};      // items per second, kernel only
    double end_to_end[3] = {0, 0, 0};  // including upload and download
};

OpenClRates opencl_rates(kernels::BrdfBatch& batch, const Workload& w, int repeats) {
    OpenClRates rates;
    double n = double(w.index.size());
    for (int op = 0; op < 3; ++op) {
        double best_kernel = 1e30, best_total = 1e30;
        for (int r = 0; r < repeats; ++r) {
            if (op == 0) g_sink = g_sink + batch.eval(w.index, w.wo, w.wi)[0].x;
            else if (op == 1) g_sink = g_sink + batch.pdf(w.index, w.wo, w.wi)[0];
            else g_sink = g_sink + batch.sample(w.index, w.wo, w.u)[0].pdf;
            const kernels::BatchTiming& t = batch.last_timing();
            best_kernel = std::min(best_kernel, t.kernel);
            best_total = std::min(best_total, t.upload + t.kernel + t.download);
        }
        rates.kernel[op] = n / best_kernel;
        rates.end_to_end[op] = n / best_total;
    }
    return rates;
}

constexpr int kRowName = 26;

void print_rate_row(const std::string& name, const double rates[3], const double baseline[3]) {
    std::printf("  %-*s", kRowName, name.c_str());
    for (int op = 0; op < 3; ++op) std::printf(" %9.2f", rates[op] * 1e-6);
    std::printf("  ");
    for (int op = 0; op < 3; ++op) std::printf(" %8.2fx", rates[op] / baseline[op]);
    std::printf("\n");
}

std::string percent(double fraction) { return std::to_string(int(std::lround(100.0 * fraction))) + "%"; }

void print_efficiency(const std::vector<brdf::Preset>& presets, const BenchBrdfOptions& o) {
    const float thetas[3] = {0.0f, 45.0f, 75.0f};
    std::vector<validation::SamplingEfficiency> results(presets.size() * 3);
    lab::parallel_for(int(results.size()), o.threads, [&](int k) {
        brdf::float3 wo = brdf::direction_from_degrees(thetas[k % 3], 0.0f);
        results[size_t(k)] = validation::sampling_efficiency(presets[size_t(k / 3)].material, wo, o.efficiency_samples, 7);
    });
    size_t width = 6;
    for (const brdf::Preset& p : presets) width = std::max(width, p.name.size());
    std::printf("\nsampling efficiency at theta_o = 0, 45, 75 deg: variance of f|cos|/pdf (mean of RGB) with cosine-weighted\n");
    std::printf("sampling over that with the material's sampler (> 1: the material's sampler is better; %ld samples each;\n",
                o.efficiency_samples);
    std::printf("delta lobes excluded from both: cosine sampling cannot reach them)\n");
    std::printf("  %-*s %9s %9s %9s   %s\n", int(width), "preset", "0 deg", "45 deg", "75 deg", "notes");
    for (size_t p = 0; p < presets.size(); ++p) {
        std::printf("  %-*s", int(width), presets[p].name.c_str());
        bool two_sided = false, continuous = false;
        double delta = 0.0, failed = 0.0;
        for (int a = 0; a < 3; ++a) {
            const validation::SamplingEfficiency& e = results[p * 3 + size_t(a)];
            if (std::isnan(e.ratio)) std::printf(" %9s", "-");
            else if (std::isinf(e.ratio)) std::printf(" %9s", "inf");
            else std::printf(" %9.3g", e.ratio);
            delta = std::max(delta, e.delta_fraction);
            failed = std::max(failed, e.failed_fraction);
            two_sided = two_sided || e.two_sided;
            continuous = continuous || e.continuous_part;
        }
        std::string notes;
        if (!continuous) notes += "no continuous part; ";
        if (delta > 0.0) notes += "delta lobe excluded (up to " + percent(delta) + " of samples); ";
        if (failed >= 0.005) notes += "up to " + percent(failed) + " of samples fail; ";
        if (two_sided) notes += "cosine sampling two-sided; ";
        if (!notes.empty()) notes.resize(notes.size() - 2);
        std::printf("   %s\n", notes.c_str());
    }
}

void run_bench_brdf(const BenchBrdfOptions& o) {
    if (o.samples < 1000 || o.samples > 100000000) throw InputError("command line", "--samples", "must be in [1000, 100000000]");
    if (o.efficiency_samples < 1000 || o.efficiency_samples > 100000000)
        throw InputError("command line", "--efficiency-samples", "must be in [1000, 100000000]");
    if (o.threads < 1 || o.threads > 256) throw InputError("command line", "--threads", "must be in [1, 256]");
    if (o.repeats < 1 || o.repeats > 100) throw InputError("command line", "--repeats", "must be in [1, 100]");
    if (o.models.samples < 1000 || o.models.samples > 100000000)
        throw InputError("command line", "--model-samples", "must be in [1000, 100000000]");
    if (o.models.repeats < 0 || o.models.repeats > 100) throw InputError("command line", "--model-repeats", "must be in [0, 100]");
    if (!(o.models.preview_seconds >= 0.0 && o.models.preview_seconds <= 3600.0))
        throw InputError("command line", "--preview-seconds", "must be in [0, 3600]");

    std::vector<brdf::Preset> presets = load_preset_folder(o.presets, "--presets");
    opencl::Runtime runtime(o.device);
    std::vector<brdf::Material> materials;
    for (const brdf::Preset& p : presets) materials.push_back(p.material);
    Workload w = make_workload(materials, o.samples, o.sorted);
    std::printf("dtoadq bench brdf: %ld items %s %zu presets in %s, best of %d runs\n", o.samples,
                o.sorted ? "in blocks of" : "cycling through", presets.size(), o.presets.c_str(), o.repeats);
    std::printf("OpenCL device %s, %u compute units, %s\n", runtime.device().description().c_str(), runtime.device().compute_units,
                runtime.device().version.c_str());

    // A unique -D changes the program's hash, so the first build misses PoCL's kernel cache (and
    // leaves an entry of about 0.3 MB there). The plain build twice: the second is warm for sure.
    std::string nonce = "-D DTOADQ_COLD_BUILD=" + std::to_string(Clock::now().time_since_epoch().count());
    kernels::BrdfBatch cold(runtime, nonce);
    kernels::BrdfBatch first(runtime);  // warm if an earlier run cached it
    kernels::BrdfBatch batch(runtime);  // warm now in any case
    std::printf("\nOpenCL build of kernels/brdf_batch.cl (%s):\n", kernels::BrdfBatch::kBuildOptions);
    std::printf("  cold  %7.3f s clBuildProgram + %7.3f s first launch of the 3 kernels\n", cold.build_seconds(), cold.first_launch_seconds());
    std::printf("  warm  %7.3f s clBuildProgram + %7.3f s first launch (PoCL kernel cache)\n", batch.build_seconds(),
                batch.first_launch_seconds());
    batch.set_materials(w.materials);

    double single[3], multi[3];
    for (int op = 0; op < 3; ++op) {
        single[op] = cpp_rate(w, Operation(op), 1, o.repeats);
        multi[op] = cpp_rate(w, Operation(op), o.threads, o.repeats);
    }
    OpenClRates cl = opencl_rates(batch, w, o.repeats);

    std::printf("\n  %-*s %9s %9s %9s   %s\n", kRowName, "million per second", "eval", "pdf", "sample",
                "ratio to C++ 1 thread: eval, pdf, sample");
    print_rate_row("C++, 1 thread", single, single);
    print_rate_row("C++, " + std::to_string(o.threads) + " threads", multi, single);
    print_rate_row("OpenCL, kernel only", cl.kernel, single);
    print_rate_row("OpenCL, with transfers", cl.end_to_end, single);

    if (o.models.repeats > 0) print_model_speed(presets, runtime, batch, o.models);
    print_efficiency(presets, o);
}

}  // namespace

void register_bench(CLI::App& app) {
    auto* bench = app.add_subcommand("bench", "Performance figures (not timed tests)");
    bench->require_subcommand(1);

    auto options = std::make_shared<BenchBrdfOptions>();
    auto* brdf_cmd = bench->add_subcommand(
        "brdf", "Evaluations and samples per second, C++ vs OpenCL, and each preset's sampling efficiency against cosine sampling");
    brdf_cmd->add_option("--samples", options->samples, "Items per timed batch")->capture_default_str();
    brdf_cmd->add_option("--device", options->device,
                         "OpenCL device: P:D, gpu, cpu or part of its name (default: first GPU, else first CPU)");
    brdf_cmd->add_option("--presets", options->presets, "Folder of preset JSON files")->capture_default_str();
    brdf_cmd->add_option("--efficiency-samples", options->efficiency_samples, "Samples per strategy, preset and angle")
        ->capture_default_str();
    brdf_cmd->add_option("--threads", options->threads, "Threads of the multi-threaded C++ figures")->capture_default_str();
    brdf_cmd->add_option("--repeats", options->repeats, "Timed runs per figure; the best is reported")->capture_default_str();
    brdf_cmd->add_option("--model-samples", options->models.samples, "Items per timed batch of one material in the openpbr-against-lab tables")
        ->capture_default_str();
    brdf_cmd->add_option("--model-repeats", options->models.repeats, "Paired repeats of the openpbr-against-lab tables (0: leave them out)")
        ->capture_default_str();
    brdf_cmd->add_option("--preview-seconds", options->models.preview_seconds,
                         "Preview render time per figure of the same-base table (0: no preview columns)")
        ->capture_default_str();
    brdf_cmd->add_option("--preview-size", options->models.preview_size, "Preview image size of the same-base table")->capture_default_str();
    brdf_cmd->add_option("--preview-env", options->models.preview_env, "Preview environment of the same-base table (file or constant:R,G,B)")
        ->capture_default_str();
    brdf_cmd->add_flag("--sorted", options->sorted, "Give the presets consecutive blocks of items instead of alternating them");
    brdf_cmd->callback([options] { run_bench_brdf(*options); });
    register_bench_preview(*bench);
    register_bench_render(*bench);
    register_bench_objects(*bench);
    register_bench_compare(*bench);
    register_bench_vectorization(*bench);
    register_bench_breakdown(*bench);
    register_bench_denoise(*bench);
}

}  // namespace lab::cli
