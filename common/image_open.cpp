#include "common/image_open.hpp"

#include <filesystem>

#include "common/input_error.hpp"

namespace lab::codec {

std::unique_ptr<ImageFile> open_flat_image(const std::string& path, const std::string& kind, const std::string& context) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path, "", "no such file" + context);
    if (!fs::is_regular_file(path, ec)) throw InputError(path, "", "not a regular file" + context);
    std::string error;
    std::unique_ptr<ImageFile> file = image_codec().open(path, &error);
    if (!file) throw InputError(path, "", "cannot be read as " + kind + context);
    if (file->header().deep) throw InputError(path, "", "deep image (expected flat pixels)" + context);
    return file;
}

}  // namespace lab::codec
