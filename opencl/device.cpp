#include "opencl/device.hpp"

#include <algorithm>
#include <cctype>

#include "opencl/error.hpp"

namespace lab::opencl {

namespace {

std::string platform_string(cl_platform_id platform, cl_platform_info what) {
    size_t size = 0;
    check_cl(clGetPlatformInfo(platform, what, 0, nullptr, &size), "clGetPlatformInfo");
    std::string text(size, '\0');
    check_cl(clGetPlatformInfo(platform, what, size, text.data(), nullptr), "clGetPlatformInfo");
    return std::string(text.c_str());  // drop the terminating NUL
}

std::string device_string(cl_device_id device, cl_device_info what) {
    size_t size = 0;
    check_cl(clGetDeviceInfo(device, what, 0, nullptr, &size), "clGetDeviceInfo");
    std::string text(size, '\0');
    check_cl(clGetDeviceInfo(device, what, size, text.data(), nullptr), "clGetDeviceInfo");
    return std::string(text.c_str());
}

template <typename T>
T device_value(cl_device_id device, cl_device_info what) {
    T value{};
    check_cl(clGetDeviceInfo(device, what, sizeof(T), &value, nullptr), "clGetDeviceInfo");
    return value;
}

std::string type_name(cl_device_type type) {
    if (type & CL_DEVICE_TYPE_GPU) return "gpu";
    if (type & CL_DEVICE_TYPE_CPU) return "cpu";
    if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
    return "other";
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool parse_index_pair(const std::string& s, int* platform, int* device) {
    size_t colon = s.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == s.size()) return false;
    auto all_digits = [](const std::string& t) { return std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); }); };
    std::string p = s.substr(0, colon), d = s.substr(colon + 1);
    if (!all_digits(p) || !all_digits(d) || p.size() > 6 || d.size() > 6) return false;
    *platform = std::stoi(p);
    *device = std::stoi(d);
    return true;
}

}  // namespace

std::string DeviceInfo::id() const { return std::to_string(platform_index) + ":" + std::to_string(device_index); }

std::string DeviceInfo::description() const { return id() + " " + type + " " + device_name + " (" + platform_name + ")"; }

std::vector<DeviceInfo> list_devices() {
    cl_uint platform_count = 0;
    cl_int err = clGetPlatformIDs(0, nullptr, &platform_count);
    // The ICD loader answers CL_PLATFORM_NOT_FOUND_KHR (-1001) when no driver is installed.
    if (err == -1001 || platform_count == 0) return {};
    check_cl(err, "clGetPlatformIDs");
    std::vector<cl_platform_id> platforms(platform_count);
    check_cl(clGetPlatformIDs(platform_count, platforms.data(), nullptr), "clGetPlatformIDs");

    std::vector<DeviceInfo> devices;
    for (cl_uint p = 0; p < platform_count; ++p) {
        cl_uint device_count = 0;
        err = clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, 0, nullptr, &device_count);
        if (err == CL_DEVICE_NOT_FOUND || device_count == 0) continue;
        check_cl(err, "clGetDeviceIDs");
        std::vector<cl_device_id> ids(device_count);
        check_cl(clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, device_count, ids.data(), nullptr), "clGetDeviceIDs");
        std::string platform_name = platform_string(platforms[p], CL_PLATFORM_NAME);
        for (cl_uint d = 0; d < device_count; ++d) {
            DeviceInfo info;
            info.platform_index = int(p);
            info.device_index = int(d);
            info.platform_name = platform_name;
            info.device_name = device_string(ids[d], CL_DEVICE_NAME);
            info.type = type_name(device_value<cl_device_type>(ids[d], CL_DEVICE_TYPE));
            info.version = device_string(ids[d], CL_DEVICE_VERSION);
            info.c_version = device_string(ids[d], CL_DEVICE_OPENCL_C_VERSION);
            info.compute_units = device_value<cl_uint>(ids[d], CL_DEVICE_MAX_COMPUTE_UNITS);
            info.max_work_group_size = device_value<size_t>(ids[d], CL_DEVICE_MAX_WORK_GROUP_SIZE);
            info.platform = platforms[p];
            info.device = ids[d];
            devices.push_back(info);
        }
    }
    return devices;
}

DeviceInfo select_device(const std::string& selector) {
    std::vector<DeviceInfo> devices = list_devices();
    if (devices.empty())
        throw DeviceNotFound("no OpenCL device found: no platform reports a device (is an OpenCL driver such as pocl-opencl-icd installed?)");

    auto first_of_type = [&](const std::string& type) -> const DeviceInfo* {
        for (const DeviceInfo& d : devices)
            if (d.type == type) return &d;
        return nullptr;
    };
    const DeviceInfo* found = nullptr;
    std::string wanted = lower(selector);
    int platform = 0, device = 0;
    if (wanted.empty()) {
        found = first_of_type("gpu");
        if (!found) found = first_of_type("cpu");
        if (!found) found = &devices.front();
    } else if (parse_index_pair(wanted, &platform, &device)) {
        for (const DeviceInfo& d : devices)
            if (d.platform_index == platform && d.device_index == device) found = &d;
    } else if (wanted == "gpu" || wanted == "cpu" || wanted == "accelerator") {
        found = first_of_type(wanted);
    } else {
        for (const DeviceInfo& d : devices)
            if (!found && lower(d.platform_name + " " + d.device_name).find(wanted) != std::string::npos) found = &d;
    }
    if (found) return *found;

    std::string available;
    for (const DeviceInfo& d : devices) available += (available.empty() ? "" : "; ") + d.description();
    throw DeviceNotFound("no OpenCL device matches \"" + selector + "\" (available: " + available + ")");
}

}  // namespace lab::opencl
