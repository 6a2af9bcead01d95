#include "scene/compile.hpp"

#include "scene/generated_source.hpp"
#include "scene/geometry_paths.hpp"
#include "scene/lipschitz.hpp"
#include "scene/scene_bounds.hpp"

namespace lab::scene {

CompiledScene compile_scene(const Scene& input, const CompileOptions& options) {
    Scene scene = apply_options(input, options);
    SceneAnalysis analysis = analyse_scene(scene);
    CompiledScene out;
    out.file = scene.file;
    for (const MaterialSlot& slot : scene.materials) {
        out.materials.push_back(slot.material);
        out.material_names.push_back(slot.name);
        out.emission.push_back(slot.emission);
    }
    out.shadow_catcher.assign(out.materials.size(), false);
    for (const Object& object : scene.objects)
        if (object.shadow_catcher) out.shadow_catcher[size_t(object.material)] = true;
    out.emitters = scene.emitters;
    out.point_lights = scene.point_lights;
    scene_bounds(scene, &out.bounds_center, &out.bounds_radius);
    if (options.object_bounds) surface_box(scene, analysis, &out.surface_lo, &out.surface_hi);
    out.lipschitz = analysis.lipschitz;
    out.is_distance_bound = analysis.is_distance_bound;
    out.warnings = analysis.warnings;
    out.geometry_paths = geometry_paths(scene);
    out.camera = scene.camera;
    out.environment = scene.environment;
    out.source = generate_source(scene, analysis, options.object_bounds);
    out.material_source = generate_material_source(scene, out.materials);
    return out;
}

}  // namespace lab::scene
