// Host side of environment importance sampling: the cdfs that ibl/distribution2d.h samples, and their
// guide tables, built over the texels of a cube map with weights luminance x solid angle.
#pragma once

#include <vector>

#include "brdf/brdf.hpp"

namespace lab::ibl {

// Every weight is raised to at least this fraction of the weights' sum before normalising, so that
// every cell keeps a probability that a float cdf resolves (a step of about 2^-22 against the
// 2^-24 spacing of floats below 1) and no texel with radiance is ever unreachable. At most
// n 2^-22 of the mass moves to floored cells (7e-4 for the 3072 rows of 512-texel faces).
constexpr double kCdfFloor = 0x1.0p-22;

// The n + 1 entries of the cdf of n non-negative weights with a positive sum: 0, ..., exactly 1,
// strictly increasing thanks to the floor above. Accumulated in double, stored as float.
std::vector<float> piecewise_constant_cdf(const std::vector<double>& weights);

// The guide table of a cdf of n + 1 entries (ibl/distribution2d.h): guide_size entries (a power of
// two), entry m the largest k < n with cdf[k] <= m / guide_size. Appended to `guide`.
void append_cdf_guide(const float* cdf, int n, int guide_size, std::vector<unsigned short>* guide);

// Exact solid angle of the rectangle [a0, a1] x [b0, b1] on a cube face at distance 1:
// the integral of (1 + a^2 + b^2)^(-3/2) da db, whose antiderivative in a and b is
// F(a, b) = atan(a b / sqrt(1 + a^2 + b^2)), so the integral is F(a1,b1) - F(a0,b1) - F(a1,b0) + F(a0,b0).
double face_rectangle_solid_angle(double a0, double a1, double b0, double b1);

// Solid angle of texel (i, j) of a face of `face_size` texels (the same on every face).
double texel_solid_angle(int face_size, int i, int j);

// Luminance Y of linear Rec. 709 / sRGB primaries (ITU-R BT.709 weights).
double luminance(double r, double g, double b);

struct CubemapDistribution {
    std::vector<float> marginal_cdf;     // 6N + 1 entries: over the rows r = face * N + j
    std::vector<float> conditional_cdf;  // 6N (N + 1) entries: row r's cdf over its texels
    std::vector<unsigned short> guide;   // the marginal's guide table, then each row's (distribution2d.h)
};

// Texel weight = luminance x exact solid angle. A row without light falls back to its texels'
// solid angles (uniform within the row) and gets the floor's share of the marginal; an environment
// without light falls back to solid angles everywhere: uniform over the sphere.
CubemapDistribution build_cubemap_distribution(const std::vector<brdf::float4>& texels, int face_size);

// Writes into every texel's w its probability under `d`: distribution2d_probability() of the
// cdfs, the very float the sampler realises, which environment_pdf() reads back (ibl/environment.h).
// Must run again whenever the texels or their distribution change.
void store_texel_probabilities(const CubemapDistribution& d, int face_size, std::vector<brdf::float4>* texels);

}  // namespace lab::ibl
