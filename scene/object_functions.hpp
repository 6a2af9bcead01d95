// The generated functions of one object: its distance (scene_object_N, in component form) and, for a
// primitive under rigid transforms and uniform scales, its analytic normal, each written as
// numbered locals with the sdf/ headers they use.
#pragma once

#include <set>
#include <string>

#include "scene/scene.hpp"

namespace lab::scene {

// The body of one generated function: numbered locals, one statement each, and the headers used.
class FunctionWriter {
public:
    explicit FunctionWriter(std::set<std::string>* headers) : headers_(headers) {}

    std::string point(const std::string& expression) { return local("float3", "p", expression); }
    // A point as three float locals pNx, pNy, pNz (one statement); returns "pN".
    std::string point_components(const std::string& x, const std::string& y, const std::string& z) {
        std::string name = "p" + std::to_string(next_++);
        body_ += "    SDF_FLOAT " + name + "x = " + x + ", " + name + "y = " + y + ", " + name + "z = " + z + ";\n";
        return name;
    }
    std::string distance(const std::string& expression) { return local("SDF_FLOAT", "d", expression); }
    std::string normal(const std::string& expression) { return local("float3", "n", expression); }
    std::string scalar(const std::string& expression) { return local("float", "t", expression); }
    std::string lane_scalar(const std::string& expression) { return local("SDF_FLOAT", "t", expression); }
    void use(const std::string& header) { headers_->insert(header); }
    const std::string& body() const { return body_; }

private:
    std::string local(const char* type, const char* prefix, const std::string& expression) {
        std::string name = prefix + std::to_string(next_++);
        body_ += std::string("    ") + type + " " + name + " = " + expression + ";\n";
        return name;
    }
    std::set<std::string>* headers_;
    std::string body_;
    int next_ = 1;
};

// The distance of `node` at the point whose components are named px, py, pz (p the stem); returns
// the local that holds it.
std::string emit_distance(const Node& node, const std::string& p, FunctionWriter* w);

// A primitive under rigid transforms and uniform scales only: its normal is the primitive's
// analytic one (nX) turned back by the rotations (translation and uniform scale leave it).
bool has_analytic_normal(const Node& node);

// The analytic normal of a node has_analytic_normal() accepts, at the float3 point p.
std::string emit_normal(const Node& node, const std::string& p, FunctionWriter* w);

// The exact hit (sdf/exact/) of the ray from the float3 o along the unit float3 v, with t in
// (0, t_max] (t_max a float), of a node has_analytic_normal() accepts, EXACT_MISS without one: the
// ray taken down to the primitive's frame (a rotation turns both o and v, a uniform scale s divides
// o and t_max by s and multiplies the hit by s, v staying unit), as the host interpreter does.
std::string emit_exact_hit(const Node& node, const std::string& o, const std::string& v, const std::string& t_max, FunctionWriter* w);

// Whether the primitive under the rigid transforms and uniform scales of a node has_analytic_normal()
// accepts has a lane form of its exact hit (xX_lanes in sdf/exact/: all but the torus).
bool has_exact_hit_lanes(const Node& node);

// emit_exact_hit's lane form, for a node has_exact_hit_lanes() accepts: the ray's components are
// the SDF_FLOAT locals ox, oy, oz and vx, vy, vz (o and v the stems), t_max an SDF_FLOAT, and the
// same transforms are applied component by component (the same roundings).
std::string emit_exact_hit_lanes(const Node& node, const std::string& o, const std::string& v, const std::string& t_max, FunctionWriter* w);

// A rough cost of evaluating the node, in primitive evaluations: where an object costs more than its
// box test (about one and a half primitives), the test pays when it skips the object.
float evaluation_cost(const Node& node);

}  // namespace lab::scene
