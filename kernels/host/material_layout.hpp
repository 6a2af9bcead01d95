// Materials travel to kernels as a buffer of brdf::Material copied byte for byte, so the device's
// struct layout must be the host's. Every program that reads materials includes
// kernels/material_layout.h, and its host checks the layout once after building.
#pragma once

#include "opencl/runtime.hpp"

namespace lab::kernels {

// Throws opencl::OpenClError naming the device and both layouts when they differ.
void check_material_layout(const opencl::Runtime& runtime, const opencl::Program& program);

}  // namespace lab::kernels
