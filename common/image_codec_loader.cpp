// Loads the image codec module (common/image_codec.hpp) on first use: from the build tree's common/
// folder beside the running program's folder (build/cli/dtoadq, build/tests/dtoadq_tests), else
// from where it was built.
#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

#include "common/image_codec.hpp"

#ifdef DTOADQ_IMAGE_CODEC_LINKED
// the sanitized build links the codec in (common/CMakeLists.txt)
extern "C" const lab::codec::ImageCodec* dtoadq_image_codec();

const lab::codec::ImageCodec& lab::codec::image_codec() { return *dtoadq_image_codec(); }
#else
namespace lab::codec {

namespace {

constexpr const char* kModuleName = "libdtoadq_image_codec.so";

std::string module_beside_program() {
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    return (program.parent_path().parent_path() / "common" / kModuleName).string();
}

const ImageCodec* load() {
    const std::string beside = module_beside_program(), built = DTOADQ_IMAGE_CODEC_MODULE;
    for (const std::string& path : {beside, built}) {
        if (path.empty() || !std::filesystem::exists(path)) continue;
        void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) throw std::runtime_error(std::string("cannot load the image codec module: ") + dlerror());
        auto entry = reinterpret_cast<const ImageCodec* (*)()>(dlsym(module, "dtoadq_image_codec"));
        if (!entry) throw std::runtime_error(path + ": not the image codec module (no dtoadq_image_codec)");
        return entry();
    }
    const std::string looked = beside.empty() || beside == built ? built : beside + " and " + built;
    throw std::runtime_error(std::string("cannot find the image codec module ") + kModuleName + " (looked for " + looked +
                             "; build the target dtoadq_image_codec)");
}

}  // namespace

const ImageCodec& image_codec() {
    static std::once_flag once;
    static const ImageCodec* codec = nullptr;
    std::call_once(once, [] { codec = load(); });
    return *codec;
}

}  // namespace lab::codec
#endif
