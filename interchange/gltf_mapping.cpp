#include "interchange/gltf_mapping.hpp"

#include <algorithm>
#include <cmath>

#include "brdf/brdf.hpp"

namespace interchange {

GltfAnisotropy gltf_anisotropy_of(float specular_roughness, float specular_roughness_anisotropy) {
    const brdf::Microfacet lobe = brdf::openpbr_microfacet(specular_roughness, specular_roughness_anisotropy);
    const float alpha_t = std::min(lobe.ax, 1.0f), alpha_b = lobe.ay;
    const float stretch = alpha_b < 1.0f ? (alpha_t - alpha_b) / (1.0f - alpha_b) : 0.0f;
    const bool clamped = lobe.ax > 1.0f || lobe.ax <= BRDF_MIN_ALPHA || lobe.ay <= BRDF_MIN_ALPHA;
    return {std::sqrt(alpha_b), std::sqrt(std::max(stretch, 0.0f)), clamped};
}

void openpbr_anisotropy_of(const GltfAnisotropy& gltf, float* specular_roughness, float* specular_roughness_anisotropy) {
    const float alpha_b = gltf.roughness * gltf.roughness;
    const float alpha_t = alpha_b + (1.0f - alpha_b) * gltf.strength * gltf.strength;
    // alpha_b = (1 - a) alpha_t and alpha_t = alpha sqrt(2 / (1 + (1 - a)^2)), solved for a and alpha
    const float a = alpha_t > 0.0f ? 1.0f - alpha_b / alpha_t : 0.0f;
    const float alpha = alpha_t / std::sqrt(2.0f / (1.0f + (1.0f - a) * (1.0f - a)));
    *specular_roughness = std::sqrt(alpha);
    *specular_roughness_anisotropy = a;
}

}  // namespace interchange
