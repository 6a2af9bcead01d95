// Host side of importance sampling: the cdfs that ibl/distribution1d.h samples (the lights'
// selection), and the environment's distribution over the texels of a cube map with weights
// luminance x solid angle, as the alias tables that ibl/environment.h samples.
#pragma once

#include <functional>
#include <vector>

#include "single_source/host_vocabulary.hpp"
#include "ibl/alias_table.hpp"

namespace lab::ibl {

// Every weight is raised to at least this fraction of the weights' sum before normalising, so that
// every cell keeps a probability that the float sampler resolves (a cdf step of about 2^-22 against
// the 2^-24 spacing of floats below 1; in an alias table of n cells, a threshold of n 2^-22 against
// the n 2^-24 that separates two of the generator's numbers in one entry) and no texel with
// radiance is ever unreachable. At most n 2^-22 of the mass moves to floored cells (7e-4 for the
// 3072 rows of 512-texel faces).
constexpr double kSamplingFloor = 0x1.0p-22;

// The weights raised to the floor above (their sum must be positive and finite).
std::vector<double> floored_weights(const std::vector<double>& weights);

// The n + 1 entries of the cdf of n non-negative weights with a positive sum: 0, ..., exactly 1,
// strictly increasing thanks to the floor above. Accumulated in double, stored as float.
std::vector<float> piecewise_constant_cdf(const std::vector<double>& weights);

// Exact solid angle of the rectangle [a0, a1] x [b0, b1] on a cube face at distance 1:
// the integral of (1 + a^2 + b^2)^(-3/2) da db, whose antiderivative in a and b is
// F(a, b) = atan(a b / sqrt(1 + a^2 + b^2)), so the integral is F(a1,b1) - F(a0,b1) - F(a1,b0) + F(a0,b0).
double face_rectangle_solid_angle(double a0, double a1, double b0, double b1);

// Solid angle of texel (i, j) of a face of `face_size` texels (the same on every face).
double texel_solid_angle(int face_size, int i, int j);

// Luminance Y of linear Rec. 709 / sRGB primaries (ITU-R BT.709 weights).
double luminance(double r, double g, double b);

// Alias tables over a grid of `rows` x `columns` texels (row-major, rows x (columns + 1) entries):
// the table over the rows first, then row r's over its texels at rows + r columns. Texel weight =
// luminance x texel_measure(r, i) (a solid angle, an area), floored within its row; a row's weight
// is the sum of its texels', floored among the rows. A row without light falls back to its texels'
// measures and gets the floor's share of the rows' table; a grid without light falls back to the
// measures everywhere. Two levels, not one table over all texels: a table of n cells resolves
// probabilities only to n 2^-24 (alias_entry_starts), too coarse for a million texels.
std::vector<AliasEntry> build_row_alias_tables(const std::vector<single_source::float4>& texels, int rows, int columns,
                                              const std::function<double(int row, int column)>& texel_measure);

// The probability with which the two-level sampler draws each texel through those tables: its row's
// times the texel's in the row, each exact for the generator's numbers (alias_table_probabilities),
// their product rounded once to float.
std::vector<float> row_texel_probabilities(const std::vector<AliasEntry>& alias, int rows, int columns);

// The environment's alias tables over the texels of a cube map (build_row_alias_tables over its 6N
// rows r = face * N + j of N texels, measured by exact solid angle; ibl/environment.h samples them):
// an environment without light falls back to solid angles everywhere, uniform over the sphere.
std::vector<AliasEntry> build_cubemap_alias_tables(const std::vector<single_source::float4>& texels, int face_size);

// The probability with which the sampler draws each of the 6N^2 texels through those tables
// (row_texel_probabilities).
std::vector<float> cubemap_texel_probabilities(const std::vector<AliasEntry>& alias, int face_size);

// Writes into every texel's w its probability through `alias`, which environment_pdf() reads back
// (ibl/environment.h). Must run again whenever the texels or their tables change.
void store_texel_probabilities(const std::vector<AliasEntry>& alias, int face_size, std::vector<single_source::float4>* texels);

}  // namespace lab::ibl
