// The TOML run configuration: the same selections and scene keys as the command line.
//
//   [run]
//   scenes  = ["cylinder_free"]
//   schemes = ["direct", "zvw_corrected"]
//   dt      = [1e-3, 1e-4]
//   t_end   = 0.5
//
//   [cylinder_free]              # one table per scene: its parameters
//   omega0 = [0.0, 1.0, 100.0]
//
// Errors name the file, line and column (InputError).
#pragma once

#include "harness/analysis/sweep_plan.hpp"

#include <string>
#include <vector>

namespace rotbench {

SweepSpec load_config(const std::string& path);
// The same for text already read; `name` stands for the file in messages.
SweepSpec parse_config(std::string_view text, const std::string& name);

// One `--set SCENE.KEY=VALUE` (VALUE: a number or a comma list), added to `spec`.
void add_setting(SweepSpec& spec, const std::string& text);

// The `--set` settings of a command on one scene (KEY=VALUE, or SCENE.KEY=VALUE naming it).
ParamOverrides scene_settings(const std::string& scene, const std::vector<std::string>& settings);

}  // namespace rotbench
