#include "scene/rotation.hpp"

namespace lab::scene {

std::vector<std::pair<float, int>> rotation_terms(const glm::mat3& r, int i, bool inverse) {
    std::vector<std::pair<float, int>> terms;
    for (int j = 0; j < 3; ++j) {
        // glm is column-major: r[col][row]. (R^T p)_i = sum_j R_ji p_j; (R n)_i = sum_j R_ij n_j.
        float c = inverse ? r[i][j] : r[j][i];
        if (c != 0.0f) terms.emplace_back(c, j);
    }
    return terms;
}

Vec3 apply_rotation(const glm::mat3& r, Vec3 v, bool inverse) {
    Vec3 out(0.0f);
    for (int i = 0; i < 3; ++i) {
        auto terms = rotation_terms(r, i, inverse);
        if (terms.empty()) continue;
        float sum = terms[0].first * v[terms[0].second];
        for (size_t k = 1; k < terms.size(); ++k) sum = sum + terms[k].first * v[terms[k].second];
        out[i] = sum;
    }
    return out;
}

}  // namespace lab::scene
