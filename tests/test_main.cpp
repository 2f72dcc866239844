#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "harness/exec/isolation.hpp"

// Plug-in runs made in this test program are isolated in the real binary, as they are when a
// user runs rotbench (whose main() names its own executable).
static const bool worker_named = (rotbench::set_worker_executable(ROTBENCH_EXE), true);
