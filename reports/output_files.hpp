// Writing output files so that a kill never leaves a half-written one: write a temporary
// file beside the target, then rename it over the target (atomic on POSIX).
#pragma once

#include <filesystem>
#include <string>

namespace rotbench {

void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// A number in the shortest form that reads back to the same double; "nan", "inf", "-inf".
std::string format_number(double value);

}  // namespace rotbench
