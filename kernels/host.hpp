// The scene-independent single-source kernel headers (random numbers, MIS weights, the camera,
// the lights, the render settings, the scene's buffers, the film), compiled as C++ for the host:
// namespace kernel, on the vocabularies of the BRDF
// module (namespace brdf) and the environment (namespace ibl), whose headers these include and
// whose include guards make them visible here through the using-directives.
//
// Host code that fills a kernel argument (kernel::Camera, kernel::Light) uses these very structs,
// so the layout the kernel reads is the one written; the static_asserts pin the sizes OpenCL sees.
#pragma once

#include "brdf/brdf.hpp"
#include "ibl/ibl.hpp"
#include "single_source/host_vocabulary.hpp"

namespace kernel {
using namespace ::single_source;
using namespace ::brdf;
using namespace ::ibl;
#include "kernels/rng.h"
#include "kernels/mis.h"
#include "kernels/camera.h"
#include "kernels/lights/light.h"
#include "kernels/lights/sphere_light.h"
#include "kernels/lights/area_light.h"
#include "kernels/lights/point_light.h"
#include "kernels/lights/environment_light.h"
#include "kernels/lights/image_emitter.h"
#include "kernels/lights/light_selection.h"
#include "kernels/render_settings.h"
#include "kernels/ray_march.h"
#include "kernels/render_scene.h"
#include "kernels/film.h"

}  // namespace kernel

static_assert(sizeof(kernel::Camera) == 64, "Camera must match its OpenCL layout: 16 four-byte words");
static_assert(sizeof(kernel::Light) == 64, "Light must match its OpenCL layout: 16 four-byte words");
static_assert(sizeof(kernel::RayMarch) == 12, "RayMarch must match its OpenCL layout: 3 four-byte words");
static_assert(sizeof(kernel::RenderKernelSettings) == 152, "RenderKernelSettings must match its OpenCL layout: 38 four-byte words");
