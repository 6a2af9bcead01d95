// Bad environments are refused with one exact line naming the file (or the --env spec) and the
// problem; images written with the lab's image codec for the purpose, in a scratch folder.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "common/image_claim.hpp"
#include "common/image_codec.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "ibl/environment.hpp"

namespace fs = std::filesystem;
using single_source::float3;
using lab::ibl::EnvironmentOptions;

namespace {

fs::path scratch_folder() {
    const fs::path folder = fs::temp_directory_path() / "dtoadq_ibl_tests";
    fs::create_directories(folder);
    return folder;
}

// A float image of width x height x channels, every value `fill`, encoded by the lab's image codec
// (OpenImageIO) in the format of the name's extension: 8-bit for .png, float otherwise.
std::string write_image(const std::string& name, int width, int height, int channels, float fill,
                        const std::vector<std::pair<size_t, float>>& overrides = {}, const std::string& compression = "") {
    const std::string path = (scratch_folder() / name).string();
    std::vector<float> pixels(size_t(width) * height * channels, fill);
    for (const auto& [index, value] : overrides) pixels[index] = value;
    lab::codec::Encoding encoding;
    encoding.width = width;
    encoding.height = height;
    encoding.channels = channels;
    if (!compression.empty()) {
        lab::codec::Attribute a;
        a.name = "compression";
        a.text = compression;
        encoding.attributes.push_back(a);
    }
    std::vector<uint8_t> bytes;
    if (fs::path(path).extension() == ".png") {
        for (float v : pixels) bytes.push_back(uint8_t(std::lround(255.0f * std::fmin(std::fmax(v, 0.0f), 1.0f))));
        encoding.bytes = true;
        encoding.pixels = bytes.data();
    } else {
        encoding.pixels = pixels.data();
    }
    std::vector<unsigned char> file;
    std::string error;
    const bool encoded = lab::codec::image_codec().encode(path, encoding, &file, &error);
    INFO(error);
    REQUIRE(encoded);
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()));
    return path;
}

