// Opening an image file the lab reads its pixels from (an environment, an emitter's image or
// frame): the checks every reader makes before it looks at the header's claims
// (common/image_claim.hpp), each failure one line naming the file.
#pragma once

#include <memory>
#include <string>

#include "common/image_codec.hpp"

namespace lab::codec {

// The open file at `path`, which must exist, be a regular file, open as `kind` ("an image", "an
// OpenEXR or Radiance HDR image") and hold flat (not deep) pixels. Throws lab::InputError(path, "",
// problem + `context`), where `context` says what the file is for (" (frame 7 of ...)") or is empty.
// OpenImageIO's own text is left out of the messages: its wording varies with the version.
std::unique_ptr<ImageFile> open_flat_image(const std::string& path, const std::string& kind, const std::string& context);

}  // namespace lab::codec
