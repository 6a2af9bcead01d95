#include "scene/look_dev_references.hpp"

#include <cctype>
#include <cmath>

#include "brdf/host/parameters.hpp"
#include "common/input_error.hpp"
#include "film/tone_map.hpp"
#include "scene/shadow_catcher.hpp"

namespace lab::scene {

const std::array<ColorCheckerPatch, 24> kColorCheckerPatches = {{
    {"dark skin", {115, 82, 68}},     {"light skin", {194, 150, 130}},   {"blue sky", {98, 122, 157}},
    {"foliage", {87, 108, 67}},       {"blue flower", {133, 128, 177}},  {"bluish green", {103, 189, 170}},
    {"orange", {214, 126, 44}},       {"purplish blue", {80, 91, 166}},  {"moderate red", {193, 90, 99}},
    {"purple", {94, 60, 108}},        {"yellow green", {157, 188, 64}},  {"orange yellow", {224, 163, 46}},
    {"blue", {56, 61, 150}},          {"green", {70, 148, 73}},          {"red", {175, 54, 60}},
    {"yellow", {231, 199, 31}},       {"magenta", {187, 86, 149}},       {"cyan", {8, 133, 161}},
    {"white 9.5", {243, 243, 242}},   {"neutral 8", {200, 200, 200}},    {"neutral 6.5", {160, 160, 160}},
    {"neutral 5", {122, 122, 121}},   {"neutral 3.5", {85, 85, 85}},     {"black 2", {52, 52, 52}},
}};

LookDevReferences parse_look_dev_references(const std::string& text, const std::string& option) {
    LookDevReferences r;
    if (text == "none") return r;
    if (text == "all") return LookDevReferences{true, true, true, false};
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = text.find(',', start);
        const std::string word = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (word == "chrome")
            r.chrome_ball = true;
        else if (word == "grey")
            r.grey_ball = true;
        else if (word == "chart")
            r.color_chart = true;
        else if (word == "catcher")
            r.shadow_catcher = true;
        else
            throw InputError(option, "", "unknown reference \"" + word + "\" (none, all, or a list of chrome, grey, chart, catcher)");
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return r;
}

std::string look_dev_references_text(const LookDevReferences& r) {
    std::string words;
    for (const auto& [on, word] : {std::pair{r.chrome_ball, "chrome"}, {r.grey_ball, "grey"}, {r.color_chart, "chart"}, {r.shadow_catcher, "catcher"}})
        if (on) words += (words.empty() ? "" : ",") + std::string(word);
    return words.empty() ? "none" : words;
}

namespace {

// "neutral 6.5" -> "neutral_6_5"
std::string identifier(const std::string& name) {
    std::string out;
    for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return out;
}

brdf::Material lambert(float r, float g, float b) {
    brdf::Material m = brdf::default_material();
    m.albedo[0] = r;
    m.albedo[1] = g;
    m.albedo[2] = b;
    m.weight_diffuse = 1.0f;
    m.weight_glossy = m.weight_specular = m.weight_transmission = 0.0f;
    return m;
}

brdf::Material chrome() {
    brdf::Material m = brdf::default_material();
    for (int c = 0; c < 3; ++c) m.albedo[c] = kChromeF0[c];
    m.metallic = 1.0f;
    m.roughness = 0.0f;
    m.weight_specular = 1.0f;  // a mirror: the environment's reflection, sharp
    m.weight_diffuse = m.weight_glossy = m.weight_transmission = 0.0f;
    return m;
}

Node leaf(NodeKind kind, const std::string& path) { return Node{std::move(kind), path, {}}; }
Node with_child(NodeKind kind, const std::string& path, Node child) { return Node{std::move(kind), path, {std::move(child)}}; }

// The camera's frame and the view's half extents at distance d: where a point at (x, y) of the
// view (-1..1 across each half extent) lies.
struct ViewPlane {
    Vec3 origin, forward, right, up;
    float half_width, half_height;
    Vec3 at(float x_units, float y_units) const { return origin + right * x_units + up * y_units; }
};

ViewPlane view_plane(const Camera& c, float aspect) {
    ViewPlane v;
    const Vec3 to_subject = c.look_at - c.position;
    const float distance = 0.7f * glm::length(to_subject);
    v.forward = glm::normalize(to_subject);
    v.right = glm::normalize(glm::cross(v.forward, c.up));
    v.up = glm::cross(v.right, v.forward);
    v.half_height = distance * std::tan(0.5f * c.fov_degrees * 3.14159265f / 180.0f);
    v.half_width = v.half_height * aspect;
    v.origin = c.position + v.forward * distance;
    return v;
}

}  // namespace

Scene with_look_dev_references(const Scene& scene, const LookDevReferences& which, float aspect) {
    Scene out = which.shadow_catcher ? with_shadow_catcher(scene) : scene;
    if (!which.any()) return out;
    const ViewPlane v = view_plane(scene.camera, aspect);
    const float h = v.half_height;
    std::vector<MaterialSlot> slots;
    std::vector<Object> objects;
    // Their slots go last, so every slot of the scene keeps its index (the viewer edits them by index).
    const size_t first = out.materials.size();
    auto add = [&](const std::string& name, const brdf::Material& material, Node shape) {
        slots.push_back(MaterialSlot{name, "reference", material, Vec3(0.0f), -1});
        objects.push_back(Object{name, int(first + slots.size() - 1), std::move(shape)});
    };
    // The balls in the lower right corner, the chrome one outermost; radius 0.14 of the half height.
    const float radius = 0.14f * h;
    if (which.chrome_ball)
        add("reference_chrome", chrome(),
            with_child(Translate{v.at(v.half_width - 0.18f * h, -0.72f * h)}, "references.chrome.translate",
                       leaf(Sphere{radius}, "references.chrome")));
    if (which.grey_ball)
        add("reference_grey", lambert(kGreyBallAlbedo, kGreyBallAlbedo, kGreyBallAlbedo),
            with_child(Translate{v.at(v.half_width - 0.54f * h, -0.72f * h)}, "references.grey.translate",
                       leaf(Sphere{radius}, "references.grey")));
    // The chart in the lower left corner, facing the camera: 6 x 4 patches at a pitch of 0.1 of the
    // half height, each a thin box with a gap around it.
    if (which.color_chart) {
        const glm::mat3 facing(v.right, v.up, -v.forward);  // world from the chart's frame (z towards the camera)
        const float pitch = 0.1f * h;
        const Vec3 centre = v.at(-v.half_width + 0.38f * h, -0.72f * h);
        for (size_t i = 0; i < kColorCheckerPatches.size(); ++i) {
            const ColorCheckerPatch& p = kColorCheckerPatches[i];
            const float col = float(i % 6) - 2.5f, row = 1.5f - float(i / 6);
            const std::string name = "reference_chart_" + identifier(p.name);
            const std::string path = "references.chart[" + std::to_string(i) + "]";
            Node box = leaf(Box{Vec3(0.425f * pitch, 0.425f * pitch, 0.05f * pitch)}, path);
            add(name,
                lambert(film::srgb_decode(p.srgb8[0] / 255.0f), film::srgb_decode(p.srgb8[1] / 255.0f), film::srgb_decode(p.srgb8[2] / 255.0f)),
                with_child(Translate{centre + v.right * (col * pitch) + v.up * (row * pitch)}, path + ".translate",
                           with_child(Rotate{facing}, path + ".rotate", std::move(box))));
        }
    }
    out.materials.insert(out.materials.end(), slots.begin(), slots.end());
    out.objects.insert(out.objects.end(), objects.begin(), objects.end());
    return out;
}

}  // namespace lab::scene
