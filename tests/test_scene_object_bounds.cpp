// Object bounds (scene/object_tree.hpp): the generated field skips an object, or a group of them,
// whose box is farther than the nearest surface so far. That is exact only if every object's field
// is at least the distance to its box outside the box (scene/lipschitz.hpp's box_center and
// box_half), so the first test checks that property itself on the host, for every object of every
// scene, at points near and far; the second that renders with and without the box tests, and
// with and without the surface box that ends a march where the ray leaves every object's box
// (sdf/march_lanes.h), are the same bits on the device.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include "opencl/runtime.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/compile.hpp"
#include "scene/interpreter.hpp"
#include "scene/lipschitz.hpp"
#include "scene/load_scene.hpp"
#include "scene/object_tree.hpp"
#include "sdf/sdf.hpp"
#include "test_scene_points.hpp"
#include "tests/render_inputs.hpp"

using lab::scene::Vec3;

namespace {

// The distance from p to the box (0 inside); an infinite half extent leaves that axis out.
double box_distance(Vec3 p, Vec3 center, Vec3 half) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        double q = std::fabs(double(p[i]) - double(center[i])) - double(half[i]);
        if (q > 0.0) sum += q * q;
    }
    return std::sqrt(sum);
}

}  // namespace

TEST_CASE("Object bounds: every object's field is at least the distance to its box outside the box", "[scene][object-bounds]") {
    const std::vector<Vec3> points = scene_test::random_points(4000, 77);
    size_t objects = 0, checked = 0;
    for (const std::string& file : scene_test::all_scene_files()) {
        lab::scene::Scene scene = lab::scene::load_scene(file);
        for (const lab::scene::Object& object : scene.objects) {
            lab::scene::ShapeAnalysis a = lab::scene::analyse_shape(object.shape);
            if (!a.broken.empty()) continue;  // not a distance bound: the compiler gives it no box
            ++objects;
            // points around the box too, so its faces are tested where they are tight
            std::vector<Vec3> near = points;
            bool finite = std::isfinite(a.box_half.x) && std::isfinite(a.box_half.y) && std::isfinite(a.box_half.z);
            if (finite)
                for (const Vec3& p : points) near.push_back(a.box_center + (p * 0.25f) * (a.box_half + Vec3(0.2f)));
            double worst = 0.0;
            for (const Vec3& p : near) {
                double outside = box_distance(p, a.box_center, a.box_half);
                if (outside <= 0.0) continue;
                ++checked;
                double f = lab::scene::shape_distance(object.shape, p);
                // float rounding of f: a few ulps of the magnitudes involved
                double slack = 1e-5 * std::fmax(1.0, std::fabs(f));
                worst = std::fmax(worst, outside - f - slack);
            }
            INFO(file << ": object \"" << object.name << "\": box centre (" << a.box_center.x << ", " << a.box_center.y << ", "
                      << a.box_center.z << "), half (" << a.box_half.x << ", " << a.box_half.y << ", " << a.box_half.z
                      << "): the field is below the box distance by " << worst);
            CHECK(worst <= 0.0);
        }
    }
    std::printf("object bounds: %zu objects, %zu points outside their boxes\n", objects, checked);
    CHECK(checked > 10000);
}

TEST_CASE("Object bounds: the tree holds every bounded object once, each inside its group's box", "[scene][object-bounds]") {
    std::vector<lab::scene::ObjectBox> boxes;
    for (int i = 0; i < 13; ++i) {
        Vec3 c(float(i % 4) * 2.0f, float(i / 4) * 1.5f, float(i % 3));
        boxes.push_back({i, c - Vec3(0.5f), c + Vec3(0.5f), false});
    }
    std::vector<lab::scene::ObjectTreeNode> tree = lab::scene::build_object_tree(boxes);
    std::vector<int> seen(boxes.size(), 0);
    for (const lab::scene::ObjectTreeNode& n : tree) {
        if (n.object >= 0) {
            ++seen[size_t(n.object)];
            continue;
        }
        for (int child : {n.left, n.right}) {
            const lab::scene::ObjectTreeNode& c = tree[size_t(child)];
            CHECK(glm::all(glm::lessThanEqual(n.lo, c.lo)));
            CHECK(glm::all(glm::greaterThanEqual(n.hi, c.hi)));
        }
    }
    for (int s : seen) CHECK(s == 1);
    CHECK(tree.size() == 2 * boxes.size() - 1);
}

TEST_CASE("Object bounds: renders with and without the box tests are the same bits", "[scene][object-bounds][opencl]") {
    lab::opencl::Runtime runtime("");
    // under a grey sky, so that what a ray sees after leaving every box counts too; most of the
    // distant sphere's camera rays miss the surface box, and their marches end before their first
    // step. The box tests skip objects of the marched field: scenes of plain primitives, which would
    // otherwise be intersected exactly and march nothing, are marched whole (`--geometry march`);
    // the test model and the metaballs march their fields beside exact objects.
    const struct {
        const char* file;
        bool march_everything;
    } cases[] = {{"scenes/primitives.json", true},
                 {"scenes/shader_ball.json", false},
                 {"scenes/metaballs.json", false},
                 {"tests/scene_data/object_grid.json", true},
                 {"tests/scene_data/distant_sphere.json", true}};
    for (const auto& c : cases) {
        const char* file = c.file;
        lab::film::ImageRgb images[2];
        for (int bounds = 0; bounds < 2; ++bounds) {
            lab::render::RenderInput input;
            input.scene = lab::scene::load_scene(file);
            input.environment = lab::ibl::Environment::constant(brdf::float3(0.5f), "grey", lab::ibl::EnvironmentOptions{});
            input.settings.width = input.settings.height = 16;
            input.settings.object_bounds = bounds == 1;
            input.settings.march_everything = c.march_everything;
            lab::render::OpenClRenderer renderer(runtime, input);
            images[bounds] = render_samples(renderer, 2).image;
        }
        INFO(file);
        CHECK(images[0].rgb.size() == images[1].rgb.size());
        CHECK(std::memcmp(images[0].rgb.data(), images[1].rgb.data(), images[0].rgb.size() * sizeof(float)) == 0);
    }
}
