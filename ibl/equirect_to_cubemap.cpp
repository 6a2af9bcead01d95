#include "ibl/equirect_to_cubemap.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "common/parallel_for.hpp"
#include "ibl/ibl.hpp"

namespace lab::ibl {

namespace {


// Whether a face's points have x and z that depend on a alone and y on b alone (+x, -x, +z, -z), as
// ibl/cubemap.h's cubemap_face_point lays them out.
bool around_y_axis(int face) {
    const single_source::float3 p = ::ibl::cubemap_face_point(face, 0.5f, 0.25f);
    const single_source::float3 other_b = ::ibl::cubemap_face_point(face, 0.5f, -0.75f), other_a = ::ibl::cubemap_face_point(face, -0.5f, 0.25f);
    return p.x == other_b.x && p.z == other_b.z && p.y == other_a.y;
}

}  // namespace

double latlong_azimuth(double x, double z) { return std::atan2(-x, z) / (2.0 * M_PI) + 0.5; }

double latlong_elevation(double y, double horizontal) { return 0.5 - std::atan2(y, horizontal) / M_PI; }

void latlong_coordinates(single_source::float3 d, double* u, double* v) {
    const double x = d.x, y = d.y, z = d.z;
    *u = latlong_azimuth(x, z);
    *v = latlong_elevation(y, std::sqrt(x * x + z * z));
}

single_source::float3 latlong_direction(double u, double v) {
    const double phi = (u - 0.5) * 2.0 * M_PI;     // atan2(-x, z)
    const double elevation = (0.5 - v) * M_PI;     // atan2(y, hypot(x, z))
    const double c = std::cos(elevation);
    return single_source::float3(float(-c * std::sin(phi)), float(std::sin(elevation)), float(c * std::cos(phi)));
}

LatLongTaps latlong_column_taps(int width, double u) {
    const double fx = u * width - 0.5;
    const double x0f = std::floor(fx);
    int x0 = int(x0f) % width;
    if (x0 < 0) x0 += width;
    return {x0, (x0 + 1) % width, fx - x0f};
}

LatLongTaps latlong_row_taps(int height, double v) {
    const double fy = std::clamp(v * height - 0.5, 0.0, double(height - 1));
    const double y0f = std::floor(fy);
    const int y0 = int(y0f);
    return {y0, std::min(y0 + 1, height - 1), fy - y0f};
}

single_source::float3 latlong_bilinear(const LatLongImage& image, const LatLongTaps& column, const LatLongTaps& row) {
    const int w = image.width;
    auto pixel = [&](int x, int y, int c) { return double(image.rgb[(size_t(y) * w + x) * 3 + c]); };
    double rgb[3];
    for (int c = 0; c < 3; ++c) {
        const double top = pixel(column.first, row.first, c) + (pixel(column.second, row.first, c) - pixel(column.first, row.first, c)) * column.t;
        const double bottom = pixel(column.first, row.second, c) + (pixel(column.second, row.second, c) - pixel(column.first, row.second, c)) * column.t;
        rgb[c] = top + (bottom - top) * row.t;
    }
    return single_source::float3(float(rgb[0]), float(rgb[1]), float(rgb[2]));
}

single_source::float3 latlong_bilinear(const LatLongImage& image, double u, double v) {
    return latlong_bilinear(image, latlong_column_taps(image.width, u), latlong_row_taps(image.height, v));
}

int cubemap_supersampling(int image_width, int face_size) {
    // A texel spans (pi/2) / N radians, an image pixel 2 pi / W: W / (4N) pixels per texel.
    const int per_pixel = (image_width + 2 * face_size - 1) / (2 * face_size);  // ceil(2 W / (4 N))
    return std::clamp(per_pixel, 4, 64);
}

std::vector<single_source::float4> equirect_to_cubemap(const LatLongImage& image, int face_size, int threads) {
    const int n = face_size;
    if (n <= 0 || image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != size_t(image.width) * size_t(image.height) * 3)
        throw std::invalid_argument("equirect_to_cubemap: empty image or face size");
    const int s = cubemap_supersampling(image.width, n);
    const int samples = n * s;  // sample positions along a face's axis
    std::vector<single_source::float4> texels(size_t(CUBEMAP_FACES) * n * n);

    // Texel i's stratum si lies at face coordinate axis[i s + si], on both axes of every face.
    std::vector<float> axis(samples);
    for (int i = 0; i < n; ++i)
        for (int si = 0; si < s; ++si) axis[size_t(i) * s + si] = float(-1.0 + 2.0 * (i + (si + 0.5) / s) / n);

    // On the four faces around the y axis a point's x and z depend on a alone and its y on b alone, so
    // its azimuth, the image columns it reads and its distance from the axis are per a: computed once.
    // Its image rows depend on y and that distance, which the four faces share (y = -b, x^2 + z^2 =
    // 1 + a^2): computed on the first of them, and taken by another whose two values equal them at
    // every point (shares_rows).
    struct SideSample {
        LatLongTaps column;
        double horizontal;  // hypot(x, z)
    };
    bool side_face[CUBEMAP_FACES], shares_rows[CUBEMAP_FACES] = {};
    int first_side = -1;
    std::vector<SideSample> side(size_t(CUBEMAP_FACES) * samples);
    for (int face = 0; face < CUBEMAP_FACES; ++face) {
        side_face[face] = around_y_axis(face);
        if (!side_face[face]) continue;
        if (first_side < 0) first_side = face;
        for (int k = 0; k < samples; ++k) {
            const single_source::float3 p = ::ibl::cubemap_face_point(face, axis[k], 0.0f);
            const double x = p.x, z = p.z;
            side[size_t(face) * samples + k] = {latlong_column_taps(image.width, latlong_azimuth(x, z)), std::sqrt(x * x + z * z)};
        }
        shares_rows[face] = true;
        for (int k = 0; k < samples; ++k)
            shares_rows[face] = shares_rows[face] &&
                                side[size_t(face) * samples + k].horizontal == side[size_t(first_side) * samples + k].horizontal &&
                                ::ibl::cubemap_face_point(face, 0.0f, axis[k]).y == ::ibl::cubemap_face_point(first_side, 0.0f, axis[k]).y;
    }
    struct RowScratch {
        std::vector<double> weight;       // per stratum row sj and sample k
        std::vector<LatLongTaps> rows;    // the first side face's image rows, per sj and k
    };

    // Row j of every face: the strata's solid-angle weights are the same on all six.
    auto convert_rows = [&](int j, RowScratch& scratch) {
        for (int sj = 0; sj < s; ++sj) {
            const float b = axis[size_t(j) * s + sj];
            // Points equally spaced in (a, b) stand for d(omega) = dA / (1 + a^2 + b^2)^(3/2).
            for (int k = 0; k < samples; ++k)
                scratch.weight[size_t(sj) * samples + k] = 1.0 / double(::ibl::cubemap_area_per_solid_angle(axis[k], b));
            if (first_side < 0) continue;
            const double y = ::ibl::cubemap_face_point(first_side, 0.0f, b).y;
            for (int k = 0; k < samples; ++k)
                scratch.rows[size_t(sj) * samples + k] =
                    latlong_row_taps(image.height, latlong_elevation(y, side[size_t(first_side) * samples + k].horizontal));
        }
        for (int face = 0; face < CUBEMAP_FACES; ++face) {
            const SideSample* face_side = &side[size_t(face) * samples];
            for (int i = 0; i < n; ++i) {
                double sum[3] = {0.0, 0.0, 0.0}, weight_sum = 0.0;
                for (int sj = 0; sj < s; ++sj) {
                    const float b = axis[size_t(j) * s + sj];
                    for (int si = 0; si < s; ++si) {
                        const int k = i * s + si;
                        const double w = scratch.weight[size_t(sj) * samples + k];
                        single_source::float3 l;
                        if (side_face[face]) {
                            const LatLongTaps row =
                                shares_rows[face] ? scratch.rows[size_t(sj) * samples + k]
                                                  : latlong_row_taps(image.height, latlong_elevation(::ibl::cubemap_face_point(face, 0.0f, b).y,
                                                                                                     face_side[k].horizontal));
                            l = latlong_bilinear(image, face_side[k].column, row);
                        } else {
                            double u, v;
                            latlong_coordinates(::ibl::cubemap_face_point(face, axis[k], b), &u, &v);
                            l = latlong_bilinear(image, u, v);
                        }
                        sum[0] += w * l.x;
                        sum[1] += w * l.y;
                        sum[2] += w * l.z;
                        weight_sum += w;
                    }
                }
                texels[(size_t(face) * n + j) * n + i] =
                    single_source::float4(float(sum[0] / weight_sum), float(sum[1] / weight_sum), float(sum[2] / weight_sum), 1.0f);
            }
        }
    };

    if (threads <= 0) threads = hardware_threads();
    threads = std::min(threads, n);
    std::atomic<int> next{0};
    auto worker = [&]() {
        RowScratch scratch{std::vector<double>(size_t(s) * samples), std::vector<LatLongTaps>(size_t(s) * samples)};
        for (int j = next++; j < n; j = next++) convert_rows(j, scratch);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    return texels;
}

}  // namespace lab::ibl
