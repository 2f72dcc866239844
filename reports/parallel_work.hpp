// How a report runs independent pieces of work (its plots: most of their time is gnuplot):
// parallel(count, work) calls work(0) ... work(count - 1), in any order and on any threads,
// and returns when all have finished. The report owns no threads; the caller hands one in.
#pragma once

#include <cstddef>
#include <functional>

namespace rotbench {

using ParallelWork = std::function<void(std::size_t count, const std::function<void(std::size_t)>& work)>;

inline void run_serially(std::size_t count, const std::function<void(std::size_t)>& work) {
    for (std::size_t i = 0; i < count; ++i) work(i);
}

}  // namespace rotbench
