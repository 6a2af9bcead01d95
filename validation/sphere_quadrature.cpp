#include "validation/sphere_quadrature.hpp"

#include <algorithm>
#include <cmath>

#include "common/parallel_for.hpp"

namespace lab::validation {

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

struct Simpson {
    const std::function<double(double)>& f;
    QuadratureLimits limits;

    // Simpson on [a, b] is `whole`; fa, fm, fb are f at a, (a + b) / 2, b.
    double refine(double a, double b, double fa, double fm, double fb, double whole, double tolerance, int depth) const {
        double m = 0.5 * (a + b), h = b - a;
        double flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
        double left = h / 12.0 * (fa + 4.0 * flm + fm);
        double right = h / 12.0 * (fm + 4.0 * frm + fb);
        double halves = left + right;
        double error = halves - whole;
        if (depth >= limits.max_depth || (depth >= limits.min_depth && std::fabs(error) <= 15.0 * tolerance))
            return halves + error / 15.0;
        return refine(a, m, fa, flm, fm, left, 0.5 * tolerance, depth + 1) +
               refine(m, b, fm, frm, fb, right, 0.5 * tolerance, depth + 1);
    }
};

}  // namespace

brdf::float3 direction_from_z_phi(double z, double phi) {
    double r = std::sqrt(std::fmax(0.0, 1.0 - z * z));
    return brdf::float3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}

double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double tolerance,
                        QuadratureLimits limits) {
    if (!(b > a)) return 0.0;
    double fa = f(a), fm = f(0.5 * (a + b)), fb = f(b);
    double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    return Simpson{f, limits}.refine(a, b, fa, fm, fb, whole, tolerance, 0);
}

double integrate_z_phi(const std::function<double(double, double)>& f, double z0, double z1, double phi0, double phi1,
                       double tolerance, QuadratureLimits limits) {
    // The outer rule sums inner integrals with weights adding up to (phi1 - phi0): the inner
    // tolerance is scaled so their errors stay well inside the outer one.
    double inner_tolerance = 0.25 * tolerance / std::fmax(phi1 - phi0, 1e-300);
    std::function<double(double)> over_z = [&](double phi) {
        return adaptive_simpson([&](double z) { return f(z, phi); }, z0, z1, inner_tolerance, limits);
    };
    return adaptive_simpson(over_z, phi0, phi1, 0.5 * tolerance, limits);
}

double integrate_hemisphere(const std::function<double(brdf::float3)>& g, double tolerance, QuadratureLimits limits,
                            double horizon_power) {
    if (horizon_power == 1.0)
        return integrate_z_phi([&](double z, double phi) { return g(direction_from_z_phi(z, phi)); }, 0.0, 1.0, 0.0,
                               kTwoPi, tolerance, limits);
    // dz = p s^(p - 1) ds
    auto f = [&](double s, double phi) {
        return s > 0.0 ? horizon_power * std::pow(s, horizon_power - 1.0) * g(direction_from_z_phi(std::pow(s, horizon_power), phi))
                       : 0.0;
    };
    return integrate_z_phi(f, 0.0, 1.0, 0.0, kTwoPi, tolerance, limits);
}

double integrate_sphere(const std::function<double(brdf::float3)>& g, double tolerance, QuadratureLimits limits) {
    // two hemispheres, so the integrand's usual kink at the horizon lies on a panel edge
    auto f = [&](double z, double phi) { return g(direction_from_z_phi(z, phi)); };
    return integrate_z_phi(f, -1.0, 0.0, 0.0, kTwoPi, 0.5 * tolerance, limits) +
           integrate_z_phi(f, 0.0, 1.0, 0.0, kTwoPi, 0.5 * tolerance, limits);
}

int SphereGrid::cell_of(brdf::float3 w) const {
    double z = std::clamp(double(w.z), -1.0, 1.0);
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0.0) phi += kTwoPi;
    int iz = std::clamp(int((z + 1.0) * 0.5 * z_cells), 0, z_cells - 1);
    int ip = std::clamp(int(phi / kTwoPi * phi_cells), 0, phi_cells - 1);
    return iz * phi_cells + ip;
}

void SphereGrid::bounds(int cell, double* z0, double* z1, double* phi0, double* phi1) const {
    int iz = cell / phi_cells, ip = cell % phi_cells;
    *z0 = -1.0 + 2.0 * iz / z_cells;
    *z1 = -1.0 + 2.0 * (iz + 1) / z_cells;
    *phi0 = kTwoPi * ip / phi_cells;
    *phi1 = kTwoPi * (ip + 1) / phi_cells;
}

std::vector<double> integrate_cells(const std::function<double(int, brdf::float3)>& f, const SphereGrid& grid,
                                    const std::function<double(int)>& tolerance, int threads, QuadratureLimits limits) {
    std::vector<double> integral(size_t(grid.cells()), 0.0);
    parallel_for(grid.z_cells, threads, [&](int iz) {
        for (int ip = 0; ip < grid.phi_cells; ++ip) {
            int cell = iz * grid.phi_cells + ip;
            double z0, z1, p0, p1;
            grid.bounds(cell, &z0, &z1, &p0, &p1);
            auto in_cell = [&](double z, double phi) { return f(cell, direction_from_z_phi(z, phi)); };
            integral[size_t(cell)] = integrate_z_phi(in_cell, z0, z1, p0, p1, tolerance(cell), limits);
        }
    });
    return integral;
}

}  // namespace lab::validation
