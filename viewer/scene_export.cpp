#include "viewer/scene_export.hpp"

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "common/read_text_file.hpp"
#include "film/atomic_file.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_limits.hpp"
#include "viewer/json_members.hpp"

namespace lab::viewer {

namespace {

using Json = nlohmann::ordered_json;

// One line, with a space after each colon and comma: {"albedo": [0.5, 0.5, 0.5]}.
std::string one_line(const Json& j) {
    std::string out;
    if (j.is_object()) {
        for (const auto& [k, v] : j.items()) out += (out.empty() ? "{" : ", ") + Json(k).dump() + ": " + one_line(v);
        return out.empty() ? "{}" : out + "}";
    }
    if (j.is_array()) {
        for (const Json& v : j) out += (out.empty() ? "[" : ", ") + one_line(v);
        return out.empty() ? "[]" : out + "]";
    }
    return j.dump();
}

// The value as the file writes its neighbours: over several lines indented two spaces from the
// member's own line (as nlohmann's dump(2), the bundled scenes' style), or on one line.
std::string formatted(const Json& value, const std::optional<std::string>& indent, bool several_lines) {
    if (!several_lines || !indent) return one_line(value);
    std::string out;
    for (char c : value.dump(2)) out += c == '\n' ? "\n" + *indent : std::string(1, c);
    return out;
}

// The scene text with the material put in place, every other byte as it was; none where the text
// is not laid out as expected (the caller then rewrites the whole file).
std::optional<std::string> edited_in_place(const std::string& text, const std::string& name, const Json& material) {
    const std::optional<JsonObjectSpan> top = json_object_at(text, 0);
    if (!top) return std::nullopt;
    const JsonMember* materials = nullptr;
    for (const JsonMember& m : top->members)
        if (m.key == "materials") materials = &m;
    // A member after the last one of `object` (or first in an empty one), indented like its siblings.
    auto added = [&](const JsonObjectSpan& object, const std::string& key, const Json& value) -> std::optional<std::string> {
        const std::string member_key = Json(key).dump() + ": ";
        if (object.members.empty()) {
            const std::optional<std::string> outer = json_line_indent(text, object.open);
            const std::string inner = outer ? *outer + "  " : "";
            const bool lines = outer.has_value() && text.find('\n') != std::string::npos;
            const std::string member = lines ? "\n" + inner + member_key + formatted(value, inner, true) + "\n" + *outer
                                             : member_key + one_line(value);
            std::string out = text;
            return out.replace(object.open + 1, object.close - object.open - 1, member);
        }
        const JsonMember& last = object.members.back();
        const std::optional<std::string> indent = json_line_indent(text, last.key_begin);
        const bool lines = text.substr(last.value_begin, last.value_end - last.value_begin).find('\n') != std::string::npos;
        const std::string member =
            indent ? ",\n" + *indent + member_key + formatted(value, indent, lines || value.is_object()) : ", " + member_key + one_line(value);
        std::string out = text;
        return out.insert(last.value_end, member);
    };
    if (!materials) return added(*top, "materials", Json::object({{name, material}}));
    const std::optional<JsonObjectSpan> table = json_object_at(text, materials->value_begin);
    if (!table) return std::nullopt;
    for (const JsonMember& m : table->members)
        if (m.key == name) {
            const bool lines = text.substr(m.value_begin, m.value_end - m.value_begin).find('\n') != std::string::npos;
            std::string out = text;
            return out.replace(m.value_begin, m.value_end - m.value_begin, formatted(material, json_line_indent(text, m.key_begin), lines));
        }
    return added(*table, name, material);
}

}  // namespace

void parse_export_target(const std::string& text, std::string* scene_file, std::string* material_name) {
    size_t colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
        throw InputError("--export-to", "", "expected SCENE.json:NAME or a material file FILE.mtlx|.gltf|.xml|.pbrt, got \"" + text + "\"");
    *scene_file = text.substr(0, colon);
    *material_name = text.substr(colon + 1);
}

void export_to_scene(const brdf::Preset& preset, const std::string& scene_file, const std::string& material_name) {
    std::string text = read_text_file(scene_file, scene::kMaxSceneFileBytes, "scene");
    Json doc;
    try {
        doc = Json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(scene_file, "", std::string("malformed JSON: ") + e.what());
    }
    if (!doc.is_object()) throw InputError(scene_file, "", "expected a JSON object");
    if (doc.contains("materials") && !doc["materials"].is_object()) throw InputError(scene_file, "materials", "expected an object");
    brdf::Preset named = preset;
    named.name = material_name;
    const Json material = Json::parse(brdf::preset_to_json(named).dump());
    Json expected = doc;
    expected["materials"][material_name] = material;
    // Only the material's own span changes when the edit reads back as the whole document with the
    // material set (same keys, same order, same values); otherwise the whole file is rewritten.
    std::string out;
    const std::optional<std::string> edited = edited_in_place(text, material_name, material);
    try {
        if (edited && Json::parse(*edited) == expected) out = *edited;
    } catch (const nlohmann::json::exception&) {
    }
    if (out.empty()) out = expected.dump(2) + "\n";
    scene::parse_scene(out, scene_file);  // refuses what `dtoadq render` would refuse, before writing
    film::write_file_atomically(scene_file, out.data(), out.size());
}

}  // namespace lab::viewer
