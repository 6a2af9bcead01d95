// A committed energy table's row against a regeneration at the generator's own resolution
// (tools/generate_energy_tables), rounded up to the tables' 16-bit step (brdf/energy_grid.h): never
// below the estimate, less than a step above it (2e-7: a margin for float rounding between this
// regeneration and the generator's). Shared by the lab's and the openpbr model's table tests.
#pragma once

#include <catch2/catch.hpp>

#include <functional>
#include <vector>

#include "brdf/brdf.hpp"
#include "validation/energy_tables.hpp"

inline void check_energy_table_row(const std::function<double(float, float)>& albedo, int n_r, int n_mu, int i,
                                   const unsigned short* committed) {
    std::vector<float> row = lab::validation::energy_slice(albedo, n_r, n_mu, 2, i, i);
    for (int j = 0; j < n_mu; ++j) {
        INFO("roughness node " << i << ", mu node " << j);
        float stored = brdf::energy_grid_albedo_value(committed, i * n_mu + j);
        CHECK(stored >= row[size_t(j)] - 2e-7f);
        CHECK(stored <= row[size_t(j)] + 1.0f / ENERGY_TABLE_ONE + 2e-7f);
    }
}
