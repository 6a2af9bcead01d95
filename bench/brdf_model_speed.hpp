// bench brdf's comparison of the openpbr model with the lab model: evaluations and samples per
// second of every preset in the C++ build (one thread) and the OpenCL build, each as a ratio to the
// lab presets' rates (their geometric mean) measured in the same repeat; and each openpbr preset's
// base with coat, fuzz and thin film off against the lab model on the same base (the lobes a kernel
// then compiles are the base's alone), in evaluations, samples and preview paths and rays per
// second. Every ratio is paired within one repeat; the tables give the median over the repeats and
// the range.
#pragma once

#include <string>
#include <vector>

#include "brdf/host/preset.hpp"
#include "kernels/host/brdf_batch.hpp"
#include "opencl/runtime.hpp"

namespace lab::cli {

struct ModelSpeedOptions {
    long samples = 200000;          // items per timed batch of one material
    int repeats = 5;                // paired repeats; median and range of their ratios
    double preview_seconds = 1.0;   // per preview figure; 0: no preview column
    std::string preview_size = "64x64";
    std::string preview_env = "envmaps/courtyard.exr";  // file or constant:R,G,B
};

// Lab's materials closest to an openpbr material's base: its colour, metalness, roughness,
// anisotropy, index (as F0), subsurface and transmission, a Lambert diffuse under a GGX glossy lobe
// weighted by that F0.
brdf::Material lab_on_same_base(const brdf::Material& openpbr);
// The openpbr material with coat, fuzz and thin film off.
brdf::Material openpbr_base_only(const brdf::Material& openpbr);

// Prints both tables; `batch` holds no materials of its own (set_materials is called here).
void print_model_speed(const std::vector<brdf::Preset>& presets, const opencl::Runtime& runtime, kernels::BrdfBatch& batch,
                       const ModelSpeedOptions& options);

}  // namespace lab::cli
