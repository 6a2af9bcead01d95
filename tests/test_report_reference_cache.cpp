// The report's cached references (report/reference_cache.hpp): a reference is rendered once and
// read back while its key holds; another key, another image size, or a file that is no reference
// of the lab renders it again. On the host build of the path tracer, a white sphere at 8 x 8.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include "render/host_renderer.hpp"
#include "report/reference_cache.hpp"
#include "tests/render_inputs.hpp"

namespace {

struct CountingFactory {
    int made = 0;
    lab::report::RendererFactory factory() {
        return [this](const lab::render::RenderInput& input) {
            ++made;
            return std::make_unique<lab::render::HostRenderer>(input, 1);
        };
    }
};

bool same_pixels(const lab::film::ImageRgb& a, const lab::film::ImageRgb& b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("Report references: rendered once, reused while the key holds, rendered again when it does not", "[report]") {
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / "dtoadq_test_reference_cache";
    fs::remove_all(folder);
    const std::string exr = (folder / "references" / "sphere.exr").string();
    lab::render::RenderInput input =
        render_input(std::nullopt, "constant:0.5,0.5,0.5", 8, lab::render::LightSampling::mis, 3, kWhiteSphereScene);
    CountingFactory counting;
    bool reused = true;
    const lab::report::Reference first = lab::report::cached_reference(exr, "key A", counting.factory(), input, 0.05, &reused);
    CHECK_FALSE(reused);
    CHECK(counting.made == 2);  // its two halves
    REQUIRE(fs::is_regular_file(exr));
    CHECK(first.samples_per_pixel > 0);
    CHECK(first.relative_noise > 0.0);

    const lab::report::Reference again = lab::report::cached_reference(exr, "key A", counting.factory(), input, 0.05, &reused);
    CHECK(reused);
    CHECK(counting.made == 2);
    CHECK(same_pixels(again.image, first.image));
    CHECK(again.samples_per_pixel == first.samples_per_pixel);
    CHECK(again.relative_noise == Approx(first.relative_noise).epsilon(1e-6));  // stored as a float

    lab::report::cached_reference(exr, "key B", counting.factory(), input, 0.05, &reused);
    CHECK_FALSE(reused);
    CHECK(counting.made == 4);

    lab::render::RenderInput larger = input;
    larger.settings.width = larger.settings.height = 12;
    lab::report::cached_reference(exr, "key B", counting.factory(), larger, 0.05, &reused);
    CHECK_FALSE(reused);
    CHECK(counting.made == 6);

    std::ofstream(exr, std::ios::trunc) << "not an image";
    const lab::report::Reference rendered = lab::report::cached_reference(exr, "key B", counting.factory(), larger, 0.05, &reused);
    CHECK_FALSE(reused);
    CHECK(counting.made == 8);
    CHECK(rendered.image.width == 12);
    fs::remove_all(folder);
}

TEST_CASE("Report references: the digest of a key tells texts apart", "[report]") {
    CHECK(lab::report::text_digest("") == "cbf29ce484222325");  // FNV-1a's offset basis: nothing hashed
    CHECK(lab::report::text_digest("a") == "af63dc4c8601ec8c");
    CHECK(lab::report::text_digest("scene 1") != lab::report::text_digest("scene 2"));
}
