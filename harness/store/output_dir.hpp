// The directories rotbench writes into, and the rule that keeps it from losing anything:
// a directory is rotbench's when it is new, or empty, or carries rotbench's manifest of the
// files it wrote there (DIR/.rotbench/manifest). Anything else needs --overwrite, and even
// then no file that rotbench did not write is deleted or replaced: --overwrite removes only
// files the manifest lists. Each file is listed with the family of commands that wrote it
// (run, stability, gate, compare): a family replaces its own files only, so that a gate
// never replaces a finished run's results.csv. While a command writes into a directory it
// holds a lock on it (flock), and a second process is refused, never mixed in.
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace rotbench {

class OutputDir {
public:
    struct Request {
        std::string family;               // run, stability, gate, compare
        std::string marker;               // the file whose presence means the family's outputs are there ("" : none)
        std::vector<std::string> files;   // the names it will write that are known now, checked before any work
        bool overwrite = false;           // replace the family's earlier outputs (and write into a foreign directory)
        bool resuming = false;            // the directory holds the journal being resumed
    };

    // Refused (InputError, one line) before anything is written: a directory holding the
    // family's outputs without overwrite, an interrupted run (unless resuming), one in use
    // by another process, a foreign directory without overwrite, a known name taken by a
    // file rotbench did not write, a sub-directory name taken by a file, or one that cannot
    // be written. A directory it had to create is removed again when the command is refused.
    static OutputDir open(const std::filesystem::path& dir, const Request& request);

    const std::filesystem::path& path() const { return state_->dir; }

    // Writes dir/relative atomically and lists it. InputError when the name is taken by a
    // file rotbench did not write here, or by another family's.
    void write(const std::string& relative, const std::string& content) const;
    // For a file another program writes (gnuplot) or one appended to (the journal): checks
    // the name as write() does and lists it; returns the full path.
    std::filesystem::path claim(const std::string& relative) const;

private:
    struct State {
        std::filesystem::path dir;
        std::string family;
        int lock_fd = -1;
        std::mutex mutex;
        std::vector<std::pair<std::string, std::string>> manifest;  // (family, relative path)
        ~State();
    };
    explicit OutputDir(std::shared_ptr<State> state) : state_(std::move(state)) {}
    void check(const std::string& relative) const;  // with the mutex held
    void record(const std::string& relative) const;
    std::shared_ptr<State> state_;
};

// A single output file (--junit, --summary, reference and trajectory --out): refused when it
// exists, unless overwrite and it begins with `signature` (the start of a file of this kind
// that rotbench writes); so no other file is ever replaced. Checked before the work, written
// after it by write_output_file, which makes its missing folders.
void check_output_file(const std::filesystem::path& file, const std::string& option, bool overwrite, const std::string& signature);
void write_output_file(const std::filesystem::path& file, const std::string& content);

// Refused (InputError, one line) when two of a command's outputs, each (option, file), are one
// file: the one written last would silently take the other's place. An empty file is not given.
void check_distinct_outputs(const std::vector<std::pair<std::string, std::filesystem::path>>& outputs);

}  // namespace rotbench
