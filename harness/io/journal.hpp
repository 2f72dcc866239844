// The runs of a sweep finished so far, kept on disk as they finish so that a kill or a
// signal loses at most the runs in flight; `rotbench run --resume DIR` reads them back and
// runs only the rest. Layout, under DIR/partial:
//   command   the arguments of the run, one per line (what --resume runs again)
//   cwd       the directory it was started in (relative paths in the arguments are from there)
//   plan      the plan fingerprint and the number of runs
//   plugins   the plug-ins loaded, each with the hash of its file (a changed one is refused on resume)
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
#include "harness/io/output_dir.hpp"

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

class Journal {
public:
    static bool exists(const std::filesystem::path& out_dir);
    // A new journal in out/partial for the runs of `plan`, the plug-ins loaded now named by
    // their hashes.
    static Journal start(const OutputDir& out, const std::vector<std::string>& arguments, const std::string& plan_id,
                         const std::vector<RunSpec>& plan);
    // The journal of an interrupted run. InputError when out has none, when the sweep its
    // arguments describe now is another one (a scheme or scene changed), or when a plug-in it
    // ran has changed since (another hash).
    static Journal reopen(const OutputDir& out, const std::string& plan_id, const std::vector<RunSpec>& plan);
    // The arguments the interrupted run was given. InputError when out_dir has no journal.
    static std::vector<std::string> arguments(const std::filesystem::path& out_dir);
    static std::filesystem::path working_directory(const std::filesystem::path& out_dir);

    // The runs on disk, by plan index. A record cut short by a kill does not count; a record
    // that does not belong to the plan (an index out of range, another run, a duplicate) is
    // an InputError: the journal was changed by something else.
    std::map<std::size_t, RunResult> finished() const;
    // Writes one finished run (OutputError when it cannot). Safe to call from several threads.
    void record(std::size_t plan_index, const RunResult& result) const;
    // The journal's files in out_dir, once the outputs it served are written.
    static void discard(const std::filesystem::path& out_dir);

private:
    Journal(OutputDir out, std::vector<RunSpec> plan) : out_(std::move(out)), plan_(std::move(plan)) {}
    OutputDir out_;
    std::vector<RunSpec> plan_;
};

}  // namespace rotbench
