// Which points of a long check a run makes, when making all of them in every run costs too much:
// each run draws `count` of the `n` points at random from a seed it prints once, so a change at any
// point can be caught by some run and a failing run can be repeated. Two environment variables
// per kind of draw: SEED_VARIABLE=S draws what the run of seed S drew, ALL_VARIABLE=all makes every
// point. Each named set of points draws from its own stream (the seed and the name), so a set added
// or resized changes no other set's draw. Points named in `always` are made in every run (the only
// point of its kind, one that a demonstration of the check's power relies on) and are not counted
// in `count`.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

struct RunDraw {
    const char* what;           // printed: "energy table rows"
    const char* seed_variable;  // DTOADQ_..._SEED
    const char* all_variable;   // DTOADQ_...: "all" makes every point
};

// The run's seed of a kind of draw: the seed variable's, else a random one, printed on first use.
inline uint64_t run_draw_seed(const RunDraw& draw) {
    static std::map<std::string, uint64_t> seeds;
    const auto known = seeds.find(draw.seed_variable);
    if (known != seeds.end()) return known->second;
    const char* given = std::getenv(draw.seed_variable);
    const uint64_t s = given != nullptr ? std::strtoull(given, nullptr, 10) : (uint64_t(std::random_device{}()) << 32) ^ std::random_device{}();
    std::printf("%s: seed %llu (%s=%llu draws these again, %s=all makes every one)\n", draw.what, (unsigned long long)s, draw.seed_variable,
                (unsigned long long)s, draw.all_variable);
    seeds[draw.seed_variable] = s;
    return s;
}

// The points of 0 .. n-1 that this run makes, in ascending order: `always`, and `count` drawn from
// the others (all of them when ALL_VARIABLE is "all" or count covers them).
inline std::vector<int> points_of_run(const RunDraw& draw, const std::string& name, int n, int count, const std::vector<int>& always = {}) {
    std::vector<int> all(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) all[size_t(i)] = i;
    const char* every = std::getenv(draw.all_variable);
    std::vector<int> others;
    for (int i : all)
        if (std::find(always.begin(), always.end(), i) == always.end()) others.push_back(i);
    if ((every != nullptr && std::string(every) == "all") || count >= int(others.size())) return all;
    const uint64_t seed = run_draw_seed(draw);
    std::seed_seq seq{uint32_t(seed), uint32_t(seed >> 32), uint32_t(std::hash<std::string>{}(name))};
    std::mt19937 rng(seq);
    std::shuffle(others.begin(), others.end(), rng);
    others.resize(size_t(count));
    std::vector<int> chosen = always;
    chosen.insert(chosen.end(), others.begin(), others.end());
    std::sort(chosen.begin(), chosen.end());
    std::string drawn;
    for (int i : chosen) drawn += " " + std::to_string(i);
    std::printf("%s: %s:%s of %d\n", draw.what, name.c_str(), drawn.c_str(), n);
    return chosen;
}

// The draw of the long statistical sweeps (docs/testing.md, "Sweeps that check a drawn part of
// their points").
inline std::vector<int> sweep_points_of_run(const std::string& name, int n, int count, const std::vector<int>& always = {}) {
    return points_of_run(RunDraw{"sweep points", "DTOADQ_SWEEP_POINTS_SEED", "DTOADQ_SWEEP_POINTS"}, name, n, count, always);
}
