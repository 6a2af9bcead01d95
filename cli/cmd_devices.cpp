// dtoadq devices: the OpenCL devices this machine offers, numbered as --device names them, and
// the one a command picks by default.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "opencl/device.hpp"
#include "opencl/error.hpp"

namespace lab::cli {

namespace {
// "OpenCL C 1.2 PoCL" -> "1.2 PoCL"; other text as it is.
std::string without_prefix(const std::string& text, const std::string& prefix) {
    return text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
}
}  // namespace

void register_devices(CLI::App& app) {
    auto* cmd = app.add_subcommand("devices", "List the OpenCL devices; --device takes the P:D id, gpu, cpu or part of a name");
    cmd->callback([] {
        std::vector<opencl::DeviceInfo> devices = opencl::list_devices();
        // Throws DeviceNotFound (non-zero exit, one line) when there is no platform or device.
        opencl::DeviceInfo chosen = opencl::select_device("");
        std::printf("%-5s %-6s %-4s %-10s %-14s %s\n", "id", "type", "CUs", "OpenCL", "OpenCL C", "device (platform)");
        for (const opencl::DeviceInfo& d : devices)
            std::printf("%-5s %-6s %-4u %-10s %-14s %s (%s)%s\n", d.id().c_str(), d.type.c_str(), d.compute_units,
                        d.version.substr(0, d.version.find(' ', 7)).c_str(), without_prefix(d.c_version, "OpenCL C ").c_str(), d.device_name.c_str(),
                        d.platform_name.c_str(), d.id() == chosen.id() ? "  <- default" : "");
    });
}

}  // namespace lab::cli
