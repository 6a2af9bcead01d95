#include "scene/generated_source.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "brdf/host/features.hpp"
#include "scene/emitter_geometry.hpp"
#include "scene/geometry_paths.hpp"
#include "scene/json_fields.hpp"
#include "scene/nearest_writer.hpp"
#include "scene/object_functions.hpp"
#include "scene/source_literals.hpp"

namespace lab::scene {

namespace {

// The body of a nearest-object function (its name: `name`, and name_counted in a measurement build)
// over what `writer` wrote.
void write_nearest(std::ostringstream& out, const std::string& name, const NearestWriter& writer) {
    out << "#ifdef SCENE_COUNT_EVALUATIONS\n#define SCENE_COUNT_EVALUATION (*evaluations += 1u)\n"
        << "SS_FN float " << name << "_counted_xyz(float px, float py, float pz, int* nearest, uint* evaluations) {\n"
        << "#else\n#define SCENE_COUNT_EVALUATION ((void)0)\n"
        << "SS_FN float " << name << "_xyz(float px, float py, float pz, int* nearest) {\n#endif\n    int k = 0;\n    float d = INFINITY, e;\n";
    if (writer.box_tests()) out << "    float b; /* a box test */\n";
    out << writer.body() << "    *nearest = k;\n    return d;\n}\n#undef SCENE_COUNT_EVALUATION\n\n"
        << "#ifdef SCENE_COUNT_EVALUATIONS\n"
        << "SS_FN float " << name << "_xyz(float px, float py, float pz, int* nearest) {\n    uint n = 0u;\n"
        << "    return " << name << "_counted_xyz(px, py, pz, nearest, &n);\n}\n#endif\n\n";
}

// A measurement build's counting distance `distance`_counted over the nearest-object function
// `nearest` (write_nearest).
void write_counted_distance(std::ostringstream& out, const std::string& distance, const std::string& nearest) {
    out << "#ifdef SCENE_COUNT_EVALUATIONS\n"
        << "SS_FN float " << distance << "_counted(float3 p, uint* evaluations) {\n    int k;\n"
        << "    return " << nearest << "_counted_xyz(p.x, p.y, p.z, &k, evaluations);\n}\n#endif\n\n";
}

// The lane form of the exact hit of object `name` (scene_object_N_hit_lanes): the primitive's own
// (emit_exact_hit_lanes) where it has one, else the scalar name_hit lane by lane.
void write_exact_hit_lanes(std::ostringstream& out, const Node& shape, const std::string& name, std::set<std::string>* headers) {
    out << "SS_FN SDF_FLOAT " << name << "_hit_lanes(SDF_FLOAT ox, SDF_FLOAT oy, SDF_FLOAT oz, SDF_FLOAT vx, SDF_FLOAT vy, SDF_FLOAT vz, SDF_FLOAT t_max) {\n";
    if (has_exact_hit_lanes(shape)) {
        FunctionWriter w(headers);
        std::string hit = emit_exact_hit_lanes(shape, "o", "v", "t_max", &w);
        out << w.body() << "    return " << hit << ";\n}\n\n";
        return;
    }
    out << "    float r[7][8], t[8];\n"
        << "    vstore8(ox, 0, r[0]);\n    vstore8(oy, 0, r[1]);\n    vstore8(oz, 0, r[2]);\n"
        << "    vstore8(vx, 0, r[3]);\n    vstore8(vy, 0, r[4]);\n    vstore8(vz, 0, r[5]);\n    vstore8(t_max, 0, r[6]);\n"
        << "    for (int l = 0; l < 8; ++l)\n"
        << "        t[l] = " << name << "_hit(make_float3(r[0][l], r[1][l], r[2][l]), make_float3(r[3][l], r[4][l], r[5][l]), r[6][l]);\n"
        << "    return vload8(0, t);\n}\n\n";
}

// scene_exact_hit in one of its forms (`type` float, or SDF_FLOAT for the lanes): the nearest of the
// exact objects' `hits`, each call lowering t; INFINITY when the scene intersects nothing exactly
// (`any` false), its parameters unused.
void write_exact_hit(std::ostringstream& out, const std::string& type, const std::string& name,
                     const std::vector<std::pair<std::string, std::string>>& parameters, bool any, const std::string& hits) {
    out << "SS_FN " << type << " " << name << "(";
    for (size_t i = 0; i < parameters.size(); ++i) out << (i ? ", " : "") << parameters[i].first << " " << parameters[i].second;
    out << ") {\n";
    if (any) {
        out << "    " << type << " t = EXACT_MISS;\n" << hits << "    return t;\n}\n\n";
        return;
    }
    for (const auto& parameter : parameters) out << "    (void)" << parameter.second << ";\n";
    out << "    return INFINITY;\n}\n\n";
}

}  // namespace

std::string generate_source(const Scene& scene, const SceneAnalysis& analysis, bool object_bounds) {
    std::set<std::string> headers;
    std::ostringstream functions, exact_functions, exact_lane_functions, exact_lane_hits;
    std::ostringstream normals, slot_cases, normal_cases, exact_normal_cases, exact_hits;
    std::vector<bool> marched;
    size_t index = 0;
    for (const Object& object : scene.objects) {
        FunctionWriter w(&headers);
        std::string d = emit_distance(object.shape, "p", &w);
        std::string name = "scene_object_" + std::to_string(index);
        const bool exact = object_is_exact(scene, object);
        functions << "/* object \"" << object.name << "\" (" << object.shape.path << "), material slot " << object.material
                  << (exact ? ", intersected exactly" : ", sphere-traced") << " */\n"
                  << "SS_FN SDF_FLOAT " << name << "(SDF_FLOAT px, SDF_FLOAT py, SDF_FLOAT pz) {\n" << w.body() << "    return " << d << ";\n}\n\n";
        if (has_analytic_normal(object.shape)) {
            FunctionWriter wn(&headers);
            std::string n = emit_normal(object.shape, "p", &wn);
            normals << "SS_FN float3 " << name << "_normal(float3 p) {\n" << wn.body() << "    return " << n << ";\n}\n\n";
            normal_cases << "    case " << index << ": *n = " << name << "_normal(p); return 1;\n";
            if (exact) exact_normal_cases << "    case " << index << ": *n = " << name << "_normal(p); return 1;\n";
        }
        if (exact) {
            FunctionWriter wx(&headers);
            std::string hit = emit_exact_hit(object.shape, "o", "v", "t_max", &wx);
            exact_functions << "/* object \"" << object.name << "\" (" << object.shape.path << ") */\n"
                            << "SS_FN float " << name << "_hit(float3 o, float3 v, float t_max) {\n" << wx.body() << "    return " << hit << ";\n}\n\n";
            exact_hits << "    t = fmin(t, " << name << "_hit(o, v, fmin(t, t_max)));\n";
            write_exact_hit_lanes(exact_lane_functions, object.shape, name, &headers);
            exact_lane_hits << "    t = fmin(t, " << name << "_hit_lanes(ox, oy, oz, vx, vy, vz, fmin(t, t_max)));\n";
        }
        marched.push_back(!exact);
        slot_cases << "    case " << index << ": return " << object.material << ";\n";
        ++index;
    }
    const bool split = std::find(marched.begin(), marched.end(), false) != marched.end() ||
                       std::any_of(scene.emitters.begin(), scene.emitters.end(), [&](const Emitter& e) { return emitter_is_exact(scene, e); });
    NearestWriter nearest(scene, object_bounds, false, &headers);
    NearestWriter march(scene, object_bounds, false, &headers, marched), packet(scene, object_bounds, true, &headers, marched);
    for (size_t i = 0; i < scene.emitters.size(); ++i) {
        const Emitter& e = scene.emitters[i];
        const std::string k = std::to_string(index);
        const std::string local = "p - " + vec3_literal(e.center);
        const std::string origin = "o - " + vec3_literal(e.center);
        const std::string lane_origin = "ox - " + float_literal(e.center.x) + ", oy - " + float_literal(e.center.y) + ", oz - " + float_literal(e.center.z);
        std::string distance, normal, hit, lane_hit;
        if (e.shape == EmitterShape::sphere) {
            headers.insert("sdf/primitives/sphere.h");
            headers.insert("sdf/exact/sphere.h");
            distance = "fSphere_xyz(" + offset_components(e.center) + ", " + float_literal(e.radius) + ")";
            normal = "nSphere(" + local + ", " + float_literal(e.radius) + ")";
            hit = "xSphere(" + origin + ", v, " + float_literal(e.radius) + ", fmin(t, t_max))";
            lane_hit = "xSphere_lanes(" + lane_origin + ", vx, vy, vz, " + float_literal(e.radius) + ", fmin(t, t_max))";
        } else if (e.shape == EmitterShape::rect) {
            headers.insert("sdf/primitives/rect.h");
            headers.insert("sdf/exact/rect.h");
            const std::string n = vec3_literal(e.normal), du = vec3_literal(rect_dual_u(e)), dv = vec3_literal(rect_dual_v(e));
            distance = "fRect_xyz(" + offset_components(e.center) + ", " + vec3_literal(e.edge_u) + ", " + vec3_literal(e.edge_v) + ", " + n + ", " + du +
                       ", " + dv + ")";
            normal = "nRect(" + n + ")";
            hit = "xRect(" + origin + ", v, " + n + ", " + du + ", " + dv + ", fmin(t, t_max))";
            lane_hit = "xRect_lanes(" + lane_origin + ", vx, vy, vz, " + n + ", " + du + ", " + dv + ", fmin(t, t_max))";
        } else {
            headers.insert("sdf/primitives/disk.h");
            headers.insert("sdf/exact/disk.h");
            const std::string n = vec3_literal(e.normal), r = float_literal(e.radius);
            distance = "fDisk_xyz(" + offset_components(e.center) + ", " + n + ", " + r + ")";
            normal = "nDisk(" + n + ")";
            hit = "xDisk(" + origin + ", v, " + n + ", " + r + ", fmin(t, t_max))";
            lane_hit = "xDisk_lanes(" + lane_origin + ", vx, vy, vz, " + n + ", " + r + ", fmin(t, t_max))";
        }
        nearest.candidate(distance, int(index), "    ");
        const std::string normal_case = "    case " + k + ": *n = " + normal + "; return 1;\n";
        if (emitter_is_exact(scene, e)) {
            exact_hits << "    t = fmin(t, " << hit << ");\n";
            exact_lane_hits << "    t = fmin(t, " << lane_hit << ");\n";
            exact_normal_cases << normal_case;
        } else {
            march.candidate(distance, int(index), "    ");
            packet.candidate(distance, int(index), "    ");
        }
        slot_cases << "    case " << index << ": return " << e.material << ";\n";
        normal_cases << normal_case;
        ++index;
    }

    std::ostringstream out;
    out << "/* Generated by the dtoadq scene compiler from " << scene.file << "; do not edit.\n"
        << " * Objects: " << scene.objects.size() << ", emitters: " << scene.emitters.size()
        << " (" << nearest.box_tests() << " box tests). Lipschitz bound " << format_number(analysis.lipschitz)
        << (analysis.is_distance_bound ? "" : "; NOT a distance bound (a repetition breaks it)") << ".\n"
        << " * Geometry paths (docs/scenes.md): intersected exactly, or sphere-traced in the march's field:\n";
    for (const std::string& line : geometry_paths(scene)) out << " *   " << line << "\n";
    out << " */\n"
        << "#ifndef SCENE_GENERATED_H\n#define SCENE_GENERATED_H\n\n"
        << "#define SCENE_LIPSCHITZ " << float_literal(analysis.lipschitz) << "\n"
        << "#define SCENE_EMITTER_COUNT " << scene.emitters.size() << "\n\n"
        << "#include \"single_source/vocabulary.h\"\n";
    if (split) headers.insert("sdf/exact/interval.h");
    for (const std::string& h : headers) out << "#include \"" << h << "\"\n";
    out << "\n" << functions.str() << exact_functions.str();
    // What every kernel, packet or not, calls per ray (sdf/exact/with_march.h).
    out << "/* The objects in the march's field. */\n"
        << "SS_FN int scene_march_objects(void) { return " << marched_count(scene) << "; }\n\n"
        << "/* The nearest exact hit of the ray o + t v (v unit) with t in (0, t_max], INFINITY for none. */\n";
    write_exact_hit(out, "float", "scene_exact_hit", {{"float3", "o"}, {"float3", "v"}, {"float", "t_max"}}, split, exact_hits.str());
    out << "#ifdef SDF_LANES\n" << exact_lane_functions.str()
        << "/* scene_exact_hit of SDF_LANES rays at once (a packet kernel), to the bit. */\n";
    const std::string lane = "SDF_FLOAT";
    write_exact_hit(out, lane, "scene_exact_hit_lanes",
                    {{lane, "ox"}, {lane, "oy"}, {lane, "oz"}, {lane, "vx"}, {lane, "vy"}, {lane, "vz"}, {lane, "t_max"}}, split,
                    exact_lane_hits.str());
    out << "/* The march's field at SDF_LANES points at once (a packet kernel, kernels/march_packets.cl): the\n"
        << " * nearest distance only, exact in the lanes of `active`; a box test skips a group only when it may\n"
        << " * for every one of them. */\n"
        << "SS_FN SDF_FLOAT scene_distance_xyz(SDF_FLOAT px, SDF_FLOAT py, SDF_FLOAT pz, SDF_MASK active) {\n    SDF_FLOAT d = INFINITY;\n";
    out << (packet.box_tests() ? "    SDF_FLOAT b; /* a box test */\n" : "    (void)active;\n");
    out << packet.body() << "    return d;\n}\n\n#else /* one point at a time */\n\n" << normals.str();
    // A measurement build (-DSCENE_COUNT_EVALUATIONS, `dtoadq bench breakdown`) counts the distance
    // functions evaluated; the default build has no counter at all.
    out << "/* The nearest object or emitter (index: objects, then emitters) and its distance. */\n";
    write_nearest(out, "scene_nearest", nearest);
    write_counted_distance(out, "scene_distance", "scene_nearest");
    out << "SS_FN float scene_nearest(float3 p, int* nearest) { return scene_nearest_xyz(p.x, p.y, p.z, nearest); }\n\n"
        << "SS_FN int scene_material_slot(int nearest) {\n    switch (nearest) {\n"
        << slot_cases.str() << "    default: return 0;\n    }\n}\n\n"
        << "/* The field at a point given as three floats: what a vectorised march calls. */\n"
        << "SS_FN float scene_distance_xyz(float px, float py, float pz) {\n    int k;\n    return scene_nearest_xyz(px, py, pz, &k);\n}\n\n"
        << "SS_FN float scene_distance(float3 p) { return scene_distance_xyz(p.x, p.y, p.z); }\n\n";
    if (split) {
        out << "/* The march's field: the objects that are not intersected exactly. */\n";
        write_nearest(out, "scene_march_nearest", march);
        write_counted_distance(out, "scene_march_distance", "scene_march_nearest");
        out << "SS_FN float scene_march_distance(float3 p) {\n    int k;\n    return scene_march_nearest_xyz(p.x, p.y, p.z, &k);\n}\n\n";
    } else {
        out << "/* The march's field: every object. */\n"
            << "#ifdef SCENE_COUNT_EVALUATIONS\n"
            << "SS_FN float scene_march_distance_counted(float3 p, uint* evaluations) { return scene_distance_counted(p, evaluations); }\n#endif\n\n"
            << "SS_FN float scene_march_distance(float3 p) { return scene_distance(p); }\n\n";
    }
    out << "/* The distance and the material slot of the nearest object. */\n"
        << "SS_FN float scene_distance_material(float3 p, int* material) {\n    int k;\n"
        << "    float d = scene_nearest(p, &k);\n    *material = scene_material_slot(k);\n    return d;\n}\n\n"
        << "/* The nearest object's analytic normal where it is one primitive under rigid transforms and\n"
        << " * uniform scales; 0 (no normal) elsewhere. */\n"
        << "SS_FN int scene_analytic_normal(float3 p, float3* n) {\n    int k;\n    scene_nearest(p, &k);\n"
        << "    switch (k) {\n" << normal_cases.str() << "    default: return 0;\n    }\n}\n\n"
        << "/* At a hit point, one nearest-object search for both: the material slot and, where that object is\n"
        << " * intersected exactly, its analytic normal (1; 0 elsewhere). */\n"
        << "SS_FN int scene_surface(float3 p, int* slot, float3* n) {\n    int k;\n    scene_nearest(p, &k);\n"
        << "    *slot = scene_material_slot(k);\n";
    if (split)
        out << "    switch (k) {\n" << exact_normal_cases.str() << "    default: return 0;\n    }\n}\n\n";
    else
        out << "    (void)n;\n    return 0;\n}\n\n";
    out << "#endif /* SDF_LANES */\n\n#endif\n";
    return out.str();
}

std::string generate_material_source(const Scene& scene, const std::vector<brdf::Material>& materials) {
    std::ostringstream out;
    out << "/* Generated by the dtoadq scene compiler from " << scene.file << "; do not edit. */\n"
        << "#ifndef SCENE_MATERIALS_H\n#define SCENE_MATERIALS_H\n\n"
        << "#define SCENE_MATERIAL_COUNT " << materials.size() << "\n\n"
        << "/* The BRDF features this scene's materials need (brdf/features.h). */\n"
        << brdf::feature_defines(materials) << "\n#endif\n";
    return out.str();
}

}  // namespace lab::scene
