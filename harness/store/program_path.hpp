// Where a program named without a '/' is found: the first folder of PATH holding an executable
// file of that name, as execvp would look. One lookup for a client file's load-time check and
// for starting a program (harness/exec/isolation.hpp).
#pragma once

#include <string>

namespace rotbench {

// The full path, or "" when no folder of PATH holds it (or PATH is unset).
std::string find_on_path(const std::string& name);

}  // namespace rotbench
