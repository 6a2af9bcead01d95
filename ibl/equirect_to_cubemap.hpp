// Resampling an equirectangular (lat-long) environment onto the cube map of ibl/cubemap.h, each
// texel the average radiance over its solid angle, so the sphere integral of radiance is kept.
#pragma once

#include <vector>

#include "single_source/host_vocabulary.hpp"

namespace lab::ibl {

// Linear RGB radiance, 3 floats per pixel, row 0 at the top (+y); finite and non-negative.
struct LatLongImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
};

// The lat-long convention (OpenImageIO's): for a unit direction d,
//   u = atan2(-d.x, d.z) / (2 pi) + 0.5   (wraps; u = 0.5 looks down +z, u = 0.25 down +x)
//   v = 0.5 - atan2(d.y, hypot(d.x, d.z)) / pi   (v = 0: +y, the top row)
// Pixel (x, y) of a W x H image covers u in [x/W, (x+1)/W], v in [y/H, (y+1)/H].
void latlong_coordinates(single_source::float3 d, double* u, double* v);
// Its two halves: u from the direction's x and z, v from its y and hypot(x, z).
double latlong_azimuth(double x, double z);
double latlong_elevation(double y, double horizontal);
single_source::float3 latlong_direction(double u, double v);  // the inverse, a unit vector

// Bilinear interpolation between pixel centres, wrapping around in u and clamped in v.
single_source::float3 latlong_bilinear(const LatLongImage& image, double u, double v);
// The same in two halves: the two pixel columns (rows) around u (v) and the second one's weight, so
// that lookups that share a u share its columns.
struct LatLongTaps {
    int first, second;
    double t;
};
LatLongTaps latlong_column_taps(int width, double u);
LatLongTaps latlong_row_taps(int height, double v);
single_source::float3 latlong_bilinear(const LatLongImage& image, const LatLongTaps& column, const LatLongTaps& row);

// Supersamples per texel and axis: at least 4, and about two per image pixel a texel spans, so a
// small face still averages every pixel it covers (at most 64).
int cubemap_supersampling(int image_width, int face_size);

// 6 N^2 texels (w = 1) in the layout of ibl/cubemap.h. Each texel is the solid-angle-weighted mean
// of a stratified grid of bilinear lookups over its square, computed in double: a constant image
// gives exactly that constant. Runs on up to `threads` threads (0: the hardware's count).
std::vector<single_source::float4> equirect_to_cubemap(const LatLongImage& image, int face_size, int threads = 0);

}  // namespace lab::ibl
