#include "harness/store/output_files.hpp"

#include "schemes/registry.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <functional>
#include <fmt/format.h>
#include <mutex>
#include <random>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rotbench {

namespace {

// All of `content` to fd, again after EINTR: 0, or the errno (ENOSPC when nothing was written).
int write_all(int fd, const std::string& content) {
    for (std::size_t done = 0; done < content.size();) {
        const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? errno : ENOSPC;
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

// The temporaries in flight, for a signal handler: fixed storage, read with atomics only.
constexpr std::size_t temporary_slots = 256;
struct TemporarySlot {
    std::atomic<bool> used{false};
    char path[4096] = {};
};
TemporarySlot temporaries[temporary_slots];

void list_temporary(const std::filesystem::path& temporary) {
    const std::string& text = temporary.native();
    if (text.size() >= sizeof TemporarySlot::path) return;
    for (auto& slot : temporaries) {
        if (slot.used.load(std::memory_order_relaxed)) continue;
        static std::mutex claim;
        std::lock_guard lock(claim);
        if (slot.used.load(std::memory_order_relaxed)) continue;
        std::memcpy(slot.path, text.c_str(), text.size() + 1);
        slot.used.store(true, std::memory_order_release);
        return;
    }  // all in use: this one is not removed by a signal (256 writes at once)
}

// The process groups of the programs in flight (gnuplot, a client): a signal stops them before
// it removes the temporaries, or a program that outlives rotbench would write one back.
constexpr std::size_t child_slots = 64;
std::atomic<pid_t> child_groups[child_slots];

extern "C" void remove_temporaries_and_end(int signal) {
    for (auto& group : child_groups)
        if (const pid_t pid = group.load(std::memory_order_acquire); pid > 0 && ::kill(-pid, SIGKILL) == 0) ::waitpid(pid, nullptr, 0);
    for (auto& slot : temporaries)
        if (slot.used.load(std::memory_order_acquire)) ::unlink(slot.path);
    ::signal(signal, SIG_DFL);
    ::raise(signal);
}

}  // namespace

void release_temporary(const std::filesystem::path& temporary) {
    for (auto& slot : temporaries)
        if (slot.used.load(std::memory_order_acquire) && temporary.native() == slot.path) slot.used.store(false, std::memory_order_release);
}

void list_child_group(pid_t group) {
    for (auto& slot : child_groups) {
        pid_t free = 0;
        if (slot.compare_exchange_strong(free, group, std::memory_order_acq_rel)) return;
    }  // all in use: this one is not stopped by a signal (64 programs at once)
}

void release_child_group(pid_t group) {
    for (auto& slot : child_groups) {
        pid_t listed = group;
        if (slot.compare_exchange_strong(listed, 0, std::memory_order_acq_rel)) return;
    }
}

void remove_temporaries_on_signal() {
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_end;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    struct sigaction hangup {};
    sigaction(SIGHUP, nullptr, &hangup);
    if (hangup.sa_handler != SIG_IGN) sigaction(SIGHUP, &action, nullptr);  // ignored on purpose under nohup
}

std::pair<std::filesystem::path, int> open_temporary(const std::filesystem::path& path) {
    // Made new (O_EXCL, never through a link) under a name nobody can guess ahead: in a shared
    // folder (ROTBENCH_CACHE) another user cannot plant a link or a file there for rotbench to
    // write through, and two writers each rename a complete file.
    thread_local std::mt19937_64 random{std::random_device{}() ^ static_cast<std::uint64_t>(::getpid())};
    std::filesystem::path temporary;
    int fd = -1;
    // Listed before it exists: a signal between its creation and its listing would leave it.
    for (int attempt = 0; fd < 0 && attempt < 16; ++attempt) {
        temporary = path.parent_path() / fmt::format(".{}.{:016x}.tmp", path.filename().string(), random());
        list_temporary(temporary);
        fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        const int error = errno;
        if (fd < 0) release_temporary(temporary);
        errno = error;
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) throw OutputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
    return {temporary, fd};
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
    const auto [temporary, fd] = open_temporary(path);
    int error = write_all(fd, content);
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
    if (error != 0) ::unlink(temporary.c_str());
    release_temporary(temporary);
    if (error != 0) {
        throw OutputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(error)));
    }
}

