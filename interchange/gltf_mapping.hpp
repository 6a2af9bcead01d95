// The parts of the glTF mapping both directions use: OpenPBR's anisotropic roughness against glTF's
// (KHR_materials_anisotropy) and the thin film's thickness in glTF's nanometres.
#pragma once

namespace interchange {

// glTF's anisotropic GGX: alpha_b = roughness^2 across the direction, alpha_t = mix(alpha_b, 1,
// strength^2) along it. OpenPBR's stretch (brdf/openpbr_model.h) gives alpha_t and alpha_b; these
// are the glTF roughness and strength with the same two alphas, and back.
struct GltfAnisotropy {
    float roughness;
    float strength;
    // the lab's alphas lie outside glTF's reach (alpha_t above 1) or at the lab's smallest alpha
    // (BRDF_MIN_ALPHA, brdf/microfacet.h), where the lobe the lab renders is not the parameters' own
    bool clamped = false;
};
GltfAnisotropy gltf_anisotropy_of(float specular_roughness, float specular_roughness_anisotropy);
// OpenPBR's specular_roughness and specular_roughness_anisotropy of a glTF roughness and strength.
void openpbr_anisotropy_of(const GltfAnisotropy& gltf, float* specular_roughness, float* specular_roughness_anisotropy);

inline constexpr float kNanometresPerMicrometre = 1000.0f;

}  // namespace interchange
