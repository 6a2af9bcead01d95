// The viewer's parts that need no window: the newest-job-wins thread and the validation's
// cancellation behind the badges, --set through the preset loader, export into a scene file, the
// frame-time quantiles, and the render worker restarting on a new state.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "brdf/host/parameters.hpp"
#include "common/input_error.hpp"
#include "interchange/mtlx_reader.hpp"
#include "render/host_renderer.hpp"
#include "scene/load_scene.hpp"
#include "scene/test_model.hpp"
#include "validation/report.hpp"
#include "viewer/frame_stats.hpp"
#include "viewer/json_members.hpp"
#include "viewer/latest_job.hpp"
#include "viewer/material_export.hpp"
#include "viewer/material_edit.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/scene_export.hpp"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// Waits for `done` up to 20 s (a loaded machine), polling.
template <typename F>
bool eventually(F done) {
    const auto start = Clock::now();
    while (!done()) {
        if (Clock::now() - start > std::chrono::seconds(20)) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
}

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The test model under a white constant environment at size x size.
lab::render::RenderInput test_model_under_white(int size) {
    lab::render::RenderInput input;
    input.scene = lab::scene::load_test_model();
    input.environment = lab::ibl::Environment::constant(brdf::float3(1.0f), "white", {});
    input.settings.width = input.settings.height = size;
    return input;
}

// The view state a render worker opens with: the scene's materials and camera.
lab::viewer::ViewState view_state_of(const lab::render::RenderInput& input) {
    lab::viewer::ViewState state;
    for (const lab::scene::MaterialSlot& s : input.scene.materials) state.materials.push_back(s.material);
    state.camera = input.scene.camera;
    return state;
}

}  // namespace

TEST_CASE("a newer job cancels the running one, and only the newest pending job runs", "[viewer]") {
    std::atomic<int> first_state{0};  // 1 running, 2 saw cancelled
    std::atomic<int> ran{0}, last{0};
    std::atomic<bool> both_submitted{false};
    {
        lab::viewer::LatestJob jobs;
        // The first job returns only once both later jobs are in: were it to return at the first
        // cancellation, the worker could start job 2 before job 3 replaced it.
        jobs.submit([&](const lab::viewer::LatestJob::Cancelled& cancelled) {
            first_state = 1;
            while (!cancelled() || !both_submitted.load()) std::this_thread::yield();
            first_state = 2;
        });
        REQUIRE(eventually([&] { return first_state.load() == 1; }));
        // Two submissions while the first runs: the second replaces the first of them before it starts.
        jobs.submit([&](const lab::viewer::LatestJob::Cancelled&) { ran += 1; last = 2; });
        jobs.submit([&](const lab::viewer::LatestJob::Cancelled&) { ran += 1; last = 3; });
        both_submitted = true;
        REQUIRE(eventually([&] { return first_state.load() == 2 && !jobs.busy(); }));
    }
    CHECK(ran.load() == 1);
    CHECK(last.load() == 3);
}

TEST_CASE("validate_material stops at once when cancelled, saying so", "[viewer]") {
    brdf::Preset p;
    p.name = "default";
    p.material = brdf::default_material();
    lab::validation::ValidationOptions options;
    options.cancelled = [] { return true; };
    lab::validation::MaterialValidation v = lab::validation::validate_material(p, options);
    CHECK(v.cancelled);
    CHECK(v.albedo.albedo == 0.0);  // the furnace never ran
    CHECK(v.smallest_p_value == 1.0);
}

TEST_CASE("Viewer: --set goes through the preset loader: units, ranges and names", "[viewer]") {
    brdf::Preset p;
    p.name = "x";
    p.material = brdf::default_material();
    CHECK(lab::viewer::with_parameter(p, "roughness", "0.25", "--set").material.roughness == 0.25f);
    CHECK(lab::viewer::with_parameter(p, "lobes.glossy", "0.5", "--set").material.weight_glossy == 0.5f);
    CHECK(lab::viewer::with_parameter(p, "tangent_rotation", "90", "--set").material.tangent_rotation == Approx(1.5707964f));
    brdf::Material m = lab::viewer::with_parameter(p, "albedo", "0.1,0.2,0.3", "--set").material;
    CHECK((m.albedo[0] == 0.1f && m.albedo[1] == 0.2f && m.albedo[2] == 0.3f));
    CHECK(lab::viewer::with_parameter(p, "model", "dtoadq2017", "--set").material.model == BRDF_MODEL_DTOADQ2017);
    CHECK_THROWS_WITH(lab::viewer::with_parameter(p, "roughness", "1.5", "--set"), "--set: roughness: value 1.5 is out of range [0, 1]");
    CHECK_THROWS_WITH(lab::viewer::with_parameter(p, "roughnes", "0.5", "--set"), "--set: roughnes: unknown key");
    CHECK_THROWS_AS(lab::viewer::with_parameter(p, "roughness", "nan", "--set"), lab::InputError);
    CHECK_THROWS_AS(lab::viewer::with_parameter(p, "albedo", "0.1,0.2", "--set"), lab::InputError);
    brdf::Preset glow = p;
    glow.material = brdf::default_material(BRDF_MODEL_OPENPBR);
    CHECK(lab::viewer::with_parameter(glow, "emission_luminance", "250", "--set").material.emission_luminance == 250.0f);
    CHECK(lab::viewer::with_parameter(glow, "emission_color", "1,0.5,0.25", "--set").material.emission_color[2] == 0.25f);
    CHECK_THROWS_AS(lab::viewer::with_parameter(glow, "emission_luminance", "nan", "--set"), lab::InputError);
    CHECK_THROWS_WITH(lab::viewer::with_parameter(glow, "emission_luminance", "-5", "--set"),
                      "--set: emission_luminance: value -5 is out of range [0, 1e+06]");
}

