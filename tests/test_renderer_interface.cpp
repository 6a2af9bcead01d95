// The renderer interface every integrator and the viewer rely on: chunks bounded by a time
// budget, reset and resize, and edits of the material, camera and environment that change the
// image without rebuilding the kernel unless a BRDF feature the kernel lacks is needed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "brdf/host/preset.hpp"
#include "opencl/runtime.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "tests/lobe_material.hpp"
#include "tests/render_inputs.hpp"

namespace {

using lab::render::LightSampling;

lab::render::RenderInput diffuse_model(const std::string& env) {
    brdf::Material m = lobe_material(1, 0, 0, 0);
    return render_input(m, env, 16, LightSampling::mis, 5);
}

}  // namespace

TEST_CASE("Renderer: a time budget ends a call after the launch that reaches it", "[render][interface][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::render::OpenClRenderer renderer(runtime, diffuse_model("constant:1,1,1"));
    renderer.set_samples_per_launch(2);
    CHECK(renderer.add_samples(1000, 0.0) == 2);  // one launch, whatever the budget
    CHECK(renderer.add_samples(3) == 3);          // no budget: every sample asked for
    CHECK(renderer.statistics().samples_per_pixel == 5);
    renderer.reset();
    CHECK(renderer.statistics().samples_per_pixel == 0);
    lab::film::ImageRgb black = renderer.image();
    CHECK(*std::max_element(black.rgb.begin(), black.rgb.end()) == 0.0f);
    renderer.resize(20, 12);
    RenderResult r = render_samples(renderer, 1);
    CHECK(r.image.width == 20);
    CHECK(r.image.height == 12);
}

TEST_CASE("Renderer: exposure scales the image exactly and a full turn leaves it as it was", "[render][interface][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::render::OpenClRenderer renderer(runtime, diffuse_model("envmaps/courtyard.exr"));
    lab::film::ImageRgb base = render_samples(renderer, 2).image;
    // A power of two scales every sample exactly, and the light selection does not change (one light).
    renderer.set_environment_transform(0.0f, 1.0f);
    lab::film::ImageRgb doubled = render_samples(renderer, 2).image;
    bool exact = true;
    for (size_t k = 0; k < base.rgb.size(); ++k) exact = exact && doubled.rgb[k] == 2.0f * base.rgb[k];
    CHECK(exact);
    renderer.set_environment_transform(360.0f, 0.0f);
    CHECK(render_samples(renderer, 2).image.rgb == base.rgb);
    renderer.set_environment_transform(90.0f, 0.0f);
    CHECK(render_samples(renderer, 2).image.rgb != base.rgb);
}

TEST_CASE("Renderer: materials and camera change without a rebuild unless a new BRDF feature is needed",
          "[render][interface][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::render::RenderInput input = diffuse_model("constant:0.8,0.9,1");
    lab::render::OpenClRenderer renderer(runtime, input);
    lab::film::ImageRgb base = render_samples(renderer, 2).image;
    std::vector<brdf::Material> materials = renderer.compiled_scene().materials;

    // Another diffuse albedo: the same features, an upload only, and the image follows it.
    size_t sample = 0;
    while (renderer.compiled_scene().material_names[sample] != lab::scene::kSampleMaterialSlot) ++sample;
    materials[sample].albedo[0] = 0.1f;
    CHECK_FALSE(renderer.set_materials(materials));
    lab::film::ImageRgb redder = render_samples(renderer, 2).image;
    CHECK(redder.rgb != base.rgb);
    // An edit, then its undo, renders the very image of before: nothing else changed.
    materials[sample].albedo[0] = input.scene.materials[sample].material.albedo[0];
    CHECK_FALSE(renderer.set_materials(materials));
    CHECK(render_samples(renderer, 2).image.rgb == base.rgb);

    // Gold needs the glossy lobe, which the diffuse model's kernel was built without.
    materials[sample] = brdf::load_preset("presets/gold.json").material;
    CHECK(renderer.set_materials(materials));
    CHECK(render_samples(renderer, 2).image.rgb != base.rgb);

    lab::scene::Camera camera = renderer.compiled_scene().camera;
    camera.position = camera.position * 1.5f;
    renderer.set_camera(camera);
    CHECK(render_samples(renderer, 2).stats.samples_per_pixel == 2);
}

TEST_CASE("Renderer: hiding the background blackens what the camera sees of the sky, and lights the model the same",
          "[render][interface][host]") {
    lab::render::RenderInput input = diffuse_model("constant:1,1,1");
    input.settings.width = input.settings.height = 8;
    lab::render::HostRenderer renderer(input, 1);
    lab::film::ImageRgb shown = render_samples(renderer, 2).image;
    renderer.set_background(0.0f, 0.0f);
    lab::film::ImageRgb hidden = render_samples(renderer, 2).image;
    // The sky is 1; the model (albedo 0.8) is darker. A pixel whose samples all saw the sky goes
    // black, one whose samples all saw the model keeps its value, one between loses its sky samples.
    size_t black = 0, same = 0, darker = 0;
    for (size_t p = 0; p < shown.pixel_count(); ++p) {
        float s = shown.rgb[3 * p], h = hidden.rgb[3 * p];
        if (s == 1.0f && h == 0.0f) ++black;
        else if (h == s) ++same;
        else if (h < s) ++darker;
    }
    INFO(black << " sky pixels went black, " << same << " model pixels unchanged, " << darker << " darker, of " << shown.pixel_count());
    CHECK(black > 0);
    CHECK(same > 0);
    CHECK(black + same + darker == shown.pixel_count());
}

// The integrators' kernels take the materials as the renderer clamped them (render/renderer.cpp),
// not clamping at each vertex: a material outside its ranges, handed to the renderer, must render
// as its clamped form does (the BSDF module's own entry points clamp; kernels/path_tracer.h and
// BDPT's vertices, through brdf/bsdf_transport.h, rely on the renderer having done it). BDPT runs
// on one host thread: its splats then add in a fixed order, so the bits repeat.
TEST_CASE("Renderer: a material outside its ranges renders as its clamped form on the device and the host",
          "[render][interface][opencl][host]") {
    lab::render::RenderInput input = diffuse_model("envmaps/courtyard.exr");
    input.settings.width = input.settings.height = 16;
    lab::opencl::Runtime runtime("");
    lab::render::OpenClRenderer device(runtime, input);
    lab::render::HostRenderer host(input, 2);
    input.settings.integrator = lab::render::Integrator::bdpt;
    lab::render::HostRenderer bdpt(input, 1);
    for (lab::render::Renderer* renderer : {static_cast<lab::render::Renderer*>(&device), static_cast<lab::render::Renderer*>(&host),
                                            static_cast<lab::render::Renderer*>(&bdpt)}) {
        std::vector<brdf::Material> wild = renderer->compiled_scene().materials;
        size_t sample = 0;
        while (renderer->compiled_scene().material_names[sample] != lab::scene::kSampleMaterialSlot) ++sample;
        wild[sample].albedo[0] = 1.7f;      // above 1: a material that makes light
        wild[sample].albedo[1] = NAN;       // clamped to 0
        wild[sample].weight_diffuse = 4.0f; // clamped to 1
        std::vector<brdf::Material> clamped = wild;
        clamped[sample] = brdf::material_clamped(&wild[sample]);
        CHECK_FALSE(renderer->set_materials(clamped));
        lab::film::ImageRgb expected = render_samples(*renderer, 2).image;
        CHECK_FALSE(renderer->set_materials(wild));
        lab::film::ImageRgb got = render_samples(*renderer, 2).image;
        CHECK(got.rgb == expected.rgb);
    }
}
