// What the machine offers: the defaults of --jobs and the limits a plan is checked against.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <malloc.h>
#include <sys/resource.h>
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

// Under an address-space limit, threads share two malloc arenas: glibc reserves 64 MiB of
// address space for each of up to 8 per core, which took a 2 GB `ulimit -v` before the work did.
inline void fit_allocator_to_address_space() {
    rlimit space{};
    if (::getrlimit(RLIMIT_AS, &space) == 0 && space.rlim_cur != RLIM_INFINITY) ::mallopt(M_ARENA_MAX, 2);
}

// The threads this process can add and still keep half of what is left of its address space
// for their work, under an address-space limit (ulimit -v, as batch systems set); each takes
// a stack of RLIMIT_STACK (8 MiB by default). Without a limit, as many as asked.
inline int affordable_threads() {
    rlimit space{}, stack{};
    if (::getrlimit(RLIMIT_AS, &space) != 0 || space.rlim_cur == RLIM_INFINITY) return std::numeric_limits<int>::max();
    const double stack_bytes = ::getrlimit(RLIMIT_STACK, &stack) == 0 && stack.rlim_cur != RLIM_INFINITY ? double(stack.rlim_cur) : 8.0 * (1 << 20);
    double used = 0;  // the address space in use now: the first field of /proc/self/statm, in pages
    if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
        unsigned long pages = 0;
        if (std::fscanf(statm, "%lu", &pages) == 1) used = double(pages) * double(::sysconf(_SC_PAGE_SIZE));
        std::fclose(statm);
    }
    const double left = double(space.rlim_cur) - used;
    return left > 0 ? static_cast<int>(std::min(left / (2 * stack_bytes), 1e6)) : 0;
}

}  // namespace rotbench
