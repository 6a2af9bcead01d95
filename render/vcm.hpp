// Vertex merging's radius (`--integrator vcm`, kernels/vcm.h, docs/bdpt.md): r_0 from --merge-radius
// or the scene's size, and the radius of each sample index, which shrinks so the estimate converges
// (Hachisuka and Jensen 2009's progressive radius, as in Georgiev et al. 2012): r_i = r_0 (i + 1)^((alpha - 1) / 2).
// Both renderers set their samples' radii from here.
#pragma once

#include <cstddef>

#include "kernels/host.hpp"
#include "render/render_settings.hpp"

namespace lab::render {

// alpha of the radius's shrinking: the share of the previous radius's area a sample keeps, in the
// limit (Knaus and Zwicker 2011); 0.75 as Georgiev et al. use.
constexpr float kMergeRadiusAlpha = 0.75f;
// r_0 without --merge-radius: this fraction of the scene's bounding radius (CompiledScene::bounds_radius).
constexpr float kMergeRadiusOfScene = 0.01f;

// r_0: --merge-radius when given (settings.bdpt.merge_radius > 0), else the scene's share.
float vcm_base_radius(const RenderSettings& settings, float scene_radius);
// Sample index `sample`'s radius from launch_settings->bdpt.merge_radius0, and its merging count
// N_L pi r^2 (merge_samples), into launch_settings.
void set_vcm_sample_radius(const RenderSettings& settings, int sample, kernel::RenderKernelSettings* launch_settings);
// The hash grid's buckets (kernels/hash_grid.h): one per cache slot.
size_t vcm_grid_buckets(const RenderSettings& settings);
// Throws lab::InputError naming --merge-radius unless r is a finite length > 0.
void check_merge_radius(float r);
// check_merge_radius of settings.bdpt.merge_radius unless it is 0 (the scene's share).
void check_vcm_settings(const RenderSettings& settings);

}  // namespace lab::render
