// Reading the CSV files rotbench writes: the header must be exactly the one given, and every
// row must have as many fields; errors name the file and line (InputError).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

std::vector<std::vector<std::string>> read_csv(const std::string& text, const std::string& name, const std::string& header);
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path, const std::string& header);
// A number field, the whole text consumed.
double csv_number(const std::string& text, const std::string& name);

}  // namespace rotbench
