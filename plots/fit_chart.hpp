// The fit's chart: measured against fitted lobes in the plane of incidence at several incident
// angles (the lobe plot's slice, analysis/lobe_data.hpp, with the measured curve from merl_eval), and
// the fit's error over (theta_h, theta_d), drawn by the embedded fit_chart.py.
#pragma once

#include <string>
#include <vector>

#include "brdf/host/merl_file.hpp"
#include "brdf/host/preset.hpp"

namespace lab::plots {

struct FitChartData {
    std::vector<float> theta_in_deg = {0.0f, 30.0f, 60.0f, 75.0f};
    float plane_step_deg = 0.5f;
    // fit::ErrorMap::error: MERL_THETA_H_BINS rows x MERL_THETA_D_BINS columns, NaN below the horizon
    std::vector<double> error_map;
    double error = 0.0;  // the fit's total, for the title
};

// Throws lab::InputError naming png_path when it cannot be written, std::runtime_error when no
// Python with matplotlib is found or the script fails.
void write_fit_chart(const brdf::MeasuredTable& table, const brdf::Preset& fitted, const FitChartData& data, const std::string& png_path);

}  // namespace lab::plots