void append_to_file(const std::filesystem::path& path, const std::string& content) {
    // Without blocking (a FIFO with no reader would wait for one), and only to a regular file
    // named directly (not through a symbolic link), which is what every caller's file is.
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0644);
    if (fd < 0 && errno == ELOOP)
        throw OutputError(fmt::format("cannot write {}: a symbolic link; rotbench appends only to a regular file named directly",
                                      path.string()));
    const std::string not_regular = fmt::format("cannot write {}: not a regular file (a FIFO, a device or a directory)", path.string());
    if (fd < 0 && errno == ENXIO) throw OutputError(not_regular);  // a FIFO with no reader
    if (fd < 0) throw OutputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw OutputError(not_regular);
    }
    int error = write_all(fd, content);
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) throw OutputError(fmt::format("cannot write {}: {}", path.string(), std::strerror(error)));
}

std::string read_program_output(const std::filesystem::path& file, const std::string& name, double most_bytes, const std::string& bound,
                                std::string& text) {
    std::error_code ec;
    const auto status = std::filesystem::symlink_status(file, ec);
    if (ec || !std::filesystem::exists(status)) return "its program wrote no " + file.filename().string();
    if (!std::filesystem::is_regular_file(status)) return name + " is not a regular file (a FIFO, a link or a device)";
    if (static_cast<double>(std::filesystem::file_size(file, ec)) > most_bytes || ec)
        return fmt::format("{} is larger than {} can make it ({:.0f} bytes)", name, bound, most_bytes);
    try {
        text = read_input_file(file, name);  // opened without blocking: a file swapped in between is refused
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

namespace {

// Hands what fd holds to `take` a block at a time, to its end or until `take` answers false;
// false on a read error.
bool read_blocks(int fd, const std::function<bool(std::string_view)>& take) {
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n == 0;
        if (!take(std::string_view(buffer, static_cast<std::size_t>(n)))) return true;
    }
}

// What fd holds, to its end or until it is longer than max_bytes; false on a read error.
bool read_to_end(int fd, std::string& text, std::size_t max_bytes) {
    return read_blocks(fd, [&](std::string_view block) {
        text.append(block);
        return text.size() <= max_bytes;
    });
}

}  // namespace

bool feed_file(const std::filesystem::path& path, Fnv1a& hash) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return false;
    struct stat st {};
    const bool ok = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && read_blocks(fd, [&](std::string_view block) {
                        hash.feed(block);
                        return true;
                    });
    ::close(fd);
    return ok;
}

std::optional<std::string> read_file(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return std::nullopt;
    struct stat st {};
    std::string text;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) read_to_end(fd, text, std::string().max_size());
    ::close(fd);
    if (!S_ISREG(st.st_mode)) return std::nullopt;
    return text;
}

namespace {

// An input file open for reading, InputError naming `where` unless it is a regular file.
// O_NONBLOCK: opening a FIFO with no writer would otherwise wait forever.
int open_regular_input(const std::filesystem::path& path, const std::string& where, struct stat& st) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) throw InputError(fmt::format("{}: cannot read the file ({})", where, std::strerror(errno)));
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw InputError(where + ": not a regular file" + (S_ISDIR(st.st_mode) ? " (a directory)" : ""));
    }
    return fd;
}

std::string input_name(const std::filesystem::path& path, const std::string& what) {
    return what.empty() ? path.string() : what + " " + path.string();
}

}  // namespace

std::string read_input_file(const std::filesystem::path& path, const std::string& what, std::size_t max_bytes) {
    const std::string where = input_name(path, what);
    struct stat st {};
    const int fd = open_regular_input(path, where, st);
    if (static_cast<std::size_t>(st.st_size) > max_bytes) {
        ::close(fd);
        throw InputError(fmt::format("{}: {} bytes, more than the {} this input may have", where, st.st_size, max_bytes));
    }
    std::string text;
    const bool read = read_to_end(fd, text, max_bytes);
    const int error = errno;
    ::close(fd);
    if (!read) throw InputError(fmt::format("{}: cannot read the file ({})", where, std::strerror(error)));
    if (text.size() > max_bytes)  // it grew while being read, or its size said nothing (/proc)
        throw InputError(fmt::format("{}: more than the {} bytes this input may have", where, max_bytes));
    return text;
}

std::ifstream open_input_stream(const std::filesystem::path& path, const std::string& what) {
    const std::string where = input_name(path, what);
    struct stat st {};
    const int fd = open_regular_input(path, where, st);
    // The stream opens the file that fd has open (its /proc link), not whatever the path names now.
    std::ifstream in(fmt::format("/proc/self/fd/{}", fd), std::ios::binary);
    ::close(fd);
    if (!in) throw InputError(where + ": cannot read the file");
    return in;
}

std::string format_number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return fmt::format("{}", value);  // shortest representation that round-trips
}

}  // namespace rotbench
