// Kernel sources assembled from files a lookup serves (kernels/host/ serves the ones embedded in the
// binary): every `#include "..."` is expanded in place, and each line of the result remembers where it came from,
// so a compiler message about generated line N can name the original file and line.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace lab::opencl {

struct SourceLocation {
    std::string file;  // repository-relative path, e.g. "brdf/ggx.h"
    int line = 0;      // 1-based
};

struct AssembledSource {
    std::string entry;                   // the file assembly started from
    std::string text;                    // what the OpenCL compiler sees
    std::vector<SourceLocation> origin;  // origin[k]: where generated line k + 1 came from

    // Original location of a 1-based generated line; {"?", 0} when out of range.
    SourceLocation locate(int generated_line) const;
    // Text of a 1-based generated line, empty when out of range.
    std::string line_text(int generated_line) const;
};

// Returns a file's text by repository-relative path, or an empty view when there is no such file.
using SourceLookup = std::function<std::string_view(const std::string& path)>;

// Expands `#include "name"` recursively. `name` resolves against the including file's folder first,
// then against the repository root. A file is expanded at its first include only (like #pragma once)
// unless that include sits in a block the compiler may switch off: every header here has an include
// guard, so a second copy preprocesses to nothing when both are compiled.
// Feature switches are resolved while assembling: a block `#if NAME` / `#ifndef NAME` whose NAME an
// earlier line defined (as 0 or 1 for #if; see brdf/features.h) is kept or dropped here, includes
// and all, so a kernel's source holds only the parts of the modules its scene uses.
// Throws OpenClError naming the file and line of an include that resolves to no file.
AssembledSource assemble_source(const std::string& entry, const SourceLookup& lookup);

// One "FILE:LINE:COL: message" diagnostic found in a compiler log, mapped back to its origin.
struct BuildDiagnostic {
    int generated_line = 0;
    int column = 0;
    SourceLocation origin;
    std::string message;  // the log line's text after "LINE:COL:"
};

std::vector<BuildDiagnostic> parse_build_log(const std::string& log, const AssembledSource& source);

// The log with, under every line that points into the generated source, the original file:line
// and the generated line's text.
std::string annotate_build_log(const std::string& log, const AssembledSource& source);

}  // namespace lab::opencl
