#include "harness/store/output_dir.hpp"

#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "schemes/registry.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <stdexcept>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

constexpr const char* meta = ".rotbench";
constexpr const char* manifest_header = "rotbench manifest 1\n";

fs::path manifest_path(const fs::path& dir) { return dir / meta / "manifest"; }

// A name rotbench may write under an output folder: relative, below it, outside its
// bookkeeping. A manifest is input (the folder may come from someone else): it is held to this.
bool own_name(const std::string& relative) {
    const fs::path path(relative);
    if (relative.empty() || path.is_absolute() || *path.begin() == meta) return false;
    for (const auto& part : path)
        if (part.empty() || part == "." || part == "..") return false;
    return std::none_of(relative.begin(), relative.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; });
}

// Nothing is written, read back or removed through a symbolic link inside an output folder:
// one planted there (or in a folder received from someone else) would lead outside it.
void refuse_links(const fs::path& dir, const fs::path& relative) {
    fs::path at = dir;
    for (const auto& part : relative) {
        at /= part;
        std::error_code ec;
        if (fs::symlink_status(at, ec).type() == fs::file_type::symlink)
            throw InputError("--out " + dir.string() + ": " + at.string() + " is a symbolic link; rotbench writes nothing through a link in its folder");
    }
}

std::vector<std::pair<std::string, std::string>> read_manifest(const fs::path& dir) {
    std::vector<std::pair<std::string, std::string>> entries;
    refuse_links(dir, fs::path(meta) / "manifest");
    const auto text = read_file(manifest_path(dir));
    if (!text) return entries;
    if (text->rfind(manifest_header, 0) != 0) throw InputError((manifest_path(dir)).string() + ": not a rotbench manifest");
    for (const auto& line : split_on(text->substr(std::string(manifest_header).size()), '\n')) {
        if (line.empty()) continue;
        const auto tab = line.find('\t');
        if (tab == std::string::npos) throw InputError(manifest_path(dir).string() + ": a line without its family");
        if (!own_name(line.substr(tab + 1)))
            throw InputError(manifest_path(dir).string() + ": lists '" + line.substr(tab + 1) +
                             "', which is not a name rotbench writes in its folder; the folder's bookkeeping was changed by something else");
        entries.push_back({line.substr(0, tab), line.substr(tab + 1)});
    }
    return entries;
}

void write_manifest(const fs::path& dir, const std::vector<std::pair<std::string, std::string>>& entries) {
    std::string text = manifest_header;
    for (const auto& [family, file] : entries) text += family + "\t" + file + "\n";
    write_file_atomically(manifest_path(dir), text);
}

bool empty_directory(const fs::path& dir) {
    std::error_code ec;
    return fs::is_directory(dir, ec) && fs::directory_iterator(dir, ec) == fs::directory_iterator();
}

// The folders a command writes into: taken by a file, they would fail it mid-way.
const char* const subfolders[] = {"plots", "series", "snapshots", "walls", "partial", meta};

}  // namespace

OutputDir::State::~State() {
    if (lock_fd >= 0) ::close(lock_fd);  // releases the flock
}

