// dtoadq fit: fits the lab model to a measured MERL table and writes the fitted preset, a report of
// its error per channel and per incident angle, and optionally the chart (docs/fitting.md).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "brdf/host/merl_file.hpp"
#include "brdf/host/parameters.hpp"
#include "cli/commands.hpp"
#include "common/input_error.hpp"
#include "fit/fit_metric.hpp"
#include "fit/fit_optimizer.hpp"
#include "fit/fit_pairs.hpp"
#include "fit/fit_report.hpp"
#include "fit/fit_space.hpp"
#include "plots/fit_chart.hpp"
#include "plots/output_file.hpp"

namespace lab::cli {
namespace {

namespace fs = std::filesystem;

struct FitCommandOptions {
    std::string measured;
    std::string distribution = "ggx";
    bool anisotropic = false;
    std::string lobes = "diffuse,glossy";
    std::string output;
    std::string report;
    std::string chart;
    int starts = 8;
    int max_evaluations = 3000;
    std::string stride = "3,3,10";
    bool quiet = false;
};

fit::PairGrid parse_stride(const std::string& text) {
    std::stringstream in(text);
    int v[3];
    char comma1 = 0, comma2 = 0;
    const int bins[3] = {MERL_THETA_H_BINS, MERL_THETA_D_BINS, MERL_PHI_D_BINS};
    if (!(in >> v[0] >> comma1 >> v[1] >> comma2 >> v[2]) || comma1 != ',' || comma2 != ',' || !in.eof())
        throw InputError("command line", "--stride", "expected THETA_H,THETA_D,PHI_D bin strides, got \"" + text + "\"");
    for (int k = 0; k < 3; ++k)
        if (v[k] < 1 || v[k] > bins[k])
            throw InputError("command line", "--stride", "strides must lie in [1, 90], [1, 90] and [1, 180], got \"" + text + "\"");
    return fit::PairGrid{v[0], v[1], v[2], 1};
}

// The report beside the preset: fitted.json -> fitted.report.json.
std::string default_report_path(const std::string& output) {
    fs::path p(output);
    return (p.parent_path() / (p.stem().string() + ".report.json")).string();
}

// One line redrawn in place on a terminal; in a log, one line per finished start.
class FitProgressLine {
public:
    FitProgressLine(int starts, bool quiet) : starts_(starts), quiet_(quiet), terminal_(isatty(fileno(stderr)) != 0) {}
    ~FitProgressLine() {
        if (open_) std::fputc('\n', stderr);
    }
    void update(int start, int evaluations, double error, double best) {
        if (quiet_) return;
        if (start != start_ && start_ >= 0 && !terminal_) print_line();
        start_ = start;
        evaluations_ = evaluations;
        error_ = error;
        best_ = best;
        const auto now = std::chrono::steady_clock::now();
        if (terminal_ && now - last_ > std::chrono::milliseconds(100)) {
            last_ = now;
            std::fputc('\r', stderr);
            print_line(false);
            open_ = true;
        }
    }
    void finish() {
        if (quiet_) return;
        if (terminal_) {
            std::fputc('\r', stderr);
            print_line();
            open_ = false;
        } else if (start_ >= 0) {
            print_line();
        }
    }

private:
    void print_line(bool newline = true) {
        std::fprintf(stderr, "fit: start %d/%d  %5d evaluations  error %.4g  best %.4g%s", start_ + 1, starts_, evaluations_, error_,
                     best_, newline ? "\n" : "   ");
        std::fflush(stderr);
    }
    int starts_;
    bool quiet_, terminal_;
    bool open_ = false;
    int start_ = -1, evaluations_ = 0;
    double error_ = 0.0, best_ = 0.0;
    std::chrono::steady_clock::time_point last_{};
};

void run_fit(const FitCommandOptions& o) {
    fit::FitSpace space;
    if (o.distribution == "ggx") space.distribution = BRDF_DISTRIBUTION_GGX;
    else if (o.distribution == "hyper_cauchy") space.distribution = BRDF_DISTRIBUTION_HYPER_CAUCHY;
    else throw InputError("command line", "--distribution", "expected ggx or hyper_cauchy, got \"" + o.distribution + "\"");
    fit::parse_lobes(o.lobes, &space);
    space.anisotropic = o.anisotropic;
    if (space.anisotropic && !space.glossy) throw InputError("command line", "--anisotropic", "needs the glossy lobe in --lobes");
    fit::FitOptions options;
    options.starts = o.starts;
    options.max_evaluations = o.max_evaluations;
    fit::check_fit_options(options, "--starts", "--max-evaluations");
    fit::PairGrid grid = parse_stride(o.stride);
    grid.phi_h_count = space.anisotropic ? 4 : 1;
    const std::string report_path = o.report.empty() ? default_report_path(o.output) : o.report;
    // fail on a bad output path before reading and fitting anything
    plots::require_writable(o.output, "-o");
    plots::require_writable(report_path, "--report");
    if (!o.chart.empty()) plots::require_writable(o.chart, "--chart");

    const brdf::MeasuredTable table = brdf::read_merl_file(o.measured);
    const std::vector<fit::FitPair> pairs = fit::fit_pairs(table, grid);
    if (pairs.empty()) throw InputError(o.measured, "", "no table entry above the horizon at these strides");

    FitProgressLine line(o.starts, o.quiet);
    const fit::FitResult result = fit::fit_material(pairs, space, options, [&line](int s, int n, double e, double best) {
        line.update(s, n, e, best);
    });
    line.finish();
    const fit::ErrorBreakdown breakdown = fit::error_breakdown(result.material, pairs);

    brdf::Preset preset;
    preset.name = fs::path(o.measured).stem().string() + "_fit";
    char description[256];
    std::snprintf(description, sizeof description, "Fitted to %s by dtoadq fit (%s, %s): log-space RMSE %.4g over %d direction pairs.",
                  fs::path(o.measured).filename().string().c_str(), o.distribution.c_str(), fit::lobes_text(space).c_str(),
                  result.error, result.pairs);
    preset.description = description;
    preset.source = o.output;
    preset.material = result.material;
    brdf::save_preset(preset, o.output);
    {
        std::ofstream out = plots::open_output(report_path, "--report");
        out << fit::fit_report(o.measured, space, result, breakdown).dump(2) << "\n";
        if (!out.flush()) throw InputError(report_path, "--report", "write failed");
    }
    if (!o.chart.empty()) {
        plots::FitChartData data;
        data.error_map = fit::error_map(table, result.material, 10).error;
        data.error = result.error;
        plots::write_fit_chart(table, preset, data, o.chart);
    }
    std::printf("fit: error %.4g (r %.4g, g %.4g, b %.4g) over %d pairs; %d of %d starts reached it; %d evaluations in %.1f s\n",
                breakdown.total, breakdown.channel[0], breakdown.channel[1], breakdown.channel[2], result.pairs,
                fit::starts_at_best(result), int(result.starts.size()), result.evaluations, result.seconds);
    std::printf("fit: wrote %s and %s%s%s\n", o.output.c_str(), report_path.c_str(), o.chart.empty() ? "" : " and ", o.chart.c_str());
}

}  // namespace

void register_fit(CLI::App& app) {
    auto o = std::make_shared<FitCommandOptions>();
    auto* cmd = app.add_subcommand("fit", "Fit the lab model to a measured MERL BRDF table (docs/fitting.md)");
    cmd->add_option("--measured", o->measured, "Measured BRDF in MERL's .binary format")->required();
    cmd->add_option("--distribution", o->distribution, "Microfacet distribution of the glossy lobe: ggx or hyper_cauchy")
        ->capture_default_str();
    cmd->add_flag("--anisotropic", o->anisotropic, "Fit the anisotropy too");
    cmd->add_option("--lobes", o->lobes, "Lobes to fit: diffuse, glossy, retroreflection, subsurface (comma-separated)")
        ->capture_default_str();
    cmd->add_option("-o,--output", o->output, "Fitted preset (JSON) to write")->required();
    cmd->add_option("--report", o->report, "Error report (JSON); default: beside the preset, NAME.report.json");
    cmd->add_option("--chart", o->chart, "Also draw measured against fitted lobes and the error map to this PNG");
    cmd->add_option("--starts", o->starts, "Starting points of the local search")->capture_default_str();
    cmd->add_option("--max-evaluations", o->max_evaluations, "Evaluations per start at most")->capture_default_str();
    cmd->add_option("--stride", o->stride, "Bins per stratum of the direction pairs along theta_h, theta_d, phi_d")->capture_default_str();
    cmd->add_flag("--quiet", o->quiet, "No progress line");
    cmd->callback([o] { run_fit(*o); });
}

}  // namespace lab::cli
