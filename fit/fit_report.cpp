#include "fit/fit_report.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "brdf/host/parameters.hpp"

namespace lab::fit {
namespace {

nlohmann::json named(const std::vector<FitParameter>& parameters, const std::vector<double>& x) {
    nlohmann::json j = nlohmann::json::object();
    for (size_t i = 0; i < parameters.size() && i < x.size(); ++i) j[parameters[i].name] = x[i];
    return j;
}

// JSON has no NaN: a band without pairs gets null.
nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

}  // namespace

int starts_at_best(const FitResult& result) {
    int n = 0;
    for (const FitStart& s : result.starts)
        if (s.error <= std::fmax(1.01 * result.error, result.error + 1e-4)) ++n;
    return n;
}

std::string lobes_text(const FitSpace& s) {
    std::string text;
    auto add = [&](bool on, const char* name) {
        if (on) text += (text.empty() ? "" : ",") + std::string(name);
    };
    add(s.diffuse, "diffuse");
    add(s.glossy, "glossy");
    add(s.retroreflection, "retroreflection");
    add(s.subsurface, "subsurface");
    return text;
}

nlohmann::json fit_report(const std::string& measured_path, const FitSpace& space, const FitResult& result,
                          const ErrorBreakdown& breakdown) {
    const std::vector<FitParameter> parameters = fit_parameters(space);
    nlohmann::json j;
    j["measured"] = measured_path;
    j["metric"] = "cosine-weighted log-space RMSE: sqrt(mean over pairs and channels of (ln(1 + cos_i f_fit) - ln(1 + cos_i f_measured))^2)";
    j["distribution"] = brdf::distribution_name(space.distribution);
    j["anisotropic"] = space.anisotropic;
    j["lobes"] = lobes_text(space);
    j["pairs"] = result.pairs;
    j["parameters"] = named(parameters, result.x);
    nlohmann::json bounds = nlohmann::json::object();
    for (const FitParameter& p : parameters) bounds[p.name] = {p.min, p.max};
    j["bounds"] = bounds;
    nlohmann::json error;
    error["total"] = breakdown.total;
    error["channel"] = {{"r", breakdown.channel[0]}, {"g", breakdown.channel[1]}, {"b", breakdown.channel[2]}};
    nlohmann::json bands = nlohmann::json::array();
    for (const IncidenceBand& b : breakdown.incidence)
        bands.push_back({{"theta_i_min_deg", b.theta_min_deg}, {"theta_i_max_deg", b.theta_max_deg}, {"pairs", b.pairs},
                         {"error", number_or_null(b.error)}});
    error["incidence"] = bands;
    j["error"] = error;
    nlohmann::json starts = nlohmann::json::array();
    for (const FitStart& s : result.starts)
        starts.push_back({{"error", s.error}, {"evaluations", s.evaluations}, {"parameters", named(parameters, s.x)}});
    j["starts"] = starts;
    j["starts_at_best"] = starts_at_best(result);
    j["evaluations"] = result.evaluations;
    j["seconds"] = result.seconds;
    return j;
}

}  // namespace lab::fit
