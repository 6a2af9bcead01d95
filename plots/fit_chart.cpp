#include "plots/fit_chart.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/child_process.hpp"
#include "analysis/lobe_data.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

namespace fs = std::filesystem;

void write_fit_chart(const brdf::MeasuredTable& table, const brdf::Preset& fitted, const FitChartData& data, const std::string& png_path) {
    if (data.error_map.size() != std::size_t(MERL_THETA_H_BINS) * MERL_THETA_D_BINS)
        throw std::invalid_argument("fit chart: the error map has the wrong size");
    require_writable(png_path, "--chart");
    TempFolder folder("plot");
    {
        std::ofstream lobes = open_output((folder.path() / "lobes.csv").string(), "");
        lobes << "theta_in_deg,angle_deg,measured,fitted\n";
        const brdf::Material& m = fitted.material;
        for (float theta_in : data.theta_in_deg) {
            const std::vector<analysis::PlaneSample> measured = analysis::plane_slice(
                [&table](brdf::float3 wi, brdf::float3 wo) { return brdf::merl_eval(table.rgb.data(), wo, wi); }, theta_in, 0.0f,
                data.plane_step_deg, false);
            const std::vector<analysis::PlaneSample> model = analysis::plane_slice(
                [&m](brdf::float3 wi, brdf::float3 wo) { return brdf::bsdf_eval(&m, wi, wo); }, theta_in, 0.0f, data.plane_step_deg, false);
            for (size_t k = 0; k < measured.size(); ++k)
                lobes << csv_number(theta_in) << "," << csv_number(measured[k].angle_deg) << "," << csv_number(measured[k].value) << ","
                      << csv_number(model[k].value) << "\n";
        }
        std::ofstream map = open_output((folder.path() / "error_map.csv").string(), "");
        map << "theta_h_deg,theta_d_deg,error\n";
        for (int ih = 0; ih < MERL_THETA_H_BINS; ++ih)
            for (int id = 0; id < MERL_THETA_D_BINS; ++id) {
                const brdf::HalfDiffAngles a = brdf::merl_bin_center(ih, id, 0);
                map << csv_number(a.theta_h * 180.0 / M_PI) << "," << csv_number(a.theta_d * 180.0 / M_PI) << ","
                    << csv_number(data.error_map[std::size_t(ih) * MERL_THETA_D_BINS + id]) << "\n";
            }
        if (!lobes.flush() || !map.flush()) throw std::runtime_error("cannot write plot data in " + folder.path().string());
    }
    const fs::path png = folder.path() / "fit.png";
    run_plot_script("fit_chart.py",
                    {"--data", folder.path().string(), "--out", png.string(), "--measured", table.source, "--fitted", fitted.name,
                     "--error", csv_number(data.error)},
                    folder.path());
    install_output(png, png_path, "--chart");
}

}  // namespace lab::plots
