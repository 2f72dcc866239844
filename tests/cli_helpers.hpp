// Running the CLI in-process from a test: exit status, stdout and stderr as a user sees them.
#pragma once

#include "harness/cli/cli.hpp"
#include "harness/io/parse.hpp"
#include "harness/engine/run.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace rotbench::test {

namespace fs = std::filesystem;

struct Cli {
    int status;
    std::string out, err;
};

inline Cli cli(std::vector<std::string> args) {
    args.insert(args.begin(), "rotbench");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int status = run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
    return {status, out.str(), err.str()};
}

inline fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("rotbench_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

inline std::string read(const fs::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), {}};
}

// A CSV without the rows that hold a timing metric: what two runs of one command share.
inline std::string without_timing(const std::string& csv) {
    std::istringstream in(csv);
    std::string line, out;
    while (std::getline(in, line)) {
        const auto fields = split_commas(line);
        if (std::none_of(fields.begin(), fields.end(), is_timing_metric)) out += line + "\n";
    }
    return out;
}

inline bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == s.size() - 1; }


inline void write(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

}  // namespace rotbench::test
