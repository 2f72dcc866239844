// The runs of a sweep finished so far, kept on disk as they finish so that a kill or a
// signal loses at most the runs in flight; `rotbench run --resume DIR` reads them back and
// runs only the rest. Layout, under DIR/partial:
//   command   the arguments of the run, one per line (what --resume runs again)
//   cwd       the directory it was started in (relative paths in the arguments are from there)
//   plan      the plan fingerprint and the number of runs
//   runs      the finished runs, one record each, appended as they finish:
//             "run INDEX R N S" (its index in the plan, then byte counts), R bytes of its
//             results.csv, N of its runs.csv, S of its energy series (0: none), "end INDEX".
// A record is appended by one write in append mode; only a kill in the middle of one can
// leave it cut short, at the end of the file, and a cut record counts as not finished.
// (One file for all runs: a directory of files per run made the file system allocate
// thousands of inodes per sweep, 1-1.5 s of the default suite.) The journal goes once the
// final outputs are written.
#pragma once

#include "harness/engine/run.hpp"

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

class Journal {
public:
    static bool exists(const std::filesystem::path& out_dir);
    // A new journal in out_dir/partial (an old one is removed).
    static Journal start(const std::filesystem::path& out_dir, const std::vector<std::string>& arguments,
                         const std::string& plan_id, std::size_t plan_size);
    // The journal of an interrupted run. InputError when out_dir has none, or when the
    // sweep its arguments describe now is another one (a scheme or scene changed).
    static Journal reopen(const std::filesystem::path& out_dir, const std::string& plan_id, std::size_t plan_size);
    // The arguments the interrupted run was given. InputError when out_dir has no journal.
    static std::vector<std::string> arguments(const std::filesystem::path& out_dir);
    static std::filesystem::path working_directory(const std::filesystem::path& out_dir);

    // The runs on disk, by plan index (half-written temporaries are discarded).
    std::map<std::size_t, RunResult> finished() const;
    // Writes one finished run. Safe to call from several threads for different indices.
    void record(std::size_t plan_index, const RunResult& result) const;
    void remove() const;
    // The journal of out_dir, once the outputs it served are written.
    static void discard(const std::filesystem::path& out_dir);

private:
    explicit Journal(std::filesystem::path dir) : dir_(std::move(dir)) {}
    std::filesystem::path dir_;
};

}  // namespace rotbench
