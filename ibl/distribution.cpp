#include "ibl/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/luminance.hpp"
#include "ibl/ibl.hpp"

namespace lab::ibl {

std::vector<float> piecewise_constant_cdf(const std::vector<double>& weights) {
    const size_t n = weights.size();
    double sum = 0.0;
    for (double w : weights) sum += w;
    if (n == 0 || !(sum > 0.0) || !std::isfinite(sum))
        throw std::invalid_argument("piecewise_constant_cdf: weights need a positive finite sum");
    const double floor = kCdfFloor * sum;
    std::vector<double> cumulative(n + 1, 0.0);
    for (size_t k = 0; k < n; ++k) cumulative[k + 1] = cumulative[k] + std::max(weights[k], floor);
    std::vector<float> cdf(n + 1);
    for (size_t k = 0; k < n; ++k) cdf[k] = float(cumulative[k] / cumulative[n]);
    cdf[n] = 1.0f;
    return cdf;
}

void append_cdf_guide(const float* cdf, int n, int guide_size, std::vector<unsigned short>* guide) {
    if (n <= 0 || n > 65536 || guide_size < n || (guide_size & (guide_size - 1)) != 0)
        throw std::invalid_argument("append_cdf_guide: needs 1 to 65536 cells and a power-of-two size >= their count");
    int k = 0;
    for (int m = 0; m < guide_size; ++m) {
        const double bucket_start = double(m) / double(guide_size);  // exact
        while (k + 1 < n && double(cdf[k + 1]) <= bucket_start) ++k;
        guide->push_back((unsigned short)k);
    }
}

double face_rectangle_solid_angle(double a0, double a1, double b0, double b1) {
    auto F = [](double a, double b) { return std::atan2(a * b, std::sqrt(1.0 + a * a + b * b)); };
    return F(a1, b1) - F(a0, b1) - F(a1, b0) + F(a0, b0);
}

double texel_solid_angle(int face_size, int i, int j) {
    const double step = 2.0 / face_size;
    return face_rectangle_solid_angle(-1.0 + i * step, -1.0 + (i + 1) * step, -1.0 + j * step, -1.0 + (j + 1) * step);
}

double luminance(double r, double g, double b) { return lab::luminance(r, g, b); }

CubemapDistribution build_cubemap_distribution(const std::vector<brdf::float4>& texels, int face_size) {
    const int n = face_size;
    const int rows = CUBEMAP_FACES * n;
    if (n <= 0 || texels.size() != size_t(rows) * size_t(n))
        throw std::invalid_argument("build_cubemap_distribution: texel count does not match the face size");

    // The solid angles of one face's texels serve all six faces.
    std::vector<double> solid_angle(size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) solid_angle[size_t(j) * n + i] = texel_solid_angle(n, i, j);

    CubemapDistribution d;
    d.conditional_cdf.reserve(size_t(rows) * (n + 1));
    std::vector<double> row_weight(rows), row_solid_angle(rows), weights(n), fallback(n);
    for (int r = 0; r < rows; ++r) {
        const int j = r % n;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const brdf::float4& t = texels[size_t(r) * n + i];
            fallback[i] = solid_angle[size_t(j) * n + i];
            weights[i] = luminance(t.x, t.y, t.z) * fallback[i];
            sum += weights[i];
        }
        row_weight[r] = sum;
        for (int i = 0; i < n; ++i) row_solid_angle[r] += fallback[i];
        const std::vector<float> cdf = piecewise_constant_cdf(sum > 0.0 ? weights : fallback);
        d.conditional_cdf.insert(d.conditional_cdf.end(), cdf.begin(), cdf.end());
    }
    double total = 0.0;
    for (double w : row_weight) total += w;
    d.marginal_cdf = piecewise_constant_cdf(total > 0.0 ? row_weight : row_solid_angle);

    const int row_guide = ::ibl::distribution_guide_size(rows), column_guide = ::ibl::distribution_guide_size(n);
    d.guide.reserve(size_t(row_guide) + size_t(rows) * column_guide);
    append_cdf_guide(d.marginal_cdf.data(), rows, row_guide, &d.guide);
    for (int r = 0; r < rows; ++r) append_cdf_guide(d.conditional_cdf.data() + size_t(r) * (n + 1), n, column_guide, &d.guide);
    return d;
}

void store_texel_probabilities(const CubemapDistribution& d, int face_size, std::vector<brdf::float4>* texels) {
    const int n = face_size, rows = CUBEMAP_FACES * n;
    if (n <= 0 || texels->size() != size_t(rows) * size_t(n) || d.marginal_cdf.size() != size_t(rows) + 1 ||
        d.conditional_cdf.size() != size_t(rows) * size_t(n + 1))
        throw std::invalid_argument("store_texel_probabilities: texels or cdfs do not match the face size");
    for (int r = 0; r < rows; ++r)
        for (int i = 0; i < n; ++i)
            (*texels)[size_t(r) * n + i].w =
                ::ibl::distribution2d_probability(d.marginal_cdf.data(), d.conditional_cdf.data(), n, r, i);
}

}  // namespace lab::ibl
