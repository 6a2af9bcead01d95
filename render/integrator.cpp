#include "render/integrator.hpp"

#include <array>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/input_error.hpp"
#include "kernels/host.hpp"
#include "render/option_words.hpp"

namespace lab::render {

namespace {

// The integrators, in the order the command line lists them.
constexpr IntegratorDescriptor kIntegrators[] = {
    {Integrator::pt, "pt", "path tracing with next-event estimation and MIS", "the path tracer", "kernels/path_tracer.cl", "render_pt",
     0, true, nullptr},
    {Integrator::bdpt, "bdpt", "bidirectional, every strategy", "bidirectional path tracing", "kernels/bdpt.cl", "render_bdpt",
     STRATEGY_ALL, false, nullptr},
    // lt is bdpt's kernel with a strategy mask, not a kernel of its own. The lens is never hit from
    // infinity, and light subpaths from the environment start on a disk of finite radius, which an
    // endless surface outruns (docs/bdpt.md): t = 1 alone misses both.
    {Integrator::lt, "lt", "light tracing", "the light tracer", "kernels/bdpt.cl", "render_bdpt", STRATEGY_T1, false,
     "lt cannot render an environment light (light tracing never reaches the lens from infinity, nor an endless surface "
     "beyond the environment's light disk): use --integrator bdpt or pt"},
    // bdpt's strategies and weights, its light subpaths traced once per sample index for all pixels
    {Integrator::bdpt_cache, "bdpt-cache", "bidirectional, light subpaths shared by all pixels through a light-vertex cache",
     "bidirectional path tracing with a light-vertex cache", "kernels/bdpt.cl", "render_bdpt_cache", STRATEGY_ALL, false, nullptr, true},
    // bdpt-cache's estimator and vertex merging, with MIS over both (Georgiev et al. 2012)
    {Integrator::vcm, "vcm", "vertex connection and merging: bdpt-cache, its light vertices also merged within a shrinking radius",
     "vertex connection and merging", "kernels/bdpt.cl", "render_bdpt_cache", STRATEGY_ALL, false, nullptr, true, true},
};
constexpr size_t kIntegratorCount = std::size(kIntegrators);

// The command line's words, from the table.
const std::array<std::pair<const char*, Integrator>, kIntegratorCount>& integrator_words() {
    static const auto words = [] {
        std::array<std::pair<const char*, Integrator>, kIntegratorCount> w;
        for (size_t i = 0; i < kIntegratorCount; ++i) w[i] = {kIntegrators[i].name, kIntegrators[i].integrator};
        return w;
    }();
    return words;
}

// "a, b or c"
std::string listed(const std::vector<std::string>& items) {
    std::string text;
    for (size_t i = 0; i < items.size(); ++i) text += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
    return text;
}

}  // namespace

bool IntegratorDescriptor::splats() const { return (strategies & STRATEGY_T1) != 0; }

bool IntegratorDescriptor::sees_emissive_materials() const { return strategies == 0 || (strategies & STRATEGY_S0) != 0; }

const IntegratorDescriptor& integrator_descriptor(Integrator integrator) {
    for (const IntegratorDescriptor& d : kIntegrators)
        if (d.integrator == integrator) return d;
    throw std::invalid_argument("integrator_descriptor: an integrator outside the table");
}

Integrator parse_integrator(const std::string& text, const std::string& option) { return parse_word(text, option, integrator_words()); }
const char* integrator_name(Integrator integrator) { return word_of(integrator, integrator_words()); }

std::string integrator_names() {
    std::string names;
    for (const IntegratorDescriptor& d : kIntegrators) names += std::string(names.empty() ? "" : ", ") + d.name;
    return names;
}

std::string integrator_help() {
    std::vector<std::string> items;
    for (const IntegratorDescriptor& d : kIntegrators) items.push_back(std::string(d.name) + " (" + d.description + ")");
    return listed(items);
}

bool integrator_runs_strategy(Integrator integrator, int s, int t) {
    return kernel::bdpt_strategy_enabled(integrator_descriptor(integrator).strategies, s, t);
}

void check_integrator_has_strategies(Integrator integrator, const std::string& option) {
    const IntegratorDescriptor& d = integrator_descriptor(integrator);
    if (d.bidirectional()) return;
    std::vector<std::string> names;
    for (const IntegratorDescriptor& other : kIntegrators)
        if (other.bidirectional()) names.push_back(other.name);
    throw InputError(option, "", "needs --integrator " + listed(names) + " (" + d.noun + " has no (s, t) strategies)");
}

void check_integrator_lights(Integrator integrator, const std::string& file, bool has_lights, bool has_environment) {
    const IntegratorDescriptor& d = integrator_descriptor(integrator);
    if (d.bidirectional() && !has_lights)
        throw InputError(file, "--integrator",
                         std::string(d.name) + " starts its light subpaths on the lights, and the scene has none (no emissive sphere, " +
                             (d.sees_emissive_materials() ? "point light, environment or emissive material" : "point light or environment") +
                             "): add one, or give --env");
    if (!d.renders_environment() && has_environment) throw InputError(file, "--integrator", d.environment_refusal);
}

}  // namespace lab::render
