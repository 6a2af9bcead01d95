// A lab, dtoadq2017 or measured material carried to the openpbr model, which every interchange
// format speaks, by fitting (fit/): openpbr's base colour, specular roughness, metalness and
// dielectric index (and its anisotropy where the material has one) chosen by the fit's multi-start
// search to minimise the fit's error (fit/fit_metric.hpp) against the material's BRDF on the
// stratified direction pairs of MERL's grid (fit/fit_pairs.hpp): a measured table's entries, or the
// lab material evaluated at the pairs (turned about the normal too when it is anisotropic). The
// Hyper-Cauchy distribution, which no format has, becomes the GGX lobe nearest to it in that error.
// docs/interchange.md.
#pragma once

#include <nlohmann/json.hpp>

#include "fit/fit_optimizer.hpp"
#include "fit/fit_pairs.hpp"
#include "interchange/openpbr_mapping.hpp"

namespace interchange {

struct OpenpbrFit {
    brdf::Preset preset;    // the openpbr material, named and described as the input
    nlohmann::json report;  // fit/fit_report.hpp's report, with "model": "openpbr" and the input
    double error = 0.0;     // the fit's error, cosine-weighted log-space RMSE
};

// Throws lab::InputError naming the preset for a material a reflectance table cannot hold (a
// delta or transmission lobe) and for an openpbr one (nothing to fit).
OpenpbrFit fit_to_openpbr(const brdf::Preset& preset, const lab::fit::FitOptions& options, const lab::fit::PairGrid& grid);

}  // namespace interchange