std::string write_bytes(const std::string& name, const std::string& bytes) {
    const std::string path = (scratch_folder() / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// The message load_environment() throws, or "" when it loads.
std::string load_error(const std::string& spec, const EnvironmentOptions& options = {}) {
    try {
        lab::ibl::load_environment(spec, options);
    } catch (const lab::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("ibl: unreadable environment files are refused with one line", "[ibl]") {
    CHECK(load_error("envmaps/no_such_file.exr") == "envmaps/no_such_file.exr: no such file");
    CHECK(load_error("envmaps") == "envmaps: not a regular file");
    CHECK(load_error("envmaps/SOURCES.txt") == "envmaps/SOURCES.txt: unsupported image format \".txt\" (expected .exr or .hdr)");

    const std::string garbage = write_bytes("garbage.exr", "these bytes are not an OpenEXR image\n");
    CHECK(load_error(garbage) == garbage + ": cannot be read as an OpenEXR or Radiance HDR image");

    // The header of a real file without most of its pixel data.
    std::ifstream real("envmaps/courtyard.exr", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(real)), std::istreambuf_iterator<char>());
    REQUIRE(bytes.size() > 100000);
    const std::string truncated = write_bytes("truncated.exr", bytes.substr(0, bytes.size() / 3));
    CHECK(load_error(truncated) == truncated + ": pixels: cannot be read (corrupt or truncated file)");

    // A PNG behind an .exr name.
    const std::string png = write_image("picture.png", 8, 4, 3, 0.5f);
    const std::string disguised = (scratch_folder() / "picture.exr").string();
    fs::copy_file(png, disguised, fs::copy_options::overwrite_existing);
    CHECK(load_error(disguised) == disguised + ": holds a png image, not OpenEXR or Radiance HDR");
}

TEST_CASE("ibl: environment images with a bad shape or bad pixels are refused", "[ibl]") {
    const std::string wide = write_image("size.exr", 40, 30, 3, 1.0f);
    CHECK(load_error(wide) == wide + ": size: 40 x 30 is not 2:1 (a lat-long image is twice as wide as it is tall)");
    const std::string two = write_image("two_channels.exr", 16, 8, 2, 1.0f);
    CHECK(load_error(two) == two + ": channels: 2 (expected 1 for grey, or 3 or more with R, G, B first)");

    // NaN in G of pixel (5, 3); +infinity in R of pixel (2, 1).
    const std::string nan = write_image("nan.exr", 16, 8, 3, 1.0f, {{(3 * 16 + 5) * 3 + 1, NAN}});
    CHECK(load_error(nan) == nan + ": pixel (5, 3): G is NaN (radiance must be finite)");
    const std::string inf = write_image("inf.exr", 16, 8, 4, 1.0f, {{(1 * 16 + 2) * 4 + 0, INFINITY}});
    CHECK(load_error(inf) == inf + ": pixel (2, 1): R is infinite (radiance must be finite)");
}

TEST_CASE("ibl: negative pixels become 0, grey and Radiance HDR images load", "[ibl]") {
    EnvironmentOptions small;
    small.face_size = 4;
    // Negative everywhere but one channel: what lossy DWAB compression leaves behind, clamped.
    const std::string negative = write_image("negative.exr", 16, 8, 3, -0.5f);
    const lab::ibl::Environment dark = lab::ibl::load_environment(negative, small);
    CHECK(dark.radiance(float3(0, 0, 1)) == float3(0.0f));
    CHECK(dark.source() == negative);

    const std::string grey = write_image("grey.exr", 16, 8, 1, 0.75f);
    CHECK(lab::ibl::load_environment(grey, small).radiance(float3(1, 2, 3)) == float3(0.75f));

    // RGBE stores 8-bit mantissas with a shared exponent: 1, 2 and 4 are exact.
    std::vector<std::pair<size_t, float>> rgb;
    for (size_t p = 0; p < 16 * 8; ++p) rgb.push_back({p * 3 + 1, 2.0f}), rgb.push_back({p * 3 + 2, 4.0f});
    const std::string hdr = write_image("colour.hdr", 16, 8, 3, 1.0f, rgb);
    CHECK(lab::ibl::load_environment(hdr, small).radiance(float3(0, -1, 0)) == float3(1.0f, 2.0f, 4.0f));
}

TEST_CASE("ibl: bad constant specs and options are refused with one line", "[ibl]") {
    CHECK(load_error("") == "--env: empty environment (expected an .exr or .hdr file, or constant:R,G,B)");
    CHECK(load_error("constant:1,2") == "--env: constant: expected three numbers R,G,B, got 2 in \"1,2\"");
    CHECK(load_error("constant:1,2,3,4") == "--env: constant: expected three numbers R,G,B, got 4 in \"1,2,3,4\"");
    CHECK(load_error("constant:") == "--env: constant: expected three numbers R,G,B, got 1 in \"\"");
    CHECK(load_error("constant:1,x,3") == "--env: constant: G is not a number: \"x\"");
    CHECK(load_error("constant:1,2,3cd") == "--env: constant: B is not a number: \"3cd\"");
    CHECK(load_error("constant:1,,3") == "--env: constant: G is not a number: \"\"");
    CHECK(load_error("constant:nan,1,1") == "--env: constant: R is not a finite float: \"nan\"");
    CHECK(load_error("constant:1,inf,1") == "--env: constant: G is not a finite float: \"inf\"");
    CHECK(load_error("constant:1,1,1e39") == "--env: constant: B is not a finite float: \"1e39\"");
    CHECK(load_error("constant:1,1,-0.5") == "--env: constant: B is negative: \"-0.5\"");
    // Spaces around numbers are fine; the source keeps the spec as written.
    CHECK(lab::ibl::load_environment("constant: 1, 2 ,3").radiance(float3(1, 0, 0)) == float3(1, 2, 3));

    EnvironmentOptions scene;
    scene.origin = "scenes/room.json: environment";
    CHECK(load_error("constant:1", scene) ==
          "scenes/room.json: environment: constant: expected three numbers R,G,B, got 1 in \"1\"");

    EnvironmentOptions bad;
    bad.face_size = -1;
    CHECK(load_error("constant:1,1,1", bad) == "--env: face_size: must be in [1, 4096] (0: automatic), got -1");
    bad.face_size = 5000;
    CHECK(load_error("constant:1,1,1", bad) == "--env: face_size: must be in [1, 4096] (0: automatic), got 5000");
    bad = {};
    bad.rotation_degrees = NAN;
    CHECK(load_error("constant:1,1,1", bad) == "--env: rotation_degrees: not a finite number");
    bad = {};
    bad.exposure_stops = 100.0f;
    CHECK(load_error("constant:1,1,1", bad) == "--env: exposure_stops: must be a number in [-64, 64], got 100");
    bad.exposure_stops = NAN;
    CHECK(load_error("constant:1,1,1", bad) == "--env: exposure_stops: must be a number in [-64, 64], got nan");
}

TEST_CASE("ibl: a header that claims more pixels than its file or the machine can hold is refused before they are allocated", "[ibl]") {
    // A Radiance header that says 32768 x 16384 over 100 bytes: 32768 is past the run-length
    // encoding's 32767, so its scanlines are flat, 4 bytes a pixel. Read, it would allocate 6.4 GB
    // for the pixels before finding them missing.
    const std::string hdr = write_bytes("claims_32k.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16384 +X 32768\n" + std::string(100, '\x02'));
    CHECK(load_error(hdr) == hdr + ": size: 32768 x 16384 cannot be held by a file of 153 bytes (at least 2147483648 in hdr): a corrupt header");
    const std::string rle = write_bytes("claims_16k.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 16384\n" + std::string(100, '\x02'));
    CHECK(load_error(rle) == rle + ": size: 16384 x 8192 cannot be held by a file of 152 bytes (at least 8552448 in hdr): a corrupt header");

    // An OpenEXR file of 16 x 8 (ZIP: one chunk of 16 scanlines) made to say 32768 x 16384: the
    // header's box2i "dataWindow" given xMax, yMax, and a line-offset table of the 1024 chunks that
    // claims, all pointing at the one chunk, so that OpenEXR opens it and would read on.
    std::ifstream small(write_image("small.exr", 16, 8, 3, 1.0f, {}, "zip"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(small)), std::istreambuf_iterator<char>());
    const std::string key = std::string("dataWindow") + '\0' + "box2i" + '\0';
    const size_t at = bytes.find(key);
    REQUIRE(at != std::string::npos);
    const int32_t window[4] = {0, 0, 32767, 16383};
    bytes.replace(at + key.size() + 4, sizeof window, reinterpret_cast<const char*>(window), sizeof window);
    size_t table = 0;  // the one offset: the 8 bytes just before the chunk they point at
    for (size_t p = at; p + 8 <= bytes.size() && table == 0; ++p) {
        uint64_t offset;
        std::memcpy(&offset, bytes.data() + p, 8);
        if (offset == p + 8) table = p;
    }
    REQUIRE(table > 0);
    std::string offsets;
    for (int chunk = 0; chunk < 1024; ++chunk) {
        const uint64_t offset = table + 1024 * 8;
        offsets.append(reinterpret_cast<const char*>(&offset), 8);
    }
    bytes = bytes.substr(0, table) + offsets + bytes.substr(table + 8);
    const std::string exr = write_bytes("claims_32k.exr", bytes);
    CHECK(load_error(exr) == exr + ": size: 32768 x 16384 cannot be held by a file of " + std::to_string(bytes.size()) +
                                 " bytes (at least 48771 in openexr): a corrupt header");
    // the films that merge and --resume read go through the same check
    CHECK_THROWS_WITH(lab::film::read_image(exr, nullptr), exr + ": size: 32768 x 16384 cannot be held by a file of " +
                                                               std::to_string(bytes.size()) + " bytes (at least 48771 in openexr): a corrupt header");

    // Memory: the floats to be read against half of a machine's memory.
    lab::codec::Header header;
    header.format = "openexr";
    header.width = 2048;
    header.height = 1024;
    header.channels = 3;
    try {
        lab::codec::check_image_claim("map.exr", header, 1u << 20, 3, 40000000);
        FAIL("25 MB of floats accepted on a machine of 40 MB");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == "map.exr: size: 2048 x 1024 needs 25 MB to read, more than half of this machine's 40 MB");
    }
    CHECK_NOTHROW(lab::codec::check_image_claim("map.exr", header, 1u << 20, 3, 60000000));
    CHECK_NOTHROW(lab::codec::check_image_claim("map.exr", header, 1u << 20, 3, 0));  // memory unknown: no bound
}

TEST_CASE("ibl: no image is smaller than the claim check's least size for it: constant images, the most compressible, in each encoding", "[ibl]") {
    // A constant image is what every encoding shrinks most; were the bound not a bound, a real file
    // would be refused. 1024 x 512 (RLE scanlines of 1024 pixels) and 2048 x 8 (many per chunk).
    for (const auto& [width, height] : {std::pair<int, int>{1024, 512}, {2048, 8}}) {
        struct Case {
            std::string name, compression;
            int channels;
        };
        const std::vector<Case> cases = {{"constant.hdr", "", 3},           {"constant_dwab.exr", "dwab", 3}, {"constant_dwaa.exr", "dwaa", 3},
                                         {"constant_zip.exr", "zip", 3},     {"constant_piz.exr", "piz", 4},   {"constant_rle.exr", "rle", 1},
                                         {"constant_b44a.exr", "b44a", 3},   {"constant.png", "", 3}};
        for (const Case& c : cases) {
            const std::string path = write_image(c.name, width, height, c.channels, 0.25f, {}, c.compression);
            std::string error;
            std::unique_ptr<lab::codec::ImageFile> file = lab::codec::image_codec().open(path, &error);
            INFO(error);
            REQUIRE(file);
            const uint64_t least = lab::codec::minimum_encoded_bytes(file->header().format, width, height, c.channels);
            const uint64_t size = uint64_t(fs::file_size(path));
            INFO(c.name << " " << width << " x " << height << ": " << size << " bytes, bound " << least);
            CHECK(least > 0);
            CHECK(size >= least);
        }
    }
}
