// The scene compiler: a Scene becomes OpenCL C source (the virtual files "scene/generated.h" and
// "scene/materials.h") that defines the scene's distance field with only the sdf/ headers it uses,
// plus what the renderer needs beside it (material slots, emitters, camera, environment, the
// Lipschitz bound).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "scene/compile_options.hpp"
#include "scene/scene.hpp"

namespace lab::scene {

struct CompiledScene {
    std::string file;                            // the scene file, for messages
    // scene/generated.h, the geometry: defines SCENE_LIPSCHITZ, SCENE_EMITTER_COUNT, and
    // scene_distance / scene_distance_material / scene_analytic_normal.
    std::string source;
    // scene/materials.h: SCENE_MATERIAL_COUNT and the BRDF_FEATURE_ switches of its materials.
    // A kernel that shades includes it before any brdf/ header (the switches must come first); one
    // that only marches leaves it out, and so is the same program whatever the materials.
    std::string material_source;
    std::vector<brdf::Material> materials;       // per slot: declared materials, then one per emitter
    std::vector<std::string> material_names;     // per slot
    std::vector<Vec3> emission;                  // per slot: an emitter's radiance, else 0
    std::vector<bool> shadow_catcher;            // per slot: a shadow catcher's (Object::shadow_catcher)
    std::vector<Emitter> emitters;         // spheres, rects and disks; emitters[k].material is its slot
    std::vector<PointLight> point_lights;        // lights only: not in the source
    // A sphere that holds the camera, the lights and every bounded part of the objects (the axes
    // along which an object is unbounded, a plane or an endless repetition, are left out) and, in a
    // scene with such an endless part, the cube around the camera out to its look-at distance: the
    // scene's size for the environment's power (docs/lights.md) and the disk its light subpaths
    // start on (docs/bdpt.md).
    Vec3 bounds_center{0.0f};
    float bounds_radius = 0.0f;
    // A box that holds every surface the march looks for, the boxes (scene/lipschitz.hpp) of the
    // objects and emitters not intersected exactly, -inf / inf along what is unbounded: rays that
    // leave it stop marching (sdf/march_lanes.h).
    // All of space when the object bounds are off.
    Vec3 surface_lo{-std::numeric_limits<float>::infinity()};
    Vec3 surface_hi{std::numeric_limits<float>::infinity()};
    float lipschitz = 1.0f;                      // SCENE_LIPSCHITZ
    bool is_distance_bound = true;               // false when a repetition breaks the bound
    std::vector<std::string> warnings;           // for the command line to print
    std::vector<std::string> geometry_paths;     // which objects are intersected exactly (scene/geometry_paths.hpp)
    Camera camera;
    std::optional<EnvironmentSpec> environment;
};

CompiledScene compile_scene(const Scene& scene, const CompileOptions& options = {});

}  // namespace lab::scene
