#include "fit/fit_optimizer.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <nlopt.h>

#include "common/input_error.hpp"
#include "fit/fit_metric.hpp"

namespace lab::fit {
namespace {

// The radical inverse of i in a prime base: the Halton sequence's coordinate.
double radical_inverse(int i, int base) {
    double inverse = 1.0 / base, scale = inverse, value = 0.0;
    for (; i > 0; i /= base, scale *= inverse) value += (i % base) * scale;
    return value;
}

std::vector<double> start_point(const std::vector<FitParameter>& parameters, int start) {
    static const int kPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47};
    std::vector<double> x;
    for (size_t d = 0; d < parameters.size(); ++d) {
        // start 0 is the box's centre; Halton index start keeps the later ones spread over the box
        const double u = start == 0 ? 0.5 : radical_inverse(start, kPrimes[d % 15]);
        x.push_back(parameters[d].min + u * (parameters[d].max - parameters[d].min));
    }
    return x;
}

struct Objective {
    const std::vector<FitPair>* pairs;
    const FitSpace* space;
    const FitProgress* progress;
    int start = 0;
    int evaluations = 0;
    double best = std::numeric_limits<double>::infinity();
};

double objective(unsigned n, const double* x, double*, void* data) {
    Objective& o = *static_cast<Objective*>(data);
    const brdf::Material m = material_from_parameters(*o.space, std::vector<double>(x, x + n));
    double e = fit_error(m, *o.pairs);
    if (!std::isfinite(e)) e = 1e15;  // keeps BOBYQA's model defined; never the answer
    ++o.evaluations;
    if (e < o.best) o.best = e;
    if (*o.progress) (*o.progress)(o.start, o.evaluations, e, o.best);
    // BOBYQA minimises E^2: the same minimiser, but smooth there (E itself is a cone at a perfect
    // fit), which its quadratic models need to converge
    return e * e;
}

}  // namespace

void check_fit_options(const FitOptions& options, const std::string& starts_field, const std::string& evaluations_field) {
    if (options.starts < 1 || options.starts > 1000)
        throw InputError("command line", starts_field, "must be in [1, 1000], got " + std::to_string(options.starts));
    if (options.max_evaluations < 10 || options.max_evaluations > 1000000)
        throw InputError("command line", evaluations_field, "must be in [10, 1000000], got " + std::to_string(options.max_evaluations));
}

FitResult fit_material(const std::vector<FitPair>& pairs, const FitSpace& space, const FitOptions& options,
                       const FitProgress& progress) {
    if (options.starts < 1) throw std::invalid_argument("fit: at least one start is needed");
    if (options.max_evaluations < 10) throw std::invalid_argument("fit: at least 10 evaluations per start are needed");
    if (pairs.empty()) throw std::invalid_argument("fit: no direction pairs above the horizon");
    const auto clock_start = std::chrono::steady_clock::now();
    const std::vector<FitParameter> parameters = fit_parameters(space);
    const unsigned n = unsigned(parameters.size());
    std::vector<double> lower, upper, step;
    for (const FitParameter& p : parameters) {
        lower.push_back(p.min);
        upper.push_back(p.max);
        step.push_back(0.1 * (p.max - p.min));
    }

    FitResult result;
    result.pairs = int(pairs.size());
    result.error = std::numeric_limits<double>::infinity();
    Objective o{&pairs, &space, &progress};
    for (int s = 0; s < options.starts; ++s) {
        nlopt_opt opt = nlopt_create(NLOPT_LN_BOBYQA, n);
        if (!opt) throw std::runtime_error("fit: NLopt could not create the optimiser");
        nlopt_set_lower_bounds(opt, lower.data());
        nlopt_set_upper_bounds(opt, upper.data());
        nlopt_set_initial_step(opt, step.data());
        nlopt_set_min_objective(opt, objective, &o);
        nlopt_set_xtol_rel(opt, options.relative_tolerance);
        nlopt_set_maxeval(opt, options.max_evaluations);
        // E below 1e-6 is a perfect fit (float rounding of the model is about that); no measurement gets near it
        nlopt_set_stopval(opt, 1e-12);
        o.start = s;
        o.evaluations = 0;
        std::vector<double> x = start_point(parameters, s);
        double squared = 0.0;
        const nlopt_result status = nlopt_optimize(opt, x.data(), &squared);
        const double error = std::sqrt(squared);
        nlopt_destroy(opt);
        if (status < 0 && status != NLOPT_ROUNDOFF_LIMITED)
            throw std::runtime_error("fit: NLopt failed (status " + std::to_string(int(status)) + ") in start " + std::to_string(s + 1));
        result.starts.push_back({x, error, o.evaluations});
        result.evaluations += o.evaluations;
        if (error < result.error) {
            result.error = error;
            result.x = x;
        }
    }
    result.material = material_from_parameters(space, result.x);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    return result;
}

}  // namespace lab::fit
