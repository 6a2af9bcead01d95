// MERL's ".binary" measured-BRDF files: reading with one-line errors, writing, and tabulating a
// BRDF at the bin centres (which is how the project makes its own test files; MERL's data set
// cannot be bundled). The table layout and the parameterisation are brdf/merl.h's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"

namespace brdf {

// MERL's per-channel scale factors: the file stores value / scale as doubles.
constexpr double kMerlScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

// A measured isotropic BRDF: interleaved RGB floats in 1/sr, MERL_ENTRY_COUNT entries.
struct MeasuredTable {
    std::string source;  // the file it came from, for messages
    std::vector<float> rgb;
    // Entries the file marks unmeasured (negative in all three channels: MERL's files hold -1 at
    // some grazing bins). Empty when every entry was measured. Their rgb holds a fill (see below),
    // so lookups stay continuous; fits and checks that compare against measurements skip them.
    std::vector<bool> unmeasured;
};

inline bool is_unmeasured(const MeasuredTable& t, int entry) {
    return !t.unmeasured.empty() && t.unmeasured[std::size_t(entry)];
}

// Reads FILE; a missing or truncated file, other dimensions than 90 x 90 x 180, trailing bytes,
// NaN or infinite entries, and an entry negative in some channels but not all throw
// lab::InputError naming the file and the entry. An unmeasured entry takes the value of the
// nearest measured entry at smaller theta_d with the same theta_h and phi_d (MERL's holes lie
// towards grazing theta_d), else the nearest at larger theta_d, else 0.
MeasuredTable read_merl_file(const std::string& path);

// Writes the table in MERL's format (int32 dimensions, then the R, G and B blocks of scaled doubles;
// unmeasured entries as -1);
// written to a temporary file and renamed, so a failed write never leaves a partial file.
void write_merl_file(const std::string& path, const MeasuredTable& table);

// The table of f(wo, wi) sampled at every bin centre (brdf/merl.h's merl_bin_center, phi_h = 0).
MeasuredTable tabulate_merl(const std::function<float3(float3 wo, float3 wi)>& f, const std::string& source);

}  // namespace brdf
