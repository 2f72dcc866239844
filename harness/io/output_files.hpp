// Writing output files so that a kill never leaves a half-written one: write a temporary
// file beside the target, then rename it over the target (atomic on POSIX).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace rotbench {

void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// The whole file as it is on disk, or nothing when it cannot be opened.
std::optional<std::string> read_file(const std::filesystem::path& path);

// A number in the shortest form that reads back to the same double; "nan", "inf", "-inf".
std::string format_number(double value);

}  // namespace rotbench
