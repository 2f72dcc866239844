// Reading and writing files. Output is written to a temporary file beside the target and
// renamed over it (atomic on POSIX), so a kill or a full disk never leaves half a file; input
// is read only from regular files of bounded size, so /dev/zero or a FIFO is refused, not
// read forever.
#pragma once

#include "harness/core/fnv1a.hpp"

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <sys/types.h>
#include <utility>

namespace rotbench {

// A file that could not be written once the work had started (a full disk, a directory made
// read-only under it): the command stops, keeps what it finished, and exits 3.
struct OutputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// OutputError naming the file and the reason; no temporary file is left behind.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// A new, empty temporary file beside `path` (O_EXCL, never through a link, under a random
// name), open for writing: the one way rotbench names a temporary. OutputError when it cannot.
// It is listed until release_temporary (after its rename, or its removal), so that a signal
// that ends the process removes it (remove_temporaries_on_signal).
std::pair<std::filesystem::path, int> open_temporary(const std::filesystem::path& path);
void release_temporary(const std::filesystem::path& temporary);

// From now on SIGINT, SIGTERM or SIGHUP, where nothing else handles them (an executor stops its runs
// itself), first kills the programs in flight and removes the temporaries in flight, then ends
// the process by that signal.
void remove_temporaries_on_signal();
// A started program's process group, listed from its start until it is killed, for that signal.
void list_child_group(pid_t group);
void release_child_group(pid_t group);

// Appends `content` to the regular file (made if absent) in append mode: one write(2) a call,
// so that records appended by several threads do not interleave. OutputError naming the file,
// at once, for a symbolic link, a FIFO, a device or a directory.
void append_to_file(const std::filesystem::path& path, const std::string& content);

// A file another program wrote (a client's trajectory.csv or samples.csv), called `name` in
// messages: "" with its text in `text` when it is a regular file of at most `most_bytes` (what
// `bound` says can make it), else why not; never waits on a FIFO, never reads a file too large.
std::string read_program_output(const std::filesystem::path& file, const std::string& name, double most_bytes, const std::string& bound,
                                std::string& text);

// Feeds a regular file's bytes to `hash` a block at a time, so that a file of gigabytes (a
// plug-in, a client's interpreter) is never held whole; false when it is not a regular file
// that can be read.
bool feed_file(const std::filesystem::path& path, Fnv1a& hash);

// The whole file as it is on disk, or nothing when it cannot be opened.
std::optional<std::string> read_file(const std::filesystem::path& path);

// An input file a user names (config, gate, CSV): InputError unless it is a regular file of
// at most `max_bytes`, naming `what` (the option or role) and the path.
inline constexpr std::size_t max_input_bytes = 256u << 20;  // 256 MiB: twice a default suite's CSVs, many times over
std::string read_input_file(const std::filesystem::path& path, const std::string& what, std::size_t max_bytes = max_input_bytes);

// An input file of any size, to be read as a stream (the run store, the journal): InputError
// as above unless it is a regular file that opens.
std::ifstream open_input_stream(const std::filesystem::path& path, const std::string& what);

// A number in the shortest form that reads back to the same double; "nan", "inf", "-inf".
std::string format_number(double value);

}  // namespace rotbench
