// OpenCL platform and device discovery, and choosing one device from a user's selector string.
#pragma once

#include <string>
#include <vector>

#include <CL/cl.h>

namespace lab::opencl {

struct DeviceInfo {
    int platform_index = 0;
    int device_index = 0;  // within its platform
    std::string platform_name;
    std::string device_name;
    std::string type;            // "gpu", "cpu", "accelerator" or "other"
    std::string version;         // CL_DEVICE_VERSION
    std::string c_version;       // CL_DEVICE_OPENCL_C_VERSION
    unsigned compute_units = 0;
    size_t max_work_group_size = 0;
    cl_platform_id platform = nullptr;
    cl_device_id device = nullptr;

    std::string id() const;           // "P:D", what a selector may name
    std::string description() const;  // "0:0 cpu pthread-... (Portable Computing Language)"
};

// Every device of every platform, in platform then device order. Empty when no platform exists.
std::vector<DeviceInfo> list_devices();

// Selector grammar:
//   ""          first GPU, else first CPU, else the first device
//   "P:D"       platform P, device D (indices as list_devices() numbers them)
//   "gpu"/"cpu" the first device of that type
//   other text  the first device whose "platform device" name contains it, ignoring case
// Throws DeviceNotFound naming the selector and the available devices.
DeviceInfo select_device(const std::string& selector);

}  // namespace lab::opencl
