// Errors from the OpenCL runtime: a missing platform or device, a failed call, a kernel that does
// not compile. One line each (a build failure adds the compiler log below), so the command line can
// print what() and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>

#include <CL/cl.h>

namespace lab::opencl {

class OpenClError : public std::runtime_error {
public:
    explicit OpenClError(const std::string& message) : std::runtime_error(message) {}
};

// No platform, no device, or no device matching the user's selector.
class DeviceNotFound : public OpenClError {
public:
    explicit DeviceNotFound(const std::string& message) : OpenClError(message) {}
};

// A kernel failed to compile; what() holds the first error mapped to its original file:line, then
// the annotated compiler log.
class KernelBuildError : public OpenClError {
public:
    explicit KernelBuildError(const std::string& message) : OpenClError(message) {}
};

// "CL_INVALID_VALUE" for -30, "error -1234" for codes this table does not know.
std::string cl_error_name(cl_int code);

// Throws OpenClError("<what> failed: <name> (<code>)") unless code is CL_SUCCESS.
void check_cl(cl_int code, const char* what);

}  // namespace lab::opencl
