// Rect and disk emitters that show an image (kernels/lights/image_emitter.h, render/emitter_images.hpp):
// chi-square of their samples against image_emitter_pdf on a rect and a disk, the test's power to
// reject a wrong image pdf, the image shown unmirrored and the disk's inverse map, their power
// against the flux through a sphere, and reading their images: PNG decoded from sRGB, and bad images
// giving one line naming the scene's field and the file (docs/lights.md, "Image emitters").
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include "common/input_error.hpp"
#include "common/luminance.hpp"
#include "film/image_output.hpp"
#include "film/tone_map.hpp"
#include "kernels/host.hpp"
#include "render/emitter_images.hpp"
#include "render/light_set.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "validation/chi_square.hpp"

#include "tests/light_sampling_fixtures.hpp"

using brdf::float3;
namespace validation = lab::validation;
using light_fixtures::area_case_point;
using light_fixtures::area_light_reach;
using light_fixtures::AreaCase;
using light_fixtures::check_flux_through_sphere;
using light_fixtures::ConeZoom;
using light_fixtures::kAreaCases;
using light_fixtures::kAreaCenter;
using light_fixtures::kAreaFrame;
using light_fixtures::kDisk;
using light_fixtures::kPi;
using light_fixtures::kRect;
using light_fixtures::light_chi_square_options;

namespace {

// Image emitters (kernels/lights/image_emitter.h): an 8 x 4 image with a dark row (the file's row 1,
// all 0), a bright texel (20 at column 5 of row 2) and a gradient elsewhere, shown by the rect and
// the disk of tests/light_sampling_fixtures.hpp with a scale of (1, 0.5, 2), bound after one alias entry of its own
// (offset 0 means no image).
constexpr int kImageWidth = 8, kImageHeight = 4;
std::vector<float> test_image_pixels() {
    std::vector<float> rgb(size_t(kImageWidth) * kImageHeight * 3);
    for (int y = 0; y < kImageHeight; ++y)
        for (int x = 0; x < kImageWidth; ++x) {
            const float v = y == 1 ? 0.0f : (x == 5 && y == 2 ? 20.0f : 0.2f + 0.1f * float(x + 3 * y));
            float* p = &rgb[3 * (size_t(y) * kImageWidth + size_t(x))];
            p[0] = v;
            p[1] = 0.5f * v + 0.05f;
            p[2] = y == 1 ? 0.0f : 0.3f;
        }
    return rgb;
}

struct ImageLights {
    lab::render::LightSet set;
    std::vector<brdf::float4> texels;
    std::vector<kernel::AliasEntry> alias{kernel::AliasEntry{1.0f, 0}};
    ImageLights() {
        const lab::render::EmitterImage image = lab::render::emitter_image_from_pixels("test.exr", kImageWidth, kImageHeight, test_image_pixels());
        for (const kernel::Light* l : {&kRect, &kDisk}) {
            kernel::Light copy = *l;
            kernel::float3_to_array(float3(1.0f, 0.5f, 2.0f), copy.emission);
            set.lights.push_back(copy);
        }
        bind_emitter_images({image, image}, &set, &texels, &alias);
    }
    kernel::EnvironmentBuffers buffers() const { return kernel::EnvironmentBuffers{texels.data(), alias.data()}; }
};

// Whether st lies within `margin` of a line between two texels.
bool near_texel_edge(kernel::float2 st, double margin) {
    const double x = st.x * kImageWidth, y = st.y * kImageHeight;
    return std::fabs(x - std::round(x)) < margin * kImageWidth || std::fabs(y - std::round(y)) < margin * kImageHeight;
}

// The image emitter's sampler as a direction sampler, each sample keeping kernels/lights/light.h's
// promises: its point lies on the light, its pdf is image_emitter_pdf of its direction and its
// radiance image_emitter_radiance at its point (the texel the direction finds again may be the
// neighbour only for a point within float rounding, 1e-5, of a texel edge).
validation::DirectionSampler image_sampler(const kernel::Light& l, kernel::EnvironmentBuffers b, float3 p, const ConeZoom& zoom) {
    return [&l, b, p, &zoom](float3 u) {
        validation::DirectionSample s;
        const kernel::LightSample ls = kernel::image_emitter_sample(&l, b, p, kernel::make_float2(u.x, u.y));
        if (!(ls.pdf > 0.0f)) return s;  // Failed
        s.kind = validation::SampleKind::Continuous;
        s.wi = zoom.forward(ls.wi);
        const float pdf = kernel::image_emitter_pdf(&l, b, p, ls.wi);
        const float3 radiance = kernel::image_emitter_radiance(&l, b, ls.position, -ls.wi);
        if (!kernel::area_light_contains(&l, ls.position))
            s.defect = "sampled point off the light";
        else if (!(radiance == ls.radiance))
            s.defect = "radiance is not the texel's at the sampled point";
        else if (!(std::fabs(pdf - ls.pdf) <= 2e-4f * ls.pdf) && !near_texel_edge(kernel::area_light_st(&l, ls.position), 1e-5))
            s.defect = "sample pdf " + std::to_string(ls.pdf) + " but image_emitter_pdf " + std::to_string(pdf);
        return s;
    };
}

// image_emitter_pdf through the zoom, or a broken density: `broken` 1 reads the texel one column to
// the right of the direction's (wrapping), 2 ignores the texels (the uniform area density).
validation::DirectionDensity image_density(const kernel::Light& l, kernel::EnvironmentBuffers b, float3 p, const ConeZoom& zoom, int broken = 0) {
    return [&l, b, p, &zoom, broken](float3 w) {
        float3 original;
        if (!zoom.backward(w, &original)) return 0.0;
        if (broken == 0) return double(kernel::image_emitter_pdf(&l, b, p, original)) * zoom.jacobian();
        float t, cos_l;
        if (!kernel::area_light_ray_hit(&l, p, original, &t, &cos_l)) return 0.0;
        double pdf_area = 1.0 / double(kernel::area_light_area(&l));
        if (broken == 1) {
            const kernel::float2 st = kernel::area_light_st(&l, p + original * t);
            const int column = (std::min(int(st.x * kImageWidth), kImageWidth - 1) + 1) % kImageWidth;
            const int row = std::min(int(st.y * kImageHeight), kImageHeight - 1);
            const kernel::EmitterImage im = kernel::emitter_image(&l, b);
            pdf_area *= double(b.texels[im.texels + row * kImageWidth + column].w) * kImageWidth * kImageHeight;
        }
        return pdf_area * double(t) * t / cos_l * zoom.jacobian();
    };
}

}  // namespace

