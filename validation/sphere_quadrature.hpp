// Adaptive quadrature over directions. Directions are parametrised by z = cos theta and phi, in
// which the solid angle element is dz dphi: a rectangle in (z, phi) has solid angle (dz)(dphi).
#pragma once

#include <functional>
#include <vector>

#include "brdf/brdf.hpp"

namespace lab::validation {

brdf::float3 direction_from_z_phi(double z, double phi);

struct QuadratureLimits {
    int min_depth = 1;   // bisections always made, so a lobe between two nodes is not missed
    int max_depth = 12;  // bisections allowed, per axis
};

// Adaptive Simpson on [a, b] to an absolute `tolerance` (Richardson-corrected).
double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double tolerance,
                        QuadratureLimits limits = {});

// Integral of f(z, phi) dz dphi over [z0, z1] x [phi0, phi1]: an adaptive Simpson over phi of
// adaptive Simpsons over z, so a feature narrow along one axis only refines that axis.
double integrate_z_phi(const std::function<double(double z, double phi)>& f, double z0, double z1, double phi0,
                       double phi1, double tolerance, QuadratureLimits limits = {});

// Integral of g(w) over the upper hemisphere (z in [0, 1]) or the whole sphere.
// horizon_power p > 1 substitutes z = s^p: nodes cluster at the horizon, which makes integrable
// singularities there (heavy-tailed normal distributions, D ~ z^(2g - 4)) smooth; p (2g - 3) >= 2 suffices.
double integrate_hemisphere(const std::function<double(brdf::float3)>& g, double tolerance, QuadratureLimits limits = {},
                            double horizon_power = 1.0);
double integrate_sphere(const std::function<double(brdf::float3)>& g, double tolerance, QuadratureLimits limits = {});

// The sphere cut into z_cells equal-area bands of cos theta over [-1, 1] (the horizon on a band
// edge when z_cells is even) times phi_cells sectors of [0, 2 pi).
struct SphereGrid {
    int z_cells = 100;
    int phi_cells = 100;

    int cells() const { return z_cells * phi_cells; }
    int cell_of(brdf::float3 w) const;
    void bounds(int cell, double* z0, double* z1, double* phi0, double* phi1) const;
};

// Integral of f(cell, w) over each cell of the grid, each to its own absolute tolerance; the bands
// are shared among `threads` threads, each cell's result is independent of the thread count.
std::vector<double> integrate_cells(const std::function<double(int cell, brdf::float3 w)>& f, const SphereGrid& grid,
                                    const std::function<double(int cell)>& tolerance, int threads,
                                    QuadratureLimits limits = {});

}  // namespace lab::validation
