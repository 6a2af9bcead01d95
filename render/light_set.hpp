// The lights of a compiled scene as the kernels see them (kernels/lights/light.h), with the cdf that
// chooses one per next-event estimate. docs/lights.md gives every power formula.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ibl/environment.hpp"
#include "kernels/host.hpp"
#include "scene/compile.hpp"

namespace lab::render {

// How a light is chosen: in proportion to its power (the default), or uniformly.
enum class LightSelection { power, uniform };

// "power" or "uniform"; lab::InputError naming `option` otherwise.
LightSelection parse_light_selection(const std::string& text, const std::string& option = "--light-selection");
const char* light_selection_name(LightSelection selection);

struct LightSet {
    // The environment first (index 0) when there is one, then the emitters (spheres, rects, disks)
    // in file order, then the point lights in file order.
    std::vector<kernel::Light> lights;
    // lights.size() + 1 entries for kernels/lights/light_selection.h: 0, ..., 1 (empty without lights).
    std::vector<float> selection_cdf;
    // Per material slot: the index in `lights` of the emitter with that slot, -1 otherwise.
    std::vector<int> light_of_slot;
    // Per light: its power as luminance, W (docs/lights.md), whatever the selection.
    std::vector<double> power;
};

// Power of each kind of light, in luminance (lab::luminance of the RGB radiometric quantity).
double sphere_light_power(const kernel::Light& light);   // pi Le 4 pi r^2: the flux leaving its outside
double area_light_power(const kernel::Light& light);     // pi Le A: a rect or disk, one side
// An image emitter's: pi A times the luminance of its scale (`emission`) times the image's mean RGB.
double image_light_power(const kernel::Light& light, const std::array<double, 3>& image_mean_rgb);
double point_light_power(const kernel::Light& light);    // 4 pi I
// pi R^2 times the integral of L over the sphere: the flux through a disk of radius R facing each
// direction, R the radius of the sphere that holds the scene (CompiledScene::bounds_radius).
double environment_light_power(const ibl::Environment& environment, double scene_radius);

// environment: the scene's environment as loaded (null: none). image_means: per emitter of the scene,
// the mean RGB of the image it shows (render/emitter_images.hpp), or none; empty: no emitter shows one.
LightSet build_light_set(const scene::CompiledScene& scene, const ibl::Environment* environment, LightSelection selection,
                         const std::vector<std::optional<std::array<double, 3>>>& image_means = {});

// The kinds of its lights, a bit (1 << LIGHT_*) each, and 1 << LIGHT_IMAGE when an emitter shows an
// image (after bind_emitter_images): the OpenCL kernel's SCENE_LIGHT_TYPES
// (kernels/lights/light_selection.h), so that a scene's kernel samples only the kinds it has.
int light_type_mask(const LightSet& lights);

}  // namespace lab::render
