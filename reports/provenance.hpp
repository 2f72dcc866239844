// Where a result comes from: rotbench's version and commit, the compiler and flags, the CPU
// and the date, for every report and summary.
#pragma once

#include <string>

namespace rotbench {

struct Provenance {
    std::string version, commit, compiler, build_type, flags, cpu, date;  // date: UTC, ISO 8601
};
Provenance provenance();

}  // namespace rotbench
