// The cost tables that the benchmark scripts write beside a run, read and checked once so that
// the report only formats them: DIR/cost.csv (benchmarks/cost.py: per body-step times, batched
// and one body at a time, and instruction counts) and DIR/granular_speed.csv
// (benchmarks/granular_speed.py: rotbench's granular step beside LIGGGHTS's).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rotbench {

struct CostRow {
    std::string scheme, public_code, failure;  // public_code: the public code's counterpart compared with, if any
    std::map<std::string, double> values;      // every numeric column; NaN where the field is empty
    double value(const std::string& column) const;  // NaN when absent or empty
};

struct CostTable {
    bool thorough = false;      // benchmarks/cost.py --thorough: 10 processes, not two consecutive tables
    std::vector<CostRow> rows;  // costed schemes, in the file's order
    std::vector<CostRow> failed;  // schemes whose process failed: the id and why
};

// Nothing when DIR has no cost.csv; InputError naming the line and column for a field that
// should be a number and is not (the file may be hand-edited).
std::optional<CostTable> read_cost_table(const std::filesystem::path& dir);

struct GranularSpeedRow {
    std::string code, phase;  // code: rotbench or liggghts; phase: fill or discharge
    double t_end = 0, steps = 0, spheres = 0, cpu_seconds = 0, cpu_per_sphere_step = 0;
};

// Empty when DIR has no granular_speed.csv; InputError as above.
std::vector<GranularSpeedRow> read_granular_speed(const std::filesystem::path& dir);

}  // namespace rotbench
