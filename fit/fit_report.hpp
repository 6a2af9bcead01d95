// The fit's report: the fitted parameters, the error in total, per channel and per band of incident
// angle, and every start's end point, so a reader can see whether the starts agree.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "fit/fit_metric.hpp"
#include "fit/fit_optimizer.hpp"
#include "fit/fit_space.hpp"

namespace lab::fit {

// Starts that ended within 1 % or 1e-4 of the best error: the ones that found the same floor (the
// absolute margin counts starts that all reached a perfect fit of noise-free data).
int starts_at_best(const FitResult& result);

nlohmann::json fit_report(const std::string& measured_path, const FitSpace& space, const FitResult& result,
                          const ErrorBreakdown& breakdown);

// The lobe names of a space, comma-separated as --lobes takes them.
std::string lobes_text(const FitSpace& space);

}  // namespace lab::fit
