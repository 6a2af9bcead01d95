// The settings every renderer takes (image size, path depth, how lights are found, the march and
// the normals, the seed) and the words the command line gives them; with them, the parts only some
// readers take: the bidirectional integrators' (render/bdpt_settings.hpp) and the OpenCL
// renderer's tuning (render/opencl_tuning.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "render/bdpt_settings.hpp"
#include "render/integrator.hpp"
#include "render/opencl_tuning.hpp"

namespace lab::render {

// How paths find lights (kernels/render_settings.h): BSDF sampling alone, light sampling (next-event
// estimation) alone, or both by multiple importance sampling.
enum class LightSampling { bsdf, lights, mis };
enum class NormalMethod { tetrahedral, central, analytic };

// Parse the command-line words; errors are lab::InputError naming `option`.
MisHeuristic parse_mis_heuristic(const std::string& text, const std::string& option = "--mis");
NormalMethod parse_normal_method(const std::string& text, const std::string& option = "--normals");
// "bsdf" (or "brdf"), "lights" (or "env", the preview's word) and "mis".
LightSampling parse_light_sampling(const std::string& text, const std::string& option);
const char* mis_heuristic_name(MisHeuristic heuristic);
const char* light_sampling_name(LightSampling sampling);
const char* normal_method_name(NormalMethod method);

// The largest image side a renderer takes (and the command line accepts).
constexpr int kMaxImageSide = 16384;

struct RenderSettings {
    int width = 512, height = 512;
    Integrator integrator = Integrator::pt;
    int max_depth = 16;      // scattering events per path, for every integrator (bdpt_max_vertices)
    int roulette_depth = 3;  // Russian roulette from this many events on
    LightSampling light_sampling = LightSampling::mis;
    NormalMethod normals = NormalMethod::tetrahedral;
    float normal_step = 5e-4f;     // finite-difference step, scene units
    // Keinert et al.'s over-relaxed sphere tracing with its step back (sdf/march.h): 10-20 % more
    // paths/s on the bundled scenes and the same image within noise (docs/render.md). Renderers
    // use 1 (plain) on a scene whose field is not a distance bound.
    float over_relaxation = 1.5f;
    int max_steps = 1024;
    float max_distance = 100.0f;
    // What escaping camera rays see of the environment (kernels/background.h); lighting unchanged.
    float background_opacity = 1.0f;       // in [0, 1]; 0 hides the backdrop (the EXR's alpha says where)
    float background_blur_degrees = 0.0f;  // in [0, 90]; 0 sharp, else ibl::blur_cubemap's sigma
    bool object_bounds = true;     // box tests skip far objects (scene::CompileOptions; the field is unchanged)
    bool march_everything = false; // --geometry march: no exact intersection (scene::CompileOptions)
    uint64_t seed = 0;
    BdptSettings bdpt;                     // bdpt, lt
    StrategyDebugSettings strategy_debug;  // bdpt, lt
    OpenClTuning opencl;                   // the OpenCL renderer only
};

// The most scattering events a bidirectional path (bdpt, lt) may have: its host build's private
// vertex arrays hold kBdptMaxDepth + 2 vertices (BDPT_VERTEX_LIMIT, kernels/render_settings.h).
constexpr int kBdptMaxDepth = 62;

// bdpt, lt: the most vertices of a path, s + t: the lens, max_depth scattering events and the light,
// so that every integrator estimates the same image at the same max_depth.
inline int bdpt_max_vertices(const RenderSettings& settings) { return settings.max_depth + 2; }

// Throws lab::InputError naming the option for a size, depth, step count or over-relaxation out of
// range. Renderers call it too; callers call it first to fail before any loading.
void check_render_settings(const RenderSettings& settings);

// "WxH" with both in [1, kMaxImageSide]; `option` names the flag in errors.
void parse_image_size(const std::string& text, const std::string& option, int* width, int* height);

}  // namespace lab::render
