#include "ibl/background_blur.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "common/parallel_for.hpp"
#include "ibl/distribution.hpp"
#include "ibl/ibl.hpp"

namespace lab::ibl {

namespace {

// The largest angle between a face's centre direction and any direction on it (its corners): acos(1/sqrt(3)).
const double kFaceHalfAngle = std::acos(1.0 / std::sqrt(3.0));

struct Texel {
    double x, y, z;     // unit centre direction
    double weight;      // solid angle
    double r, g, b;     // radiance
};

// The unit direction of texel (i, j) of `face` at face size n.
void texel_direction(int n, int face, int i, int j, double* x, double* y, double* z) {
    const float a = -1.0f + 2.0f * (float(i) + 0.5f) / float(n), b = -1.0f + 2.0f * (float(j) + 0.5f) / float(n);
    const single_source::float3 p = ::ibl::cubemap_face_point(face, a, b);
    const double len = std::sqrt(double(p.x) * p.x + double(p.y) * p.y + double(p.z) * p.z);
    *x = p.x / len;
    *y = p.y / len;
    *z = p.z / len;
}

// The source averaged by solid angle onto faces of `n` texels: each source texel goes to the coarse
// texel its centre falls in (the source itself when the sizes agree).
std::vector<Texel> coarse_source(const std::vector<single_source::float4>& texels, int face_size, int n) {
    std::vector<Texel> out(size_t(6) * size_t(n) * size_t(n), Texel{0, 0, 0, 0, 0, 0, 0});
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < face_size; ++j)
            for (int i = 0; i < face_size; ++i) {
                const single_source::float4 t = texels[(size_t(face) * size_t(face_size) + size_t(j)) * size_t(face_size) + size_t(i)];
                const double w = texel_solid_angle(face_size, i, j);
                const int ci = int((double(i) + 0.5) * n / face_size), cj = int((double(j) + 0.5) * n / face_size);
                Texel& c = out[(size_t(face) * size_t(n) + size_t(cj)) * size_t(n) + size_t(ci)];
                c.weight += w;
                c.r += w * t.x;
                c.g += w * t.y;
                c.b += w * t.z;
            }
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                Texel& c = out[(size_t(face) * size_t(n) + size_t(j)) * size_t(n) + size_t(i)];
                if (c.weight > 0.0) {
                    c.r /= c.weight;
                    c.g /= c.weight;
                    c.b /= c.weight;
                }
                c.weight = texel_solid_angle(n, i, j);  // the coarse texel's own solid angle
                texel_direction(n, face, i, j, &c.x, &c.y, &c.z);
            }
    return out;
}

}  // namespace

int blurred_face_size(int source_face_size, float sigma_degrees) {
    const double sigma = double(sigma_degrees) * M_PI / 180.0;
    const int wanted = int(std::ceil(8.0 / sigma));  // 2/N radians <= sigma / 4
    return std::max(1, std::min({source_face_size, kMaxBlurredFaceSize, std::max(4, wanted)}));
}

BlurredCubemap blur_cubemap(const std::vector<single_source::float4>& texels, int face_size, float sigma_degrees) {
    if (!(sigma_degrees > 0.0f && sigma_degrees <= kMaxBackgroundBlurDegrees))
        throw std::invalid_argument("blur_cubemap: the blur angle is in (0, 90] degrees");
    if (face_size < 1 || texels.size() != size_t(6) * size_t(face_size) * size_t(face_size))
        throw std::invalid_argument("blur_cubemap: 6 N^2 texels");
    const int n = blurred_face_size(face_size, sigma_degrees);
    const std::vector<Texel> source = coarse_source(texels, face_size, n);
    const double sigma = double(sigma_degrees) * M_PI / 180.0;
    const double kappa = 1.0 / (sigma * sigma);
    const double cutoff = std::min(M_PI, 4.0 * sigma);
    const double cos_cutoff = std::cos(cutoff);
    // the face centre directions, in face order: +x, -x, +y, -y, +z, -z
    const double centres[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

    BlurredCubemap out;
    out.face_size = n;
    out.texels.assign(size_t(6) * size_t(n) * size_t(n), single_source::float4(0.0f));
    const size_t face_texels = size_t(n) * size_t(n);
    std::atomic<int> next{0};
    auto work = [&] {
        for (int row = next++; row < 6 * n; row = next++) {
            const int face = row / n, j = row % n;
            for (int i = 0; i < n; ++i) {
                double x, y, z;
                texel_direction(n, face, i, j, &x, &y, &z);
                double w_sum = 0.0, r = 0.0, g = 0.0, b = 0.0;
                for (int f = 0; f < 6; ++f) {
                    // a face whose every direction lies beyond the cut-off adds nothing
                    const double to_centre = std::acos(std::clamp(x * centres[f][0] + y * centres[f][1] + z * centres[f][2], -1.0, 1.0));
                    if (to_centre - kFaceHalfAngle > cutoff) continue;
                    const Texel* s = &source[size_t(f) * face_texels];
                    for (size_t k = 0; k < face_texels; ++k) {
                        const double c = x * s[k].x + y * s[k].y + z * s[k].z;
                        if (c < cos_cutoff) continue;
                        const double w = s[k].weight * std::exp(kappa * (c - 1.0));
                        w_sum += w;
                        r += w * s[k].r;
                        g += w * s[k].g;
                        b += w * s[k].b;
                    }
                }
                // the texel's own direction is always in reach, so w_sum > 0
                out.texels[size_t(row) * size_t(n) + size_t(i)] = single_source::float4(float(r / w_sum), float(g / w_sum), float(b / w_sum), 0.0f);
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < hardware_threads(); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    return out;
}

}  // namespace lab::ibl
