// A test that cannot run in this build says so and stops: CTest then counts it as skipped, not
// passed (SKIP_REGULAR_EXPRESSION in tests/CMakeLists.txt; Catch2 2.13 has no SKIP of its own).
#pragma once

#include <iostream>

#define ROTBENCH_SKIP(reason)                                               \
    do {                                                                    \
        std::cout << "rotbench: test skipped: " << (reason) << std::endl;   \
        return;                                                             \
    } while (false)