TEST_CASE("export to scene adds or replaces one material and keeps the rest in place", "[viewer]") {
    const fs::path dir = fs::temp_directory_path() / ("dtoadq_viewer_export_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "s.json";
    {
        std::ofstream out(file);
        out << R"({"description": "d", "camera": {"type": "pinhole", "position": [0, 1, 4], "look_at": [0, 0, 0], "fov_degrees": 40},
                   "materials": {"b": {"albedo": [0.5, 0.5, 0.5]}, "a": {"albedo": [0.2, 0.2, 0.2]}},
                   "objects": [{"name": "ball", "material": "a", "shape": {"type": "sphere", "radius": 1}}]})";
    }
    const std::string text = read(file);
    const nlohmann::ordered_json before = nlohmann::ordered_json::parse(text);
    brdf::Preset p;
    p.name = "ignored";
    p.material = brdf::default_material();
    p.material.roughness = 0.125f;
    lab::viewer::export_to_scene(p, file.string(), "a");  // replaces
    // Every byte around the material's value is the file's own.
    const std::string old_value = R"({"albedo": [0.2, 0.2, 0.2]})";
    const size_t at = text.find(old_value);
    const std::string replaced = read(file);
    CHECK(replaced.compare(0, at, text, 0, at) == 0);
    const size_t tail = text.size() - at - old_value.size();
    REQUIRE(replaced.size() > tail);
    CHECK(replaced.compare(replaced.size() - tail, tail, text, at + old_value.size(), tail) == 0);
    const std::optional<lab::viewer::JsonObjectSpan> new_a = lab::viewer::json_object_at(replaced, at);
    REQUIRE(new_a);
    CHECK(replaced.find('\n', at) > new_a->close);  // on one line, as the material it replaces
    lab::viewer::export_to_scene(p, file.string(), "fresh");  // adds, last
    const std::string added = read(file);
    const size_t end_of_a = new_a->close + 1;
    CHECK(added.compare(0, end_of_a, replaced, 0, end_of_a) == 0);
    CHECK(added.compare(added.size() - (replaced.size() - end_of_a), std::string::npos, replaced, end_of_a) == 0);
    const nlohmann::ordered_json after = nlohmann::ordered_json::parse(read(file));
    std::vector<std::string> keys, material_keys;
    for (const auto& [k, v] : after.items()) keys.push_back(k);
    for (const auto& [k, v] : after["materials"].items()) material_keys.push_back(k);
    CHECK(keys == std::vector<std::string>{"description", "camera", "materials", "objects"});
    CHECK(material_keys == std::vector<std::string>{"b", "a", "fresh"});
    CHECK(after["materials"]["b"] == before["materials"]["b"]);
    CHECK(after["camera"] == before["camera"]);
    CHECK(after["objects"] == before["objects"]);
    lab::scene::Scene loaded = lab::scene::load_scene(file.string());  // what `dtoadq render` reads
    REQUIRE(loaded.materials.size() == 3);
    CHECK(loaded.materials[1].name == "a");
    CHECK(loaded.materials[1].material.roughness == 0.125f);

    // A scene whose materials are not an object is refused and left as it was.
    const fs::path bad = dir / "bad.json";
    { std::ofstream(bad) << R"({"materials": [1, 2]})"; }
    CHECK_THROWS_WITH(lab::viewer::export_to_scene(p, bad.string(), "a"), Catch::Contains("materials: expected an object"));
    CHECK(read(bad) == R"({"materials": [1, 2]})");
    fs::remove_all(dir);
}