namespace {

using Manifest = std::vector<std::pair<std::string, std::string>>;  // (family, file)

// What stands in the way of the request in an existing `dir`: a link where rotbench writes, a
// file it did not write, another family's, an interrupted run, a finished one (its marker). Its
// manifest when nothing does.
Manifest refuse_what_is_in_the_way(const fs::path& dir, const OutputDir::Request& r) {
    const std::string name = dir.string();
    std::error_code ec;
    refuse_links(dir, fs::path(meta) / "lock");
    for (const char* sub : subfolders) refuse_links(dir, sub);
    refuse_links(dir, "partial/runs.jsonl");
    const bool ours = fs::exists(manifest_path(dir), ec);
    if (!empty_directory(dir) && !ours && !r.overwrite)
        throw InputError("--out " + name + " holds files rotbench did not write; choose another directory, or pass --overwrite to "
                         "write beside them (none of them is replaced)");
    Manifest manifest = ours ? read_manifest(dir) : Manifest{};
    if (!r.resuming && fs::exists(dir / "partial" / "runs.jsonl", ec) && !r.overwrite)
        throw InputError("--out " + name + " holds an interrupted run; rotbench run --resume " + name +
                         " finishes it, --overwrite starts again");
    if (!r.marker.empty() && !r.overwrite && !r.resuming && fs::exists(dir / r.marker, ec))
        throw InputError("--out " + name + " already holds " + r.marker + "; pass --overwrite or choose another directory");
    for (const char* sub : subfolders)
        if (fs::exists(dir / sub, ec) && !fs::is_directory(dir / sub, ec))
            throw InputError("--out " + name + ": " + (dir / sub).string() + " is a file where rotbench writes a directory");
    for (const auto& file : r.files) {
        if (!fs::exists(dir / file, ec)) continue;
        const auto entry = std::find_if(manifest.begin(), manifest.end(), [&](const auto& e) { return e.second == file; });
        if (entry == manifest.end())
            throw InputError("--out " + name + ": " + (dir / file).string() + " exists and was not written by rotbench; it is never replaced");
        if (entry->first != r.family)
            throw InputError("--out " + name + ": " + (dir / file).string() + " was written by rotbench " + entry->first +
                             "; it is not replaced by " + r.family + " (choose another directory)");
    }
    return manifest;
}

// The folder's lock, held (flock) by this process and holding its pid; InputError when another
// rotbench holds it or it cannot be taken.
int take_lock(const fs::path& dir) {
    const std::string name = dir.string(), lock = (dir / meta / "lock").string();
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError("--out " + name + ": the directory is not writable");
    struct stat lock_stat {};
    if (::fstat(fd, &lock_stat) != 0 || !S_ISREG(lock_stat.st_mode)) {
        ::close(fd);
        throw InputError("--out " + name + ": " + lock + " is not a regular file; the folder's bookkeeping was changed by something else");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd);
        const auto holder = read_file(lock).value_or("");
        throw InputError("--out " + name + " is in use by another rotbench" + (holder.empty() ? "" : " (process " + holder + ")") +
                         "; wait for it or choose another directory");
    }
    const std::string pid = std::to_string(::getpid());
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
        ::close(fd);
        throw InputError("--out " + name + ": the directory is not writable");
    }
    return fd;
}

}  // namespace

OutputDir OutputDir::open(const fs::path& dir, const Request& r) {
    const std::string name = dir.string();
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) throw InputError("--out " + name + ": cannot create the directory (a file is there)");
    const bool existed = fs::exists(dir, ec);
    Manifest manifest = existed ? refuse_what_is_in_the_way(dir, r) : Manifest{};
    if (!existed) {
        fs::create_directories(dir, ec);
        if (ec || !fs::is_directory(dir)) throw InputError("--out " + name + ": cannot create the directory");
    }
    auto state = std::make_shared<State>();
    state->dir = dir;
    state->family = r.family;
    try {  // a refused command leaves no directory of its own behind
        fs::create_directories(dir / meta, ec);
        if (ec) throw InputError("--out " + name + ": the directory is not writable");
        state->lock_fd = take_lock(dir);
        // --overwrite replaces the family's earlier outputs: only the files its manifest lists.
        if (r.overwrite && !r.resuming) {
            Manifest kept;
            for (const auto& entry : manifest) {
                if (entry.first != r.family) {
                    kept.push_back(entry);
                    continue;
                }
                refuse_links(dir, fs::path(entry.second).parent_path());
                fs::remove(dir / entry.second, ec);  // the name itself, were it a link: never what it points to
            }
            manifest = std::move(kept);
        }
        state->manifest = std::move(manifest);
        write_manifest(dir, state->manifest);
    } catch (const InputError&) {
        if (!existed) fs::remove_all(dir, ec);
        throw;
    }
    return OutputDir(std::move(state));
}