TEST_CASE("lights: image emitter samples follow image_emitter_pdf on a rect and a disk (chi-square)", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    for (int k = 0; k < 2; ++k) {
        const kernel::Light& l = lights.set.lights[size_t(k)];
        const AreaCase& c = kAreaCases[k == 0 ? 0 : 4];  // near the rect's centre, near the disk's rim
        const float3 p = area_case_point(c);
        const ConeZoom zoom(kAreaCenter, area_light_reach(l), p);
        validation::ChiSquareOptions options = light_chi_square_options(1000000, 2);
        const validation::ChiSquareResult r = validation::chi_square_test(image_sampler(l, b, p, zoom), image_density(l, b, p, zoom), options);
        INFO((k == 0 ? "rect" : "disk") << ": " << validation::describe(r));
        std::printf("[lights] chi-square image emitter, %s, %s: %s\n", k == 0 ? "rect" : "disk", c.what, validation::describe(r).c_str());
        CHECK(r.passed);
        CHECK(r.failed_fraction == 0.0);
        CHECK(r.pdf_integral == Approx(1.0).margin(2e-3));
        // a light subpath's origin: drawn by image_emitter_sample_point, its density light_area_pdf
        const float3 q = kernel::image_emitter_sample_point(&l, b, kernel::make_float2(0.3f, 0.7f));
        float3 n;
        const float3 q2 = kernel::light_sample_area(&l, b, kernel::make_float2(0.3f, 0.7f), &n);
        CHECK(q == q2);
        CHECK(kernel::light_area_pdf(&l, b, q) == kernel::image_emitter_area_pdf(&l, b, q));
        // behind it: nothing
        const glm::dvec3 behind = glm::dvec3(p) - 2.0 * kAreaFrame.n * c.offset.z;
        CHECK(kernel::image_emitter_sample(&l, b, float3(behind), kernel::make_float2(0.3f, 0.6f)).pdf == 0.0f);
        CHECK(kernel::image_emitter_pdf(&l, b, float3(behind), float3(glm::normalize(kAreaCenter - behind))) == 0.0f);
    }
}

