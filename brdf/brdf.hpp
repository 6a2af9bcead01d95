// The single-source BRDF module, compiled as C++ for the host: namespace brdf, on the vocabulary of
// namespace single_source.
#pragma once

#include "single_source/host_vocabulary.hpp"

namespace brdf {
using namespace single_source;
#include "bsdf.h"
#include "merl.h"
// the OpenPBR model's lobes, for the tests and table generators that call them on their own
#include "dielectric_reflection.h"
#include "eon_diffuse.h"
#include "sheen.h"
#include "thin_film.h"
// the anisotropic energy table's arrays, which kernels read from the tables buffer (bsdf_tables.h)
#include "energy_table_ggx_anisotropic.h"
}  // namespace brdf
