#include "render/render_settings.hpp"

#include <algorithm>
#include <utility>

#include "common/input_error.hpp"
#include "ibl/background_blur.hpp"
#include "kernels/host.hpp"
#include "render/light_cache.hpp"
#include "render/vcm.hpp"
#include "render/option_words.hpp"

namespace lab::render {

namespace {

// Images beyond 2^26 pixels are refused up front: the kernels count pixels in an int.
constexpr long kMaxPixels = 1L << 26;

constexpr std::pair<const char*, MisHeuristic> kMisWords[] = {{"balance", MisHeuristic::balance}, {"power", MisHeuristic::power}};
// The first word of each value is its name; the others are accepted as synonyms.
constexpr std::pair<const char*, LightSampling> kLightSamplingWords[] = {
    {"bsdf", LightSampling::bsdf}, {"lights", LightSampling::lights}, {"mis", LightSampling::mis},
    {"brdf", LightSampling::bsdf}, {"env", LightSampling::lights}};
constexpr std::pair<const char*, NormalMethod> kNormalWords[] = {
    {"tetrahedral", NormalMethod::tetrahedral}, {"central", NormalMethod::central}, {"analytic", NormalMethod::analytic}};

}  // namespace

MisHeuristic parse_mis_heuristic(const std::string& text, const std::string& option) { return parse_word(text, option, kMisWords); }
const char* mis_heuristic_name(MisHeuristic heuristic) { return word_of(heuristic, kMisWords); }
NormalMethod parse_normal_method(const std::string& text, const std::string& option) { return parse_word(text, option, kNormalWords); }
LightSampling parse_light_sampling(const std::string& text, const std::string& option) {
    return parse_word(text, option, kLightSamplingWords);
}
const char* light_sampling_name(LightSampling sampling) { return word_of(sampling, kLightSamplingWords); }
const char* normal_method_name(NormalMethod method) { return word_of(method, kNormalWords); }

static_assert(kBdptMaxDepth + 2 == BDPT_VERTEX_LIMIT, "bdpt's depth limit is what the host build's vertex arrays hold");

void check_render_settings(const RenderSettings& settings) {
    if (settings.width < 1 || settings.height < 1 || settings.width > kMaxImageSide || settings.height > kMaxImageSide ||
        long(settings.width) * settings.height > kMaxPixels)
        throw InputError("--size", "", std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                                           " is outside 1x1 .. " + std::to_string(kMaxImageSide) + " a side and 2^26 pixels");
    if (settings.max_depth < 0 || settings.max_depth > 1024)
        throw InputError("--max-depth", "", "must be in [0, 1024], got " + std::to_string(settings.max_depth));
    if (integrator_descriptor(settings.integrator).bidirectional() && settings.max_depth > kBdptMaxDepth)
        throw InputError("--max-depth", "", std::string(integrator_name(settings.integrator)) + " takes at most " +
                                                std::to_string(kBdptMaxDepth) + " scattering events, got " + std::to_string(settings.max_depth));
    check_light_cache_settings(settings);
    check_vcm_settings(settings);
    if (!(settings.bdpt.connection_roulette >= 0.0f && settings.bdpt.connection_roulette < 1.0f))
        throw InputError("--connection-roulette", "", "must be a weight in [0, 1)");
    if (settings.opencl.local_size < 0 || settings.opencl.local_size > 4096)
        throw InputError("local size", "", "must be in [0, 4096], got " + std::to_string(settings.opencl.local_size));
    if (settings.max_steps < 1 || settings.max_steps > 1 << 20)
        throw InputError("--max-steps", "", "must be in [1, 1048576], got " + std::to_string(settings.max_steps));
    if (!(settings.over_relaxation >= 1.0f && settings.over_relaxation <= 2.0f))
        throw InputError("--over-relaxation", "", "must be in [1, 2]");
    if (!(settings.background_opacity >= 0.0f && settings.background_opacity <= 1.0f))
        throw InputError("--background-opacity", "", "must be a number in [0, 1]");
    if (!(settings.background_blur_degrees >= 0.0f && settings.background_blur_degrees <= ibl::kMaxBackgroundBlurDegrees))
        throw InputError("--background-blur", "", "must be a number of degrees in [0, 90]");
}

namespace {

// One to six decimal digits, the most an image side can be written with.
bool is_side_digits(const std::string& text) {
    return !text.empty() && text.size() <= 6 && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

void parse_image_size(const std::string& text, const std::string& option, int* width, int* height) {
    const size_t x = text.find('x');
    const std::string w = text.substr(0, x), h = x == std::string::npos ? std::string() : text.substr(x + 1);
    if (!is_side_digits(w) || !is_side_digits(h)) throw InputError(option, "", "expected WIDTHxHEIGHT, e.g. 512x512, got \"" + text + "\"");
    *width = std::stoi(w);
    *height = std::stoi(h);
    if (*width < 1 || *height < 1 || *width > kMaxImageSide || *height > kMaxImageSide)
        throw InputError(option, "", text + " is outside 1 .. " + std::to_string(kMaxImageSide) + " pixels a side");
}

}  // namespace lab::render
