// The integrators, described once, as pbrt-v4's Integrator::Create knows them: each one's name, its
// OpenCL program, the (s, t) strategies it adds up, what it splats and what it can render. Every
// place that depends on the integrator asks its descriptor, so a new integrator is one new entry
// of the table (render/integrator.cpp) and its kernels.
#pragma once

#include <string>

namespace lab::render {

// Which transport algorithm fills the film. `pt`: the path tracer with next-event estimation
// (kernels/path_tracer.h); `bdpt`: bidirectional path tracing, every strategy (kernels/bdpt.h);
// `lt`: light tracing, the same code with only its t = 1 strategies (docs/bdpt.md); `bdpt-cache`:
// every strategy, the light subpaths shared by all pixels in a light-vertex cache (kernels/bdpt_cache.h).
// `vcm`: bdpt-cache with its light vertices also merged with the camera vertices near them (kernels/vcm.h).
enum class Integrator { pt, bdpt, lt, bdpt_cache, vcm };

struct IntegratorDescriptor {
    Integrator integrator;
    const char* name;         // the command line's word (--integrator), and the metadata's
    const char* description;  // for the command line's help
    const char* noun;         // what the integrator is called in a sentence
    const char* program;      // the OpenCL program: its entry file, and the render kernel in it
    const char* kernel;
    // The (s, t) strategies it adds up, a STRATEGY_* mask of kernels/render_settings.h: s light-subpath
    // vertices joined to t camera-subpath vertices. 0: it has none (the path tracer's paths start at
    // the camera only).
    int strategies;
    // The path tracer's wavefront (render/wavefront_driver.hpp) renders it on a CPU device.
    bool wavefront;
    // Why it cannot render an environment light; nullptr: it can.
    const char* environment_refusal;
    // Its light subpaths are a pool per sample index that every pixel shares (kernels/bdpt_cache.h):
    // the program's light pass and offsets kernels run before `kernel`, the camera pass.
    bool light_cache = false;
    // With light_cache: a hash grid over each pool (the program's render_vcm_grid kernel) and camera
    // vertices merged with the light vertices near them (kernels/vcm.h, render/vcm.hpp).
    bool merges = false;

    // Subpaths from the lens and from the lights (kernels/bdpt.h): the lights start its light
    // subpaths, its vertex arrays bound the depth (kBdptMaxDepth), and it has an MIS heuristic.
    bool bidirectional() const { return strategies != 0; }
    bool renders_environment() const { return environment_refusal == nullptr; }
    // Its t = 1 strategies add to the pixel the lens sample reaches, on the splat film.
    bool splats() const;
    // Its paths from the camera can reach a material's emission, which no light subpath starts
    // from (the path tracer; bdpt's s = 0): the light tracer's cannot.
    bool sees_emissive_materials() const;
};

const IntegratorDescriptor& integrator_descriptor(Integrator integrator);

// Parse the command line's word; errors are lab::InputError naming `option`.
Integrator parse_integrator(const std::string& text, const std::string& option = "--integrator");
const char* integrator_name(Integrator integrator);
// "pt, bdpt, lt": every integrator's name.
std::string integrator_names();
// "pt (...), bdpt (...) or lt (...)": every integrator with its description, for the help.
std::string integrator_help();

// Whether `integrator` adds strategy (s, t) (kernels/bdpt_settings.h, bdpt_strategy_enabled).
bool integrator_runs_strategy(Integrator integrator, int s, int t);
// Throws lab::InputError naming `option` unless `integrator` has (s, t) strategies to show one by one.
void check_integrator_has_strategies(Integrator integrator, const std::string& option);
// Throws lab::InputError naming `file` and --integrator when `integrator` cannot render a scene
// with these lights, before anything is built or rendered, instead of coming out black.
// has_lights: lights, or emissive materials bdpt's s = 0 finds.
void check_integrator_lights(Integrator integrator, const std::string& file, bool has_lights, bool has_environment);

}  // namespace lab::render
