// Replacing a file all at once: the new content goes to a temporary file beside the target, which
// is then renamed over it (rename is atomic within a file system). Readers see the old file or the
// new one, never half of one, and a failure leaves the old file untouched.
#pragma once

#include <cstddef>
#include <string>

namespace lab::film {

// Writes `size` bytes to PATH atomically. The new file keeps the mode of the file it replaces
// (else 0666 less the umask). Throws lab::InputError(path, "", "cannot write: <reason>") on any
// failure (no folder, no space, file too large, a folder in the way), after removing the
// temporary file.
void write_file_atomically(const std::string& path, const void* data, size_t size);

}  // namespace lab::film
