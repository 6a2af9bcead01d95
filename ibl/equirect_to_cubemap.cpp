#include "ibl/equirect_to_cubemap.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "ibl/ibl.hpp"

namespace lab::ibl {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

void latlong_coordinates(brdf::float3 d, double* u, double* v) {
    const double x = d.x, y = d.y, z = d.z;
    *u = std::atan2(-x, z) / (2.0 * kPi) + 0.5;
    *v = 0.5 - std::atan2(y, std::sqrt(x * x + z * z)) / kPi;
}

brdf::float3 latlong_direction(double u, double v) {
    const double phi = (u - 0.5) * 2.0 * kPi;     // atan2(-x, z)
    const double elevation = (0.5 - v) * kPi;     // atan2(y, hypot(x, z))
    const double c = std::cos(elevation);
    return brdf::float3(float(-c * std::sin(phi)), float(std::sin(elevation)), float(c * std::cos(phi)));
}

brdf::float3 latlong_bilinear(const LatLongImage& image, double u, double v) {
    const int w = image.width, h = image.height;
    const double fx = u * w - 0.5, fy = std::clamp(v * h - 0.5, 0.0, double(h - 1));
    const double x0f = std::floor(fx), y0f = std::floor(fy);
    const double tx = fx - x0f, ty = fy - y0f;
    int x0 = int(x0f) % w;
    if (x0 < 0) x0 += w;
    const int x1 = (x0 + 1) % w;
    const int y0 = int(y0f), y1 = std::min(y0 + 1, h - 1);
    auto pixel = [&](int x, int y, int c) { return double(image.rgb[(size_t(y) * w + x) * 3 + c]); };
    double rgb[3];
    for (int c = 0; c < 3; ++c) {
        const double top = pixel(x0, y0, c) + (pixel(x1, y0, c) - pixel(x0, y0, c)) * tx;
        const double bottom = pixel(x0, y1, c) + (pixel(x1, y1, c) - pixel(x0, y1, c)) * tx;
        rgb[c] = top + (bottom - top) * ty;
    }
    return brdf::float3(float(rgb[0]), float(rgb[1]), float(rgb[2]));
}

int cubemap_supersampling(int image_width, int face_size) {
    // A texel spans (pi/2) / N radians, an image pixel 2 pi / W: W / (4N) pixels per texel.
    const int per_pixel = (image_width + 2 * face_size - 1) / (2 * face_size);  // ceil(2 W / (4 N))
    return std::clamp(per_pixel, 4, 64);
}

std::vector<brdf::float4> equirect_to_cubemap(const LatLongImage& image, int face_size, int threads) {
    const int n = face_size;
    if (n <= 0 || image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != size_t(image.width) * size_t(image.height) * 3)
        throw std::invalid_argument("equirect_to_cubemap: empty image or face size");
    const int s = cubemap_supersampling(image.width, n);
    const int rows = CUBEMAP_FACES * n;
    std::vector<brdf::float4> texels(size_t(rows) * n);

    auto convert_row = [&](int r) {
        const int face = r / n, j = r % n;
        for (int i = 0; i < n; ++i) {
            double sum[3] = {0.0, 0.0, 0.0}, weight_sum = 0.0;
            for (int sj = 0; sj < s; ++sj) {
                const float b = float(-1.0 + 2.0 * (j + (sj + 0.5) / s) / n);
                for (int si = 0; si < s; ++si) {
                    const float a = float(-1.0 + 2.0 * (i + (si + 0.5) / s) / n);
                    // Points equally spaced in (a, b) stand for d(omega) = dA / (1 + a^2 + b^2)^(3/2).
                    const double weight = 1.0 / double(::ibl::cubemap_area_per_solid_angle(a, b));
                    double u, v;
                    latlong_coordinates(::ibl::cubemap_face_point(face, a, b), &u, &v);
                    const brdf::float3 l = latlong_bilinear(image, u, v);
                    sum[0] += weight * l.x;
                    sum[1] += weight * l.y;
                    sum[2] += weight * l.z;
                    weight_sum += weight;
                }
            }
            texels[size_t(r) * n + i] =
                brdf::float4(float(sum[0] / weight_sum), float(sum[1] / weight_sum), float(sum[2] / weight_sum), 1.0f);
        }
    };

    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, rows);
    std::atomic<int> next{0};
    auto worker = [&]() {
        for (int r = next++; r < rows; r = next++) convert_row(r);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    return texels;
}

}  // namespace lab::ibl
