// What the machine offers: the defaults of --jobs and the limits a plan is checked against.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <unistd.h>

namespace rotbench {

// The cores this machine offers (at least 1): the default number of threads.
inline int core_count() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

// Its physical memory in bytes (8 GB when the system does not say).
inline double memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 8e9;
}

}  // namespace rotbench
