// The runs of a command finished so far, kept on disk as they finish so that a kill or a
// signal loses at most the runs in flight; `--resume DIR` reads them back and the command
// makes only the rest. A run is found again by its key (RunSpec), so a command whose runs
// depend on earlier ones (advise) is resumed as simply as a fixed plan. One file, DIR/partial/runs.jsonl:
//   its first line  what the command was: {"journal": {"command": [its arguments], "cwd": the
//                   directory it was started in (relative paths in the arguments are from
//                   there), "files": [[hash, path] of each plug-in and client file loaded]}};
//                   written whole before any run, its presence marks a journal
//   then            the finished runs, one record each (harness/store/run_record.hpp), appended
//                   as they finish; a record's index counts the records
// A record is appended by one write in append mode; only a kill in the middle of one can
// leave it cut short, at the end of the file, and a cut record counts as not finished.
// (One file for all runs: a directory of files per run made the file system allocate
// thousands of inodes per sweep, 1-1.5 s of the default suite.) The journal goes once the
// final outputs are written.
#pragma once

#include "harness/core/run.hpp"
#include "harness/store/output_dir.hpp"

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rotbench {

class Journal {
public:
    // A new journal in out/partial, the plug-ins and client files loaded now named by their hashes.
    static Journal start(const OutputDir& out, const std::vector<std::string>& arguments);
    // The journal of an interrupted command. InputError when out has none, or when a plug-in or
    // client file it ran has changed since (another hash).
    static Journal reopen(const OutputDir& out);
    // The arguments the interrupted command was given. InputError when out_dir has no journal.
    static std::vector<std::string> arguments(const std::filesystem::path& out_dir);
    static std::filesystem::path working_directory(const std::filesystem::path& out_dir);

    // The runs on disk, by key. A record cut short by a kill does not count; a key recorded
    // twice is an InputError: the journal was changed by something else.
    std::map<RunSpec, RunResult> finished() const;
    // Writes one finished run (OutputError when it cannot). Safe to call from several threads.
    void record(const RunResult& result) const;
    // The journal's files in out_dir, once the outputs it served are written.
    static void discard(const std::filesystem::path& out_dir);
    const std::filesystem::path& directory() const { return out_.path(); }

private:
    Journal(OutputDir out, std::size_t records) : out_(std::move(out)), records_(std::make_shared<std::atomic<std::size_t>>(records)) {}
    OutputDir out_;
    std::shared_ptr<std::atomic<std::size_t>> records_;  // the next record's index
};

}  // namespace rotbench
