// A committed energy table's row against a regeneration at the generator's own resolution
// (tools/generate_energy_tables), rounded up to the tables' 16-bit step (brdf/energy_grid.h): never
// below the estimate, less than a step above it (2e-7: a margin for float rounding between this
// regeneration and the generator's). Shared by the lab's and the openpbr model's table tests.
#pragma once

#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "tests/points_of_run.hpp"
#include "validation/energy_tables.hpp"

// The committed entries of a row that are not its regeneration rounded up, each reported.
inline int energy_table_entries_off(const std::vector<float>& regenerated, const unsigned short* committed, const std::string& where) {
    int off = 0;
    for (size_t j = 0; j < regenerated.size(); ++j) {
        float stored = brdf::energy_grid_albedo_value(committed, int(j));
        if (stored >= regenerated[j] - 2e-7f && stored <= regenerated[j] + 1.0f / ENERGY_TABLE_ONE + 2e-7f) continue;
        UNSCOPED_INFO(where << ", mu node " << j << ": committed " << stored << ", regenerated " << regenerated[j]);
        ++off;
    }
    return off;
}

inline void check_energy_table_entries(const std::vector<float>& regenerated, const unsigned short* committed, const std::string& where) {
    CHECK(energy_table_entries_off(regenerated, committed, where) == 0);
}

inline void check_energy_table_row(const std::function<double(float, float)>& albedo, int n_r, int n_mu, int i,
                                   const unsigned short* committed) {
    check_energy_table_entries(lab::validation::energy_slice(albedo, n_r, n_mu, 2, i, i), committed + i * n_mu,
                               "roughness node " + std::to_string(i));
}

// Which rows of a table of `rows` rows a run regenerates: every row costs about a second of CPU
// (the generator's resolution, and the estimates between nodes that make a row conservative), too
// much for all of the tables' rows in every run, so each run draws `count` of them
// (tests/points_of_run.hpp): DTOADQ_TABLE_ROWS_SEED=S draws what the run of seed S drew,
// DTOADQ_TABLE_ROWS=all regenerates every row. `table` names the table, so each table draws its own rows.
inline std::vector<int> energy_table_rows_of_run(const std::string& table, int rows, int count) {
    return points_of_run(RunDraw{"energy table rows", "DTOADQ_TABLE_ROWS_SEED", "DTOADQ_TABLE_ROWS"}, table, rows, count);
}
