// An environment for image-based lighting: a lat-long image (OpenEXR or Radiance HDR) or a constant
// colour, resampled to a cube map (ibl/cubemap.h) and made ready for importance sampling
// (ibl/environment.h). The buffers a kernel needs are here as flat arrays; the host can evaluate
// the very same single-source functions. See docs/environments.md.
#pragma once

#include <string>
#include <vector>

#include "ibl/alias_table.hpp"
#include "ibl/equirect_to_cubemap.hpp"
#include "ibl/ibl.hpp"

namespace lab::ibl {

struct EnvironmentOptions {
    float rotation_degrees = 0.0f;  // about +y, right-handed: 90 brings the image's +x to world -z
    float exposure_stops = 0.0f;    // radiance x 2^stops, in [-64, 64]
    int face_size = 0;              // texels per face edge, in [1, 4096]; 0: image width / 4 within [16, 512]
    std::string origin = "--env";   // names the spec and these options in error messages
};

constexpr int kMinAutomaticFaceSize = 16;
constexpr int kMaxAutomaticFaceSize = 512;
constexpr int kMaxFaceSize = 4096;
constexpr float kMaxExposureStops = 64.0f;

class Environment {
public:
    // A lat-long image (finite, non-negative radiance; see read_latlong_image) on the cube.
    static Environment from_image(const LatLongImage& image, std::string source, const EnvironmentOptions& options);
    // The same radiance from every direction (non-negative, finite).
    static Environment constant(single_source::float3 radiance, std::string source, const EnvironmentOptions& options);

    // What a kernel gets: the struct by value and two __global buffers.
    const ::ibl::EnvironmentMap& map() const { return map_; }
    // 6 N^2: xyz the radiance before intensity, w the texel's probability (ibl/environment.h)
    const std::vector<single_source::float4>& texels() const { return texels_; }
    // 6N + 6N^2: the rows' alias table, then each row's (ibl/environment.h)
    const std::vector<AliasEntry>& alias() const { return alias_; }
    int face_size() const { return map_.face_size; }
    // The file name, or the constant spec, this environment came from.
    const std::string& source() const { return source_; }

    // Turns and scales the environment anew: absolute values, as EnvironmentOptions gives them
    // (InputError naming the source for a non-finite rotation, an exposure outside [-64, 64], or one
    // that makes the brightest radiance overflow a float).
    // Only the kernel argument map() changes: the texels, their distribution and the probabilities
    // in the texels' w stay, since the rotation turns directions and the intensity scales every
    // texel alike. (The texels are set only by the constructor, which fills w.)
    void set_transform(float rotation_degrees, float exposure_stops);
    float rotation_degrees() const { return rotation_degrees_; }
    float exposure_stops() const { return exposure_stops_; }

    // The single-source functions of ibl/environment.h on this environment (world directions).
    single_source::float3 radiance(single_source::float3 direction) const;
    single_source::float3 radiance_filtered(single_source::float3 direction) const;
    single_source::float3 sample(float u1, float u2, float* pdf) const;
    float pdf(single_source::float3 direction) const;

private:
    Environment(std::vector<single_source::float4> texels, int face_size, std::string source, const EnvironmentOptions& options);

    ::ibl::EnvironmentMap map_{};
    std::vector<single_source::float4> texels_;
    std::vector<AliasEntry> alias_;
    std::string source_;
    float rotation_degrees_ = 0.0f, exposure_stops_ = 0.0f;
    float brightest_ = 0.0f;  // the largest texel channel: an exposure must keep it finite
};

// Reads an equirectangular OpenEXR (.exr) or Radiance HDR (.hdr) file: 2:1, one channel (grey) or
// three and more (the first three as R, G, B). Negative values (lossy DWAB compression) become 0.
// Throws lab::InputError naming the file for a missing, unreadable or corrupt file, another format,
// a size that is not 2:1, a size the file cannot hold or half the machine's memory cannot
// (common/image_claim.hpp: checked before the pixels are allocated), and a NaN or infinite pixel.
LatLongImage read_latlong_image(const std::string& path);

// The largest lat-long image read: 32768 x 16384 (6.4 GB of float RGB, held once).
constexpr int kMaxLatLongHeight = 16384;

// What read_latlong_image checks of the size (2:1, at most kMaxLatLongHeight rows), and of the
// pixels it read (width x height x 1 or 3 floats, channel_names.size() channels): each an
// InputError naming `path` and the field. Separate so that any float data can be tested and fuzzed.
void check_latlong_size(const std::string& path, int width, int height);
LatLongImage latlong_from_pixels(const std::string& path, int width, int height, std::vector<float> pixels,
                                 const std::vector<std::string>& channel_names);

// "constant:R,G,B" (three finite non-negative numbers) or the path of a lat-long image.
// Throws lab::InputError naming the file, or options.origin for the spec and the options.
Environment load_environment(const std::string& spec, const EnvironmentOptions& options = {});

}  // namespace lab::ibl
