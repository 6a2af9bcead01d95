// What bench brdf times: a batch of (material, wo, wi, u) items and the C++ build's loop over it.
// Item i uses materials[index[i]]; wo lies in the upper hemisphere, wi anywhere, u in [0, 1)^3.
#pragma once

#include <vector>

#include "brdf/brdf.hpp"
#include "validation/random_inputs.hpp"
#include "validation/uniform_random.hpp"

namespace lab::cli {

struct Workload {
    std::vector<brdf::Material> materials;
    std::vector<int> index;
    std::vector<brdf::float3> wo, wi, u;
};

// n items over `materials`: material i mod M (neighbours differ: the worst case for SIMD lanes) or,
// sorted, the materials in consecutive blocks.
inline Workload make_workload(const std::vector<brdf::Material>& materials, long n, bool sorted) {
    Workload w;
    w.materials = materials;
    validation::UniformRandom rng(2017);
    long count = long(materials.size());
    for (long i = 0; i < n; ++i) {
        w.index.push_back(sorted ? int(i * count / n) : int(i % count));
        w.wo.push_back(validation::uniform_hemisphere_direction(rng));
        w.wi.push_back(validation::uniform_sphere_direction(rng));
        w.u.push_back(rng.next_float3());
    }
    return w;
}

// Keeps the optimiser from dropping the timed calls.
inline volatile float g_sink = 0.0f;

enum class Operation { eval, pdf, sample };

// The C++ build over items [begin, end); returns a sum the caller hands to g_sink.
inline float run_cpp(const Workload& w, Operation op, long begin, long end) {
    float sum = 0.0f;
    for (long i = begin; i < end; ++i) {
        const brdf::Material& m = w.materials[size_t(w.index[size_t(i)])];
        if (op == Operation::eval) sum += brdf::bsdf_eval(&m, w.wo[size_t(i)], w.wi[size_t(i)]).x;
        else if (op == Operation::pdf) sum += brdf::bsdf_pdf(&m, w.wo[size_t(i)], w.wi[size_t(i)]);
        else sum += brdf::bsdf_sample(&m, w.wo[size_t(i)], w.u[size_t(i)]).pdf;
    }
    return sum;
}

}  // namespace lab::cli
