#include "ibl/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>

#include "common/luminance.hpp"
#include "ibl/ibl.hpp"

namespace lab::ibl {

std::vector<double> floored_weights(const std::vector<double>& weights) {
    double sum = 0.0;
    for (double w : weights) sum += w;
    if (weights.empty() || !(sum > 0.0) || !std::isfinite(sum))
        throw std::invalid_argument("floored_weights: weights need a positive finite sum");
    std::vector<double> floored(weights.size());
    for (size_t k = 0; k < weights.size(); ++k) floored[k] = std::max(weights[k], kSamplingFloor * sum);
    return floored;
}

std::vector<float> piecewise_constant_cdf(const std::vector<double>& weights) {
    const std::vector<double> w = floored_weights(weights);
    const size_t n = w.size();
    std::vector<double> cumulative(n + 1, 0.0);
    for (size_t k = 0; k < n; ++k) cumulative[k + 1] = cumulative[k] + w[k];
    std::vector<float> cdf(n + 1);
    for (size_t k = 0; k < n; ++k) cdf[k] = float(cumulative[k] / cumulative[n]);
    cdf[n] = 1.0f;
    return cdf;
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

std::vector<AliasEntry> build_row_alias_tables(const std::vector<single_source::float4>& texels, int rows, int columns,
                                              const std::function<double(int row, int column)>& texel_measure) {
    const int n = columns;
    if (rows <= 0 || n <= 0 || texels.size() != size_t(rows) * size_t(n))
        throw std::invalid_argument("build_row_alias_tables: texel count does not match rows x columns");
    std::vector<AliasEntry> alias(size_t(rows) * size_t(n + 1));
    std::vector<double> row_weight(rows), row_measure(rows), weights(n), fallback(n);
    for (int r = 0; r < rows; ++r) {
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const single_source::float4& t = texels[size_t(r) * n + i];
            fallback[i] = texel_measure(r, i);
            weights[i] = luminance(t.x, t.y, t.z) * fallback[i];
            sum += weights[i];
        }
        row_weight[r] = sum;
        for (int i = 0; i < n; ++i) row_measure[r] += fallback[i];
        const std::vector<AliasEntry> table = build_alias_table(floored_weights(sum > 0.0 ? weights : fallback));
        std::copy(table.begin(), table.end(), alias.begin() + rows + ptrdiff_t(r) * n);
    }
    double total = 0.0;
    for (double w : row_weight) total += w;
    const std::vector<AliasEntry> row_table = build_alias_table(floored_weights(total > 0.0 ? row_weight : row_measure));
    std::copy(row_table.begin(), row_table.end(), alias.begin());
    return alias;
}

std::vector<float> row_texel_probabilities(const std::vector<AliasEntry>& alias, int rows, int columns) {
    const int n = columns;
    if (rows <= 0 || n <= 0 || alias.size() != size_t(rows) * size_t(n + 1))
        throw std::invalid_argument("row_texel_probabilities: the tables do not match rows x columns");
    const std::vector<double> row = alias_table_probabilities(alias.data(), rows, alias_entry_starts(rows));
    // every row's table has n cells: where each entry's numbers begin is shared (alias_entry_starts)
    const std::vector<int64_t> column_starts = alias_entry_starts(n);
    std::vector<float> probability(size_t(rows) * n);
    for (int r = 0; r < rows; ++r) {
        const std::vector<double> column = alias_table_probabilities(alias.data() + rows + ptrdiff_t(r) * n, n, column_starts);
        for (int i = 0; i < n; ++i) probability[size_t(r) * n + i] = float(row[size_t(r)] * column[size_t(i)]);
    }
    return probability;
}

std::vector<AliasEntry> build_cubemap_alias_tables(const std::vector<single_source::float4>& texels, int face_size) {
    const int n = face_size;
    if (n <= 0 || texels.size() != size_t(CUBEMAP_FACES) * size_t(n) * size_t(n))
        throw std::invalid_argument("build_cubemap_alias_tables: texel count does not match the face size");
    // The solid angles of one face's texels serve all six faces.
    std::vector<double> solid_angle(size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) solid_angle[size_t(j) * n + i] = texel_solid_angle(n, i, j);
    return build_row_alias_tables(texels, CUBEMAP_FACES * n, n, [&](int r, int i) { return solid_angle[size_t(r % n) * n + i]; });
}

std::vector<float> cubemap_texel_probabilities(const std::vector<AliasEntry>& alias, int face_size) {
    const int n = face_size;
    if (n <= 0 || alias.size() != size_t(CUBEMAP_FACES) * size_t(n) * size_t(n + 1))
        throw std::invalid_argument("cubemap_texel_probabilities: the tables do not match the face size");
    return row_texel_probabilities(alias, CUBEMAP_FACES * n, n);
}

void store_texel_probabilities(const std::vector<AliasEntry>& alias, int face_size, std::vector<single_source::float4>* texels) {
    const std::vector<float> probability = cubemap_texel_probabilities(alias, face_size);
    if (texels->size() != probability.size())
        throw std::invalid_argument("store_texel_probabilities: texels do not match the face size");
    for (size_t t = 0; t < texels->size(); ++t) (*texels)[t].w = probability[t];
}

}  // namespace lab::ibl