TEST_CASE("export material writes the edited material for another tool, chosen by the file's extension", "[viewer]") {
    for (const char* target : {"a.mtlx", "a.gltf", "a.xml", "a.pbrt"}) CHECK(lab::viewer::is_material_file_target(target));
    for (const char* target : {"scene.json:a", "a.json", "a.txt", ""}) CHECK(!lab::viewer::is_material_file_target(target));
    const brdf::Preset car = brdf::load_preset("presets/car_paint.json");
    const fs::path file = fs::temp_directory_path() / ("dtoadq-viewer-export-" + std::to_string(::getpid()) + ".mtlx");
    CHECK(lab::viewer::export_material_file(car, file.string()).empty());  // MaterialX carries every openpbr parameter
    const brdf::Material back = interchange::read_mtlx(file.string()).preset.material;
    fs::remove(file);
    CHECK(std::memcmp(&back, &car.material, sizeof back) == 0);
    const std::vector<std::string> notes = lab::viewer::export_material_file(car, (fs::temp_directory_path() / "dtoadq-viewer-export.gltf").string());
    fs::remove(fs::temp_directory_path() / "dtoadq-viewer-export.gltf");
    REQUIRE(notes.size() == 1);  // glTF's metal has no F82 tint
    CHECK(notes[0].find(": specular_color: ") != std::string::npos);
    CHECK_THROWS_WITH(lab::viewer::export_material_file(car, "a.json"), Catch::Contains("a preset is saved with"));
}

TEST_CASE("frame-time quantiles by the nearest rank", "[viewer]") {
    CHECK(lab::viewer::quantile({}, 0.5) == 0.0);
    CHECK(lab::viewer::quantile({3, 1, 2}, 0.5) == 2.0);
    std::vector<double> hundred;
    for (int i = 1; i <= 100; ++i) hundred.push_back(i);
    CHECK(lab::viewer::quantile(hundred, 0.95) == 95.0);
    CHECK(lab::viewer::quantile(hundred, 1.0) == 100.0);
}

TEST_CASE("the render worker accumulates, and a new state restarts it with the new material", "[viewer]") {
    lab::render::RenderInput input = test_model_under_white(8);
    lab::viewer::ViewState state = view_state_of(input);
    // At most 4 samples per pixel: the worker renders out, then sleeps until a new state comes.
    lab::viewer::RenderWorker worker([input] { return std::make_unique<lab::render::HostRenderer>(input, 1); }, state, 0.01, 4);
    lab::viewer::RenderFrame frame;
    REQUIRE(eventually([&] { return worker.take_frame(&frame) && frame.samples_per_pixel == 4; }));
    CHECK(frame.generation == 1);
    const lab::film::ImageRgb red = frame.image;
    state.materials[0].albedo[0] = state.materials[0].albedo[1] = state.materials[0].albedo[2] = 0.0f;
    const uint64_t generation = worker.submit(state);
    CHECK(generation == 2);
    // Were the film not restarted it would hold its 4 samples and add none.
    REQUIRE(eventually([&] { return worker.take_frame(&frame) && frame.generation == generation && frame.samples_per_pixel == 4; }));
    // The red channel of the centre 4 x 4 pixels, the model: its diffuse red (albedo 0.6, 80 % of
    // the lobes) is gone, leaving the glossy lobe's reflection.
    double sum_red = 0.0, sum_black = 0.0;
    for (int y = 2; y < 6; ++y)
        for (int x = 2; x < 6; ++x) {
            sum_red += red.at(x, y)[0];
            sum_black += frame.image.at(x, y)[0];
        }
    CHECK(sum_black < 0.5 * sum_red);
    CHECK(worker.error().empty());
}

