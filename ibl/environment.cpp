#include "ibl/environment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "common/input_error.hpp"
#include "common/message_number.hpp"
#include "ibl/distribution.hpp"
#include "ibl/radiance_image.hpp"

namespace lab::ibl {

// The alias tables name cells by int (ibl/alias_table.h).
static_assert(int64_t(CUBEMAP_FACES) * kMaxFaceSize * (kMaxFaceSize + 1) <= INT32_MAX, "an alias table's cell must fit an int");

namespace {

void validate(const EnvironmentOptions& options) {
    if (!std::isfinite(options.rotation_degrees))
        throw InputError(options.origin, "rotation_degrees", "not a finite number");
    if (!(std::fabs(options.exposure_stops) <= kMaxExposureStops))
        throw InputError(options.origin, "exposure_stops",
                         "must be a number in [-64, 64], got " + message_number(options.exposure_stops));
    if (options.face_size < 0 || options.face_size > kMaxFaceSize)
        throw InputError(options.origin, "face_size",
                         "must be in [1, 4096] (0: automatic), got " + std::to_string(options.face_size));
}

// cos and sin of the rotation, exact for multiples of 90 degrees so that those turns move texels
// without resampling error.
void rotation(float degrees, float* c, float* s) {
    double r = std::fmod(double(degrees), 360.0);
    if (r < 0.0) r += 360.0;
    if (r == 0.0 || r == 90.0 || r == 180.0 || r == 270.0) {
        const int quarter = int(r / 90.0);
        const float cosines[4] = {1.0f, 0.0f, -1.0f, 0.0f}, sines[4] = {0.0f, 1.0f, 0.0f, -1.0f};
        *c = cosines[quarter];
        *s = sines[quarter];
        return;
    }
    const double radians = r * (3.14159265358979323846 / 180.0);
    *c = float(std::cos(radians));
    *s = float(std::sin(radians));
}

std::string trim(const std::string& s) {
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

// "R,G,B" after "constant:".
single_source::float3 parse_constant(const std::string& text, const std::string& origin) {
    std::vector<std::string> parts;
    size_t start = 0;
    while (true) {
        size_t comma = text.find(',', start);
        parts.push_back(trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (parts.size() != 3)
        throw InputError(origin, "constant",
                         "expected three numbers R,G,B, got " + std::to_string(parts.size()) + " in \"" + text + "\"");
    const char* names[3] = {"R", "G", "B"};
    float value[3];
    for (int c = 0; c < 3; ++c) {
        const std::string& p = parts[c];
        char* end = nullptr;
        const double v = p.empty() ? 0.0 : std::strtod(p.c_str(), &end);
        if (p.empty() || end != p.c_str() + p.size())
            throw InputError(origin, "constant", std::string(names[c]) + " is not a number: \"" + p + "\"");
        value[c] = float(v);
        if (!std::isfinite(value[c]))
            throw InputError(origin, "constant", std::string(names[c]) + " is not a finite float: \"" + p + "\"");
        if (value[c] < 0.0f)
            throw InputError(origin, "constant", std::string(names[c]) + " is negative: \"" + p + "\"");
    }
    return single_source::float3(value[0], value[1], value[2]);
}

}  // namespace

Environment::Environment(std::vector<single_source::float4> texels, int face_size, std::string source,
                         const EnvironmentOptions& options)
    : texels_(std::move(texels)), source_(std::move(source)) {
    map_.face_size = face_size;
    for (const single_source::float4& t : texels_) brightest_ = std::max({brightest_, t.x, t.y, t.z});
    set_transform(options.rotation_degrees, options.exposure_stops);
    alias_ = build_cubemap_alias_tables(texels_, face_size);
    store_texel_probabilities(alias_, face_size, &texels_);  // environment_pdf() reads them
}

Environment Environment::from_image(const LatLongImage& image, std::string source, const EnvironmentOptions& options) {
    validate(options);
    const int n = options.face_size > 0 ? options.face_size
                                        : std::clamp(image.width / 4, kMinAutomaticFaceSize, kMaxAutomaticFaceSize);
    return Environment(equirect_to_cubemap(image, n), n, std::move(source), options);
}

Environment Environment::constant(single_source::float3 radiance, std::string source, const EnvironmentOptions& options) {
    validate(options);
    if (!single_source::finite3(radiance) || radiance.x < 0.0f || radiance.y < 0.0f || radiance.z < 0.0f)
        throw InputError(options.origin, "constant", "radiance must be finite and non-negative");
    const int n = options.face_size > 0 ? options.face_size : kMinAutomaticFaceSize;
    std::vector<single_source::float4> texels(size_t(CUBEMAP_FACES) * n * n, single_source::float4(radiance, 1.0f));
    return Environment(std::move(texels), n, std::move(source), options);
}

void Environment::set_transform(float rotation_degrees, float exposure_stops) {
    EnvironmentOptions options;
    options.rotation_degrees = rotation_degrees;
    options.exposure_stops = exposure_stops;
    options.origin = source_;
    validate(options);
    float intensity = std::exp2(exposure_stops);
    // Radiance is texel x intensity in float (ibl/environment.h): it must stay finite.
    if (!std::isfinite(brightest_ * intensity))
        throw InputError(source_, "exposure", "the brightest radiance, " + message_number(brightest_) + ", times 2^" +
                                                  message_number(exposure_stops) + " overflows a 32-bit float");
    rotation(rotation_degrees, &map_.rotation_cos, &map_.rotation_sin);
    map_.intensity = intensity;
    rotation_degrees_ = rotation_degrees;
    exposure_stops_ = exposure_stops;
}

single_source::float3 Environment::radiance(single_source::float3 direction) const {
    return ::ibl::environment_radiance(&map_, texels_.data(), direction);
}

single_source::float3 Environment::radiance_filtered(single_source::float3 direction) const {
    return ::ibl::environment_radiance_filtered(&map_, texels_.data(), direction);
}

single_source::float3 Environment::sample(float u1, float u2, float* pdf) const {
    return ::ibl::environment_sample(&map_, texels_.data(), alias_.data(), u1, u2, pdf);
}

float Environment::pdf(single_source::float3 direction) const {
    return ::ibl::environment_pdf(&map_, texels_.data(), direction);
}

LatLongImage read_latlong_image(const std::string& path) {
    RadianceImage image = read_radiance_image(path, {kOpenExr, kRadianceHdr}, [&](int width, int height) { check_latlong_size(path, width, height); });
    return latlong_from_pixels(path, image.width, image.height, std::move(image.pixels), image.channel_names);
}

void check_latlong_size(const std::string& path, int width, int height) {
    if (width != 2 * height || height <= 0)
        throw InputError(path, "size",
                         std::to_string(width) + " x " + std::to_string(height) +
                             " is not 2:1 (a lat-long image is twice as wide as it is tall)");
    if (height > kMaxLatLongHeight)
        throw InputError(path, "size", std::to_string(width) + " x " + std::to_string(height) + " exceeds 32768 x 16384");
}

LatLongImage latlong_from_pixels(const std::string& path, int width, int height, std::vector<float> pixels,
                                 const std::vector<std::string>& channel_names) {
    check_latlong_size(path, width, height);
    const int used = int(channel_names.size());
    if ((used != 1 && used != 3) || pixels.size() != size_t(width) * height * used)
        throw std::invalid_argument("latlong_from_pixels: pixels hold width x height x 1 or 3 floats");
    LatLongImage image;
    image.width = width;
    image.height = height;
    // RGB pixels become the image in place: a map of gigabytes is held once, not twice
    if (used == 3) image.rgb = std::move(pixels);
    else image.rgb.resize(size_t(width) * height * 3);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t p = size_t(y) * width + x;
            for (int c = 0; c < 3; ++c) {
                const int source_channel = used == 1 ? 0 : c;
                const float v = used == 1 ? pixels[p] : image.rgb[p * 3 + c];
                if (!std::isfinite(v)) {
                    std::string name = channel_names[source_channel];
                    if (name.empty()) name = "channel " + std::to_string(source_channel);
                    throw InputError(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")",
                                     name + " is " + (std::isnan(v) ? "NaN" : "infinite") + " (radiance must be finite)");
                }
                image.rgb[p * 3 + c] = std::max(v, 0.0f);  // lossy compression leaves small negatives
            }
        }
    }
    return image;
}

Environment load_environment(const std::string& spec, const EnvironmentOptions& options) {
    validate(options);
    static const std::string kConstant = "constant:";
    if (trim(spec).empty())
        throw InputError(options.origin, "", "empty environment (expected an .exr or .hdr file, or constant:R,G,B)");
    if (spec.compare(0, kConstant.size(), kConstant) == 0)
        return Environment::constant(parse_constant(spec.substr(kConstant.size()), options.origin), spec, options);
    return Environment::from_image(read_latlong_image(spec), spec, options);
}

}  // namespace lab::ibl
