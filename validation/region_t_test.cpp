#include "validation/region_t_test.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "validation/chi_square_distribution.hpp"

namespace lab::validation {

namespace {

double region_mean(const film::ImageRgb& image, const RegionTest& r) {
    double sum = 0.0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) sum += double(image.pixel(x, y)[r.channel]);
    return sum / (double(r.x1 - r.x0) * double(r.y1 - r.y0));
}

}  // namespace

const RegionTest* RegionComparison::worst() const {
    const RegionTest* w = nullptr;
    for (const RegionTest& r : regions)
        if (!w || r.result.p_value < w->result.p_value) w = &r;
    return w;
}

double detectable_difference(const RegionTest& r, double level) {
    const double z = 1.2815515655446004;  // the standard normal's quantile at kDetectionProbability
    static_assert(kDetectionProbability == 0.9, "z is the quantile at 0.9");
    // near the critical value t_c, t at the noncentrality d / se is about normal with mean d / se
    // and variance 1 + t_c^2 / (2 dof) (the noncentral t's approximation by Jennett and Welch, 1939)
    double t_critical = student_t_critical(level, r.result.dof);
    double difference = (t_critical + z * std::sqrt(1.0 + t_critical * t_critical / (2.0 * r.result.dof))) * r.result.standard_error;
    if (difference == 0.0) return 0.0;
    return r.result.mean_b != 0.0 ? difference / std::fabs(r.result.mean_b) : std::numeric_limits<double>::infinity();
}

double detectable_difference(const RegionComparison& c) {
    double worst = 0.0;
    for (const RegionTest& r : c.regions) worst = std::max(worst, detectable_difference(r, c.level));
    return worst;
}

RegionComparison compare_by_region(const std::vector<film::ImageRgb>& a, const std::vector<film::ImageRgb>& b, int columns, int rows,
                                   double significance, Pairing pairing) {
    if (a.size() < 2 || b.size() < 2) throw std::invalid_argument("compare_by_region: at least two renders of each");
    if (pairing == Pairing::paired && a.size() != b.size()) throw std::invalid_argument("compare_by_region: paired renders of each");
    const int width = a[0].width, height = a[0].height;
    for (const auto* set : {&a, &b})
        for (const film::ImageRgb& image : *set)
            if (image.width != width || image.height != height) throw std::invalid_argument("compare_by_region: images of different sizes");
    if (columns < 1 || rows < 1 || columns > width || rows > height) throw std::invalid_argument("compare_by_region: bad region grid");
    RegionComparison out;
    out.level = sidak_alpha(significance, columns * rows * 3);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i)
            for (int c = 0; c < 3; ++c) {
                RegionTest r;
                r.x0 = i * width / columns;
                r.x1 = (i + 1) * width / columns;
                r.y0 = j * height / rows;
                r.y1 = (j + 1) * height / rows;
                r.channel = c;
                std::vector<double> ma, mb;
                for (const film::ImageRgb& image : a) ma.push_back(region_mean(image, r));
                for (const film::ImageRgb& image : b) mb.push_back(region_mean(image, r));
                r.result = pairing == Pairing::paired ? paired_t_test(ma, mb) : welch_t_test(ma, mb);
                out.rejected += r.result.p_value < out.level;
                out.regions.push_back(r);
            }
    return out;
}

}  // namespace lab::validation
