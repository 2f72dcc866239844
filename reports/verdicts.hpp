// The verdict table: one row per scheme, what it claims against what the runs show.
#pragma once

#include "harness/analysis/orders.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/analysis/stability_study.hpp"

#include <string>
#include <vector>

namespace rotbench {

// The scene whose ns_per_step is the report's cost figure: asymmetric_free, or else the first
// single-body scene of the runs.
std::string cost_scene(const ResultSet& set);

// Markdown: the table and how each column is read.
std::string verdict_section(const ResultSet& set, const std::vector<OrderRow>& orders, const std::vector<StabilityRow>& stability);

}  // namespace rotbench
