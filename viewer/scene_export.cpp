#include "viewer/scene_export.hpp"

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "common/read_text_file.hpp"
#include "film/atomic_file.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_limits.hpp"

namespace lab::viewer {

void parse_export_target(const std::string& text, std::string* scene_file, std::string* material_name) {
    size_t colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
        throw InputError("--export-to", "", "expected SCENE.json:NAME, got \"" + text + "\"");
    *scene_file = text.substr(0, colon);
    *material_name = text.substr(colon + 1);
}

void export_to_scene(const brdf::Preset& preset, const std::string& scene_file, const std::string& material_name) {
    std::string text = read_text_file(scene_file, scene::kMaxSceneFileBytes, "scene");
    // ordered_json keeps the file's key order, so only the material's own lines change.
    nlohmann::ordered_json doc;
    try {
        doc = nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(scene_file, "", std::string("malformed JSON: ") + e.what());
    }
    if (!doc.is_object()) throw InputError(scene_file, "", "expected a JSON object");
    if (doc.contains("materials") && !doc["materials"].is_object()) throw InputError(scene_file, "materials", "expected an object");
    brdf::Preset named = preset;
    named.name = material_name;
    doc["materials"][material_name] = nlohmann::ordered_json::parse(brdf::preset_to_json(named).dump());
    std::string out = doc.dump(2) + "\n";
    scene::parse_scene(out, scene_file);  // refuses what `dtoadq render` would refuse, before writing
    film::write_file_atomically(scene_file, out.data(), out.size());
}

}  // namespace lab::viewer