TEST_CASE("lights: the chi-square test rejects an image pdf off by one texel or ignoring the texels", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    for (int k = 0; k < 2; ++k) {
        const kernel::Light& l = lights.set.lights[size_t(k)];
        const float3 p = area_case_point(kAreaCases[k == 0 ? 0 : 4]);
        const ConeZoom zoom(kAreaCenter, area_light_reach(l), p);
        for (int broken : {1, 2}) {
            validation::ChiSquareOptions options = light_chi_square_options(100000, 4);
            const validation::ChiSquareResult r = validation::chi_square_test(image_sampler(l, b, p, zoom), image_density(l, b, p, zoom, broken), options);
            std::printf("[lights] broken input, image emitter %s, %s: %s\n", k == 0 ? "rect" : "disk",
                        broken == 1 ? "pdf of the texel one column over" : "pdf uniform by area", validation::describe(r).c_str());
            CHECK_FALSE(r.passed);
        }
    }
}

TEST_CASE("lights: an image emitter shows its image unmirrored from the emitting side, and its inverse map is exact", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    const std::vector<float> rgb = test_image_pixels();
    const kernel::Light& rect = lights.set.lights[0];
    const glm::dvec3 u(rect.edge_u[0], rect.edge_u[1], rect.edge_u[2]), v(rect.edge_v[0], rect.edge_v[1], rect.edge_v[2]);
    // the file's pixel (x, y), rows from the top, at c + ((x + 1/2) / W - 1/2) U + (1/2 - (y + 1/2) / H) V: seen from the
    // emitting side (looking along -n, n = U x V) with U to the right, V is up, so the file's first row is at the top
    for (int y = 0; y < kImageHeight; ++y)
        for (int x = 0; x < kImageWidth; ++x) {
            const glm::dvec3 q = kAreaCenter + u * ((x + 0.5) / kImageWidth - 0.5) + v * (0.5 - (y + 0.5) / kImageHeight);
            const float3 le = kernel::image_emitter_radiance(&rect, b, float3(q), kernel::area_light_normal(&rect));
            const float* pixel = &rgb[3 * (size_t(y) * kImageWidth + size_t(x))];
            CHECK(le == float3(pixel[0] * 1.0f, pixel[1] * 0.5f, pixel[2] * 2.0f));
            CHECK(kernel::image_emitter_radiance(&rect, b, float3(q), -kernel::area_light_normal(&rect)) == float3(0.0f));
        }
    // the inverse concentric map undoes the map over the square
    validation::UniformRandom rng(5);
    double worst = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const float s = rng.next_float(), t = rng.next_float();
        const kernel::float2 d = kernel::square_to_concentric_disk(s, t);
        const kernel::float2 back = kernel::concentric_disk_to_square(d.x, d.y);
        worst = std::max(worst, double(std::max(std::fabs(back.x - s), std::fabs(back.y - t))));
    }
    CHECK(worst < 2e-6);
}

// An image emitter's power, pi A times the luminance of scale x the image's mean RGB, is the flux its
// samples send through a sphere around it (as for the constant rect and disk above).
TEST_CASE("lights: an image emitter's power is the flux through a sphere around it", "[lights][area][image]") {
    const ImageLights lights;
    const kernel::EnvironmentBuffers b = lights.buffers();
    const lab::render::EmitterImage image = lab::render::emitter_image_from_pixels("test.exr", kImageWidth, kImageHeight, test_image_pixels());
    for (size_t k = 0; k < 2; ++k) {
        const kernel::Light& l = lights.set.lights[k];
        const double power = lab::render::image_light_power(l, image.mean_rgb);
        // by hand: the mean over the texels of scale x texel, its luminance
        double r = 0.0, g = 0.0, bl = 0.0;
        const std::vector<float> rgb = test_image_pixels();
        for (size_t p = 0; p < rgb.size() / 3; ++p) {
            r += rgb[3 * p];
            g += 0.5 * rgb[3 * p + 1];
            bl += 2.0 * rgb[3 * p + 2];
        }
        const double n_texels = double(kImageWidth * kImageHeight);
        CHECK(power == Approx(kPi * lab::luminance(r / n_texels, g / n_texels, bl / n_texels) * kernel::area_light_area(&l)).epsilon(1e-6));
        check_flux_through_sphere(l, b, power, 29 + k, k == 0 ? "image rect" : "image disk");
    }
}

