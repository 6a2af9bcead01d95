#include "opencl/runtime.hpp"

#include <algorithm>
#include <list>
#include <mutex>
#include <vector>

namespace lab::opencl {

KernelHandle Program::kernel(const char* name) const {
    cl_int err = CL_SUCCESS;
    cl_kernel k = clCreateKernel(handle_.get(), name, &err);
    check_cl(err, (std::string("clCreateKernel(") + name + ")").c_str());
    return KernelHandle(k);
}

struct Runtime::BuiltPrograms {
    struct Entry {
        std::string options, text;
        ProgramHandle program;
    };
    std::mutex mutex;
    std::list<Entry> entries;
};

Runtime::Runtime(const std::string& selector) : device_(select_device(selector)), built_(std::make_unique<BuiltPrograms>()) {
    cl_int err = CL_SUCCESS;
    cl_context_properties properties[] = {CL_CONTEXT_PLATFORM, cl_context_properties(device_.platform), 0};
    context_ = ContextHandle(clCreateContext(properties, 1, &device_.device, nullptr, nullptr, &err));
    check_cl(err, "clCreateContext");
    queue_ = QueueHandle(clCreateCommandQueue(context_.get(), device_.device, 0, &err));
    check_cl(err, "clCreateCommandQueue");
}

Runtime::~Runtime() = default;
Runtime::Runtime(Runtime&&) noexcept = default;
Runtime& Runtime::operator=(Runtime&&) noexcept = default;

Program Runtime::build(const AssembledSource& source, const std::string& options) const {
    std::lock_guard<std::mutex> lock(built_->mutex);
    std::list<BuiltPrograms::Entry>& entries = built_->entries;
    auto found = std::find_if(entries.begin(), entries.end(),
                              [&](const BuiltPrograms::Entry& e) { return e.options == options && e.text == source.text; });
    if (found == entries.end()) {
        Program program = build_new(source, options);
        check_cl(clRetainProgram(program.get()), "clRetainProgram");
        entries.push_front(BuiltPrograms::Entry{options, source.text, ProgramHandle(program.get())});
        if (entries.size() > kBuiltPrograms) entries.pop_back();
        return program;
    }
    entries.splice(entries.begin(), entries, found);
    check_cl(clRetainProgram(found->program.get()), "clRetainProgram");
    return Program(ProgramHandle(found->program.get()), source);
}

Program Runtime::build_new(const AssembledSource& source, const std::string& options) const {
    cl_int err = CL_SUCCESS;
    const char* text = source.text.c_str();
    size_t length = source.text.size();
    ProgramHandle program(clCreateProgramWithSource(context_.get(), 1, &text, &length, &err));
    check_cl(err, "clCreateProgramWithSource");
    err = clBuildProgram(program.get(), 1, &device_.device, options.c_str(), nullptr, nullptr);
    if (err == CL_BUILD_PROGRAM_FAILURE || err == CL_INVALID_BUILD_OPTIONS) {
        size_t size = 0;
        clGetProgramBuildInfo(program.get(), device_.device, CL_PROGRAM_BUILD_LOG, 0, nullptr, &size);
        std::string log(size, '\0');
        clGetProgramBuildInfo(program.get(), device_.device, CL_PROGRAM_BUILD_LOG, size, log.data(), nullptr);
        log = std::string(log.c_str());
        std::string first = err == CL_INVALID_BUILD_OPTIONS ? "invalid build options \"" + options + "\"" : "see log";
        std::vector<BuildDiagnostic> diagnostics = parse_build_log(log, source);
        for (const BuildDiagnostic& d : diagnostics) {
            if (d.message.find("error") == std::string::npos) continue;  // skip warnings and notes
            first = d.origin.file + ":" + std::to_string(d.origin.line) + ":" + std::to_string(d.column) + ": " + d.message +
                    " [generated line " + std::to_string(d.generated_line) + ": " + source.line_text(d.generated_line) + "]";
            break;
        }
        throw KernelBuildError("OpenCL build of " + source.entry + " failed on " + device_.device_name + ": " + first +
                               "\ncompiler log:\n" + annotate_build_log(log, source));
    }
    check_cl(err, ("clBuildProgram(" + source.entry + ")").c_str());
    return Program(std::move(program), source);
}

BufferHandle Runtime::buffer(size_t bytes, cl_mem_flags flags) const {
    cl_int err = CL_SUCCESS;
    // OpenCL rejects zero-sized buffers; empty batches still get a valid (unused) one.
    BufferHandle b(clCreateBuffer(context_.get(), flags, bytes > 0 ? bytes : 4, nullptr, &err));
    check_cl(err, "clCreateBuffer");
    return b;
}

void Runtime::write(const BufferHandle& buffer, const void* data, size_t bytes) const {
    if (bytes == 0) return;
    check_cl(clEnqueueWriteBuffer(queue_.get(), buffer.get(), CL_TRUE, 0, bytes, data, 0, nullptr, nullptr), "clEnqueueWriteBuffer");
}

void Runtime::read(const BufferHandle& buffer, void* data, size_t bytes) const {
    if (bytes == 0) return;
    check_cl(clEnqueueReadBuffer(queue_.get(), buffer.get(), CL_TRUE, 0, bytes, data, 0, nullptr, nullptr), "clEnqueueReadBuffer");
}

void Runtime::zero(const BufferHandle& buffer, size_t bytes) const {
    if (bytes == 0) return;
    const cl_uint pattern = 0;
    check_cl(clEnqueueFillBuffer(queue_.get(), buffer.get(), &pattern, sizeof(pattern), 0, bytes, 0, nullptr, nullptr), "clEnqueueFillBuffer");
}

void Runtime::launch_1d(const KernelHandle& kernel, size_t count, size_t local) const {
    if (count == 0) return;
    size_t global = (count + local - 1) / local * local;
    check_cl(clEnqueueNDRangeKernel(queue_.get(), kernel.get(), 1, nullptr, &global, &local, 0, nullptr, nullptr),
             "clEnqueueNDRangeKernel");
}

void Runtime::finish() const { check_cl(clFinish(queue_.get()), "clFinish"); }

}  // namespace lab::opencl
