#include "harness/store/program_path.hpp"

#include "harness/store/parse.hpp"

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace rotbench {

std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    for (const auto& folder : split_on(path ? path : "", ':')) {
        if (folder.empty()) continue;
        const std::string candidate = folder + "/" + name;
        std::error_code ec;
        if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate, ec)) return candidate;
    }
    return "";
}

}  // namespace rotbench
