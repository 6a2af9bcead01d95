#include "render/light_set.hpp"

#include <cmath>

#include "common/input_error.hpp"
#include "common/luminance.hpp"
#include "ibl/distribution.hpp"

namespace lab::render {
namespace {

constexpr double kPi = 3.14159265358979323846;


double luminance_of(const float v[3]) { return lab::luminance(double(v[0]), double(v[1]), double(v[2])); }

}  // namespace

LightSelection parse_light_selection(const std::string& text, const std::string& option) {
    if (text == "power") return LightSelection::power;
    if (text == "uniform") return LightSelection::uniform;
    throw InputError(option, "", "unknown value \"" + text + "\" (power, uniform)");
}

const char* light_selection_name(LightSelection selection) { return selection == LightSelection::power ? "power" : "uniform"; }

double sphere_light_power(const kernel::Light& light) {
    return kPi * luminance_of(light.emission) * 4.0 * kPi * double(light.radius) * double(light.radius);
}

// a constant rect or disk is an image of one texel of 1
double area_light_power(const kernel::Light& light) { return image_light_power(light, {1.0, 1.0, 1.0}); }

double image_light_power(const kernel::Light& light, const std::array<double, 3>& image_mean_rgb) {
    const double r = double(light.emission[0]) * image_mean_rgb[0], g = double(light.emission[1]) * image_mean_rgb[1],
                 b = double(light.emission[2]) * image_mean_rgb[2];
    return kPi * lab::luminance(r, g, b) * double(kernel::area_light_area(&light));
}

double point_light_power(const kernel::Light& light) { return 4.0 * kPi * luminance_of(light.emission); }

double environment_light_power(const ibl::Environment& environment, double scene_radius) {
    const int n = environment.face_size();
    double integral = 0.0;  // of the luminance over the sphere: every texel's radiance is constant on it
    for (size_t t = 0; t < environment.texels().size(); ++t) {
        const brdf::float4 x = environment.texels()[t];
        const int i = int(t % size_t(n)), j = int((t / size_t(n)) % size_t(n));
        integral += lab::luminance(double(x.x), double(x.y), double(x.z)) * ibl::texel_solid_angle(n, i, j);
    }
    return kPi * scene_radius * scene_radius * double(environment.map().intensity) * integral;
}

LightSet build_light_set(const scene::CompiledScene& scene, const ibl::Environment* environment, LightSelection selection,
                         const std::vector<std::optional<std::array<double, 3>>>& image_means) {
    LightSet set;
    set.light_of_slot.assign(scene.materials.size(), -1);
    if (environment != nullptr) {
        kernel::Light l{};
        l.type = LIGHT_ENVIRONMENT;
        l.material_slot = -1;
        set.lights.push_back(l);
        set.power.push_back(environment_light_power(*environment, scene.bounds_radius));
    }
    for (size_t k = 0; k < scene.emitters.size(); ++k) {
        const scene::Emitter& e = scene.emitters[k];
        kernel::Light l{};
        l.type = e.shape == scene::EmitterShape::sphere ? LIGHT_SPHERE : (e.shape == scene::EmitterShape::rect ? LIGHT_RECT : LIGHT_DISK);
        kernel::float3_to_array(e.center, l.position);
        l.radius = e.radius;
        kernel::float3_to_array(e.radiance, l.emission);
        kernel::float3_to_array(e.edge_u, l.edge_u);
        kernel::float3_to_array(e.edge_v, l.edge_v);
        l.material_slot = e.material;
        if (e.material >= 0 && size_t(e.material) < set.light_of_slot.size()) set.light_of_slot[size_t(e.material)] = int(set.lights.size());
        set.lights.push_back(l);
        if (k < image_means.size() && image_means[k]) set.power.push_back(image_light_power(l, *image_means[k]));
        else set.power.push_back(l.type == LIGHT_SPHERE ? sphere_light_power(l) : area_light_power(l));
    }
    for (const scene::PointLight& p : scene.point_lights) {
        kernel::Light l{};
        l.type = LIGHT_POINT;
        kernel::float3_to_array(p.position, l.position);
        kernel::float3_to_array(p.intensity, l.emission);
        l.material_slot = -1;
        set.lights.push_back(l);
        set.power.push_back(point_light_power(l));
    }
    if (set.lights.empty()) return set;
    double total = 0.0;
    for (double p : set.power) total += p;
    // Uniform when asked, and when no light has power (a black scene: any choice is as good).
    const bool uniform = selection == LightSelection::uniform || !(total > 0.0) || !std::isfinite(total);
    std::vector<double> weights = uniform ? std::vector<double>(set.lights.size(), 1.0) : set.power;
    set.selection_cdf = ibl::piecewise_constant_cdf(weights);
    return set;
}

int light_type_mask(const LightSet& lights) {
    int mask = 0;
    for (const kernel::Light& l : lights.lights) mask |= 1 << l.type | (l.image > 0 ? 1 << LIGHT_IMAGE : 0);
    return mask;
}

}  // namespace lab::render
