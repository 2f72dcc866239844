// Reading TOML input files (run configurations, gates): every error names the file, line
// and column (InputError), and ids and scene keys are checked against the registries.
#pragma once

#include "harness/scenes/params.hpp"
#include "schemes/registry.hpp"

#include <string>
#include <string_view>
#include <vector>

// The fuzz build (tests/fuzz/run.sh) drops toml++'s internal debug assertions, as NDEBUG
// does in Release: 3.3.0 asserts on "[" then a newline, which its parser reports as an error.
#ifdef ROTBENCH_TOML_NO_ASSERT
#define TOML_ASSERT(expr) static_cast<void>(0)
#endif
#include <toml++/toml.h>

namespace rotbench {

// The parsed file; a syntax error or an unreadable file is an InputError.
toml::table parse_toml_file(const std::string& path);
// The same for text already read; `name` stands for the file in messages.
toml::table parse_toml_text(std::string_view text, const std::string& name);

[[noreturn]] void toml_error(const std::string& path, const toml::node& node, const std::string& message);

// A number or an array of numbers (integers convert; strings and booleans do not).
std::vector<double> numbers(const std::string& path, const std::string& key, const toml::node& node);
// One finite number greater than 0.
double positive_number(const std::string& path, const std::string& key, const toml::node& node);
std::string text(const std::string& path, const std::string& key, const toml::node& node);
std::vector<std::string> strings(const std::string& path, const std::string& key, const toml::node& node);

// An array of registered ids (valid ones listed on error, duplicates rejected).
template <class Product, class Extra>
std::vector<std::string> ids(const std::string& path, const std::string& key, const toml::node& node,
                             const Registry<Product, Extra>& registry, const std::string& kind);

// The keys of `table` as parameters of scene `scene` (checked against its declared keys).
ParamOverrides scene_overrides(const std::string& path, const std::string& scene, const toml::table& table);

}  // namespace rotbench

#include "harness/store/toml_input.ipp"
