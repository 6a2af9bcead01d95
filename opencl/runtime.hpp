// One OpenCL device with its context and in-order queue, and what every kernel host needs:
// building an assembled kernel source with mapped error messages, buffers, 1D launches.
#pragma once

#include <memory>
#include <string>

#include <CL/cl.h>

#include "opencl/device.hpp"
#include "opencl/error.hpp"
#include "opencl/handle.hpp"
#include "opencl/kernel_source.hpp"

namespace lab::opencl {

class Program {
public:
    Program(ProgramHandle handle, AssembledSource source) : handle_(std::move(handle)), source_(std::move(source)) {}
    cl_program get() const { return handle_.get(); }
    const AssembledSource& source() const { return source_; }
    KernelHandle kernel(const char* name) const;

private:
    ProgramHandle handle_;
    AssembledSource source_;
};

class Runtime {
public:
    // Selector as in select_device(); throws DeviceNotFound or OpenClError.
    explicit Runtime(const std::string& selector = "");
    ~Runtime();
    Runtime(Runtime&&) noexcept;
    Runtime& operator=(Runtime&&) noexcept;

    const DeviceInfo& device() const { return device_; }
    cl_context context() const { return context_.get(); }
    cl_command_queue queue() const { return queue_.get(); }

    // Compiles with clBuildProgram. PoCL keeps its kernel cache (POCL_CACHE_DIR, by default
    // ~/.cache/pocl/kcache), so an unchanged source and option string build warm; and this runtime
    // keeps its kBuiltPrograms most recent programs, so that the same source and options built again
    // (a renderer per seed, per light selection or per preset of the same features) are that program,
    // with no build at all: a warm build still reads and parses the program's bitcode, a tenth of a
    // second of CPU for a path tracer.
    // Throws KernelBuildError: first line the first error at its original file:line, then the log.
    Program build(const AssembledSource& source, const std::string& options) const;
    static constexpr size_t kBuiltPrograms = 8;

    BufferHandle buffer(size_t bytes, cl_mem_flags flags) const;
    void write(const BufferHandle& buffer, const void* data, size_t bytes) const;
    void read(const BufferHandle& buffer, void* data, size_t bytes) const;
    // Sets the buffer's first `bytes` (a multiple of 4) to zero, in queue order, without waiting.
    void zero(const BufferHandle& buffer, size_t bytes) const;

    // Enqueues `count` work-items in groups of `local` (the global size is rounded up, so kernels
    // check their index against the count). A fixed local size keeps PoCL from compiling a new
    // work-group function for every batch size, and so does the global offset, always 0: PoCL
    // specialises its work-group functions for offset 0 and compiles a kernel again for any other
    // (a kernel that starts elsewhere takes its first work-item as an argument, render/opencl_launch.hpp).
    void launch_1d(const KernelHandle& kernel, size_t count, size_t local) const;
    void finish() const;

private:
    struct BuiltPrograms;  // the programs build() keeps, most recent first
    Program build_new(const AssembledSource& source, const std::string& options) const;

    DeviceInfo device_;
    ContextHandle context_;
    QueueHandle queue_;
    std::unique_ptr<BuiltPrograms> built_;
};

template <typename T>
void set_kernel_arg(const KernelHandle& kernel, cl_uint index, const T& value) {
    check_cl(clSetKernelArg(kernel.get(), index, sizeof(T), &value), "clSetKernelArg");
}

inline void set_kernel_arg(const KernelHandle& kernel, cl_uint index, const BufferHandle& buffer) {
    cl_mem mem = buffer.get();
    check_cl(clSetKernelArg(kernel.get(), index, sizeof(cl_mem), &mem), "clSetKernelArg");
}

// Sets the kernel's arguments 0, 1, 2, ... to args in order.
template <typename... Args>
void set_kernel_args(const KernelHandle& kernel, const Args&... args) {
    cl_uint index = 0;
    (set_kernel_arg(kernel, index++, args), ...);
}

}  // namespace lab::opencl
