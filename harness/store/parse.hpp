// Strict parsing of the numbers and id lists given on the command line: anything that
// is not exactly what was asked for is an InputError naming the option.
#pragma once

#include "schemes/registry.hpp"

#include <string>
#include <vector>

namespace rotbench {

// A finite number > 0, the whole text consumed ("1e-3" yes; "1e-3s", "", "nan", "-1" no).
double parse_positive(const std::string& text, const std::string& option);

// A finite number, the whole text consumed.
double parse_finite(const std::string& text, const std::string& option);

// A comma list of positive numbers; duplicates are rejected.
std::vector<double> parse_positive_list(const std::string& text, const std::string& option);

// A comma list of finite numbers >= 0; duplicates are rejected.
std::vector<double> parse_nonnegative_list(const std::string& text, const std::string& option);

// A comma list of registered ids (valid ones listed on error); duplicates are rejected.
template <class Product, class Extra>
std::vector<std::string> parse_id_list(const std::string& text, const Registry<Product, Extra>& registry,
                                       const std::string& kind);

std::vector<std::string> split_commas(const std::string& text);
// An id as schemes, scenes and metrics have them: 1 to max_id_length letters, digits and
// underscores (an id is part of file names, which the file system limits to 255 bytes).
inline constexpr std::size_t max_id_length = 64;
bool is_id(const std::string& text);
std::vector<std::string> split_on(const std::string& text, char separator);

}  // namespace rotbench

#include "harness/store/parse.ipp"