namespace {

// A scene whose rect shows the image at `path` (absolute), compiled.
lab::scene::CompiledScene emitter_image_scene(const std::string& path, const std::string& radiance = "") {
    const std::string text = R"({"camera": {"type": "pinhole", "position": [0, 0, 5], "look_at": [0, 0, 0], "fov_degrees": 40},
      "emitters": [{"type": "sphere", "center": [3, 0, 0], "radius": 0.5, "radiance": [1, 1, 1]},
                   {"type": "point", "position": [0, 3, 0], "intensity": [1, 1, 1]},
                   {"type": "rect", "center": [0, 1, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "image": ")" + path + "\"" + radiance + "}]}";
    return lab::scene::compile_scene(lab::scene::parse_scene(text, "scenes/screen.json"));
}

std::string emitter_image_error(const std::string& path) {
    try {
        lab::render::load_emitter_images(emitter_image_scene(path), 0.0);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "";
}

std::string emitter_temp_file(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("dtoadq-emitter-images-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    return (folder / name).string();
}

}  // namespace

TEST_CASE("lights: an emitter's image is read as environments are, and bad images give one line naming the scene's field and the file", "[lights][image]") {
    // a 3 x 2 PNG: sRGB-decoded to linear; rows from the top of the file land at t = 1 first
    const std::string png = emitter_temp_file("screen.png");
    const std::vector<uint8_t> bytes = {0, 0, 0, 64, 64, 64, 128, 128, 128, 255, 255, 255, 10, 20, 30, 200, 100, 50};
    lab::film::write_srgb8_png(png, 3, 2, bytes, lab::film::ImageMetadata{});
    const std::vector<std::optional<lab::render::EmitterImage>> images = lab::render::load_emitter_images(emitter_image_scene(png), 0.0);
    REQUIRE(images.size() == 2);  // the sphere and the rect; the point light is no emitter
    CHECK_FALSE(images[0].has_value());
    REQUIRE(images[1].has_value());
    CHECK(images[1]->width == 3);
    CHECK(images[1]->height == 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c) {
                const brdf::float4 t = images[1]->texels[size_t(1 - y) * 3 + size_t(x)];
                CHECK(t[c] == Approx(lab::film::srgb_decode(float(bytes[size_t(3 * (3 * y + x) + c)]) / 255.0f)).epsilon(1e-6));
            }
    // the scale defaults to 1 with an image
    CHECK(emitter_image_scene(png).emitters[1].radiance == brdf::float3(1.0f));
    CHECK(emitter_image_scene(png, R"(, "radiance": [2, 1, 0.5])").emitters[1].radiance == brdf::float3(2.0f, 1.0f, 0.5f));

    const std::string missing = emitter_temp_file("none.exr");
    CHECK(emitter_image_error(missing) == "scenes/screen.json: emitters[2].image: " + missing + ": no such file");
    const std::string corrupt = emitter_temp_file("corrupt.exr");
    { std::FILE* f = std::fopen(corrupt.c_str(), "wb"); std::fputs("not an image", f); std::fclose(f); }
    CHECK(emitter_image_error(corrupt) == "scenes/screen.json: emitters[2].image: " + corrupt + ": cannot be read as an OpenEXR, Radiance HDR or PNG image");
    const std::string text = emitter_temp_file("screen.txt");
    { std::FILE* f = std::fopen(text.c_str(), "wb"); std::fputs("x", f); std::fclose(f); }
    CHECK(emitter_image_error(text) == "scenes/screen.json: emitters[2].image: " + text + ": unsupported image format \".txt\" (expected .exr, .hdr or .png)");
    for (float bad : {std::nanf(""), -0.5f, std::numeric_limits<float>::infinity()}) {
        lab::film::ImageRgb image(2, 2);
        image.rgb[3 * 1 + 2] = bad;  // pixel (1, 0), B
        const std::string path = emitter_temp_file("bad.exr");
        lab::film::write_exr(path, image, lab::film::ImageMetadata{});
        const std::string what = std::isnan(bad) ? "NaN" : (bad < 0.0f ? "negative" : "infinite");
        CHECK(emitter_image_error(path) == "scenes/screen.json: emitters[2].image: " + path + ": pixel (1, 0): B is " + what + " (radiance must be finite and >= 0)");
    }
    // a header that claims more than the file can hold is refused before anything is allocated
    // (common/image_claim.hpp), and sizes past the limit by their own line
    CHECK_THROWS_WITH(lab::render::emitter_image_from_pixels("big.exr", lab::render::kMaxEmitterImageSide + 1, 1, {}),
                      "big.exr: size: 4097 x 1 (an emitter's image has 1 to 4096 texels a side)");
    std::error_code ec;
    std::filesystem::remove_all(std::filesystem::path(png).parent_path(), ec);
}
