// Fuzzes the scene loader, its analysis and its compiler up to the generated kernel source, with
// arbitrary text read as the scene file scenes/fuzz.json (so "../presets/x.json" names a bundled
// preset; run from the repository root). Invariants: every input is refused with lab::InputError
// or accepted; an accepted scene's Lipschitz bound is a finite number >= 1; its generated source,
// and the kernel assembled around it, are the same when the text is parsed and compiled again; an
// accepted scene's camera is a camera at each of its keyframes' times (the loader checked them),
// and between them the scene at a time is one or an InputError (scene/scene_time.hpp).
#include <cmath>
#include <cstdint>
#include <string>

#include "common/input_error.hpp"
#include "fuzz/fuzz_check.hpp"
#include "kernels/host/scene_kernel_source.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_time.hpp"

namespace {

struct Compiled {
    std::string generated, kernel;
    float lipschitz = 0.0f;
};

Compiled compile(const std::string& text) {
    const lab::scene::CompiledScene c = lab::scene::compile_scene(lab::scene::parse_scene(text, "scenes/fuzz.json"));
    return {c.source, lab::kernels::assemble_scene_kernel("kernels/scene_probe.cl", c).text, c.lipschitz};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    Compiled first;
    try {
        first = compile(text);
    } catch (const lab::InputError&) {
        return 0;
    }
    FUZZ_REQUIRE(std::isfinite(first.lipschitz) && first.lipschitz >= 1.0f, "the Lipschitz bound is not a finite number >= 1");
    const Compiled second = compile(text);
    FUZZ_REQUIRE(second.generated == first.generated, "the generated source differs between two compilations");
    FUZZ_REQUIRE(second.kernel == first.kernel, "the assembled kernel differs between two compilations");
    const lab::scene::Scene scene = lab::scene::parse_scene(text, "scenes/fuzz.json");
    if (scene.camera.keyframes) {
        const std::vector<float>& times = scene.camera.keyframes->times;
        for (size_t k = 0; k < times.size(); ++k) {
            FUZZ_REQUIRE(!lab::scene::camera_problem(lab::scene::camera_at(scene.camera, times[k])), "a keyframe the loader took is no camera");
            if (k + 1 < times.size()) {
                try {
                    lab::scene::scene_at_time(scene, 0.5 * (double(times[k]) + double(times[k + 1])));
                } catch (const lab::InputError&) {
                }
            }
        }
    }
    return 0;
}
