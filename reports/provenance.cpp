#include "reports/provenance.hpp"

#include "build_info.hpp"

#include <chrono>
#include <fmt/chrono.h>
#include <fmt/format.h>
#include <fstream>

namespace rotbench {
namespace {

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

}  // namespace

Provenance provenance() {
    return {build_info::version,
            build_info::commit,
            build_info::compiler,
            build_info::build_type,
            build_info::flags,
            cpu_model(),
            fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now())))};
}

}  // namespace rotbench
