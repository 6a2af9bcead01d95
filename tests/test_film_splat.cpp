// The film's splat buffer (kernels/film.h): contributions that many work-items add to the same
// pixels at once, through a compare-and-swap loop on the float's bits, on the OpenCL device and on
// the host's threads. With splats of 1 (and 2, and 0.5) every partial sum is an exact float, so
// the sums must equal the exact counts whatever the order the splats land in: a lost update (a
// plain read-add-write) would show as a count too small. Positions off the film are dropped.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "kernels/host.hpp"
#include "kernels/host/embedded_sources.hpp"
#include "opencl/runtime.hpp"

namespace {

constexpr int kWidth = 7, kHeight = 5;

struct Splats {
    std::vector<float> xyv;        // x, y, value per splat
    std::vector<double> expected;  // per pixel: the sum of the values that land on it
};

// Splats on few pixels (so they collide), some off the film on every side; `spread` 0 puts them
// all on one pixel, where every add races with every other.
Splats make_splats(int count, float spread = 1.0f) {
    std::mt19937 rng(17);
    float cx = 0.5f * float(kWidth), cy = 0.5f * float(kHeight);
    std::uniform_real_distribution<float> x(cx - spread * (cx + 1.0f), cx + spread * (cx + 1.0f)),
        y(cy - spread * (cy + 1.0f), cy + spread * (cy + 1.0f));
    Splats s;
    s.expected.assign(size_t(kWidth * kHeight), 0.0);
    for (int i = 0; i < count; ++i) {
        float px = x(rng), py = y(rng);
        s.xyv.insert(s.xyv.end(), {px, py, 1.0f});
        if (px >= 0.0f && py >= 0.0f && px < float(kWidth) && py < float(kHeight)) s.expected[size_t(int(py) * kWidth + int(px))] += 1.0;
    }
    return s;
}

void check_sums(const std::vector<unsigned>& bits, const Splats& s) {
    for (size_t p = 0; p < s.expected.size(); ++p) {
        float r, g, b;
        std::memcpy(&r, &bits[3 * p], 4);
        std::memcpy(&g, &bits[3 * p + 1], 4);
        std::memcpy(&b, &bits[3 * p + 2], 4);
        INFO("pixel " << p << ": " << r << " " << g << " " << b << ", expected " << s.expected[p]);
        CHECK(double(r) == s.expected[p]);
        CHECK(double(g) == 2.0 * s.expected[p]);
        CHECK(double(b) == 0.5 * s.expected[p]);
    }
}

void splat_on_device(const lab::opencl::Runtime& runtime, const Splats& s) {
    int count = int(s.xyv.size() / 3);
    lab::opencl::Program program = lab::kernels::build_embedded(runtime, "kernels/film_probe.cl", "-cl-std=CL1.2");
    lab::opencl::KernelHandle kernel = program.kernel("film_splat_probe");
    lab::opencl::BufferHandle splats = runtime.buffer(s.xyv.size() * sizeof(float), CL_MEM_READ_ONLY);
    runtime.write(splats, s.xyv.data(), s.xyv.size() * sizeof(float));
    std::vector<unsigned> bits(size_t(3 * kWidth * kHeight), 0u);
    lab::opencl::BufferHandle film = runtime.buffer(bits.size() * sizeof(unsigned), CL_MEM_READ_WRITE);
    runtime.write(film, bits.data(), bits.size() * sizeof(unsigned));
    lab::opencl::set_kernel_arg(kernel, 0, count);
    lab::opencl::set_kernel_arg(kernel, 1, splats);
    lab::opencl::set_kernel_arg(kernel, 2, film);
    lab::opencl::set_kernel_arg(kernel, 3, kWidth);
    lab::opencl::set_kernel_arg(kernel, 4, kHeight);
    runtime.launch_1d(kernel, size_t(count), 64);
    runtime.finish();
    runtime.read(film, bits.data(), bits.size() * sizeof(unsigned));
    check_sums(bits, s);
}

void splat_on_threads(const Splats& s) {
    std::vector<unsigned> bits(size_t(3 * kWidth * kHeight), 0u);
    size_t count = s.xyv.size() / 3;
    auto work = [&](size_t first, size_t step) {
        for (size_t i = first; i < count; i += step) {
            float v = s.xyv[3 * i + 2];
            kernel::film_splat(bits.data(), kWidth, kHeight, s.xyv[3 * i], s.xyv[3 * i + 1], kernel::float3(v, 2.0f * v, 0.5f * v));
        }
    };
    std::vector<std::thread> threads;
    for (size_t t = 0; t < 4; ++t) threads.emplace_back(work, t, 4);
    for (std::thread& t : threads) t.join();
    check_sums(bits, s);
}

}  // namespace

TEST_CASE("Film: concurrent splats on the OpenCL device lose nothing", "[film][splat][opencl]") {
    lab::opencl::Runtime runtime("");
    splat_on_device(runtime, make_splats(200000));
    splat_on_device(runtime, make_splats(2000000, 0.0f));
}

TEST_CASE("Film: concurrent splats from the host's threads lose nothing", "[film][splat]") {
    splat_on_threads(make_splats(200000));
    splat_on_threads(make_splats(2000000, 0.0f));
}
