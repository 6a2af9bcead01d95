// The single-source BRDF module, compiled as C++ for the host: namespace brdf, on the vocabulary of
// namespace single_source.
#pragma once

#include "single_source/host_vocabulary.hpp"

namespace brdf {
using namespace single_source;
#include "bsdf.h"
#include "merl.h"
// lobes of the OpenPBR model, which no model includes yet (docs/materials.md)
#include "eon_diffuse.h"
#include "thin_film.h"
}  // namespace brdf
