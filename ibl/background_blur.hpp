// The blurred backdrop (docs/environments.md, "Background"): a copy of an environment's cube map
// convolved with a spherical Gaussian, built once per blur angle on the host, read only by camera
// rays that escape (kernels/background.h). Lighting keeps the environment's own texels.
#pragma once

#include <vector>

#include "single_source/host_vocabulary.hpp"

namespace lab::ibl {

// The widest blur, degrees: at 90 the kernel already spans the sphere.
constexpr float kMaxBackgroundBlurDegrees = 90.0f;
// The largest face of a blurred map: its cost grows as the fourth power of the face (about 0.6 s
// of CPU time at 64 with a blur of 2 or 6 degrees, docs/environments.md).
constexpr int kMaxBlurredFaceSize = 64;

struct BlurredCubemap {
    int face_size = 0;                             // N of the blurred map (its own, usually below the source's)
    std::vector<single_source::float4> texels;     // 6 N^2, the cube layout of ibl/environment.h, w = 0
};

// The face size the blur of `sigma_degrees` is stored at: texels of at most sigma / 4 at a face's
// centre (2/N radians) where the source and kMaxBlurredFaceSize allow, at least 4.
int blurred_face_size(int source_face_size, float sigma_degrees);

// The cube map `texels` (6 N^2, xyz the radiance; w ignored) convolved with the von Mises-Fisher
// kernel K(gamma) = exp(kappa (cos gamma - 1)), kappa = 1 / sigma^2 (sigma in radians: for small
// sigma a Gaussian of standard deviation sigma in each direction across the view), cut at
// gamma = 4 sigma (where K is e^-8 of its peak). The source is first averaged, by solid angle, down
// to the blurred map's face size; each output texel is the kernel-weighted mean (solid angle times
// K) of those texels about its centre direction, normalised by the weights' sum, so a constant map
// stays that constant to rounding. sigma_degrees in (0, kMaxBackgroundBlurDegrees].
BlurredCubemap blur_cubemap(const std::vector<single_source::float4>& texels, int face_size, float sigma_degrees);

}  // namespace lab::ibl
