#include "bench/grid.hpp"

#include <string>

#include "scene/load_scene.hpp"

namespace lab::cli {

nlohmann::json grid_scene_json(int count) {
    using nlohmann::json;
    int side = 1;
    while (side * side < count) ++side;
    float extent = 0.6f * float(side);
    json objects = json::array();
    for (int i = 0; i < count; ++i) {
        float x = 1.2f * float(i % side) - extent + 0.6f, z = 1.2f * float(i / side) - extent + 0.6f;
        json shape;
        if (i % 3 == 0)
            shape = {{"type", "smooth_union"}, {"radius", 0.1},
                     {"children", {{{"type", "rotate"}, {"axis", {0, 1, 0}}, {"degrees", 30},
                                    {"child", {{"type", "round_box"}, {"half_size", {0.25, 0.25, 0.25}}, {"radius", 0.05}}}},
                                   {{"type", "translate"}, {"offset", {0, 0.3, 0}},
                                    {"child", {{"type", "torus"}, {"major_radius", 0.3}, {"minor_radius", 0.07}}}}}}};
        else if (i % 3 == 1)
            shape = {{"type", "sphere"}, {"radius", 0.35}};
        else
            shape = {{"type", "capsule"}, {"radius", 0.2}, {"half_height", 0.2}};
        objects.push_back({{"name", "object" + std::to_string(i)},
                           {"material", i % 2 ? "red" : "grey"},
                           {"shape", {{"type", "translate"}, {"offset", {x, 0.4, z}}, {"child", shape}}}});
    }
    json scene = {
        {"camera", {{"type", "pinhole"}, {"position", {0.0, 1.0 + 1.6 * extent, 2.2 * extent + 1.0}}, {"look_at", {0, 0, 0}}, {"fov_degrees", 50}}},
        {"environment", {{"constant", {0.8, 0.85, 1.0}}}},
        {"materials",
         {{"grey", {{"albedo", {0.6, 0.6, 0.6}}, {"roughness", 0.3}, {"lobes", {{"diffuse", 0.7}, {"glossy", 0.3}}}}},
          {"red", {{"albedo", {0.7, 0.2, 0.1}}, {"lobes", {{"diffuse", 1}}}}}}},
        {"objects", objects}};
    return scene;
}

scene::Scene grid_scene(int count) {
    return scene::parse_scene(grid_scene_json(count).dump(), "bench grid of " + std::to_string(count) + " objects");
}

double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double mx = 0.0, my = 0.0;
    for (size_t i = 0; i < x.size(); ++i) mx += x[i] / double(x.size()), my += y[i] / double(x.size());
    double sxy = 0.0, sxx = 0.0;
    for (size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    return sxx > 0.0 ? sxy / sxx : 0.0;
}

}  // namespace lab::cli
