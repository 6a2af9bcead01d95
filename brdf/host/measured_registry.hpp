// The BSDF's tables of this process (brdf/bsdf_tables.h): the anisotropic energy table, then every
// measured material's block (brdf/measured.h: its MERL table and its sampler) in one float array, so
// that a material names its table by an offset that means the same on the host and in a kernel's
// buffer (the renderers upload this array as it is). A file is read and its sampler built once,
// however many presets name it.
//
// Registration publishes a grown copy of the array and keeps the earlier ones alive, so presets may
// be loaded (the viewer) while other threads evaluate: a pointer read before stays valid, and an
// offset handed out stays the same. Each block costs MEASURED_BLOCK_FLOATS floats (about 18 MB);
// the retired copies cost as much again per registration, for the few tables a session loads.
#pragma once

#include <string>
#include <vector>

#include "brdf/host/merl_file.hpp"

namespace brdf {

// Reads the MERL file (read_merl_file's errors), builds its sampler and returns its block's offset.
int register_measured_file(const std::string& path);
// The same for a table in memory; `table.source` names it and is the key that shares it.
int register_measured_table(const MeasuredTable& table);

// The whole array as of now: bsdf_eval's tables on the host (bsdf_tables()), and what a kernel's
// buffer argument receives. The reference stays valid for the life of the process.
const std::vector<float>& bsdf_table_data();

// The sampler of one table, appended to `block` after the table (brdf/measured.h's layout): per bin of
// theta_o, CDFs of the mean over RGB of f cos_i times solid angle, averaged over 2 x 2 points per cell,
// plus a floor of 2% of the bin's mass spread uniformly in solid angle so that no cell where f may be
// non-zero between its points is left out.
void append_measured_sampler(std::vector<float>* block);

}  // namespace brdf
