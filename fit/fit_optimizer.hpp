// Fitting the lab model to a measured table: NLopt's BOBYQA (Powell's bounded quadratic-model
// search, derivative-free) from several starting points, the best kept. The starts are the centre
// of the parameter box and then a Halton sequence over it, so repeated runs give the same answer,
// and the starts that reach the best error tell whether it is the basin's floor or a local minimum
// reached once (docs/fitting.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "fit/fit_pairs.hpp"
#include "fit/fit_space.hpp"

namespace lab::fit {

struct FitOptions {
    int starts = 8;
    int max_evaluations = 3000;          // per start
    double relative_tolerance = 1e-7;    // BOBYQA stops when the parameters move less than this
};

// The ranges a user may ask for (starts in [1, 1000], evaluations per start in [10, 1000000]):
// throws InputError("command line", FIELD, ...) naming the option that is out of range, so every
// command that fits checks them before reading its input.
void check_fit_options(const FitOptions& options, const std::string& starts_field, const std::string& evaluations_field);

struct FitStart {
    std::vector<double> x;  // where it ended
    double error;
    int evaluations;
};

struct FitResult {
    brdf::Material material;
    std::vector<double> x;
    double error = 0.0;
    std::vector<FitStart> starts;
    int evaluations = 0;
    int pairs = 0;
    double seconds = 0.0;
};

// Called after each objective evaluation: the start (0-based), the evaluations of this start, the
// current error and the best error so far over every start.
using FitProgress = std::function<void(int start, int evaluations, double error, double best)>;

// Throws std::invalid_argument for options out of range or no pairs, std::runtime_error when
// NLopt fails (not for reaching the evaluation limit, which ends a start normally).
FitResult fit_material(const std::vector<FitPair>& pairs, const FitSpace& space, const FitOptions& options,
                       const FitProgress& progress = {});

}  // namespace lab::fit
