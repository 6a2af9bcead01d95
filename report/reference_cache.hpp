// References kept in a report's folder, so that a second report reuses them: a reference costs
// many times the runs compared with it. Each is an EXR (linear, with its noise figures and the key
// it was rendered for in its metadata); a file whose key differs from the one asked for (another
// scene file, other settings or budget, another build) is rendered again and replaced.
#pragma once

#include <string>

#include "report/convergence.hpp"

namespace lab::report {

// The reference of `input` for `seconds` (render_reference), read from `exr` when that file holds
// the reference of `key`, else rendered and written there. *reused tells which. Throws
// lab::InputError naming `exr` when it cannot be written.
Reference cached_reference(const std::string& exr, const std::string& key, const RendererFactory& make, const render::RenderInput& input,
                           double seconds, bool* reused);

// A short hexadecimal digest of text (FNV-1a, 64 bits): for keys that name a file's content.
std::string text_digest(const std::string& text);

}  // namespace lab::report
