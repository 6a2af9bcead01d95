#include "interchange/export_material.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "common/input_error.hpp"
#include "interchange/fit_to_openpbr.hpp"

namespace interchange {

std::string fit_report_path(const std::string& output) {
    const std::filesystem::path p(output);
    return (p.parent_path() / (p.stem().string() + ".fit.json")).string();
}

Notes export_material(const brdf::Preset& preset, Format format, const std::string& path, const lab::fit::FitOptions& options) {
    Notes notes;
    if (preset.material.model == BRDF_MODEL_OPENPBR) {
        write_material(preset, format, path, &notes);
        return notes;
    }
    const OpenpbrFit fit = fit_to_openpbr(preset, options, lab::fit::PairGrid{3, 3, 10, 1});
    const std::string report = fit_report_path(path);
    std::ofstream out(report);
    if (!(out << fit.report.dump(2) << "\n")) throw lab::InputError(report, "", "cannot write the fit's report");
    char error[32];
    std::snprintf(error, sizeof error, "%.4g", fit.error);
    notes.add("model", "a \"" + fit.report.at("fitted_from").get<std::string>() + "\" material, fitted to openpbr: error " + error +
                           " (cosine-weighted log-space RMSE), report in " + report);
    write_material(fit.preset, format, path, &notes);
    return notes;
}

}  // namespace interchange
