// Albedo charts as PNG: directional albedo against incident angle, per channel, one panel per
// material, drawn by the embedded albedo_chart.py with matplotlib.
#pragma once

#include <string>
#include <vector>

#include "analysis/albedo_curve.hpp"
#include "brdf/host/preset.hpp"

namespace lab::plots {

// csv_path may be empty; otherwise it gets one row per material and angle:
//   material,theta,a_r,a_g,a_b,se_r,se_g,se_b  (se: standard error of the estimate).
// Throws lab::InputError naming a path that cannot be written, std::runtime_error when no Python
// with matplotlib is found or the script fails.
void write_albedo_chart(const std::vector<brdf::Preset>& presets, const std::string& png_path, const std::string& csv_path,
                        const analysis::AlbedoCurveOptions& options = {});

// The same from curves already computed with `options` (analysis::albedo_curve), one per preset.
void write_albedo_chart(const std::vector<brdf::Preset>& presets, const std::vector<std::vector<analysis::AlbedoPoint>>& curves,
                        const std::string& png_path, const std::string& csv_path, const analysis::AlbedoCurveOptions& options);

}  // namespace lab::plots
