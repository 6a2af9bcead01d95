#include "scene/load_scene.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>

#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "common/read_text_file.hpp"
#include "ibl/frame_source.hpp"
#include "scene/json_fields.hpp"
#include "scene/parse_node.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_time.hpp"

namespace lab::scene {
namespace {

namespace fs = std::filesystem;

// A path from the scene file, taken relative to the scene file's folder unless absolute.
std::string resolve(const std::string& scene_file, const std::string& relative) {
    fs::path p(relative);
    if (p.is_absolute()) return p.lexically_normal().string();
    return (fs::path(scene_file).parent_path() / p).lexically_normal().string();
}

// The camera's keyframes: every field of the camera a shot animates (the type stays).
std::vector<TrackSpec> camera_tracks(CameraType type) {
    const float big = std::numeric_limits<float>::max(), inf = std::numeric_limits<float>::infinity();
    std::vector<TrackSpec> specs = {{"position", 3, -big, big}, {"look_at", 3, -big, big}, {"up", 3, -big, big}, {"fov_degrees", 1, 0.0f, 180.0f, true}};
    if (type == CameraType::thin_lens) specs.insert(specs.end(), {{"aperture_radius", 1, 0.0f, inf, true}, {"focus_distance", 1, 0.0f, inf, true}});
    return specs;
}

Camera parse_camera(const Json& value, const std::string& file) {
    const std::string path = "camera";
    if (!value.is_object()) throw InputError(file, path, std::string("expected an object, got ") + value.type_name());
    // The type decides which keys are allowed, so it is checked first.
    if (!value.contains("type")) throw InputError(file, "camera.type", "missing required key");
    const Json& type = value.at("type");
    if (!type.is_string()) throw InputError(file, "camera.type", std::string("expected a string, got ") + type.type_name());
    Camera camera;
    std::vector<std::string> keys = {"type", "position", "look_at", "up", "fov_degrees", "keyframes"};
    if (type == "thin_lens") {
        camera.type = CameraType::thin_lens;
        keys.insert(keys.end(), {"aperture_radius", "focus_distance"});
    } else if (type != "pinhole") {
        throw InputError(file, "camera.type", "unknown camera type \"" + type.get<std::string>() + "\" (expected one of: pinhole, thin_lens)");
    }
    Fields f(value, path, file, keys);
    if (f.has("keyframes")) camera.keyframes = parse_keyframes(f.at("keyframes"), f.path_of("keyframes"), file, camera_tracks(camera.type));
    // each field is either still (here) or keyframed, and a required one is one of the two
    auto keyframed = [&](const std::string& key) {
        if (!camera.keyframes || !camera.keyframes->find(key)) return false;
        if (f.has(key)) f.fail(key, "is keyframed too (camera.keyframes." + key + "): give it in one place");
        return true;
    };
    if (!keyframed("position")) camera.position = f.vec3("position");
    if (!keyframed("look_at")) camera.look_at = f.vec3("look_at");
    if (!keyframed("up") && f.has("up")) camera.up = f.nonzero_vec3("up");
    if (!keyframed("fov_degrees") && f.has("fov_degrees")) camera.fov_degrees = f.in_open_range("fov_degrees", 0.0f, 180.0f);
    if (camera.type == CameraType::thin_lens) {
        if (!keyframed("aperture_radius")) camera.aperture_radius = f.positive("aperture_radius");
        if (!keyframed("focus_distance")) camera.focus_distance = f.positive("focus_distance");
    }
    if (!camera.keyframes) {
        if (auto problem = camera_problem(camera)) f.fail(problem->first, problem->second);
    } else {
        Scene still;
        still.file = file;
        still.camera = camera;
        for (float t : camera.keyframes->times) scene_at_time(still, double(t));  // each keyframe a camera
    }
    return camera;
}

// An inline preset goes through the preset parser; its messages "SOURCE: FIELD: problem" become
// "SCENE: materials.NAME.FIELD: problem".
brdf::Material parse_inline_preset(const Json& value, const std::string& file, const std::string& path) {
    const std::string source = file + ": " + path;
    try {
        return brdf::parse_preset(nlohmann::json(value), source, fs::path(file).parent_path().string()).material;
    } catch (const InputError& e) {
        std::string message = e.what();
        const std::string prefix = source + ": ";
        if (message.rfind(prefix, 0) != 0) throw;
        throw InputError(file, "", path + "." + message.substr(prefix.size()));
    }
}

MaterialSlot parse_material(const std::string& name, const Json& value, const std::string& file, const std::string& path) {
    if (name.empty()) throw InputError(file, path, "a material name must not be empty");
    MaterialSlot slot;
    slot.name = name;
    if (value.is_string()) {
        std::string relative = value.get<std::string>();
        std::string resolved = resolve(file, relative);
        std::error_code ec;
        if (relative.empty() || !fs::is_regular_file(resolved, ec))
            throw InputError(file, path, "preset file \"" + relative + "\" not found (looked for " + resolved + ")");
        slot.source = resolved;
        slot.material = brdf::load_preset(resolved).material;
    } else if (value.is_object()) {
        slot.source = "inline";
        slot.material = parse_inline_preset(value, file, path);
    } else {
        throw InputError(file, path,
                         std::string("expected a preset file path (string) or an inline preset (object), got ") + value.type_name());
    }
    return slot;
}

std::vector<MaterialSlot> parse_materials(const Json& value, const std::string& file) {
    if (!value.is_object()) throw InputError(file, "materials", std::string("expected an object, got ") + value.type_name());
    std::vector<MaterialSlot> slots;
    for (auto it = value.begin(); it != value.end(); ++it)
        slots.push_back(parse_material(it.key(), it.value(), file, field_path("materials", it.key())));
    return slots;
}

std::vector<Object> parse_objects(const Json& value, const std::string& file, const std::vector<MaterialSlot>& materials) {
    if (!value.is_array()) throw InputError(file, "objects", std::string("expected an array, got ") + value.type_name());
    std::vector<Object> objects;
    std::map<std::string, size_t> first_index;
    for (size_t i = 0; i < value.size(); ++i) {
        std::string path = element_path("objects", i);
        Fields f(value[i], path, file, {"name", "material", "shape", "shadow_catcher"});
        Object object;
        object.name = f.string("name");
        if (object.name.empty()) f.fail("name", "an object name must not be empty");
        auto [previous, fresh] = first_index.emplace(object.name, i);
        if (!fresh)
            f.fail("name", "duplicate object name \"" + object.name + "\" (also objects[" + std::to_string(previous->second) + "])");
        std::string material = f.string("material");
        object.material = -1;
        for (size_t m = 0; m < materials.size(); ++m)
            if (materials[m].name == material) object.material = int(m);
        if (object.material < 0) f.fail("material", "material \"" + material + "\" is not declared in \"materials\"");
        object.shape = parse_node(f.at("shape"), f.path_of("shape"), file);
        if (f.has("shadow_catcher")) {
            if (!f.at("shadow_catcher").is_boolean())
                f.fail("shadow_catcher", std::string("expected true or false, got ") + f.at("shadow_catcher").type_name());
            object.shadow_catcher = f.at("shadow_catcher").get<bool>();
        }
        objects.push_back(std::move(object));
    }
    // A catcher's slot tells the kernels what its surface is, so no other object may share it.
    for (size_t i = 0; i < objects.size(); ++i)
        for (size_t j = 0; j < objects.size(); ++j)
            if (objects[i].shadow_catcher && !objects[j].shadow_catcher && objects[i].material == objects[j].material)
                throw InputError(file, element_path("objects", i) + ".material",
                                 "a shadow catcher needs a material of its own, and \"" + materials[size_t(objects[i].material)].name +
                                     "\" is also " + element_path("objects", j) + "'s, which is no catcher");
    return objects;
}

// An emitter's slot: the declared material it names (a reflecting emitter), or a black
// material (every lobe weight 0, docs/materials.md), with its radiance.
MaterialSlot emitter_slot(const std::string& path, int index, const Emitter& e, const std::vector<MaterialSlot>& slots) {
    MaterialSlot slot;
    slot.name = path;
    slot.source = "emitter";
    slot.material = brdf::default_material();
    for (float& a : slot.material.albedo) a = 0.0f;
    slot.material.weight_diffuse = slot.material.weight_glossy = slot.material.weight_specular = slot.material.weight_transmission = 0.0f;
    for (const MaterialSlot& m : slots)
        if (m.emitter < 0 && m.name == e.surface_material) slot.material = m.material;
    slot.emission = e.radiance;
    slot.emitter = index;
    return slot;
}

// A rect's or disk's "radiance": required, unless it shows an "image", whose texels it then scales
// (1 when left out).
Vec3 area_radiance(const Fields& f) {
    if (f.has("image") && !f.has("radiance")) return Vec3(1.0f);
    return f.non_negative_vec3("radiance");
}

// "emitters": emissive spheres (type "sphere", the default), rects and disks (area lights that emit
// on one side) and point lights (type "point").
void parse_emitters(const Json& value, const std::string& file, Scene* scene) {
    if (!value.is_array()) throw InputError(file, "emitters", std::string("expected an array, got ") + value.type_name());
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string path = element_path("emitters", i);
        std::string type = "sphere";
        if (value[i].is_object() && value[i].contains("type")) {
            const Json& t = value[i].at("type");
            if (!t.is_string()) throw InputError(file, field_path(path, "type"), std::string("expected a string, got ") + t.type_name());
            type = t.get<std::string>();
        }
        if ((type == "point" || type == "sphere") && value[i].is_object() && value[i].contains("image"))
            throw InputError(file, field_path(path, "image"), "only rect and disk emitters show an image, not a " + type);
        if (type == "point") {
            Fields f(value[i], path, file, {"type", "position", "intensity"});
            scene->point_lights.push_back(PointLight{f.vec3("position"), f.non_negative_vec3("intensity")});
            continue;
        }
        Emitter e;
        if (type == "sphere") {
            Fields f(value[i], path, file, {"type", "center", "radius", "radiance", "material"});
            e = Emitter{f.vec3("center"), f.positive("radius"), f.non_negative_vec3("radiance"), int(scene->materials.size()), ""};
        } else if (type == "rect") {
            Fields f(value[i], path, file, {"type", "center", "edge_u", "edge_v", "radiance", "image", "fps", "material"});
            e = Emitter{f.vec3("center"), 0.0f, area_radiance(f), int(scene->materials.size()), ""};
            e.shape = EmitterShape::rect;
            e.edge_u = f.nonzero_vec3("edge_u");
            e.edge_v = f.nonzero_vec3("edge_v");
            const Vec3 n = glm::cross(e.edge_u, e.edge_v);
            // parallel edges span no area: |U x V| against |U| |V|, the sine of their angle
            if (!(glm::length(n) > 1e-6f * glm::length(e.edge_u) * glm::length(e.edge_v)))
                f.fail("edge_v", "parallel to edge_u: the rect has no area");
            e.normal = glm::normalize(n);
        } else if (type == "disk") {
            Fields f(value[i], path, file, {"type", "center", "normal", "radius", "radiance", "image", "fps", "material"});
            e = Emitter{f.vec3("center"), f.positive("radius"), area_radiance(f), int(scene->materials.size()), ""};
            e.shape = EmitterShape::disk;
            e.normal = glm::normalize(f.nonzero_vec3("normal"));
            const brdf::ShadingFrame frame = brdf::frame_from_normal(e.normal);
            e.edge_u = frame.t * e.radius;
            e.edge_v = frame.b * e.radius;
        } else {
            throw InputError(file, field_path(path, "type"), "unknown emitter type \"" + type + "\" (expected one of: sphere, rect, disk, point)");
        }
        Fields f(value[i], path, file, {"type", "center", "radius", "edge_u", "edge_v", "normal", "radiance", "image", "fps", "material"});
        if (f.has("image")) {
            const std::string relative = f.string("image");
            if (relative.empty()) f.fail("image", "must not be empty");
            e.image = resolve(file, relative);
            e.image_field = field_path(path, "image");
            e.image_fps_field = field_path(path, "fps");
            if (f.has("fps")) e.image_fps = f.number("fps");
            ibl::frame_source(e.image, e.image_fps, file, e.image_field, e.image_fps_field);  // a sequence has its fps, nothing else one
        } else if (f.has("fps")) {
            f.fail("fps", "only an emitter that shows an image sequence (\"image\": \"screen_%04d.exr\") takes a frame rate");
        }
        if (f.has("material")) {
            e.surface_material = f.string("material");
            const bool declared = std::any_of(scene->materials.begin(), scene->materials.end(), [&](const MaterialSlot& m) {
                return m.emitter < 0 && m.name == e.surface_material;
            });
            if (!declared) f.fail("material", "material \"" + e.surface_material + "\" is not declared in \"materials\"");
            // an emitter's radiance is its "radiance": an emissive material on it would be a second one
            for (const MaterialSlot& m : scene->materials)
                if (m.emitter < 0 && m.name == e.surface_material && brdf::material_emits(&m.material))
                    f.fail("material", "material \"" + e.surface_material + "\" emits (emission_luminance): an emitter's radiance is its \"radiance\"");
        }
        scene->materials.push_back(emitter_slot(path, int(scene->emitters.size()), e, scene->materials));
        scene->emitters.push_back(e);
    }
}

size_t count_nodes(const Node& node) {
    size_t n = 1;
    for (const Node& child : node.children) n += count_nodes(child);
    return n;
}

void check_shape_node_count(const std::vector<Object>& objects, const std::string& file) {
    size_t nodes = 0;
    for (const Object& object : objects) nodes += count_nodes(object.shape);
    if (nodes > kMaxShapeNodes)
        throw InputError(file, "objects", std::to_string(nodes) + " shape nodes, more than the " + std::to_string(kMaxShapeNodes) +
                                              " a scene may hold");
}

EnvironmentSpec parse_environment(const Json& value, const std::string& file) {
    Fields f(value, "environment", file,
             {"file", "constant", "rotation_degrees", "exposure", "background_opacity", "background_blur_degrees", "keyframes"});
    EnvironmentSpec env;
    if (f.has("file") == f.has("constant"))
        throw InputError(file, "environment", "give exactly one of \"file\" (an image) and \"constant\" (a radiance)");
    if (f.has("file")) {
        std::string relative = f.string("file");
        if (relative.empty()) f.fail("file", "must not be empty");
        env.file = resolve(file, relative);
    } else {
        env.constant = f.non_negative_vec3("constant");
    }
    if (f.has("rotation_degrees")) env.rotation_degrees = f.in_range("rotation_degrees", -360.0f, 360.0f);
    if (f.has("keyframes")) {
        // turns over time may add up to many: the command line's --env-rotation range
        env.keyframes = parse_keyframes(f.at("keyframes"), f.path_of("keyframes"), file, {{"rotation_degrees", 1, -36000.0f, 36000.0f}});
        if (f.has("rotation_degrees")) f.fail("rotation_degrees", "is keyframed too (environment.keyframes.rotation_degrees): give it in one place");
    }
    if (f.has("exposure")) env.exposure = f.in_range("exposure", -20.0f, 20.0f);
    if (f.has("background_opacity")) env.background_opacity = f.in_range("background_opacity", 0.0f, 1.0f);
    if (f.has("background_blur_degrees")) env.background_blur_degrees = f.in_range("background_blur_degrees", 0.0f, 90.0f);
    return env;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file) {
    Json doc = parse_json_document(text, file);
    Fields top(doc, "", file, {"$schema", "description", "camera", "materials", "objects", "emitters", "environment"});
    Scene scene;
    scene.file = file;
    if (top.has("$schema")) top.string("$schema");
    if (top.has("description")) scene.description = top.string("description");
    scene.camera = parse_camera(top.at("camera"), file);
    if (top.has("materials")) scene.materials = parse_materials(top.at("materials"), file);
    if (top.has("objects")) scene.objects = parse_objects(top.at("objects"), file, scene.materials);
    check_shape_node_count(scene.objects, file);
    if (top.has("emitters")) parse_emitters(top.at("emitters"), file, &scene);
    if (top.has("environment")) scene.environment = parse_environment(top.at("environment"), file);
    if (scene.objects.empty() && scene.emitters.empty())
        throw InputError(file, "", "the scene has no objects and no emitters (point lights are not geometry)");
    return scene;
}

Scene load_scene(const std::string& path) { return parse_scene(read_text_file(path, kMaxSceneFileBytes, "scene"), path); }

}  // namespace lab::scene
