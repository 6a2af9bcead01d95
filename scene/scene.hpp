// A parsed scene file (format: docs/scenes.md): camera, materials, objects built from SDF nodes,
// emissive spheres and an optional environment. Everything here has been validated; the compiler
// (scene/compile.hpp) and the host interpreter (scene/interpreter.hpp) take it as it is.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "brdf/brdf.hpp"
#include "scene/keyframes.hpp"
#include "single_source/host_vocabulary.hpp"

namespace lab::scene {

using Vec3 = single_source::float3;

// Primitives (sdf/primitives/); each sits at the origin of its local frame, axis y where it has one.
struct Sphere { float radius; };
struct Plane { Vec3 normal; float offset; };  // normal unit (normalised by the parser)
struct Box { Vec3 half_size; };
struct RoundBox { Vec3 half_size; float radius; };  // half_size is the outer extent
struct Torus { float major_radius; float minor_radius; };
struct Cylinder { float radius; float half_height; };
struct Capsule { float radius; float half_height; };
struct Cone { float radius; float height; };  // base disk at y = 0, apex at y = height

// Transforms of one child. A rotation is stored as its matrix (world from local): the child is
// evaluated at rotation^T p.
struct Translate { Vec3 offset; };
struct Rotate { glm::mat3 rotation; };
struct Scale { float factor; };

// Combinators of two or more children, folded from the left: op(op(c0, c1), c2)...
// `radius` is the blend radius of the smooth / round / chamfer variants (unused by the plain ones).
enum class Combinator {
    union_,
    intersection,
    subtraction,  // the first child minus each of the others
    smooth_union,
    round_union,
    round_intersection,
    round_subtraction,
    chamfer_union,
    chamfer_intersection,
    chamfer_subtraction,
};
struct Combine { Combinator op; float radius; };

// Domain repetition of one child: cells centred on multiples of the period.
struct Repeat { Vec3 period; };
struct RepeatLimited { Vec3 period; Vec3 count_min; Vec3 count_max; };  // integer cell indices

// The child's distance plus amplitude sin(f x) sin(f y) sin(f z).
struct Displace { float amplitude; float frequency; };

using NodeKind = std::variant<Sphere, Plane, Box, RoundBox, Torus, Cylinder, Capsule, Cone, Translate, Rotate, Scale, Combine,
                              Repeat, RepeatLimited, Displace>;

struct Node {
    NodeKind kind;
    std::string path;            // JSON path in the scene file, e.g. "objects[2].shape.children[0]"
    std::vector<Node> children;  // one for transforms, repetition and displacement; >= 2 for combinators
};

struct Object {
    std::string name;
    int material = 0;  // material slot
    Node shape;
    // A shadow catcher (docs/environments.md, "Shadow catcher"): seen by the camera it shows the
    // backdrop behind it with what the other objects change of its light; its slot is its own.
    bool shadow_catcher = false;
};

// An emitter: a light that is geometry, with a material slot of its own.
//   sphere: centre and radius, part of the distance field (intersected exactly unless the scene is
//           marched, `--geometry march`); it emits the same radiance from both sides of its surface.
//   rect:   the parallelogram center +- edge_u / 2 +- edge_v / 2, emitting on the side of
//           edge_u x edge_v only;
//   disk:   centre, unit normal and radius, emitting on the side of its normal only.
// Rects and disks have no volume: they are always intersected exactly, never marched. With a
// surface material an emitter also scatters (a reflecting emitter), on both sides; without one its
// slot is black. docs/lights.md gives their sampling, docs/scenes.md their fields.
enum class EmitterShape { sphere, rect, disk };

struct Emitter {
    Vec3 center;
    float radius;       // sphere, disk; 0 for a rect
    Vec3 radiance;      // linear RGB, W / (m^2 sr)
    int material = 0;   // its slot, after the declared materials
    std::string surface_material;  // the declared material its slot copies; empty: a black emitter
    EmitterShape shape = EmitterShape::sphere;
    Vec3 edge_u{0.0f};  // rect: its two edges; disk: an orthonormal tangent pair times the radius
    Vec3 edge_v{0.0f};  //   (so that a point is center + x edge_u + y edge_v, x^2 + y^2 <= 1)
    Vec3 normal{0.0f};  // rect, disk: unit, the emitting side
    // rect, disk: the image it shows (its path, resolved against the scene file; empty: none), whose
    // texels `radiance` then scales (docs/scenes.md, kernels/lights/image_emitter.h)
    std::string image{};
    std::string image_field{};  // "emitters[i].image", the field an error in the image names
    // a sequence's frames per second, when `image` is a pattern (screen_%04d.exr): docs/scenes.md, "Time"
    std::optional<double> image_fps{};
    std::string image_fps_field{};  // "emitters[i].fps"
};

// A point light: a light, not geometry (nothing hits it, it casts no shadow).
struct PointLight {
    Vec3 position;
    Vec3 intensity;  // linear RGB, W / sr
};

enum class CameraType { pinhole, thin_lens };

struct Camera {
    CameraType type = CameraType::pinhole;
    Vec3 position{0.0f};
    Vec3 look_at{0.0f, 0.0f, -1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 40.0f;    // vertical field of view
    float aperture_radius = 0.0f; // thin lens only
    float focus_distance = 0.0f;  // thin lens only
    // The fields that change with the scene time (scene/scene_time.hpp); a field keyframed here
    // takes no static value above.
    std::optional<Keyframes> keyframes;
};

struct EnvironmentSpec {
    std::string file;                 // resolved against the scene file's folder; empty for a constant
    Vec3 constant{0.0f};              // radiance when `file` is empty
    float rotation_degrees = 0.0f;    // about +y
    float exposure = 0.0f;            // stops
    // What camera rays that escape see of it (render::RenderSettings; the command line's
    // --background-opacity and --background-blur replace them); the lighting is unchanged.
    float background_opacity = 1.0f;       // [0, 1]
    float background_blur_degrees = 0.0f;  // [0, 90]
    std::optional<Keyframes> keyframes;    // rotation_degrees over the scene time (scene/scene_time.hpp)
};

// A material slot: declared materials first (in file order), then one per emissive sphere, then
// the look-dev references' when they are added (scene/look_dev_references.hpp).
struct MaterialSlot {
    std::string name;        // the declared name, or "emitters[k]"
    std::string source;      // the preset file it came from, or "inline" / "emitter"
    brdf::Material material;
    Vec3 emission{0.0f};     // radiance of an emitter's slot, 0 otherwise
    int emitter = -1;        // the emitter (index into Scene::emitters) of this slot, -1 for none
};

struct Scene {
    std::string file;    // the scene file as given, for messages
    std::string description;
    Camera camera;
    std::vector<MaterialSlot> materials;
    std::vector<Object> objects;
    std::vector<Emitter> emitters;  // spheres, rects and disks, in file order
    std::vector<PointLight> point_lights;
    std::optional<EnvironmentSpec> environment;
    // Sphere-trace every object and emitter, the plain primitives too (`--geometry march`, set by
    // apply_options); otherwise they are intersected exactly (scene/geometry_paths.hpp).
    bool march_everything = false;
};

// Whether the scene has a light of its own (an emitter, a point light or an environment): the
// benches and tests light one that has none with envmaps/courtyard.exr, as the commands do.
inline bool has_own_light(const Scene& scene) {
    return !scene.emitters.empty() || !scene.point_lights.empty() || scene.environment.has_value();
}

}  // namespace lab::scene
