#include "render/camera_setup.hpp"

#include <cmath>
#include <stdexcept>

#include "common/input_error.hpp"

namespace lab::render {
namespace {


}  // namespace

kernel::Camera make_camera(const scene::Camera& camera, int width, int height, const std::string& file) {
    if (width < 1 || height < 1) throw std::invalid_argument("make_camera: the image needs at least one pixel");
    if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f))
        throw InputError(file, "camera.fov_degrees", "must be in (0, 180)");
    kernel::Camera c{};
    if (camera.type == scene::CameraType::thin_lens) {
        if (!(camera.aperture_radius > 0.0f) || !std::isfinite(camera.aperture_radius))
            throw InputError(file, "camera.aperture_radius", "a thin lens needs a finite aperture radius > 0");
        if (!(camera.focus_distance > 0.0f) || !std::isfinite(camera.focus_distance))
            throw InputError(file, "camera.focus_distance", "a thin lens needs a finite focus distance > 0");
        c.lens_radius = camera.aperture_radius;
        c.focus_distance = camera.focus_distance;
    }
    const brdf::float3 forward = glm::normalize(camera.look_at - camera.position);
    const brdf::float3 right = glm::normalize(glm::cross(forward, camera.up));
    const brdf::float3 up = glm::cross(right, forward);
    const float half_height = std::tan(0.5f * camera.fov_degrees * float(3.14159265358979323846 / 180.0));
    const float aspect = float(width) / float(height);
    kernel::float3_to_array(camera.position, c.position);
    kernel::float3_to_array(forward, c.forward);
    kernel::float3_to_array(right * (half_height * aspect), c.right);
    kernel::float3_to_array(up * half_height, c.up);
    c.width = width;
    c.height = height;
    return c;
}

}  // namespace lab::render