TEST_CASE("the render worker's first pass at a reduced size never mixes into the full-size image", "[viewer]") {
    // 48 x 48: the first state is rendered first at a reduced size (nothing measured yet: the largest
    // reduction), shown enlarged, then at full size in launches of part of the image. The final
    // image must be exactly a plain render of the same samples: a low-res sample in the film, or the
    // enlarged first pass left on the screen where the full size has reached, would change it.
    lab::render::RenderInput input = test_model_under_white(48);
    lab::viewer::ViewState state = view_state_of(input);
    // A chunk of 1 ms: launches of a few work-groups, many per pass.
    lab::viewer::RenderWorker worker([input] { return std::make_unique<lab::render::HostRenderer>(input, 1); }, state, 0.001, 3);
    lab::viewer::RenderFrame frame;
    bool saw_first_pass = false;
    std::vector<lab::viewer::RenderFrame> full_size;  // every frame taken that says it is full size
    REQUIRE(eventually([&] {
        if (!worker.take_frame(&frame)) return false;
        saw_first_pass |= frame.scale > 1;
        if (frame.scale == 1) full_size.push_back(frame);
        return frame.scale == 1 && frame.samples_per_pixel == 3;
    }));
    CHECK(saw_first_pass);
    lab::render::HostRenderer plain(input, 1);
    std::vector<lab::film::ImageRgb> plain_spp{lab::film::ImageRgb(48, 48)};  // 0 spp: black
    for (int n = 1; n <= 3; ++n) {
        plain.add_samples(1);
        plain_spp.push_back(plain.image());
    }
    CHECK(frame.image.rgb == plain_spp[3].rgb);
    // A full-size frame with n complete samples shows, per pixel, the plain render's n or n + 1
    // (a pass in progress), never the first pass.
    size_t mixed = 0;
    for (const lab::viewer::RenderFrame& f : full_size)
        for (size_t i = 0; i < f.image.rgb.size(); ++i) {
            const int n = f.samples_per_pixel;
            if (f.image.rgb[i] != plain_spp[size_t(n)].rgb[i] && (n == 3 || f.image.rgb[i] != plain_spp[size_t(n + 1)].rgb[i])) ++mixed;
        }
    CHECK(mixed == 0);
}

TEST_CASE("the render worker takes a new size from the window: the render restarts at that size, on a film of its own", "[viewer]") {
    lab::render::RenderInput input = test_model_under_white(16);
    lab::viewer::ViewState state = view_state_of(input);
    lab::render::RenderInput resized = input;
    resized.settings.width = 24;
    resized.settings.height = 20;
    lab::render::HostRenderer plain(resized, 1);
    plain.add_samples(2);
    // Chunks of 5 ms start the new size with a reduced first pass; chunks of 10 s render it at once.
    for (double chunk_seconds : {0.005, 10.0}) {
        INFO("chunk " << chunk_seconds << " s");
        state.width = state.height = 16;
        lab::viewer::RenderWorker worker([input] { return std::make_unique<lab::render::HostRenderer>(input, 1); }, state, chunk_seconds, 2);
        lab::viewer::RenderFrame frame;
        REQUIRE(eventually([&] { return worker.take_frame(&frame) && frame.scale == 1 && frame.samples_per_pixel == 2; }));
        state.width = 24;
        state.height = 20;
        const uint64_t generation = worker.submit(state);
        REQUIRE(eventually([&] {
            return worker.take_frame(&frame) && frame.generation == generation && frame.scale == 1 && frame.samples_per_pixel == 2;
        }));
        REQUIRE(frame.image.width == 24);
        REQUIRE(frame.image.height == 20);
        // Exactly a plain render of that size: no sample of the 16 x 16 render is in it.
        CHECK(frame.image.rgb == plain.image().rgb);
        CHECK(worker.error().empty());
    }
}

TEST_CASE("export to scene keeps a file's own layout: 4-space indents and one-line arrays stay, the new material follows its neighbours' indent",
          "[viewer]") {
    const fs::path dir = fs::temp_directory_path() / ("dtoadq_viewer_layout_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "s.json";
    const std::string head = "{\n    \"camera\": {\"type\": \"pinhole\", \"position\": [0, 1, 4], \"look_at\": [0, 0, 0], \"fov_degrees\": 40},\n"
                             "    \"materials\": {\n        \"a\": ";
    const std::string a = "{\n            \"albedo\": [0.2, 0.2, 0.2]\n        }";
    const std::string tail = "\n    },\n    \"objects\": [{\"name\": \"ball\", \"material\": \"a\", \"shape\": {\"type\": \"sphere\", \"radius\": 1}}]\n}\n";
    { std::ofstream(file) << head << a << tail; }
    brdf::Preset p;
    p.name = "ignored";
    p.material = brdf::default_material();
    lab::viewer::export_to_scene(p, file.string(), "new");
    const std::string added = read(file);
    REQUIRE(added.size() > head.size() + a.size() + tail.size());
    CHECK(added.compare(0, head.size() + a.size(), head + a) == 0);
    CHECK(added.compare(head.size() + a.size(), 19, ",\n        \"new\": {\n") == 0);  // the new member after the last, indented as it
    CHECK(added.compare(added.size() - tail.size(), tail.size(), tail) == 0);
    lab::viewer::export_to_scene(p, file.string(), "a");
    const std::string replaced = read(file);
    CHECK(replaced.compare(0, head.size(), head) == 0);
    const std::string after_a = added.substr(head.size() + a.size());  // the new member and the tail
    CHECK(replaced.compare(replaced.size() - after_a.size(), after_a.size(), after_a) == 0);
    CHECK(lab::scene::load_scene(file.string()).materials.size() == 2);
    fs::remove_all(dir);
}
