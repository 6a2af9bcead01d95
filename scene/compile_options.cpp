#include "scene/compile_options.hpp"

#include <algorithm>

#include "common/input_error.hpp"

namespace lab::scene {
namespace {

std::string list_names(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

}  // namespace

Scene apply_options(const Scene& scene, const CompileOptions& options) {
    Scene out = scene;
    std::vector<std::string> declared, objects;
    for (const MaterialSlot& slot : scene.materials)
        if (slot.source != "emitter") declared.push_back(slot.name);
    for (const Object& o : scene.objects) objects.push_back(o.name);
    for (const auto& [name, material] : options.material_overrides) {
        auto it = std::find_if(out.materials.begin(), out.materials.end(),
                               [&](const MaterialSlot& s) { return s.name == name && s.source != "emitter"; });
        if (it == out.materials.end())
            throw InputError(scene.file, "materials", "no material named \"" + name + "\" to replace (declared: " + list_names(declared) + ")");
        it->material = material;
        it->source = "override";
        // a reflecting emitter scatters with the declared material it names: it follows the override
        for (MaterialSlot& slot : out.materials)
            if (slot.emitter >= 0 && out.emitters[size_t(slot.emitter)].surface_material == name) slot.material = material;
    }
    for (const std::string& name : options.disabled_objects) {
        auto it = std::find_if(out.objects.begin(), out.objects.end(), [&](const Object& o) { return o.name == name; });
        if (it == out.objects.end())
            throw InputError(scene.file, "objects", "no object named \"" + name + "\" to disable (objects: " + list_names(objects) + ")");
        out.objects.erase(it);
    }
    out.march_everything = options.march_everything;
    if (out.objects.empty() && out.emitters.empty())
        throw InputError(scene.file, "objects", "nothing is left to render once the disabled objects are left out");
    return out;
}

}  // namespace lab::scene