void OutputDir::check(const std::string& relative) const {
    if (!own_name(relative)) throw std::logic_error("not an output name: " + relative);
    refuse_links(state_->dir, relative);
    std::error_code ec;
    const fs::path file = state_->dir / relative;
    if (!fs::exists(file, ec)) return;
    const auto entry = std::find_if(state_->manifest.begin(), state_->manifest.end(),
                                    [&](const auto& e) { return e.second == relative; });
    if (entry == state_->manifest.end())
        throw InputError(file.string() + " exists and was not written by rotbench; it is never replaced");
    if (entry->first != state_->family)
        throw InputError(file.string() + " was written by rotbench " + entry->first + "; it is not replaced by " + state_->family);
}

void OutputDir::record(const std::string& relative) const {
    const bool known = std::any_of(state_->manifest.begin(), state_->manifest.end(), [&](const auto& e) { return e.second == relative; });
    if (known) return;
    state_->manifest.push_back({state_->family, relative});
    write_manifest(state_->dir, state_->manifest);
}

void OutputDir::write(const std::string& relative, const std::string& content) const {
    const fs::path file = claim(relative);
    write_file_atomically(file, content);
}

fs::path OutputDir::claim(const std::string& relative) const {
    std::lock_guard lock(state_->mutex);
    check(relative);
    const fs::path file = state_->dir / relative;
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    record(relative);  // listed before it exists: a kill in between leaves a listed name, never an unlisted file
    return file;
}

void check_distinct_outputs(const std::vector<std::pair<std::string, fs::path>>& outputs) {
    std::vector<std::pair<std::string, fs::path>> seen;
    for (const auto& [option, file] : outputs) {
        if (file.empty()) continue;
        std::error_code ec;
        const fs::path resolved = fs::weakly_canonical(fs::absolute(file), ec);
        for (const auto& [other, where] : seen)
            if (where == resolved) throw InputError(option + " and " + other + " name one file, " + file.string() + "; give each its own");
        seen.push_back({option, resolved});
    }
}

void check_output_file(const fs::path& file, const std::string& option, bool overwrite, const std::string& signature) {
    std::error_code ec;
    const fs::path parent = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    // The nearest folder that exists. Missing ones are made only when the file is written
    // (write_output_file): a command refused after this check leaves none behind.
    fs::path existing = parent;
    while (!existing.empty() && !fs::exists(fs::symlink_status(existing, ec))) existing = existing.parent_path();
    if (existing.empty()) existing = ".";
    if (existing != parent) {
        if (!fs::is_directory(existing, ec))
            throw InputError(option + " " + file.string() + ": cannot create the directory " + parent.string() + ": " + existing.string() +
                             " is not a directory");
    } else if (!fs::is_directory(parent, ec)) {
        throw InputError(option + " " + file.string() + ": " + parent.string() + " is not a directory");
    } else if (fs::exists(file, ec)) {
        if (!fs::is_regular_file(file, ec)) throw InputError(option + " " + file.string() + ": not a regular file");
        if (!overwrite) throw InputError(option + " " + file.string() + " exists; pass --overwrite to replace it");
        const auto head = read_file(file).value_or("");
        if (head.rfind(signature, 0) != 0)
            throw InputError(option + " " + file.string() + " exists and is not a file rotbench wrote; it is never replaced");
    }
    // The nearest folder must take a new entry: probed now, not after the work.
    const fs::path probe = existing / fmt::format(".rotbench-probe-{}", ::getpid());
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError(option + " " + file.string() + ": cannot write in " + existing.string() + ": " + std::strerror(errno));
    ::close(fd);
    fs::remove(probe, ec);
}

void write_output_file(const fs::path& file, const std::string& content) {
    std::error_code ec;
    if (!file.parent_path().empty()) fs::create_directories(file.parent_path(), ec);  // made as --out makes its folder
    if (ec) throw OutputError("cannot create the directory " + file.parent_path().string() + ": " + ec.message());
    write_file_atomically(file, content);
}

}  // namespace rotbench
