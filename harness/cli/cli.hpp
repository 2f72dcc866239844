// The command line (CLI11): `rotbench VERB [options]`, one verb per file in harness/cli/.
// Returns the exit status: 0 done (unstable runs are results, not errors), 1 a gate check
// failed, 2 bad input.
#pragma once

#include <ostream>

namespace rotbench {

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace rotbench
